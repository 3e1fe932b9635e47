// The checker's reading of a map, handed out as drawable road lines.
#include "railodd/xodr_check/map_lines.hpp"

#include "model.hpp"

#include "railodd/util/input_file.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::xodr_check {

namespace {

// The record in force at s: the last starting at or before it.
const Elevation* in_force(const std::vector<Elevation>& records, double s) {
    auto it = std::upper_bound(records.begin(), records.end(), s, [](double v, const Elevation& e) { return v < e.s; });
    return it == records.begin() ? (records.empty() ? nullptr : &records.front()) : &*std::prev(it);
}

double width_at(const MapLane& lane, double ds) {
    const Elevation* w = in_force(lane.widths, ds);
    return w ? w->at(ds) : 0.0;
}

// A lane's centre, from the road's reference line (left +): the widths of
// the lanes between it and the centre lane and half its own.
std::optional<double> lane_centre(const MapSection& sec, int lane_id, double ds) {
    const auto lane = [&](int id) -> const MapLane* {
        for (const MapLane& l : sec.lanes) {
            if (l.id == id) {
                return &l;
            }
        }
        return nullptr;
    };
    const MapLane* own = lane(lane_id);
    if (!own || lane_id == 0) {
        return lane_id == 0 ? std::optional<double>(0.0) : std::nullopt;
    }
    const int step = lane_id > 0 ? 1 : -1;
    double t = 0.0;
    for (int id = step; id != lane_id; id += step) {
        const MapLane* inner = lane(id);
        t += inner ? width_at(*inner, ds) : 0.0;
    }
    return step * (t + 0.5 * width_at(*own, ds));
}

} // namespace

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

std::optional<Pose> MapRoad::lane_position(int lane_id, double s, double offset) const {
    if (geometries.empty() || sections.empty()) {
        return std::nullopt;
    }
    auto sec = std::upper_bound(sections.begin(), sections.end(), s,
                                 [](double v, const MapSection& x) { return v < x.s; });
    const MapSection& section = sec == sections.begin() ? sections.front() : *std::prev(sec);
    const std::optional<double> centre = lane_centre(section, lane_id, s - section.s);
    if (!centre) {
        return std::nullopt;
    }
    const Elevation* shift = in_force(lane_offsets, s);
    const double t = *centre + (shift ? shift->at(s) : 0.0) + offset;
    Pose p = pose(s);
    p.x -= t * std::sin(p.hdg);
    p.y += t * std::cos(p.hdg);
    return p;
}

double MapRoad::elevation(double s) const {
    const Elevation* e = in_force(elevations, s);
    return e ? e->at(s) : 0.0;
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
        m.predecessor = r.predecessor.element_type == "road" ? r.predecessor.element_id : "";
        m.successor = r.successor.element_type == "road" ? r.successor.element_id : "";
        m.length = r.length;
        m.rail = r.rail;
        m.osm_ids = std::move(r.osm_ids);
        m.geometries = std::move(r.geometries);
        m.elevations = std::move(r.elevations);
        m.lane_offsets = std::move(r.lane_offsets);
        for (LaneSection& ls : r.sections) {
            MapSection sec{ls.s, {}};
            for (Lane& l : ls.lanes) {
                sec.lanes.push_back({l.id, std::move(l.widths)});
            }
            m.sections.push_back(std::move(sec));
        }
        lines.roads.push_back(std::move(m));
    }
    return lines;
}

} // namespace railodd::xodr_check
