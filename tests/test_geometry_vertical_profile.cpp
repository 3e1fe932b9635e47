// Vertical profile fitting: continuity, recovery of known profiles, tunnels,
// fallbacks, and the sample route's designed profile from its DEM.
#include "railodd/geometry/vertical_profile.hpp"
#include "railodd/ingest/projection.hpp"
#include "railodd/sample/sample_route.hpp"

#include "test_dem_support.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>

using namespace railodd;
using geometry::ElevationModel;
using geometry::ElevationSource;
using geometry::ProfileInput;
using nlohmann::json;

namespace {

constexpr double untagged = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = std::numbers::pi;
constexpr double route_length = 5000.0;

// A straight line due east through the projection origin, s = x + 2500.
geometry::IndexedAlignment east_line() {
    geometry::Alignment a;
    a.start = {-0.5 * route_length, 0.0, 0.0, 0.0};
    a.primitives = {geometry::make_line(route_length)};
    return geometry::IndexedAlignment(a);
}

const ingest::LocalProjection& projection() {
    static const ingest::LocalProjection p({10.0, 48.0});
    return p;
}

// Deterministic noise in [-1, 1] per pixel.
double noise(double lon, double lat) {
    auto h = static_cast<std::uint64_t>(std::llround(lon * 3600.0)) * 0x9E3779B97F4A7C15ULL ^
             static_cast<std::uint64_t>(std::llround(lat * 3600.0)) * 0xC2B2AE3D27D4EB4FULL;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 32;
    return static_cast<double>(h % 20001) / 10000.0 - 1.0;
}

// A 1" DEM around the east line whose ground at chainage s (the pixel
// centre's, projected on the line) is ground(s), plus noise(lon, lat) * noise_m.
std::filesystem::path line_dem(const std::filesystem::path& dir, const std::function<double(double s)>& ground,
                               double noise_m = 0.0) {
    test::DemSpec spec;
    spec.x0 = 9.96;
    spec.y0 = 48.01;
    spec.cols = 288; // to lon 10.04
    spec.rows = 72;  // to lat 47.99
    const auto path = dir / (noise_m > 0.0 ? "noisy_dem.tif" : "line_dem.tif");
    test::write_dem(path, spec, [&](double lon, double lat) {
        return ground(projection().forward({lon, lat}).x + 0.5 * route_length) + noise_m * noise(lon, lat);
    });
    return path;
}

ProfileInput line_input(std::vector<std::pair<double, double>> structures = {}) {
    return geometry::sample_alignment(east_line(), projection(), 10.0, std::move(structures));
}

// Value and slope of neighbouring polys agree at every joint.
void expect_c1(const std::vector<geometry::ElevationPoly>& polys) {
    for (std::size_t k = 0; k + 1 < polys.size(); ++k) {
        const auto& p = polys[k];
        const auto& q = polys[k + 1];
        const double h = q.s - p.s;
        EXPECT_NEAR(p.a + h * (p.b + h * (p.c + h * p.d)), q.a, 1e-9) << "joint " << k;
        EXPECT_NEAR(p.b + h * (2.0 * p.c + 3.0 * h * p.d), q.b, 1e-9) << "joint " << k;
    }
}

// One period over the route: no curvature at its ends, where the smoothing
// spline's natural end conditions would otherwise bias it.
constexpr double wave_length = route_length;
constexpr double wave_height = 15.0;
double wave(double s) { return 400.0 + wave_height * std::sin(2.0 * pi * s / wave_length); }

} // namespace

TEST(VerticalProfile, JointsAreC1) {
    const auto dir = test::scratch_dir();
    const ElevationModel dem(line_dem(dir, [](double s) { return wave(s) + 7.0 * std::sin(s / 37.0); }));
    const auto p = geometry::fit_vertical_profile(line_input(), &dem, {});
    ASSERT_EQ(p.source, ElevationSource::dem);
    ASSERT_EQ(p.polys.size(), 50u);
    EXPECT_EQ(p.polys.front().s, 0.0);
    expect_c1(p.polys);
}

