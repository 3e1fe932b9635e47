#include "merge_command.hpp"
#include "batch_command.hpp"
#include "option_checks.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/output_stage.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/json_input.hpp"
#include "railodd/util/file_names.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <tuple>

namespace railodd::cli {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

CLI::App* MergeCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "merge", "Merge the shard summaries, scenario coverage and ODD summaries of a batch (docs/batch.md)");
    app->add_option("OUTROOT", opt_.outroot, "Output root of `railodd batch` (all shards)")->required();
    app->add_option("-o,--output", opt_.output, "Merged summary (default: OUTROOT/batch_merged.json)")->check(non_empty_path);
    return app;
}

void MergeCommand::setup() {
    if (!fs::is_directory(opt_.outroot)) {
        throw InputError(opt_.outroot, "not a folder (give the output root of `railodd batch`)");
    }
    if (opt_.output.empty()) {
        opt_.output = (fs::path{opt_.outroot} / "batch_merged.json").string();
    }
}

namespace {

// Parses a JSON file; with `keep`, only those top-level keys are built (an
// odd_profile.json of a whole network is large, merge needs its summary).
json read_json(const fs::path& path, const std::set<std::string>& keep = {}) {
    json::parser_callback_t cb = [&keep](int depth, json::parse_event_t event, json& parsed) {
        return keep.empty() || depth != 1 || event != json::parse_event_t::key ||
               keep.contains(parsed.get<std::string>());
    };
    json j = read_json_file<json>(path, "batch output", cb);
    if (!j.is_object()) {
        throw InputError(path.string(), "not a JSON object (batch output)");
    }
    return j;
}

// `newest`: the highest format_version read (merge reads the parts that all versions share).
void require_format(const json& j, const fs::path& path, const char* format, int newest = 1) {
    const json& r = j.contains("railodd") ? j["railodd"] : json{};
    const json version = r.is_object() && r.contains("format_version") ? r["format_version"] : json{};
    if (!r.is_object() || r.value("format", "") != format || !version.is_number_integer() ||
        version.get<long long>() < 1 || version.get<long long>() > newest) {
        throw InputError(path.string(), std::string{"not a "} + format + " file of format_version 1" +
                                            (newest > 1 ? " to " + std::to_string(newest) : std::string{}));
    }
}

struct Summaries {
    std::vector<std::string> files;
    std::map<std::string, json> routes; // by id: sorted
    std::set<unsigned> shards;
    unsigned shard_count = 0;
    json first; // the first summary: the others must come from the same routes file
};

// One batch summary: the same routes file and shard count as the first,
// each route in one shard only.
void add_summary(Summaries& s, std::map<std::string, std::string>& seen_in, const fs::path& p) {
    const json j = read_json(p);
    require_format(j, p, "batch_summary");
    const json& shard = j.at("shard");
    const auto count = shard.at("count").get<long long>();
    const auto index = shard.at("index").get<long long>();
    // --shard I/N takes N up to max_shards: a larger one is not railodd's.
    if (count < 1 || count > max_shards || index < 0 || index >= count) {
        throw InputError(p.string(), "shard " + std::to_string(index) + " of " + std::to_string(count) +
                                         " is not a shard of a batch run");
    }
    if (s.files.empty()) {
        s.first = j;
        s.shard_count = static_cast<unsigned>(count);
    } else if (j["routes_file_hash"] != s.first["routes_file_hash"] || count != s.shard_count) {
        throw InputError(p.string(), "from a different routes file or shard count than " + s.files.front() +
                                         " (remove stale summaries)");
    }
    s.files.push_back(p.filename().string());
    s.shards.insert(static_cast<unsigned>(index));
    for (const auto& r : j.at("routes")) {
        const std::string id = r.at("id").get<std::string>();
        if (!is_safe_name(id)) {
            // It names the route's folder under OUTROOT, read next.
            throw InputError(p.string(), "route id '" + id + "' is not a folder name: " + safe_name_rule);
        }
        r.value("status", std::string{}); // the types run() relies on, checked here where the file is known
        r.value("scenarios", false);
        if (!seen_in.emplace(id, p.filename().string()).second) {
            throw InputError(p.string(), "route '" + id + "' is also in " + seen_in[id]);
        }
        s.routes[id] = r;
    }
}

// Every batch_summary*.json of OUTROOT.
Summaries read_summaries(const fs::path& root) {
    static const std::regex name(R"(batch_summary(\.shard-\d+-of-\d+)?\.json)");
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(root)) {
        if (e.is_regular_file() && std::regex_match(e.path().filename().string(), name)) {
            paths.push_back(e.path());
        }
    }
    std::sort(paths.begin(), paths.end());
    if (paths.empty()) {
        throw InputError(root.string(), "no batch_summary*.json (run `railodd batch` into it first)");
    }
    Summaries s;
    std::map<std::string, std::string> seen_in;
    for (const auto& p : paths) {
        reading_json(p, [&] { add_summary(s, seen_in, p); });
    }
    return s;
}

