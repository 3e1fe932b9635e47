#include "play_command.hpp"

#include "batch_runner.hpp"
#include "option_checks.hpp"
#include "play_manifest.hpp"
#include "play_results.hpp"

#include "railodd/scenario/play.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/util/file_names.hpp"
#include "railodd/util/output_stage.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <csignal>
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

// The player's binary recordings, converted and then removed: a folder of
// our own under the system's temporary directory, gone with the run. Named
// with the run's PID: folders of runs killed outright (SIGKILL) are removed
// by the next run once their PID is gone.
struct Scratch {
    fs::path dir;
    Scratch() {
        remove_dead_runs_folders();
        std::string t = (fs::temp_directory_path() / (prefix() + std::to_string(::getpid()) + "-XXXXXX")).string();
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

private:
    static std::string prefix() { return "railodd-play-"; }
    static void remove_dead_runs_folders() {
        std::error_code ec;
        std::vector<fs::path> dead;
        for (fs::directory_iterator it(fs::temp_directory_path(), ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name.rfind(prefix(), 0) != 0) {
                continue;
            }
            const long pid = std::strtol(name.c_str() + prefix().size(), nullptr, 10);
            if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
                dead.push_back(it->path());
            }
        }
        for (const auto& d : dead) {
            fs::remove_all(d, ec);
        }
    }
};

// The map's lanes as the player reads them: esmini's odrplot (setup() found
// it), on the set's map (the first scenario's, relative to SCENDIR).
std::vector<play::LaneLine> map_lanes(const ojson& manifest, const fs::path& dir, const fs::path& scratch,
                                      const std::string& odrplot) {
    if (manifest["scenarios"].empty()) {
        return {};
    }
    const fs::path map = dir / manifest["scenarios"][0].value("map", ""), csv = scratch / "lanes.csv";
    std::vector<BatchTask> task{{"lanes", {{"odrplot", {map.string(), csv.string(), "1.0"}, scratch / "odrplot.log", scratch,
                                            odrplot}}}};
    BatchProgress quiet(1, 1, false, "maps");
    TaskOutcome outcome;
    run_tasks(task, 1, quiet, [&](std::size_t, const TaskOutcome& o) { outcome = o; });
    std::ifstream in(csv);
    if (!outcome.ok || !in) {
        throw InputError(map.string(), "odrplot could not plot the map: " + outcome.error);
    }
    return play::read_lane_lines(in);
}

// Simulated seconds of the scenario as `railodd scenarios` sets its stop
// time: the ego's run at its speed, its start delay and 30 s.
double simulated_seconds(const ojson& sc) {
    const ojson& ego = sc["ego"];
    const double metres = ego.value("run_up_m", 0.0) + ego.value("overrun_m", 0.0);
    const double speed = std::max(ego.value("speed_kmh", 0.0) / 3.6, 1.0);
    return std::ceil(metres / speed) + 30.0 + std::ceil(std::max(ego.value("start_delay_s", 0.0), 0.0));
}

} // namespace

CLI::App* PlayCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "play", "Play every scenario of a set in an OpenSCENARIO player (esmini), headless, and check what happens");
    app->add_option("SCENDIR", opt_.scendir, "Scenario set (output folder of `railodd scenarios`)")->required();
    app->add_option("--player", opt_.player,
                    "esmini executable (default: $RAILODD_ESMINI, esmini on the PATH, ../shared/tools/esmini/bin/esmini)");
    app->add_option("--jobs", opt_.jobs, "Scenarios played at once (default: one per hardware thread)")
        ->check(unsigned_integer)
        ->check(CLI::Range(1u, 256u));
    app->add_option("--timestep", opt_.timestep_s, "Player time step (s)")->check(finite_range(0.001, 0.5));
    app->add_option("--reaction-time", opt_.reaction_time_s,
                    "Time from seeing the hazard to full braking, for the stopping distance (s)")
        ->check(finite_range(0.0, 10.0));
    app->add_option("--player-timeout", opt_.player_timeout_s,
                    "Seconds a scenario's run may take before the player is killed and the scenario fails "
                    "(default: from the scenario's length, 60 s plus twice its simulated time at a 0.05 s step)")
        ->check(finite_range(0.001, 1e6));
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
    // Checked before anything is played: found missing after the runs, every result would be lost.
    if (opt_.plot && !executable(player.parent_path() / "odrplot")) {
        throw InputError((player.parent_path() / "odrplot").string(),
                         "no odrplot beside the player (esmini's map plotter), needed by --plot");
    }
    if (opt_.jobs == 0) {
        opt_.jobs = std::max(1u, std::thread::hardware_concurrency());
    }
}

