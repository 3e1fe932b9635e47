#include "railodd/ingest/projection.hpp"
#include "railodd/util/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>

using railodd::ingest::LocalProjection;

TEST(IngestProjection, OriginMapsToZeroAndStringIsLocalTmerc) {
    const LocalProjection proj({10.1234567, 48.7654321});
    EXPECT_DOUBLE_EQ(proj.origin().lon, 10.123457);
    EXPECT_DOUBLE_EQ(proj.origin().lat, 48.765432);
    EXPECT_EQ(proj.proj_string(),
              "+proj=tmerc +lat_0=48.765432 +lon_0=10.123457 +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m");
    const auto xy = proj.forward(proj.origin());
    EXPECT_NEAR(xy.x, 0.0, 1e-9);
    EXPECT_NEAR(xy.y, 0.0, 1e-9);
}

TEST(IngestProjection, MetricScaleNearOrigin) {
    const LocalProjection proj({10.0, 48.0});
    // One arc-minute of latitude at 48 degrees N is 1853.3 m on the WGS84 ellipsoid.
    const auto north = proj.forward({10.0, 48.0 + 1.0 / 60.0});
    EXPECT_NEAR(north.y, 1853.3, 0.5);
    EXPECT_NEAR(north.x, 0.0, 1e-6);
}

TEST(IngestProjection, RoundTripBelowOneMillimetreOver100Km) {
    const LocalProjection proj({7.42, 43.73});
    double worst = 0.0;
    for (double dx = -0.6; dx <= 0.6; dx += 0.05) {
        for (double dy = -0.45; dy <= 0.45; dy += 0.05) {
            const railodd::ingest::LonLat p{7.42 + dx, 43.73 + dy};
            const auto xy = proj.forward(p);
            const auto back = proj.inverse(xy);
            const auto xy2 = proj.forward(back);
            worst = std::max(worst, std::hypot(xy2.x - xy.x, xy2.y - xy.y));
            EXPECT_NEAR(back.lon, p.lon, 1e-9);
            EXPECT_NEAR(back.lat, p.lat, 1e-9);
        }
    }
    EXPECT_LT(worst, 1e-3);
}

TEST(IngestProjection, RejectsInvalidOrigin) {
    EXPECT_THROW(LocalProjection({10.0, 95.0}), railodd::InputError);
}