TEST(VerticalProfile, RecoversAKnownProfileFromTheDem) {
    const auto dir = test::scratch_dir();
    const ElevationModel dem(line_dem(dir, wave));
    const auto p = geometry::fit_vertical_profile(line_input(), &dem, {});
    ASSERT_EQ(p.source, ElevationSource::dem);
    const double top_grade = wave_height * 2.0 * pi / wave_length;
    for (double s = 0.0; s <= route_length; s += 25.0) {
        // The natural end conditions (z'' = z''' = 0) bend the last few
        // hundred metres where the true profile has z''' != 0 there.
        const bool end = s < 1000.0 || s > route_length - 1000.0; // ~4 smoothing lengths
        EXPECT_NEAR(geometry::elevation_at(p.polys, s), wave(s), end ? 0.8 : 0.2) << s;
        EXPECT_NEAR(geometry::gradient_at(p.polys, s), top_grade * std::cos(2.0 * pi * s / wave_length),
                    end ? 2.5e-3 : 0.5e-3)
            << s;
    }
    EXPECT_NEAR(p.max_gradient_permille, 1000.0 * top_grade, 0.5);
    EXPECT_LT(p.rms_to_samples_m, 0.3);
    EXPECT_EQ(p.samples_rejected, 0u);
    EXPECT_TRUE(p.steep.empty());
}

TEST(VerticalProfile, DemNoiseMakesNoGradientSpikes) {
    const auto dir = test::scratch_dir();
    // +-8 m of pixel noise on an 8 permille grade.
    const ElevationModel dem(line_dem(dir, [](double s) { return 300.0 + 0.008 * s; }));
    const auto clean = geometry::fit_vertical_profile(line_input(), &dem, {});
    const ElevationModel noisy_dem(line_dem(dir, [](double s) { return 300.0 + 0.008 * s; }, 8.0));
    const auto noisy = geometry::fit_vertical_profile(line_input(), &noisy_dem, {});
    std::cout << "[ measured ] 8 permille grade under +-8 m noise: max gradient " << noisy.max_gradient_permille
              << " permille, rms to samples " << noisy.rms_to_samples_m << " m\n";
    EXPECT_NEAR(clean.max_gradient_permille, 8.0, 0.05);
    EXPECT_LT(noisy.max_gradient_permille, 12.0);
    EXPECT_TRUE(noisy.steep.empty());
    expect_c1(noisy.polys);
}

TEST(VerticalProfile, TunnelIgnoresTheHillAbove) {
    const auto dir = test::scratch_dir();
    auto track = [](double s) { return 350.0 + 0.006 * s; };
    // A 70 m hill between s 1985 and 2615; the tunnel runs 2000..2600.
    const ElevationModel dem(line_dem(dir, [&](double s) {
        const double u = (s - 1985.0) / 630.0;
        const double hill = u > 0.0 && u < 1.0 ? 70.0 * std::pow(std::sin(pi * u), 2) : 0.0;
        return track(s) + hill;
    }));
    const auto through = geometry::fit_vertical_profile(line_input({{2000.0, 2600.0}}), &dem, {});
    ASSERT_EQ(through.source, ElevationSource::dem);
    double worst = 0.0;
    for (double s = 0.0; s <= route_length; s += 10.0) {
        worst = std::max(worst, std::abs(geometry::elevation_at(through.polys, s) - track(s)));
    }
    EXPECT_LT(worst, 0.1);
    EXPECT_NEAR(through.max_gradient_permille, 6.0, 0.1);
    // Without the tunnel the fit climbs over the hill.
    const auto over = geometry::fit_vertical_profile(line_input(), &dem, {});
    EXPECT_GT(geometry::elevation_at(over.polys, 2300.0) - track(2300.0), 20.0);
}

