#include "batch_routes.hpp"

#include "railodd/convert/options.hpp"
#include "railodd/util/yaml_support.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace railodd::cli {

namespace fs = std::filesystem;

namespace {

using convert::OptionKind;

struct Key {
    std::string yaml;
    std::string flag;
    OptionKind kind;
    const convert::OptionSpec* spec = nullptr; // a convert option's row, whose check the value passes
};

// The convert options a route may set: the table's per-route rows
// (railodd/convert/options.hpp). `threads` and `no_timings` are the batch's
// to choose, `input` is the route's own key.
const std::vector<Key>& convert_keys() {
    static const std::vector<Key> keys = [] {
        std::vector<Key> k;
        for (const convert::OptionSpec& s : convert::option_table()) {
            if (s.per_route) {
                k.push_back({std::string{s.key}, convert::flag_of(s), s.kind, &s});
            }
        }
        return k;
    }();
    return keys;
}

// ScenariosOptions fields (scenarios_command.hpp); the taxonomy is the route's.
const std::vector<Key> scenario_keys = {
    {"strategy", "--strategy", OptionKind::text},       {"count", "--count", OptionKind::integer},
    {"seed", "--seed", OptionKind::integer},            {"templates", "--templates", OptionKind::path},
    {"catalog", "--catalog", OptionKind::path},         {"max_anchors", "--max-anchors", OptionKind::integer},
    {"odd_spec", "--odd-spec", OptionKind::path},       {"osc_version", "--osc-version", OptionKind::text},
    {"target", "--target", OptionKind::text},           {"map_corridor", "--map-corridor", OptionKind::number},
};

std::vector<std::string_view> key_names(const std::vector<Key>& keys, std::vector<std::string_view> own) {
    for (const Key& k : keys) {
        own.push_back(k.yaml);
    }
    return own;
}

const std::vector<std::string_view>& route_keys() {
    static const std::vector<std::string_view> names = key_names(convert_keys(), {"id", "input", "scenarios", "timeout"});
    return names;
}

using Options = std::vector<std::pair<std::string, std::vector<std::string>>>;

struct Reader {
    std::string file;
    fs::path base; // relative paths are taken from the routes file's folder

    std::string path(const YAML::Node& n, const std::string& what, BatchRoute& r) const {
        const fs::path p{yaml::scalar(file, n, what)};
        yaml::require(file, n, !p.empty(), what + ": the path is empty");
        const std::string abs = (p.is_absolute() ? p : base / p).lexically_normal().string();
        r.files.push_back(abs);
        return abs;
    }

    std::string integer(const YAML::Node& n, const std::string& what) const {
        const std::string t = yaml::scalar(file, n, what);
        yaml::require(file, n, std::regex_match(t, std::regex{"-?[0-9]+"}), what + " must be an integer, not '" + t + "'");
        return t;
    }

    std::string bbox(const YAML::Node& n) const {
        std::vector<std::string> parts;
        if (n.IsSequence()) {
            for (const auto& v : n) {
                yaml::number(file, v, "bbox value");
                parts.push_back(v.Scalar());
            }
        } else {
            std::stringstream s(yaml::scalar(file, n, "bbox"));
            for (std::string p; std::getline(s, p, ',');) {
                parts.push_back(p);
            }
        }
        yaml::require(file, n, parts.size() == 4, "bbox needs four numbers [W, S, E, N]");
        return parts[0] + "," + parts[1] + "," + parts[2] + "," + parts[3];
    }

    std::vector<std::string> values(const Key& k, const YAML::Node& n, BatchRoute& r) const {
        const std::string what = k.yaml;
        switch (k.kind) {
        case OptionKind::path: return {path(n, what, r)};
        case OptionKind::paths: {
            if (!n.IsSequence()) {
                return {path(n, what, r)};
            }
            std::vector<std::string> v;
            for (const auto& item : n) {
                v.push_back(path(item, what, r));
            }
            return v;
        }
        case OptionKind::number: yaml::number(file, n, what); return {n.Scalar()};
        case OptionKind::count:
        case OptionKind::integer: return {integer(n, what)};
        case OptionKind::bbox: return {bbox(n)};
        case OptionKind::text:
        case OptionKind::flag: break;
        }
        return {yaml::scalar(file, n, what)};
    }

