#include "way_parts.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::ingest {

namespace {

// Consecutive repeats of one node are a mapping slip, not geometry.
std::size_t remove_repeated_refs(std::vector<std::int64_t>& refs) {
    const std::size_t before = refs.size();
    refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
    return before - refs.size();
}

} // namespace

namespace {

// Great-circle distance (spherical Earth: a bound, not a survey).
double distance_m(LonLat a, LonLat b) {
    constexpr double r = 6371008.8, rad = 3.14159265358979323846 / 180.0;
    const double dlat = (b.lat - a.lat) * rad, dlon = (b.lon - a.lon) * rad;
    const double h = std::sin(dlat / 2) * std::sin(dlat / 2) +
                     std::cos(a.lat * rad) * std::cos(b.lat * rad) * std::sin(dlon / 2) * std::sin(dlon / 2);
    return 2.0 * r * std::asin(std::min(1.0, std::sqrt(h)));
}

// The drop reason of a way with two consecutive nodes farther apart than any
// mapped track or road has them: such a way (a 300-byte way from pole to
// pole) would make the fit and the samples grow with its length, not its data.
std::string overlong_segment(const Way& way) {
    for (const auto& part : way.parts) {
        for (std::size_t i = 1; i < part.size(); ++i) {
            const double d = distance_m(part[i - 1].lonlat, part[i].lonlat);
            if (d > max_segment_m) {
                return "nodes " + std::to_string(part[i - 1].id) + " and " + std::to_string(part[i].id) + " lie " +
                       std::to_string(static_cast<long long>(d / 1000.0)) + " km apart (a mapped way has at most " +
                       std::to_string(static_cast<int>(max_segment_m / 1000.0)) + " km between nodes)";
            }
        }
    }
    return {};
}

} // namespace

std::string area_outline_reason(const RawWay& raw) {
    if (!is_closed(raw.refs)) {
        return {};
    }
    if (const auto a = raw.tags.find("area"); a != raw.tags.end() && a->second == "yes") {
        return "closed way tagged area=yes: an area's outline, not a track";
    }
    for (const char* key : {"landuse", "building", "leisure", "amenity", "natural"}) {
        if (const auto t = raw.tags.find(key); t != raw.tags.end()) {
            return "closed way tagged " + t->first + "=" + t->second + ": an area's outline, not a track";
        }
    }
    return {};
}

BuiltWay build_way(RawWay raw, const Locator& locate) {
    BuiltWay built;
    Way& way = built.way;
    way.origin = Origin::osm;
    way.id = raw.id;
    way.node_count = raw.refs.size();
    if (raw.text_repaired) {
        built.repairs.push_back(text_repair_action);
    }
    if (const std::size_t repeated = remove_repeated_refs(raw.refs); repeated > 0) {
        built.repairs.push_back("removed " + std::to_string(repeated) + " repeated consecutive node reference(s)");
    }
    std::vector<NodeRef> current;
    std::size_t single_node_parts = 0;
    auto close_part = [&] {
        if (current.size() >= 2) {
            way.parts.push_back(std::move(current));
        } else if (current.size() == 1) {
            ++single_node_parts;
        }
        current.clear();
    };
    for (std::int64_t ref : raw.refs) {
        if (const auto* e = locate(ref)) {
            NodeRef n;
            n.id = ref;
            n.lonlat = e->lonlat;
            n.ele = e->ele;
            current.push_back(n);
        } else {
            ++way.missing_nodes;
            close_part();
        }
    }
    close_part();
    way.tags = std::move(raw.tags);

    if (way.parts.empty() && raw.refs.size() < 2) {
        built.drop_reason = "way has only " + std::to_string(raw.refs.size()) + " distinct node(s)";
    } else if (way.parts.empty()) {
        built.drop_reason = way.missing_nodes == way.node_count
                                ? "none of its " + std::to_string(way.node_count) + " nodes is in the input"
                                : "fewer than two consecutive of its " + std::to_string(way.node_count) +
                                      " nodes are in the input (" + std::to_string(way.missing_nodes) + " missing)";
    } else if (auto reason = overlong_segment(way); !reason.empty()) {
        built.drop_reason = std::move(reason);
    } else if (way.missing_nodes > 0) {
        std::string action = "clipped: " + std::to_string(way.missing_nodes) + " of " +
                             std::to_string(way.node_count) + " nodes missing from the input; kept " +
                             std::to_string(way.parts.size()) + " contiguous part(s)";
        if (single_node_parts > 0) {
            action += ", discarded " + std::to_string(single_node_parts) + " isolated node(s)";
        }
        built.repairs.push_back(std::move(action));
    }
    return built;
}

void add_repairs(IngestResult& result, const char* kind, const BuiltWay& built) {
    for (const auto& a : built.repairs) {
        result.repairs.push_back({kind, "way", built.way.id, a});
    }
}

} // namespace railodd::ingest
