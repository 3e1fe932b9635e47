#include "play_results.hpp"

#include "railodd/util/errors.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace railodd::cli {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
namespace play = scenario::play;

namespace {

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

void add_analysis(Played& p, const play::Analysis& a, const play::PlayerLog& pl) {
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
}

} // namespace

Played analyse_one(const ojson& sc, const TaskOutcome& outcome, const fs::path& csv, const std::string& csv_name,
                   const fs::path& log, const play::Options& o, const std::vector<play::LaneLine>* lanes,
                   const TargetPlaces& places) {
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
    play::Trajectories tr;
    try {
        std::ifstream csv_in(csv);
        if (!csv_in) {
            throw InputError(csv_name, "the player's converter (dat2csv) wrote no recording");
        }
        tr = play::read_trajectories(csv_in, csv_name);
    } catch (const InputError& e) {
        p.entry["error"] = std::string{"recording: "} + e.what();
        p.entry["passed"] = false;
        return p;
    }
    nlohmann::json scenario = nlohmann::json::parse(sc.dump());
    places.place(scenario);
    const play::Analysis a = play::analyse(scenario, tr, pl, o);
    if (lanes) {
        p.svg = play::plot_svg(scenario, tr, *lanes, a);
    }
    add_analysis(p, a, pl);
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
        if (!sc.contains("criticality")) {
            t << (sc["ran"].get<bool>() ? ": no usable recording: " : ": did not run: ")
              << sc["error"].get<std::string>() << '\n';
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

// The traceability record says what each scenario turned out to be.
void record_criticality(OutputStage& stage, ojson manifest, std::optional<ojson> coverage, const ojson& report) {
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
    if (!coverage) {
        return; // no coverage of this set to add to
    }
    ojson templates = ojson::object();
    for (const auto& [id, n] : per_template) {
        templates[id] = {{"can_stop", n.first}, {"cannot_stop", n.second}};
    }
    (*coverage)["criticality"] = {{"can_stop", can}, {"cannot_stop", cannot}, {"templates", std::move(templates)}};
    stage.write_text("coverage.json", coverage->dump(1) + "\n");
}

} // namespace railodd::cli
