#pragma once
// Collects the OSM elements of the sample route, numbering them from fixed
// bases and turning clean local positions into noisy lon/lat the way a mapper
// tracing aerial imagery would place them.
#include "osm_model.hpp"
#include "rng.hpp"

#include "railodd/ingest/projection.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace railodd::sample {

class OsmBuilder {
public:
    static constexpr std::int64_t first_node_id = 1000000;
    static constexpr std::int64_t first_way_id = 2000000;
    static constexpr std::int64_t first_relation_id = 3000000;

    // sigma: standard deviation of the position noise per axis, m.
    OsmBuilder(const ingest::LocalProjection& projection, Rng& rng, double sigma);

    std::int64_t add_node(double x, double y, Tags tags, std::optional<Placement> placement);
    std::int64_t add_way(std::vector<std::int64_t> nodes, Tags tags, std::string kind,
                         std::string track, double s_from, double s_to);
    std::int64_t add_relation(std::vector<OsmMember> members, Tags tags);

    const OsmData& data() const noexcept { return data_; }
    const OsmNode& node(std::int64_t id) const;

private:
    const ingest::LocalProjection& projection_;
    Rng& rng_;
    double sigma_;
    OsmData data_;
};

} // namespace railodd::sample
