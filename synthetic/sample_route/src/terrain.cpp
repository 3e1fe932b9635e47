#include "terrain.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace railodd::sample {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double vertex_spacing = 10.0;
constexpr double coarse_spacing = 50.0;
constexpr double exact_band = 150.0;  // e-folding distance of the exact track elevation
constexpr double smoothing = 400.0;   // kernel width of the smoothed track elevation
constexpr double hill_shoulder = 150.0; // hill rises this far outside the portals
constexpr double hill_width = 350.0;  // lateral e-folding distance
constexpr double valley_half_width = 70.0;
constexpr double valley_reach = 2500.0; // along the brook
constexpr double side_gradient = 0.012; // ground rises to the left of the line

std::vector<double> chainages(double length, double spacing) {
    const auto n = static_cast<int>(std::ceil(length / spacing));
    std::vector<double> s;
    for (int i = 0; i <= n; ++i) {
        s.push_back(length * i / n);
    }
    return s;
}

} // namespace

Terrain::Terrain(const RouteDesign& design) : profile_(design.profile), tunnel_(design.tunnel) {
    const geometry::IndexedAlignment main(design.main.alignment);
    for (const double s : chainages(main.length(), vertex_spacing)) {
        const geometry::Pose p = main.evaluate(s);
        line_.push_back({s, p.x, p.y, profile_.elevation(s)});
    }
    for (const double s : chainages(main.length(), coarse_spacing)) {
        const geometry::Pose p = main.evaluate(s);
        coarse_.push_back({s, p.x, p.y, profile_.elevation(s)});
    }
    const geometry::Pose centre = main.evaluate(0.5 * (design.bridge.s_from + design.bridge.s_to));
    brook_x_ = centre.x;
    brook_y_ = centre.y;
    brook_hdg_ = centre.hdg + design.valley_angle;
}

Terrain::Foot Terrain::nearest(double x, double y) const {
    Foot best{0.0, 0.0, std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i + 1 < line_.size(); ++i) {
        const Vertex& a = line_[i];
        const Vertex& b = line_[i + 1];
        const double ux = b.x - a.x;
        const double uy = b.y - a.y;
        const double len2 = ux * ux + uy * uy;
        const double t = std::clamp(((x - a.x) * ux + (y - a.y) * uy) / len2, 0.0, 1.0);
        const double d = std::hypot(x - (a.x + t * ux), y - (a.y + t * uy));
        if (d < best.distance) {
            // Perpendicular distance to the segment's line keeps the side slope
            // continuous beyond the ends of the route too.
            const double lateral = (ux * (y - a.y) - uy * (x - a.x)) / std::sqrt(len2);
            best = {a.s + t * (b.s - a.s), lateral, d};
        }
    }
    return best;
}

double Terrain::smoothed_track_elevation(double x, double y) const {
    double d2_min = std::numeric_limits<double>::infinity();
    for (const Vertex& v : coarse_) {
        d2_min = std::min(d2_min, (x - v.x) * (x - v.x) + (y - v.y) * (y - v.y));
    }
    double sum = 0.0;
    double weight = 0.0;
    for (const Vertex& v : coarse_) {
        // Relative to the nearest vertex, so far-out weights cannot underflow.
        const double d2 = (x - v.x) * (x - v.x) + (y - v.y) * (y - v.y);
        const double w = std::exp(-(d2 - d2_min) / (smoothing * smoothing));
        sum += w * v.z;
        weight += w;
    }
    return sum / weight;
}

double Terrain::hill(double s, double offset) const {
    const double from = tunnel_.s_from - hill_shoulder;
    const double to = tunnel_.s_to + hill_shoulder;
    if (s <= from || s >= to) {
        return 0.0;
    }
    const double w = std::sin(pi * (s - from) / (to - from));
    return hill_height * w * w * std::exp(-(offset / hill_width) * (offset / hill_width));
}

double Terrain::valley(double x, double y) const {
    const double dx = x - brook_x_;
    const double dy = y - brook_y_;
    const double across = -dx * std::sin(brook_hdg_) + dy * std::cos(brook_hdg_);
    const double along = dx * std::cos(brook_hdg_) + dy * std::sin(brook_hdg_);
    if (std::abs(across) >= valley_half_width) {
        return 0.0;
    }
    const double c = std::cos(0.5 * pi * across / valley_half_width);
    return -valley_depth * c * c * std::exp(-(along / valley_reach) * (along / valley_reach));
}

double Terrain::undulation(double x, double y) {
    return 1.1 * std::sin(2.0 * pi * x / 870.0 + 0.7) * std::sin(2.0 * pi * y / 640.0 + 1.9) +
           0.7 * std::sin(2.0 * pi * (0.6 * x + 0.8 * y) / 1500.0 + 0.3);
}

double Terrain::elevation(double x, double y) const {
    const Foot f = nearest(x, y);
    const double exact = std::exp(-(f.distance / exact_band) * (f.distance / exact_band));
    double track = profile_.elevation(f.s);
    if (exact < 1.0) {
        track = exact * track + (1.0 - exact) * smoothed_track_elevation(x, y);
    }
    return track + hill(f.s, f.lateral) + valley(x, y) + side_gradient * f.lateral + undulation(x, y);
}

std::vector<float> sample_terrain(const Terrain& terrain, const DemGrid& grid,
                                  const ingest::LocalProjection& projection) {
    std::vector<float> values;
    values.reserve(static_cast<std::size_t>(grid.cols) * static_cast<std::size_t>(grid.rows));
    for (int row = 0; row < grid.rows; ++row) {
        for (int col = 0; col < grid.cols; ++col) {
            const ingest::XY p = projection.forward({grid.lon(col), grid.lat(row)});
            values.push_back(static_cast<float>(terrain.elevation(p.x, p.y)));
        }
    }
    return values;
}

} // namespace railodd::sample
