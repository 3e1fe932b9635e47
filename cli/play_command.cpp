#include "play_command.hpp"

#include "batch_runner.hpp"

#include "railodd/scenario/play.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/util/file_names.hpp"
#include "railodd/util/output_stage.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace railodd::cli {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
namespace play = scenario::play;

namespace {

bool executable(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

// --player, else $RAILODD_ESMINI, else esmini on the PATH, else the shared
// tools folder beside the working directory or beside the source tree.
fs::path find_player(const std::string& given) {
    if (!given.empty()) {
        if (!executable(given)) {
            throw InputError(given, "no executable OpenSCENARIO player (esmini) there");
        }
        return fs::absolute(given);
    }
    if (const char* env = std::getenv("RAILODD_ESMINI"); env && executable(env)) {
        return fs::absolute(env);
    }
    if (const char* path = std::getenv("PATH")) {
        std::stringstream dirs(path);
        for (std::string dir; std::getline(dirs, dir, ':');) {
            if (!dir.empty() && executable(fs::path{dir} / "esmini")) {
                return fs::path{dir} / "esmini";
            }
        }
    }
    for (const fs::path& base : {fs::current_path(), fs::path{RAILODD_SOURCE_DIR}}) {
        const fs::path p = base / ".." / "shared" / "tools" / "esmini" / "bin" / "esmini";
        if (executable(p)) {
            return fs::weakly_canonical(p);
        }
    }
    throw UsageError("", "no OpenSCENARIO player found: give --player PATH (esmini), set RAILODD_ESMINI or put "
                         "esmini on the PATH");
}

ojson read_manifest(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw InputError(file.string(), "no scenario manifest (run `railodd scenarios` into this folder first)");
    }
    std::ostringstream text;
    text << in.rdbuf();
    ojson j = ojson::parse(text.str(), nullptr, false);
    if (!j.is_object() || !j.contains("scenarios") || !j["scenarios"].is_array()) {
        throw InputError(file.string(), "not a railodd scenario manifest (no \"scenarios\" array)");
    }
    for (const auto& s : j["scenarios"]) {
        if (!s.is_object() || !s.contains("id") || !s["id"].is_string() || !s.contains("actors") || !s.contains("ego")) {
            throw InputError(file.string(), "a scenario without id, ego or actors (written by an older railodd? "
                                            "run `railodd scenarios` again)");
        }
        if (!is_safe_name(s["id"].get<std::string>())) {
            throw InputError(file.string(), "scenario id '" + s["id"].get<std::string>() + "' is not a file name (" +
                                                safe_name_rule + ")");
        }
    }
    return j;
}

std::string player_version(const fs::path& log) {
    std::ifstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("esmini GIT REV: ", 0) == 0) {
            return line.substr(16);
        }
    }
    return {};
}

ojson criticality_json(const play::Criticality& c) {
    ojson actors = ojson::array();
    for (const auto& a : c.actors) {
        ojson j = {{"name", a.name}, {"min_distance_m", a.min_distance_m}};
        j["onset_s"] = a.onset_s ? ojson(*a.onset_s) : ojson(nullptr);
        j["distance_at_onset_m"] = a.distance_at_onset_m ? ojson(*a.distance_at_onset_m) : ojson(nullptr);
        j["ttc_at_onset_s"] = a.ttc_at_onset_s ? ojson(*a.ttc_at_onset_s) : ojson(nullptr);
        if (a.arrival_s) {
            j["arrival_s"] = *a.arrival_s;
            j["distance_at_arrival_m"] = *a.distance_at_arrival_m;
        }
        actors.push_back(std::move(j));
    }
    return {{"ego_speed_mps", c.ego_speed_mps}, {"stopping_distance_m", c.stopping_distance_m},
            {"sight_distance_m", c.sight_distance_m}, {"sight_limited_by", c.sight_limited_by},
            {"can_stop", c.can_stop}, {"actors", std::move(actors)}};
}