using Key = std::tuple<std::string, std::string, std::string>;

// Items summed per (element, attribute, class), kept in first-seen order.
struct ItemTable {
    std::vector<Key> order;
    std::map<Key, std::pair<long, long>> sums; // on_route, scenarios
    std::map<Key, long> routes;                // routes having it on the route

    void add(const json& items) {
        for (const auto& e : items) {
            const Key k{e.value("element", ""), e.value("attribute", ""), e.value("class", "")};
            auto [it, fresh] = sums.try_emplace(k, 0, 0);
            if (fresh) {
                order.push_back(k);
            }
            it->second.first += e.value("on_route", 0L);
            it->second.second += e.value("scenarios", 0L);
            routes[k] += e.value("on_route", 0L) > 0 ? 1 : 0;
        }
    }
    json item(const Key& k) const {
        return {{"element", std::get<0>(k)}, {"attribute", std::get<1>(k)}, {"class", std::get<2>(k)}};
    }
};

json merge_coverage(const fs::path& root, const std::vector<std::string>& ids) {
    ItemTable route, exercised;
    long scenarios = 0;
    for (const auto& id : ids) {
        const fs::path p = root / id / "scenarios" / "coverage.json";
        finish_pending_commit(p.parent_path());
        reading_json(p, [&] {
            const json c = read_json(p);
            require_format(c, p, "scenario_coverage");
            if (!c.contains("route") || !c["route"].contains("elements") || !c.contains("exercised")) {
                throw InputError(p.string(), "coverage without route elements or exercised items");
            }
            scenarios += c.value("scenarios", 0L);
            route.add(c["route"]["elements"]);
            exercised.add(c["exercised"]);
        });
    }
    json out;
    out["routes"] = ids;
    out["scenarios"] = scenarios;
    json elements = json::array(), gaps = json::array();
    long covered = 0;
    for (const auto& k : route.order) {
        const auto [on_route, sc] = route.sums.at(k);
        json e = route.item(k);
        e["on_route"] = on_route;
        e["routes"] = route.routes.at(k);
        e["scenarios"] = sc;
        covered += sc > 0 ? 1 : 0;
        if (sc == 0) {
            gaps.push_back(e);
        }
        elements.push_back(std::move(e));
    }
    const auto items = static_cast<long>(route.order.size());
    out["route"] = {{"items", items}, {"covered", covered},
                    {"ratio", items > 0 ? double(covered) / double(items) : 1.0}, {"elements", std::move(elements)}};
    json ex = json::array();
    for (const auto& k : exercised.order) {
        json e = exercised.item(k);
        e["scenarios"] = exercised.sums.at(k).second;
        ex.push_back(std::move(e));
    }
    out["exercised"] = std::move(ex);
    out["gaps"] = std::move(gaps);
    return out;
}

