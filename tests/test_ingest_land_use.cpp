// Land-use areas read by the OSM reader: closed ways and multipolygons (outer
// rings joined from open member ways, inner rings as holes), the kind table,
// areas that say nothing about the surroundings left out, rings that cannot
// close dropped with a reason, and the same result when the file has too many
// land-use ways to hold and they are read around the tracks instead.
#include "railodd/ingest/osm_reader.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <cmath>

using namespace railodd::ingest;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

// Track w1 runs east along 48.0 N from 10.000 to 10.020 E (about 1.5 km).
// w10: residential square over its west end; r20: a forest multipolygon
// over its east half, outer ring from w21 + w22, hole w23; w11: grass (not
// read); r30: a multipolygon whose second member is missing; w12: a farmland
// far north, outside the tracks' bounds.
const char* const opl = R"(n1 v1 x10.000 y48.000
n2 v1 x10.010 y48.000
n3 v1 x10.020 y48.000
n101 v1 x9.999 y47.999
n102 v1 x10.004 y47.999
n103 v1 x10.004 y48.001
n104 v1 x9.999 y48.001
n201 v1 x10.010 y47.995
n202 v1 x10.025 y47.995
n203 v1 x10.025 y48.005
n204 v1 x10.010 y48.005
n231 v1 x10.014 y47.999
n232 v1 x10.016 y47.999
n233 v1 x10.016 y48.001
n234 v1 x10.014 y48.001
n301 v1 x10.005 y47.998
n302 v1 x10.006 y47.998
n303 v1 x10.006 y48.002
n401 v1 x10.000 y48.100
n402 v1 x10.001 y48.100
n403 v1 x10.001 y48.101
w1 v1 Trailway=rail Nn1,n2,n3
w10 v1 Tlanduse=residential Nn101,n102,n103,n104,n101
w11 v1 Tlanduse=grass Nn101,n102,n103,n101
w12 v1 Tlanduse=farmland Nn401,n402,n403,n401
w21 v1 T Nn201,n202,n203
w22 v1 T Nn203,n204,n201
w23 v1 T Nn231,n232,n233,n234,n231
w31 v1 T Nn301,n302,n303
r20 v1 Ttype=multipolygon,natural=wood Mw21@outer,w23@inner,w22@outer
r30 v1 Ttype=multipolygon,landuse=industrial Mw31@outer,w99@outer
)";

IngestResult read(IngestOptions options = {}) {
    return read_osm(write_file(scratch_dir() / "input.opl", opl), options);
}

const LandUseArea* area(const IngestResult& r, const std::string& type, std::int64_t id) {
    for (const auto& a : r.land_use) {
        if (a.osm_type == type && a.id == id) {
            return &a;
        }
    }
    return nullptr;
}

} // namespace

TEST(IngestLandUse, ClosedWaysAndMultipolygonsWithTheirKinds) {
    const IngestResult r = read();
    ASSERT_EQ(r.land_use.size(), 2u);
    const LandUseArea* res = area(r, "way", 10);
    ASSERT_NE(res, nullptr);
    EXPECT_EQ(res->kind, "urban");
    EXPECT_EQ(res->tag, "landuse=residential");
    ASSERT_EQ(res->rings.size(), 1u);
    EXPECT_EQ(res->rings[0].size(), 4u) << "closed rings are stored open";
    // 0.005 deg lon x 0.002 deg lat at 48 N: about 372 m x 222 m.
    EXPECT_NEAR(res->area_m2, 372.5 * 222.4, 0.02 * 372.5 * 222.4);

    const LandUseArea* wood = area(r, "relation", 20);
    ASSERT_NE(wood, nullptr);
    EXPECT_EQ(wood->kind, "forest");
    EXPECT_EQ(wood->tag, "natural=wood");
    EXPECT_EQ(wood->rings.size(), 2u) << "outer joined from two ways, and the hole";
    const double outer = 0.015 * 74.5e3 * 0.010 * 111.2e3, hole = 0.002 * 74.5e3 * 0.002 * 111.2e3;
    EXPECT_NEAR(wood->area_m2, outer - hole, 0.02 * outer);

    EXPECT_EQ(area(r, "way", 11), nullptr) << "landuse=grass is verges, not surroundings";
    EXPECT_EQ(area(r, "way", 12), nullptr) << "far from the tracks";
    EXPECT_EQ(r.counts.input_land_use, 3u);
    EXPECT_EQ(r.counts.output_land_use, 2u);
    const auto dropped = std::find_if(r.dropped.begin(), r.dropped.end(), [](const Dropped& d) {
        return d.kind == "land_use" && d.osm_type == "relation" && d.id == 30;
    });
    ASSERT_NE(dropped, r.dropped.end());
    EXPECT_NE(dropped->reason.find("not closed"), std::string::npos) << dropped->reason;
}

TEST(IngestLandUse, ReadAroundTheTracksWhenTooManyToHold) {
    IngestOptions o;
    o.land_use_prefetch_refs = 3; // below any area: the three bounded passes
    const IngestResult bounded = read(o);
    const IngestResult held = read();
    ASSERT_EQ(bounded.land_use.size(), held.land_use.size());
    for (std::size_t i = 0; i < held.land_use.size(); ++i) {
        EXPECT_EQ(bounded.land_use[i].id, held.land_use[i].id);
        EXPECT_EQ(bounded.land_use[i].kind, held.land_use[i].kind);
        EXPECT_DOUBLE_EQ(bounded.land_use[i].area_m2, held.land_use[i].area_m2);
    }
}

TEST(IngestLandUse, OffWhenNotWanted) {
    IngestOptions o;
    o.land_use = false;
    const IngestResult r = read(o);
    EXPECT_TRUE(r.land_use.empty());
    EXPECT_EQ(r.counts.input_land_use, 0u);
}