    // Appends the flag and its values, checked as the command line checks
    // them; a false flag adds nothing.
    void value(const Key& k, const YAML::Node& n, BatchRoute& r, Options& out, nlohmann::ordered_json& spec) const {
        if (k.kind == OptionKind::flag) {
            spec[k.yaml] = yaml::boolean(file, n, k.yaml);
            if (spec[k.yaml].get<bool>()) {
                out.emplace_back(k.flag, std::vector<std::string>{});
            }
            return;
        }
        std::vector<std::string> v = values(k, n, r);
        for (const std::string& text : v) {
            const std::string problem = k.spec ? convert::check_value(*k.spec, text) : std::string{};
            yaml::require(file, n, problem.empty(), k.yaml + ": " + problem);
        }
        spec[k.yaml] = v.size() == 1 && k.kind != OptionKind::paths ? nlohmann::ordered_json(v[0]) : nlohmann::ordered_json(v);
        out.emplace_back(k.flag, std::move(v));
    }
};

// The route's node for `key`, else the defaults' one (undefined if neither).
YAML::Node pick(const YAML::Node& route, const YAML::Node& defaults, const char* key) {
    if (route[key] || !defaults || !defaults[key]) {
        return route[key]; // undefined when absent (a default-constructed Node is a defined null)
    }
    return defaults[key];
}

// scenarios: a map of options (merged key by key over the defaults' map), or
// true / false to switch the defaults' scenarios on or off for one route.
void read_scenarios(const Reader& rd, const YAML::Node& route, const YAML::Node& defaults, BatchRoute& r) {
    const YAML::Node d = defaults ? defaults["scenarios"] : YAML::Node{};
    const YAML::Node own = route["scenarios"];
    const YAML::Node n = own ? own : d;
    if (!n || n.IsNull()) {
        return;
    }
    if (n.IsScalar() && !yaml::boolean(rd.file, n, "scenarios")) {
        return;
    }
    yaml::require(rd.file, n, n.IsScalar() || n.IsMap(), "scenarios must be a map of options or true/false");
    const YAML::Node dmap = d && d.IsMap() ? d : YAML::Node{};
    const YAML::Node rmap = own && own.IsMap() ? own : YAML::Node{};
    for (const YAML::Node& m : {dmap, rmap}) {
        if (m) {
            yaml::check_keys(rd.file, m, key_names(scenario_keys, {}), "scenarios");
        }
    }
    r.scenarios = true;
    nlohmann::ordered_json spec = nlohmann::ordered_json::object();
    for (const Key& k : scenario_keys) {
        const YAML::Node v = rmap && rmap[k.yaml] ? rmap[k.yaml] : (dmap ? dmap[k.yaml] : YAML::Node{});
        if (v) {
            rd.value(k, v, r, r.scenario_options, spec);
        }
    }
    // Shipped defaults count as inputs too: editing them makes routes stale.
    for (const auto& [key, shipped] : {std::pair{"templates", "scenario/templates.yaml"}, {"catalog", "scenario/assets.yaml"}}) {
        if (!spec.contains(key)) {
            r.files.push_back((fs::path{RAILODD_DATA_DIR} / shipped).string());
        }
    }
    r.spec["scenarios"] = std::move(spec);
}

BatchRoute read_route(const Reader& rd, const YAML::Node& node, const YAML::Node& defaults) {
    yaml::require(rd.file, node, node.IsMap(), "a route must be a map with id, input and options");
    yaml::check_keys(rd.file, node, route_keys(), "route");
    BatchRoute r;
    r.line = yaml::line_of(node);
    yaml::require(rd.file, node, static_cast<bool>(node["id"]), "a route needs an id");
    r.id = yaml::name(rd.file, node["id"], "route id");
    const YAML::Node input = pick(node, defaults, "input");
    yaml::require(rd.file, node, static_cast<bool>(input), "route '" + r.id + "' needs an input (or defaults: input)");
    r.spec["id"] = r.id;
    r.input = rd.path(input, "input", r);
    r.spec["input"] = r.input;
    nlohmann::ordered_json convert = nlohmann::ordered_json::object();
    for (const Key& k : convert_keys()) {
        if (const YAML::Node v = pick(node, defaults, k.yaml.c_str())) {
            rd.value(k, v, r, r.convert, convert);
        }
    }
    if (!convert.contains("taxonomy")) {
        r.files.push_back((fs::path{RAILODD_DATA_DIR} / "odd" / "railway_odd.yaml").string());
    }
    r.spec["convert"] = std::move(convert);
    read_scenarios(rd, node, defaults, r);
    // Not in the spec: how long a route may run does not change its outputs.
    if (const YAML::Node t = pick(node, defaults, "timeout")) {
        const double s = yaml::number(rd.file, t, "timeout");
        yaml::require(rd.file, t, s >= 0.0 && s <= 1e7, "timeout must be 0 (no limit) to 1e7 seconds");
        r.timeout_s = s;
    }
    return r;
}

std::string file_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

std::string fnv1a_hex(std::string_view data, std::uint64_t seed) {
    std::uint64_t h = seed;
    for (const unsigned char c : data) {
        h = (h ^ c) * 1099511628211ULL;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

BatchFile load_batch_file(const fs::path& path) {
    const YAML::Node root = yaml::load_file(path, "routes file");
    const Reader rd{path.string(), fs::absolute(path).parent_path()};
    yaml::require(rd.file, root, root.IsMap(), "the routes file must be a map with `routes:` (and `defaults:`)");
    yaml::check_keys(rd.file, root, {"defaults", "routes"}, "routes file");
    const YAML::Node defaults = root["defaults"];
    if (defaults) {
        yaml::require(rd.file, defaults, defaults.IsMap(), "defaults must be a map of route options");
        yaml::check_keys(rd.file, defaults, route_keys(), "defaults");
        yaml::require(rd.file, defaults, !defaults["id"], "defaults cannot give an id");
    }
    const YAML::Node routes = root["routes"];
    yaml::require(rd.file, root, routes && routes.IsSequence() && routes.size() > 0,
                  "`routes:` must be a non-empty list of routes");
    BatchFile out;
    out.path = path;
    out.content_hash = fnv1a_hex(file_text(path));
    std::set<std::string> ids;
    for (const auto& node : routes) {
        BatchRoute r = read_route(rd, node, defaults);
        yaml::require(rd.file, node["id"], ids.insert(r.id).second, "duplicate route id '" + r.id + "'");
        out.routes.push_back(std::move(r));
    }
    return out;
}

std::vector<std::string> convert_args(const BatchRoute& r, const fs::path& outdir, bool single_thread) {
    // --no-timings: report.json byte-identical whatever the load; the batch
    // keeps the timings in batch_timings*.json.
    std::vector<std::string> a{"convert", r.input, "-o", outdir.string(), "--no-timings"};
    for (const auto& [flag, values] : r.convert) {
        for (std::size_t i = 0; i < std::max<std::size_t>(values.size(), 1); ++i) {
            a.push_back(flag);
            if (!values.empty()) {
                a.push_back(values[i]);
            }
        }
    }
    if (single_thread) {
        a.insert(a.end(), {"--threads", "1"});
    }
    return a;
}

std::vector<std::string> scenarios_args(const BatchRoute& r, const fs::path& outdir) {
    std::vector<std::string> a{"scenarios", "--map", outdir.string(), "-o", (outdir / "scenarios").string(), "-q"};
    for (const auto& [flag, values] : r.scenario_options) {
        a.push_back(flag);
        a.push_back(values.at(0));
    }
    for (const auto& [flag, values] : r.convert) {
        if (flag == "--taxonomy") {
            a.insert(a.end(), {"--taxonomy", values.at(0)});
        }
    }
    return a;
}

} // namespace railodd::cli