// The player's binary recordings, converted and then removed: a folder of
// our own under the system's temporary directory, gone with the run.
struct Scratch {
    fs::path dir;
    Scratch() {
        std::string t = (fs::temp_directory_path() / "railodd-play-XXXXXX").string();
        if (!::mkdtemp(t.data())) {
            throw OutputError(t, "cannot make a temporary folder for the recordings");
        }
        dir = t;
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
};

struct Played {
    ojson entry;
    bool passed = false;
    bool can_stop = false;
    std::string svg; // with --plot
};

// One scenario's record: ran or not, the checks on its recording, the figures.
Played analyse_one(const ojson& sc, const TaskOutcome& outcome, const fs::path& csv, const fs::path& log,
                   const play::Options& o, const std::vector<play::LaneLine>* lanes) {
    Played p;
    p.entry = {{"id", sc["id"]}, {"template", sc.value("template", "")}, {"ran", outcome.ok}};
    if (!outcome.ok) {
        p.entry["exit_code"] = outcome.exit_code;
        p.entry["error"] = outcome.failed_step + ": " + outcome.error;
        p.entry["passed"] = false;
        return p;
    }
    std::ifstream log_in(log);
    const play::PlayerLog pl = play::read_player_log(log_in);
    std::ifstream csv_in(csv);
    const play::Trajectories tr = play::read_trajectories(csv_in, csv.string());
    const nlohmann::json scenario = nlohmann::json::parse(sc.dump());
    const play::Analysis a = play::analyse(scenario, tr, pl, o);
    if (lanes) {
        p.svg = play::plot_svg(scenario, tr, *lanes, a);
    }
    ojson checks = ojson::array();
    for (const auto& c : a.checks) {
        checks.push_back({{"check", c.name}, {"passed", c.passed}, {"detail", c.detail}});
    }
    p.passed = a.passed();
    p.can_stop = a.criticality.can_stop;
    p.entry["passed"] = p.passed;
    p.entry["checks"] = std::move(checks);
    p.entry["criticality"] = criticality_json(a.criticality);
    p.entry["player_errors_ignored"] = pl.ignorable_errors.size();
    p.entry["player_warnings"] = pl.warnings;
    return p;
}

std::string text_report(const ojson& report) {
    std::ostringstream t;
    const auto& s = report["summary"];
    t << "railodd play: " << s["scenarios"].get<int>() << " scenarios, " << s["passed"].get<int>() << " pass their checks, "
      << s["failed"].get<int>() << " fail; the train can stop within its sight distance in " << s["can_stop"].get<int>()
      << "\n\n";
    for (const auto& sc : report["scenarios"]) {
        t << (sc["passed"].get<bool>() ? "ok   " : "FAIL ") << sc["id"].get<std::string>();
        if (!sc["ran"].get<bool>()) {
            t << ": did not run: " << sc["error"].get<std::string>() << '\n';
            continue;
        }
        const auto& c = sc["criticality"];
        char line[200];
        std::snprintf(line, sizeof line, ": %.0f km/h, stops in %.0f m, sees %.0f m (%s): %s", c["ego_speed_mps"].get<double>() * 3.6,
                      c["stopping_distance_m"].get<double>(), c["sight_distance_m"].get<double>(),
                      c["sight_limited_by"].get<std::string>().c_str(), c["can_stop"].get<bool>() ? "can stop" : "cannot stop");
        t << line << '\n';
        for (const auto& ch : sc["checks"]) {
            if (!ch["passed"].get<bool>()) {
                t << "       failed: " << ch["check"].get<std::string>() << ": " << ch["detail"].get<std::string>() << '\n';
            }
        }
    }
    return t.str();
}

// The manifest gains each scenario's play outcome and criticality, and
// coverage.json the criticality classes (can stop / cannot) per template and
// overall: the traceability record says what each scenario turned out to be.
void record_criticality(OutputStage& stage, const fs::path& dir, ojson manifest, const ojson& report) {
    std::map<std::string, std::pair<int, int>> per_template; // can stop, cannot
    int can = 0, cannot = 0;
    for (std::size_t i = 0; i < report["scenarios"].size(); ++i) {
        const ojson& r = report["scenarios"][i];
        ojson& m = manifest["scenarios"][i];
        m["play"] = {{"passed", r["passed"]}};
        if (!r.contains("criticality")) {
            continue;
        }
        m["play"]["criticality"] = r["criticality"];
        const bool stops = r["criticality"]["can_stop"].get<bool>();
        auto& t = per_template[m.value("template", "")];
        (stops ? t.first : t.second)++;
        (stops ? can : cannot)++;
    }
    stage.write_text("manifest.json", manifest.dump(1) + "\n");
    std::ifstream in(dir / "coverage.json", std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    ojson coverage = ojson::parse(text.str(), nullptr, false);
    if (!coverage.is_object()) {
        return; // no coverage of this set to add to
    }
    ojson templates = ojson::object();
    for (const auto& [id, n] : per_template) {
        templates[id] = {{"can_stop", n.first}, {"cannot_stop", n.second}};
    }
    coverage["criticality"] = {{"can_stop", can}, {"cannot_stop", cannot}, {"templates", std::move(templates)}};
    stage.write_text("coverage.json", coverage.dump(1) + "\n");
}

// The map's lanes as the player reads them: esmini's odrplot, beside the
// player, on the set's map (the first scenario's, relative to SCENDIR).
std::vector<play::LaneLine> map_lanes(const ojson& manifest, const fs::path& dir, const fs::path& scratch,
                                      const std::string& player) {
    if (manifest["scenarios"].empty()) {
        return {};
    }
    const fs::path map = dir / manifest["scenarios"][0].value("map", "");
    const fs::path odrplot = fs::path{player}.parent_path() / "odrplot", csv = scratch / "lanes.csv";
    if (!executable(odrplot)) {
        throw InputError(odrplot.string(), "no odrplot beside the player (esmini's map plotter), needed by --plot");
    }
    std::vector<BatchTask> task{{"lanes", {{"odrplot", {map.string(), csv.string(), "1.0"}, scratch / "odrplot.log", scratch,
                                            odrplot.string()}}}};
    BatchProgress quiet(1, 1, false, "maps");
    TaskOutcome outcome;
    run_tasks(task, 1, quiet, [&](std::size_t, const TaskOutcome& o) { outcome = o; });
    std::ifstream in(csv);
    if (!outcome.ok || !in) {
        throw InputError(map.string(), "odrplot could not plot the map: " + outcome.error);
    }
    return play::read_lane_lines(in);
}

} // namespace

CLI::App* PlayCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "play", "Play every scenario of a set in an OpenSCENARIO player (esmini), headless, and check what happens");
    app->add_option("SCENDIR", opt_.scendir, "Scenario set (output folder of `railodd scenarios`)")->required();
    app->add_option("--player", opt_.player,
                    "esmini executable (default: $RAILODD_ESMINI, esmini on the PATH, ../shared/tools/esmini/bin/esmini)");
    app->add_option("--jobs", opt_.jobs, "Scenarios played at once (default: one per hardware thread)")
        ->check(CLI::Range(1u, 256u));
    app->add_option("--timestep", opt_.timestep_s, "Player time step (s)")->check(CLI::Range(0.001, 0.5));
    app->add_option("--reaction-time", opt_.reaction_time_s,
                    "Time from seeing the hazard to full braking, for the stopping distance (s)")
        ->check(CLI::Range(0.0, 10.0));
    app->add_flag("--plot", opt_.plot, "Also draw each run as play/ID.svg: lanes (esmini odrplot), paths, train and actors at the hazard");
    app->add_flag("--quiet", opt_.quiet, "No progress lines");
    return app;
}

