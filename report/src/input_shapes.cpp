// The fields the report reads of railodd's JSON files, with their types: a
// hand-edited file is refused naming the file and the field (exit 2) before
// the page is built, not met as nlohmann's type_error (exit 4).
#include "parts.hpp"

namespace railodd::report::detail {

namespace {

using K = JsonKind;

// element, attribute and class of the ODD items in `list`, and its on_route count.
std::vector<JsonField> items(const std::string& list) {
    return {{list, K::array, false},
            {list + "/*", K::object},
            {list + "/*/element", K::string, false},
            {list + "/*/attribute", K::string, false},
            {list + "/*/class", K::string, false},
            {list + "/*/on_route", K::integer, false}};
}

std::vector<JsonField> joined(std::vector<std::vector<JsonField>> parts) {
    std::vector<JsonField> all;
    for (auto& p : parts) {
        all.insert(all.end(), p.begin(), p.end());
    }
    return all;
}

} // namespace

const std::vector<JsonField>& convert_report_shape() {
    static const std::vector<JsonField> f = {
        {"opendrive", K::object, false}, {"vertical", K::object, false}, {"vertical/sources", K::object, false},
        {"dropped", K::array, false}, {"repairs", K::array, false}, {"input", K::object, false},
        {"geometry", K::object, false}, {"geometry/summary", K::object, false},
        {"geometry/summary/node_noise", K::object, false}, {"geometry/tracks", K::array, false},
        {"geometry/tracks/*", K::object}, {"geometry/tracks/*/edge", K::integer, false},
        {"geometry/tracks/*/osm_ways", K::array, false}, {"geometry/tracks/*/length_m", K::number, false},
        {"geometry/tracks/*/nodes", K::integer, false}, {"geometry/tracks/*/rms_m", K::number, false},
        {"geometry/tracks/*/p95_m", K::number, false}, {"geometry/tracks/*/max_m", K::number, false},
        {"geometry/tracks/*/noise_sigma_m", K::number, false}};
    return f;
}

const std::vector<JsonField>& coverage_shape() {
    static const std::vector<JsonField> f =
        joined({{{"templates", K::array, false}, {"templates/*", K::object}, {"selection", K::object, false},
                 {"route", K::object, false}, {"spec", K::object, false}, {"gaps", K::array, false}},
                items("route/elements"), items("spec/elements"), items("exercised")});
    return f;
}

const std::vector<JsonField>& manifest_shape() {
    static const std::vector<JsonField> f = joined(
        {{{"scenarios", K::array, false}, {"scenarios/*", K::object}, {"scenarios/*/id", K::string, false},
          {"scenarios/*/template", K::string, false}, {"scenarios/*/text", K::string, false},
          {"scenarios/*/anchor", K::object, false}, {"scenarios/*/anchor/element", K::string, false},
          {"scenarios/*/anchor/road_id", K::string, false}, {"scenarios/*/anchor/s", K::number, false},
          {"scenarios/*/anchor/track", K::integer, false}, {"scenarios/*/anchor/chainage", K::number, false},
          {"generation", K::object, false}, {"generation/strategy", K::string, false}},
         items("scenarios/*/odd_elements")});
    return f;
}

const std::vector<JsonField>& play_shape() {
    static const std::vector<JsonField> f = {
        {"scenarios", K::array, false}, {"scenarios/*", K::object}, {"scenarios/*/id", K::string, false},
        {"scenarios/*/passed", K::boolean, false}, {"scenarios/*/ran", K::boolean, false},
        {"scenarios/*/checks", K::array, false}, {"scenarios/*/checks/*", K::object},
        {"scenarios/*/checks/*/passed", K::boolean, false}, {"scenarios/*/checks/*/check", K::string, false},
        {"scenarios/*/checks/*/detail", K::string, false}, {"player", K::object, false},
        {"player/path", K::string, false}, {"player/version", K::string, false}, {"summary", K::object, false}};
    return f;
}

ojson read_checked_json(const std::filesystem::path& file, const std::string& what,
                        const std::vector<JsonField>& shape) {
    ojson j = read_json_file(file, what);
    if (!j.is_object()) {
        throw InputError(file.string(), "not a JSON object (" + what + ")");
    }
    require_shape(j, shape, file);
    return j;
}

} // namespace railodd::report::detail