double PlayCommand::timeout_of(const ojson& sc) const {
    if (opt_.player_timeout_s > 0.0) {
        return opt_.player_timeout_s;
    }
    // A headless player runs many times faster than real time; the margin is
    // for a loaded machine and a finer time step (more steps per second).
    return 60.0 + 2.0 * simulated_seconds(sc) * std::max(1.0, 0.05 / opt_.timestep_s);
}

// One task per scenario: play into the scratch folder, then convert the
// recording into the staged play/ID.csv.
std::vector<BatchTask> PlayCommand::tasks_of(const ojson& manifest, const fs::path& dir, OutputStage& stage,
                                             const fs::path& scratch) const {
    std::vector<BatchTask> tasks;
    const std::string step = std::to_string(opt_.timestep_s);
    for (const auto& sc : manifest["scenarios"]) {
        const std::string id = sc["id"];
        const fs::path dat = scratch / (id + ".dat"), log = stage.staged_path("play/" + id + ".log"),
                       csv = stage.staged_path("play/" + id + ".csv");
        BatchTask t{id, {}, timeout_of(sc), "--player-timeout, default from the scenario's length"};
        t.steps.push_back({"play", {"--headless", "--osc", scenario_file(dir, sc).string(),
                                    "--fixed_timestep", step, "--record", dat.string(), "--disable_log"},
                           log, scratch, opt_.player, player_log_cap});
        t.steps.push_back({"dat2csv", {"--file", dat.string(), "--extended", "--precision", "6", "--csv", csv.string()},
                           scratch / (id + ".dat2csv.log"), scratch, dat2csv_, player_log_cap});
        tasks.push_back(std::move(t));
    }
    return tasks;
}

std::vector<TaskOutcome> PlayCommand::play_all(const std::vector<BatchTask>& tasks) const {
    std::vector<TaskOutcome> outcomes(tasks.size());
    BatchProgress progress(tasks.size(), opt_.jobs, !opt_.quiet && ::isatty(STDERR_FILENO) == 1, "scenarios");
    run_tasks(tasks, opt_.jobs, progress, [&](std::size_t i, const TaskOutcome& o) {
        outcomes[i] = o;
        if (!opt_.quiet) {
            progress.finished(tasks[i].id, o.ok ? "played" : "failed", o.seconds, o.error);
        }
    });
    progress.close();
    return outcomes;
}

int PlayCommand::run() {
    const fs::path dir = fs::absolute(opt_.scendir);
    // The stage first: it finishes a commit a killed run left in the folder
    // before the manifest is read.
    OutputStage stage(dir);
    const PlaySet set = read_play_set(dir);
    const ojson& manifest = set.manifest;
    const Scratch scratch;
    const std::vector<BatchTask> tasks = tasks_of(manifest, dir, stage, scratch.dir);
    const std::vector<TaskOutcome> outcomes = play_all(tasks);

    play::Options po;
    po.reaction_time_s = opt_.reaction_time_s;
    const std::vector<play::LaneLine> lanes =
        opt_.plot ? map_lanes(manifest, dir, scratch.dir, (fs::path{opt_.player}.parent_path() / "odrplot").string())
                  : std::vector<play::LaneLine>{};
    const TargetPlaces places(manifest, dir);
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
        const std::string id = sc["id"].get<std::string>();
        Played p = analyse_one(sc, outcomes[i], tasks[i].steps[1].args.back(), "play/" + id + ".csv",
                               tasks[i].steps[0].log, po, opt_.plot ? &lanes : nullptr, places);
        if (!p.svg.empty()) {
            stage.write_text("play/" + id + ".svg", p.svg);
        }
        passed += p.passed;
        can_stop += p.can_stop;
        entries.push_back(std::move(p.entry));
    }
    const int total = static_cast<int>(tasks.size());
    report["summary"] = {{"scenarios", total}, {"passed", passed}, {"failed", total - passed}, {"can_stop", can_stop}};
    report["scenarios"] = std::move(entries);
    record_criticality(stage, manifest, set.coverage, report);
    stage.write_text("play.json", report.dump(2) + "\n");
    const std::string text = text_report(report);
    stage.write_text("play.txt", text);
    stage.commit();
    std::cout << text.substr(0, text.find('\n')) << '\n' << "wrote " << (dir / "play.json").string() << '\n';
    return passed == total ? exit_ok : exit_invalid;
}

} // namespace railodd::cli