TEST(VerticalProfile, PortalCuttingsDoNotLiftTheTrack) {
    const auto dir = test::scratch_dir();
    auto track = [](double s) { return 350.0 - 0.004 * s; };
    // The hill rises 150 m before each portal of the tunnel 2000..2600, far
    // beyond the 20 m margin: the approaches run in deepening cuttings.
    const ElevationModel dem(line_dem(dir, [&](double s) {
        const double u = (s - 1850.0) / 900.0;
        const double hill = u > 0.0 && u < 1.0 ? 60.0 * std::pow(std::sin(pi * u), 2) : 0.0;
        return track(s) + hill;
    }));
    auto worst = [&](const geometry::VerticalProfile& p) {
        double w = 0.0;
        for (double s = 0.0; s <= route_length; s += 10.0) {
            w = std::max(w, std::abs(geometry::elevation_at(p.polys, s) - track(s)));
        }
        return w;
    };
    const auto robust = geometry::fit_vertical_profile(line_input({{2000.0, 2600.0}}), &dem, {});
    geometry::ProfileOptions plain_options;
    plain_options.approach_m = 0.0;
    const auto plain = geometry::fit_vertical_profile(line_input({{2000.0, 2600.0}}), &dem, plain_options);
    std::cout << "[ measured ] portal cuttings: max error " << worst(robust) << " m robust, " << worst(plain)
              << " m least squares; " << robust.samples_rejected << " samples rejected\n";
    EXPECT_LT(worst(robust), 1.0);
    EXPECT_GT(worst(plain), 2.0 * worst(robust));
    EXPECT_GT(robust.samples_rejected, 0u);
    EXPECT_EQ(plain.samples_rejected, 0u);
}

TEST(VerticalProfile, SteepRampFromTheDemIsKept) {
    const auto dir = test::scratch_dir();
    // 50 permille for 1 km: robust reweighting must not flatten a real ramp.
    const ElevationModel dem(line_dem(dir, [](double s) { return 100.0 + 0.05 * std::clamp(s - 2000.0, 0.0, 1000.0); }));
    const auto p = geometry::fit_vertical_profile(line_input({{4500.0, 4600.0}}), &dem, {});
    ASSERT_EQ(p.steep.size(), 1u);
    EXPECT_NEAR(p.max_gradient_permille, 50.0, 3.0);
    EXPECT_EQ(p.samples_rejected, 0u);
}

TEST(VerticalProfile, FlatWithoutElevations) {
    auto in = line_input();
    const auto p = geometry::fit_vertical_profile(in, nullptr, {});
    EXPECT_EQ(p.source, ElevationSource::flat);
    EXPECT_STREQ(geometry::to_string(p.source), "flat");
    ASSERT_EQ(p.polys.size(), 1u);
    EXPECT_EQ(geometry::elevation_at(p.polys, 1234.0), 0.0);
    EXPECT_EQ(p.max_gradient_permille, 0.0);
    // All-NaN ele tags are no elevations either.
    in.osm_ele.assign(in.s.size(), untagged);
    EXPECT_EQ(geometry::fit_vertical_profile(in, nullptr, {}).source, ElevationSource::flat);
}

TEST(VerticalProfile, OsmEleWhenTheDemDoesNotCover) {
    const auto dir = test::scratch_dir();
    // The DEM lies a degree away from the line.
    test::DemSpec far;
    far.x0 = 11.0;
    far.y0 = 49.0;
    far.cols = 50;
    far.rows = 50;
    test::write_dem(dir / "far.tif", far, [](double, double) { return 123.0; });
    const ElevationModel dem(dir / "far.tif");
    auto in = line_input();
    in.osm_ele.assign(in.s.size(), untagged);
    for (std::size_t i = 0; i < in.s.size(); i += 25) { // a tagged node every 250 m
        in.osm_ele[i] = 200.0 + 0.009 * in.s[i];
    }
    const auto p = geometry::fit_vertical_profile(in, &dem, {});
    EXPECT_EQ(p.source, ElevationSource::osm_ele);
    EXPECT_EQ(p.samples_used, 21u);
    for (double s = 0.0; s <= route_length; s += 50.0) {
        EXPECT_NEAR(geometry::elevation_at(p.polys, s), 200.0 + 0.009 * s, 0.01) << s;
    }
    EXPECT_NEAR(p.max_gradient_permille, 9.0, 0.01);
}

