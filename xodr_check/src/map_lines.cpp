// The checker's reading of a map, handed out as drawable road lines.
#include "railodd/xodr_check/map_lines.hpp"

#include "model.hpp"

#include "railodd/util/input_file.hpp"

#include <algorithm>

namespace railodd::xodr_check {

Pose MapRoad::pose(double s) const {
    if (geometries.empty()) {
        return {};
    }
    s = std::clamp(s, 0.0, length);
    // The last record starting at or before s.
    auto it = std::upper_bound(geometries.begin(), geometries.end(), s,
                               [](double v, const GeometryRecord& g) { return v < g.s; });
    const GeometryRecord& g = it == geometries.begin() ? geometries.front() : *std::prev(it);
    return evaluate(g, std::clamp(s - g.s, 0.0, g.length));
}

double MapRoad::elevation(double s) const {
    if (elevations.empty()) {
        return 0.0;
    }
    auto it = std::upper_bound(elevations.begin(), elevations.end(), s,
                               [](double v, const Elevation& e) { return v < e.s; });
    const Elevation& e = it == elevations.begin() ? elevations.front() : *std::prev(it);
    return e.at(s);
}

namespace {

std::string trimmed(std::string s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    const auto last = s.find_last_not_of(" \t\r\n");
    return first == std::string::npos ? std::string{} : s.substr(first, last - first + 1);
}

} // namespace

MapLines read_map_lines(const std::filesystem::path& file) {
    Document doc = read_document(read_input_file(file, "OpenDRIVE map"), file.string());
    MapLines lines;
    lines.file = file.string();
    lines.geo_reference = trimmed(doc.geo_reference);
    lines.roads.reserve(doc.roads.size());
    for (Road& r : doc.roads) {
        MapRoad m;
        m.id = std::move(r.id);
        m.name = std::move(r.name);
        m.junction = std::move(r.junction);
        m.length = r.length;
        m.rail = r.rail;
        m.osm_ids = std::move(r.osm_ids);
        m.geometries = std::move(r.geometries);
        m.elevations = std::move(r.elevations);
        lines.roads.push_back(std::move(m));
    }
    return lines;
}

} // namespace railodd::xodr_check
