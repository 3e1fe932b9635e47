#include "osm_builder.hpp"

#include <stdexcept>
#include <string>

namespace railodd::sample {

OsmBuilder::OsmBuilder(const ingest::LocalProjection& projection, Rng& rng, double sigma)
    : projection_(projection), rng_(rng), sigma_(sigma) {}

std::int64_t OsmBuilder::add_node(double x, double y, Tags tags, std::optional<Placement> placement) {
    const double nx = x + sigma_ * rng_.normal();
    const double ny = y + sigma_ * rng_.normal();
    const ingest::LonLat ll = projection_.inverse({nx, ny});
    OsmNode n;
    n.id = first_node_id + static_cast<std::int64_t>(data_.nodes.size());
    n.x = x;
    n.y = y;
    n.lon = ll.lon;
    n.lat = ll.lat;
    n.tags = std::move(tags);
    n.placement = std::move(placement);
    data_.nodes.push_back(std::move(n));
    return data_.nodes.back().id;
}

std::int64_t OsmBuilder::add_way(std::vector<std::int64_t> nodes, Tags tags, std::string kind,
                                 std::string track, double s_from, double s_to) {
    if (nodes.size() < 2) {
        throw std::logic_error("sample OSM: a " + kind + " way needs two nodes, got " +
                               std::to_string(nodes.size()));
    }
    OsmWay w;
    w.id = first_way_id + static_cast<std::int64_t>(data_.ways.size());
    w.nodes = std::move(nodes);
    w.tags = std::move(tags);
    w.kind = std::move(kind);
    w.track = std::move(track);
    w.s_from = s_from;
    w.s_to = s_to;
    data_.ways.push_back(std::move(w));
    return data_.ways.back().id;
}

std::int64_t OsmBuilder::add_relation(std::vector<OsmMember> members, Tags tags) {
    OsmRelation r;
    r.id = first_relation_id + static_cast<std::int64_t>(data_.relations.size());
    r.members = std::move(members);
    r.tags = std::move(tags);
    data_.relations.push_back(std::move(r));
    return data_.relations.back().id;
}

const OsmNode& OsmBuilder::node(std::int64_t id) const {
    const auto index = id - first_node_id;
    if (index < 0 || index >= static_cast<std::int64_t>(data_.nodes.size())) {
        throw std::logic_error("sample OSM: no node " + std::to_string(id));
    }
    return data_.nodes[static_cast<std::size_t>(index)];
}

} // namespace railodd::sample