// Numbers summed key by key, objects merged, equal values kept; anything
// else means the profiles are of different kinds and is refused.
void merge_summary(json& acc, const json& add, const fs::path& file, const std::string& at) {
    for (const auto& [key, value] : add.items()) {
        const std::string path = at.empty() ? key : at + "." + key;
        if (!acc.contains(key)) {
            acc[key] = value;
            continue;
        }
        json& a = acc[key];
        if (a.is_number_integer() && value.is_number_integer()) {
            a = a.get<long long>() + value.get<long long>();
        } else if (a.is_number() && value.is_number()) {
            // Rounded to 1e-6: the inputs carry a few decimals; no 0.30000000000000004.
            a = std::round((a.get<double>() + value.get<double>()) * 1e6) / 1e6;
        } else if (a.is_object() && value.is_object()) {
            merge_summary(a, value, file, path);
        } else if (a != value) {
            throw InputError(file.string(), "summary key '" + path + "' (" + value.type_name() +
                                                ") does not match the other routes' (" + a.type_name() + ")");
        }
    }
}

json merge_profiles(const fs::path& root, const std::vector<std::string>& ids) {
    json summary = json::object();
    for (const auto& id : ids) {
        const fs::path p = root / id / "odd_profile.json";
        finish_pending_commit(p.parent_path());
        reading_json(p, [&] {
            const json j = read_json(p, {"railodd", "summary"});
            require_format(j, p, "odd_profile", 2);
            if (!j.contains("summary") || !j["summary"].is_object()) {
                throw InputError(p.string(), "no summary object");
            }
            merge_summary(summary, j["summary"], p, "");
        });
    }
    return {{"routes", ids}, {"summary", std::move(summary)}};
}

} // namespace

int MergeCommand::run() {
    const fs::path root{opt_.outroot};
    const Summaries s = read_summaries(root);
    json out;
    out["railodd"] = {{"format", "batch_merged"}, {"format_version", 1}};
    out["routes_file"] = s.first["routes_file"];
    out["routes_file_hash"] = s.first["routes_file_hash"];
    out["routes_total"] = s.first["routes_total"];
    out["summaries"] = s.files;
    // Built as plain vectors and converted once: with JSON_DIAGNOSTICS each
    // push_back onto a JSON array re-parents all its elements (quadratic).
    std::vector<unsigned> missing;
    for (unsigned i = 0; i < s.shard_count; ++i) {
        if (!s.shards.contains(i)) {
            missing.push_back(i);
        }
    }
    out["shards"] = {{"count", s.shard_count}, {"missing", missing}};
    json counts = {{"ok", 0}, {"failed", 0}, {"skipped", 0}};
    json::array_t routes;
    std::vector<std::string> with_outputs, with_scenarios;
    for (const auto& [id, r] : s.routes) {
        const std::string status = r.value("status", "");
        counts[status] = counts.value(status, 0) + 1;
        // Failed routes may have outputs of an earlier run: not counted.
        if (status == "ok" || status == "skipped") {
            with_outputs.push_back(id);
            if (r.value("scenarios", false)) {
                with_scenarios.push_back(id);
            }
        }
        routes.push_back(r);
    }
    out["counts"] = std::move(counts);
    out["routes"] = json(std::move(routes));
    out["coverage"] = merge_coverage(root, with_scenarios);
    out["odd_profile"] = merge_profiles(root, with_outputs);
    {
        std::ofstream f(opt_.output, std::ios::binary);
        f << out.dump(2) << '\n';
        if (!f) {
            throw OutputError(opt_.output, "cannot write the merged summary");
        }
    }
    std::cout << "railodd merge: " << s.routes.size() << " routes from " << s.files.size() << " summaries ("
              << missing.size() << " shards missing), " << with_scenarios.size() << " with scenarios; wrote "
              << opt_.output << '\n';
    if (!missing.empty()) {
        // Written anyway (a partial view helps while an array job runs), but
        // a pipeline must not take it for the whole network.
        std::cerr << "railodd: input error: " << root.string() << ": " << missing.size()
                  << " shard summaries missing (see \"shards\" in " << opt_.output << ")\n";
        return exit_input;
    }
    return exit_ok;
}

} // namespace railodd::cli
