#include "play_manifest.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/file_names.hpp"
#include "railodd/util/json_input.hpp"
#include "railodd/util/json_shape.hpp"

#include <set>

namespace railodd::cli {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

namespace {

using K = JsonKind;

// Every field play and its checks read of an entry (scenario::play::analyse,
// plot_svg, the criticality), as railodd scenarios writes them.
const std::vector<JsonField>& manifest_fields() {
    static const std::vector<JsonField> fields = {
        {"scenarios", K::array},
        {"scenarios/*", K::object},
        {"scenarios/*/id", K::string},
        {"scenarios/*/file", K::string, false},
        {"scenarios/*/template", K::string, false},
        {"scenarios/*/map", K::string, false},
        {"scenarios/*/ego", K::object},
        {"scenarios/*/ego/start", K::object},
        {"scenarios/*/ego/start/road_id", K::string},
        {"scenarios/*/ego/start/lane_id", K::integer},
        {"scenarios/*/ego/start/s", K::number},
        {"scenarios/*/ego/route_roads", K::array},
        {"scenarios/*/ego/route_roads/*", K::string},
        {"scenarios/*/ego/length_m", K::number},
        {"scenarios/*/ego/width_m", K::number},
        {"scenarios/*/ego/max_deceleration", K::number, false},
        {"scenarios/*/ego/run_up_m", K::number, false},
        {"scenarios/*/ego/overrun_m", K::number, false},
        {"scenarios/*/ego/speed_kmh", K::number, false},
        {"scenarios/*/ego/start_delay_s", K::number, false},
        {"scenarios/*/ego/stops_short_of_anchor", K::boolean, false},
        {"scenarios/*/ego/end", K::object, false},
        {"scenarios/*/ego/end/road_id", K::string},
        {"scenarios/*/ego/end/s", K::number},
        {"scenarios/*/anchor", K::object},
        {"scenarios/*/anchor/road_id", K::string},
        {"scenarios/*/anchor/s", K::number},
        {"scenarios/*/actors", K::array},
        {"scenarios/*/actors/*", K::object},
        {"scenarios/*/actors/*/name", K::string},
        {"scenarios/*/actors/*/kind", K::string},
        {"scenarios/*/actors/*/place", K::string},
        {"scenarios/*/actors/*/start", K::object},
        {"scenarios/*/actors/*/start/road_id", K::string},
        {"scenarios/*/actors/*/start/s", K::number},
        {"scenarios/*/actors/*/start/offset", K::number, false},
        {"scenarios/*/actors/*/move_to", K::string, false},
        {"scenarios/*/actors/*/target", K::object, false},
        {"scenarios/*/actors/*/target/road_id", K::string},
        {"scenarios/*/actors/*/target/lane_id", K::integer, false},
        {"scenarios/*/actors/*/target/s", K::number},
        {"scenarios/*/actors/*/target/offset", K::number, false},
        {"scenarios/*/actors/*/hazard_before_m", K::number, false},
        {"scenarios/*/actors/*/length_m", K::number},
        {"scenarios/*/actors/*/width_m", K::number},
        {"scenarios/*/perturbations", K::array, false},
        {"scenarios/*/perturbations/*", K::object},
        {"scenarios/*/perturbations/*/attribute", K::string, false},
    };
    return fields;
}

// The player is handed this path: a manifest must not point it at files
// outside the set (/etc/passwd, ../../x).
void require_inside(const std::string& name, const fs::path& manifest) {
    const fs::path rel = fs::path{name}.lexically_normal();
    if (name.empty() || rel.has_root_path() || rel.empty() || *rel.begin() == ".." || rel.filename().empty()) {
        throw InputError(manifest.string(), "scenario file '" + name + "' is not a file inside the scenario folder");
    }
}

// The train's size and braking enter the stopping distance: 0 would make it
// infinite ("stops in inf m") and the scenario pass or fail on nothing.
void require_positive_ego(const ojson& ego, std::size_t i, const fs::path& file) {
    for (const char* key : {"length_m", "width_m", "max_deceleration"}) {
        if (ego.contains(key) && ego[key].is_number() && !(ego[key].get<double>() > 0.0)) {
            throw InputError(file.string(), "/scenarios/" + std::to_string(i) + "/ego/" + key + ": must be positive, not " +
                                                ego[key].dump());
        }
    }
}

void check_entries(const ojson& manifest, const fs::path& file) {
    std::set<std::string> ids;
    for (std::size_t i = 0; i < manifest["scenarios"].size(); ++i) {
        const ojson& s = manifest["scenarios"][i];
        require_positive_ego(s["ego"], i, file);
        const std::string id = s["id"].get<std::string>();
        if (!is_safe_name(id)) {
            throw InputError(file.string(), "scenario id '" + id + "' is not a file name (" + safe_name_rule + ")");
        }
        // Two runs of one id would write the same play/ID.* files.
        if (!ids.insert(id).second) {
            throw InputError(file.string(), "scenario id '" + id + "' is given twice");
        }
        require_inside(s.value("file", id + ".xosc"), file);
    }
}

} // namespace

PlaySet read_play_set(const fs::path& dir) {
    const fs::path file = dir / "manifest.json";
    PlaySet set;
    set.manifest = read_json_file(file, "scenario manifest");
    if (!set.manifest.is_object() || !set.manifest.contains("scenarios")) {
        throw InputError(file.string(), "not a railodd scenario manifest (no \"scenarios\" array)");
    }
    require_shape(set.manifest, manifest_fields(), file);
    check_entries(set.manifest, file);
    const fs::path coverage = dir / "coverage.json";
    std::error_code ec;
    if (fs::exists(coverage, ec)) {
        set.coverage = read_json_file(coverage, "scenario coverage");
        if (!set.coverage->is_object()) {
            throw InputError(coverage.string(), "not a railodd scenario coverage (not a JSON object)");
        }
    }
    return set;
}

fs::path scenario_file(const fs::path& dir, const ojson& entry) {
    return dir / entry.value("file", entry["id"].get<std::string>() + ".xosc");
}

} // namespace railodd::cli
