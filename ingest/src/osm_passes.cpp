#include "osm_passes.hpp"

#include "osm_scan.hpp"
#include "tag_rules.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>

namespace railodd::ingest {

namespace {

using bits = osmium::osm_entity_bits::type;

Tags to_tags(const osmium::TagList& list) {
    Tags tags;
    for (const auto& tag : list) {
        tags.emplace(tag.key(), tag.value());
    }
    return tags;
}

std::vector<std::int64_t> refs_of(const osmium::Way& way) {
    std::vector<std::int64_t> refs;
    refs.reserve(way.nodes().size());
    for (const auto& nr : way.nodes()) {
        refs.push_back(nr.ref());
    }
    return refs;
}

double ele_of(const osmium::TagList& tags) {
    const char* v = tags.get_value_by_key("ele");
    if (!v) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    char* end = nullptr;
    const double e = std::strtod(v, &end);
    return end != v ? e : std::numeric_limits<double>::quiet_NaN();
}

struct RelationMembers {
    bool rail_route = false;
    std::vector<std::int64_t> ways;
    std::vector<std::int64_t> relations;
};

bool is_rail_route_master(const osmium::TagList& tags) {
    const char* type = tags.get_value_by_key("type");
    const char* rm = tags.get_value_by_key("route_master");
    return type && rm && std::strcmp(type, "route_master") == 0 &&
           (std::strcmp(rm, "train") == 0 || std::strcmp(rm, "tram") == 0 || std::strcmp(rm, "subway") == 0 ||
            std::strcmp(rm, "light_rail") == 0 || std::strcmp(rm, "railway") == 0);
}

} // namespace

std::vector<std::int64_t> relation_way_members(const std::filesystem::path& file, std::int64_t relation) {
    std::map<std::int64_t, RelationMembers> relations;
    scan_osm(file, bits::relation, "reading relations", [&](const osmium::OSMObject& obj) {
        const auto& rel = static_cast<const osmium::Relation&>(obj);
        RelationMembers m;
        m.rail_route = is_rail_route(rel.tags()) || is_rail_route_master(rel.tags());
        for (const auto& member : rel.members()) {
            if (member.type() == osmium::item_type::way) {
                m.ways.push_back(member.ref());
            } else if (member.type() == osmium::item_type::relation) {
                m.relations.push_back(member.ref());
            }
        }
        relations.emplace(rel.id(), std::move(m));
    });
    const auto root = relations.find(relation);
    if (root == relations.end()) {
        throw InputError(file.string(), "relation " + std::to_string(relation) + " is not in the file");
    }
    if (!root->second.rail_route) {
        throw InputError(file.string(), "relation " + std::to_string(relation) +
                                            " is not a rail route (type=route with route=train|railway|tracks|"
                                            "tram|subway|light_rail, or a route_master of those)");
    }
    std::vector<std::int64_t> ways;
    std::vector<std::int64_t> todo{relation};
    std::vector<std::int64_t> seen;
    while (!todo.empty()) {
        const std::int64_t id = todo.back();
        todo.pop_back();
        if (std::find(seen.begin(), seen.end(), id) != seen.end()) {
            continue; // relation cycles exist in the wild
        }
        seen.push_back(id);
        const auto it = relations.find(id);
        if (it == relations.end()) {
            continue; // nested relation outside the extract
        }
        ways.insert(ways.end(), it->second.ways.begin(), it->second.ways.end());
        todo.insert(todo.end(), it->second.relations.begin(), it->second.relations.end());
    }
    std::sort(ways.begin(), ways.end());
    ways.erase(std::unique(ways.begin(), ways.end()), ways.end());
    return ways;
}

WayScan scan_track_ways(const std::filesystem::path& file, const std::vector<std::int64_t>* members,
                        std::size_t road_refs_cap) {
    WayScan scan;
    scan.roads_complete = road_refs_cap > 0;
    std::size_t road_refs = 0;
    scan_osm(file, bits::way, "reading ways", [&](const osmium::OSMObject& obj) {
        const auto& way = static_cast<const osmium::Way&>(obj);
        if (is_track(way.tags())) {
            if (!members || std::binary_search(members->begin(), members->end(), way.id())) {
                scan.tracks.push_back({way.id(), to_tags(way.tags()), refs_of(way)});
            }
        } else if (auto kind = area_feature_kind(way.tags())) {
            RawFeature f;
            f.osm_type = "way";
            f.id = way.id();
            f.kind = std::move(*kind);
            f.tags = to_tags(way.tags());
            f.refs = refs_of(way);
            scan.area_features.push_back(std::move(f));
        }
        if (scan.roads_complete && is_road(way.tags())) {
            road_refs += way.nodes().size();
            if (road_refs > road_refs_cap) {
                scan.roads_complete = false; // too many: the corridor passes read them instead
                std::vector<RawWay>().swap(scan.roads);
            } else {
                scan.roads.push_back({way.id(), to_tags(way.tags()), refs_of(way)});
            }
        }
    });
    return scan;
}

NodeScan scan_nodes(const std::filesystem::path& file, NodeLocations& wanted) {
    NodeScan scan;
    scan_osm(file, bits::node, "reading nodes", [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        ++scan.node_count;
        if (!node.location().valid()) {
            return; // deleted or location-less nodes count as missing
        }
        const LonLat ll{node.location().lon(), node.location().lat()};
        if (auto* e = wanted.find(node.id())) {
            e->lonlat = ll;
            e->ele = ele_of(node.tags());
            e->present = true;
        }
        if (auto kind = point_feature_kind(node.tags())) {
            RawFeature f;
            f.osm_type = "node";
            f.id = node.id();
            f.kind = std::move(*kind);
            f.tags = to_tags(node.tags());
            f.lonlat = ll;
            scan.point_features.push_back(std::move(f));
        }
    });
    return scan;
}

void locate_nodes(const std::filesystem::path& file, NodeLocations& wanted, const std::string& pass) {
    scan_osm(file, bits::node, pass, [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        if (auto* e = wanted.find(node.id()); e && node.location().valid()) {
            e->lonlat = {node.location().lon(), node.location().lat()};
            e->present = true;
        }
    });
}

NodeLocations collect_nodes(const std::filesystem::path& file, const std::function<bool(LonLat)>& keep) {
    NodeLocations found;
    scan_osm(file, bits::node, "reading corridor nodes", [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        if (!node.location().valid()) {
            return;
        }
        const LonLat ll{node.location().lon(), node.location().lat()};
        if (keep(ll)) {
            found.add_located(node.id(), ll);
        }
    });
    found.seal();
    return found;
}

std::vector<RawWay> scan_road_ways(const std::filesystem::path& file, const NodeLocations& corridor) {
    std::vector<RawWay> roads;
    scan_osm(file, bits::way, "reading roads", [&](const osmium::OSMObject& obj) {
        const auto& way = static_cast<const osmium::Way&>(obj);
        if (!is_road(way.tags())) {
            return;
        }
        const bool near = std::any_of(way.nodes().begin(), way.nodes().end(),
                                      [&](const osmium::NodeRef& nr) { return corridor.located(nr.ref()); });
        if (near) {
            roads.push_back({way.id(), to_tags(way.tags()), refs_of(way)});
        }
    });
    return roads;
}

} // namespace railodd::ingest