TEST(VerticalProfile, SteepStretchesAreListed) {
    auto in = line_input();
    in.osm_ele.resize(in.s.size());
    for (std::size_t i = 0; i < in.s.size(); ++i) {
        const double s = in.s[i];
        in.osm_ele[i] = 100.0 + 0.05 * std::clamp(s - 2000.0, 0.0, 1000.0); // 50 permille for 1 km
    }
    const auto p = geometry::fit_vertical_profile(in, nullptr, {});
    ASSERT_EQ(p.steep.size(), 1u);
    EXPECT_NEAR(p.steep[0].s_start, 2000.0, 250.0);
    EXPECT_NEAR(p.steep[0].s_end, 3000.0, 250.0);
    EXPECT_GT(p.steep[0].gradient_permille, 45.0);
    EXPECT_LT(p.steep[0].gradient_permille, 56.0);
    EXPECT_NEAR(p.max_gradient_permille, p.steep[0].gradient_permille, 1e-9);
    for (double s = p.steep[0].s_start + 1.0; s < p.steep[0].s_end; s += 5.0) {
        EXPECT_GT(geometry::gradient_at(p.polys, s), 0.04) << s;
    }
}

namespace {

geometry::Alignment alignment_from(const json& track) {
    geometry::Alignment a;
    a.start = {track["start"]["x"], track["start"]["y"], track["start"]["hdg"], 0.0};
    for (const auto& p : track["primitives"]) {
        const std::string kind = p["kind"];
        const auto k = kind == "line"  ? geometry::PrimitiveKind::line
                       : kind == "arc" ? geometry::PrimitiveKind::arc
                                       : geometry::PrimitiveKind::spiral;
        a.primitives.push_back({k, p["length"], p["curv_start"], p["curv_end"]});
    }
    return a;
}

std::vector<std::pair<double, double>> structures_of(const json& features) {
    std::vector<std::pair<double, double>> out;
    for (const char* kind : {"tunnels", "bridges"}) {
        for (const auto& f : features[kind]) {
            out.emplace_back(f["s_from"], f["s_to"]);
        }
    }
    return out;
}

bool inside(double s, const std::vector<std::pair<double, double>>& ranges) {
    for (const auto& [a, b] : ranges) {
        if (s >= a && s <= b) {
            return true;
        }
    }
    return false;
}

} // namespace

TEST(VerticalProfile, SampleRouteMatchesTheDesign) {
    const auto dir = test::scratch_dir();
    const auto files = sample::write_sample_route(dir);
    const json truth = json::parse(test::read_file(files.truth));
    const auto& frame = truth["frame"];
    const ingest::LocalProjection proj({frame["origin_lon"], frame["origin_lat"]});
    ASSERT_EQ(proj.proj_string(), frame["proj"].get<std::string>());
    const geometry::IndexedAlignment main(alignment_from(truth["tracks"][0]));
    const auto structures = structures_of(truth["features"]);
    ASSERT_EQ(structures.size(), 2u);

    const ElevationModel dem(files.dem);
    const auto p = geometry::fit_vertical_profile(geometry::sample_alignment(main, proj, 10.0, structures), &dem, {});
    ASSERT_EQ(p.source, ElevationSource::dem);
    expect_c1(p.polys);

    double worst_open = 0.0;
    double worst_structure = 0.0;
    double sum2 = 0.0;
    const auto& samples = truth["elevation"]["samples"];
    for (const auto& e : samples) {
        const double s = e["s"];
        const double err = std::abs(geometry::elevation_at(p.polys, s) - e["z"].get<double>());
        sum2 += err * err;
        double& worst = inside(s, structures) ? worst_structure : worst_open;
        worst = std::max(worst, err);
    }
    const double design_grade = truth["elevation"]["max_grade_permille"];
    std::cout << "[ measured ] sample route: max |fit - design| " << worst_open << " m outside structures, "
              << worst_structure << " m in tunnel/bridge, rms " << std::sqrt(sum2 / samples.size())
              << " m; max gradient " << p.max_gradient_permille << " permille (design " << design_grade
              << "); rms to DEM samples " << p.rms_to_samples_m << " m; " << p.samples_rejected << " of "
              << p.samples_used << " samples rejected on approaches\n";
    EXPECT_LT(worst_open, 2.0);
    EXPECT_LT(worst_structure, 1.0);
    EXPECT_NEAR(p.max_gradient_permille, design_grade, 2.0);
    EXPECT_TRUE(p.steep.empty());
}