void PlayCommand::setup() {
    std::error_code ec;
    if (!fs::is_directory(opt_.scendir, ec)) {
        throw InputError(opt_.scendir, "no such scenario folder");
    }
    if (!fs::is_regular_file(fs::path{opt_.scendir} / "manifest.json", ec)) {
        throw InputError((fs::path{opt_.scendir} / "manifest.json").string(),
                         "no scenario manifest (run `railodd scenarios` into this folder first)");
    }
    const fs::path player = find_player(opt_.player);
    opt_.player = player.string();
    dat2csv_ = (player.parent_path() / "dat2csv").string();
    if (!executable(dat2csv_)) {
        throw InputError(dat2csv_, "no dat2csv beside the player (esmini's recording converter)");
    }
    if (opt_.jobs == 0) {
        opt_.jobs = std::max(1u, std::thread::hardware_concurrency());
    }
}

int PlayCommand::run() {
    const fs::path dir = fs::absolute(opt_.scendir);
    const ojson manifest = read_manifest(dir / "manifest.json");
    OutputStage stage(dir);
    const Scratch scratch;
    std::vector<BatchTask> tasks;
    std::vector<fs::path> recordings; // play/ID.csv per task
    const std::string step = std::to_string(opt_.timestep_s);
    for (const auto& sc : manifest["scenarios"]) {
        const std::string id = sc["id"];
        const fs::path dat = scratch.dir / (id + ".dat"), log = stage.staged_path("play/" + id + ".log"),
                       csv = stage.staged_path("play/" + id + ".csv");
        BatchTask t{id, {}};
        t.steps.push_back({"play", {"--headless", "--osc", (dir / sc.value("file", id + ".xosc")).string(),
                                    "--fixed_timestep", step, "--record", dat.string(), "--disable_log"},
                           log, scratch.dir, opt_.player});
        t.steps.push_back({"dat2csv", {"--file", dat.string(), "--extended", "--precision", "6", "--csv", csv.string()},
                           scratch.dir / (id + ".dat2csv.log"), scratch.dir, dat2csv_});
        tasks.push_back(std::move(t));
        recordings.push_back(csv);
    }
    std::vector<TaskOutcome> outcomes(tasks.size());
    BatchProgress progress(tasks.size(), opt_.jobs, !opt_.quiet && ::isatty(STDERR_FILENO) == 1, "scenarios");
    run_tasks(tasks, opt_.jobs, progress, [&](std::size_t i, const TaskOutcome& o) {
        outcomes[i] = o;
        if (!opt_.quiet) {
            progress.finished(tasks[i].id, o.ok ? "played" : "failed", o.seconds, o.error);
        }
    });
    progress.close();

    play::Options po;
    po.reaction_time_s = opt_.reaction_time_s;
    const std::vector<play::LaneLine> lanes = opt_.plot ? map_lanes(manifest, dir, scratch.dir, opt_.player) : std::vector<play::LaneLine>{};
    ojson report;
    report["railodd"] = {{"format", "play_report"}, {"format_version", 1}};
    report["player"] = {{"path", opt_.player}, {"version", tasks.empty() ? "" : player_version(tasks[0].steps[0].log)}};
    report["options"] = {{"timestep_s", opt_.timestep_s}, {"reaction_time_s", po.reaction_time_s},
                         {"clearance_margin_m", po.clearance_margin_m}, {"sight_corridor_m", po.sight_corridor_m},
                         {"lane_tolerance_m", po.lane_tolerance_m}};
    ojson entries = ojson::array();
    int passed = 0, can_stop = 0;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const auto& sc = manifest["scenarios"][i];
        Played p = analyse_one(sc, outcomes[i], recordings[i], tasks[i].steps[0].log, po,
                               opt_.plot ? &lanes : nullptr);
        if (!p.svg.empty()) {
            stage.write_text("play/" + sc["id"].get<std::string>() + ".svg", p.svg);
        }
        passed += p.passed;
        can_stop += p.can_stop;
        entries.push_back(std::move(p.entry));
    }
    const int total = static_cast<int>(tasks.size());
    report["summary"] = {{"scenarios", total}, {"passed", passed}, {"failed", total - passed}, {"can_stop", can_stop}};
    report["scenarios"] = std::move(entries);
    record_criticality(stage, dir, manifest, report);
    stage.write_text("play.json", report.dump(2) + "\n");
    const std::string text = text_report(report);
    stage.write_text("play.txt", text);
    stage.commit();
    std::cout << text.substr(0, text.find('\n')) << '\n' << "wrote " << (dir / "play.json").string() << '\n';
    return passed == total ? exit_ok : exit_invalid;
}

} // namespace railodd::cli
