#include "osm_relations.hpp"

#include "osm_scan.hpp"
#include "tag_rules.hpp"

#include <algorithm>
#include <cstring>
#include <map>

namespace railodd::ingest {

namespace {

using bits = osmium::osm_entity_bits::type;

struct Members {
    bool rail_route = false;
    bool route_master = false;
    std::vector<std::pair<osmium::item_type, std::int64_t>> items; // ways and relations, in member order
};

bool is_rail_route_master(const osmium::TagList& tags) {
    const char* type = tags.get_value_by_key("type");
    const char* rm = tags.get_value_by_key("route_master");
    return type && rm && std::strcmp(type, "route_master") == 0 &&
           (std::strcmp(rm, "train") == 0 || std::strcmp(rm, "tram") == 0 || std::strcmp(rm, "subway") == 0 ||
            std::strcmp(rm, "light_rail") == 0 || std::strcmp(rm, "railway") == 0);
}

// Ways of `id` in member order, nested relations expanded in place; `seen`
// guards against the relation cycles that exist in the wild, and nested
// relations outside the extract are skipped.
void ordered_ways(const std::map<std::int64_t, Members>& all, std::int64_t id, std::vector<std::int64_t>& seen,
                  std::vector<std::int64_t>& out) {
    const auto it = all.find(id);
    if (it == all.end() || std::find(seen.begin(), seen.end(), id) != seen.end()) {
        return;
    }
    seen.push_back(id);
    for (const auto& [type, ref] : it->second.items) {
        if (type == osmium::item_type::way) {
            out.push_back(ref);
        } else {
            ordered_ways(all, ref, seen, out);
        }
    }
}

// The relation whose ways make the route's chainage: a route_master's routes
// run in both directions, so its first rail route member stands for it.
std::int64_t chainage_relation(const std::map<std::int64_t, Members>& all, std::int64_t id) {
    const Members& m = all.at(id);
    if (!m.route_master) {
        return id;
    }
    for (const auto& [type, ref] : m.items) {
        const auto it = all.find(ref);
        if (type == osmium::item_type::relation && it != all.end() && it->second.rail_route) {
            return ref;
        }
    }
    return id;
}

void add_land_use(const osmium::Relation& rel, RelationScan& scan) {
    const auto lu = land_use_kind(rel.tags());
    if (!lu || !is_multipolygon(rel.tags())) {
        return;
    }
    RawLandUseRelation r{rel.id(), lu->kind, lu->tag, {}};
    for (const auto& member : rel.members()) {
        if (member.type() == osmium::item_type::way) {
            r.ways.emplace_back(member.ref(), std::strcmp(member.role(), "inner") == 0);
            scan.land_use_members.push_back(member.ref());
        }
    }
    scan.land_use.push_back(std::move(r));
}

} // namespace

RelationScan scan_relations(const std::filesystem::path& file, std::optional<std::int64_t> route) {
    RelationScan scan;
    std::map<std::int64_t, Members> relations; // only kept when a route is asked for
    Tags route_tags;
    scan_osm(file, bits::relation, "reading relations", [&](const osmium::OSMObject& obj) {
        const auto& rel = static_cast<const osmium::Relation&>(obj);
        add_land_use(rel, scan);
        if (!route) {
            return;
        }
        Members m;
        m.route_master = is_rail_route_master(rel.tags());
        m.rail_route = is_rail_route(rel.tags()) || m.route_master;
        for (const auto& member : rel.members()) {
            if (member.type() == osmium::item_type::way || member.type() == osmium::item_type::relation) {
                m.items.emplace_back(member.type(), member.ref());
            }
        }
        if (rel.id() == *route) {
            route_tags = tags_of(rel.tags(), scan.route_text_repaired);
        }
        relations.emplace(rel.id(), std::move(m));
    });
    std::sort(scan.land_use.begin(), scan.land_use.end(),
              [](const RawLandUseRelation& a, const RawLandUseRelation& b) { return a.id < b.id; });
    std::sort(scan.land_use_members.begin(), scan.land_use_members.end());
    scan.land_use_members.erase(std::unique(scan.land_use_members.begin(), scan.land_use_members.end()),
                                scan.land_use_members.end());
    if (!route) {
        return scan;
    }
    const auto root = relations.find(*route);
    if (root == relations.end()) {
        throw InputError(file.string(), "relation " + std::to_string(*route) + " is not in the file");
    }
    if (!root->second.rail_route) {
        throw InputError(file.string(), "relation " + std::to_string(*route) +
                                            " is not a rail route (type=route with route=train|railway|tracks|"
                                            "tram|subway|light_rail, or a route_master of those)");
    }
    std::vector<std::int64_t> seen;
    ordered_ways(relations, *route, seen, scan.route_ways);
    std::sort(scan.route_ways.begin(), scan.route_ways.end());
    scan.route_ways.erase(std::unique(scan.route_ways.begin(), scan.route_ways.end()), scan.route_ways.end());
    RouteRelation r{*route, std::move(route_tags), {}};
    seen.clear();
    ordered_ways(relations, chainage_relation(relations, *route), seen, r.ways);
    scan.route = std::move(r);
    return scan;
}

} // namespace railodd::ingest
