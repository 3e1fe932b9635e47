#pragma once
// The ground the railway was built into: the designed track elevation, a hill
// over the tunnel, a brook valley under the viaduct, a gentle side slope and a
// small undulation. On the track the ground equals the design within the
// undulation; away from it the track elevation is smoothed, so the DEM has no
// steps where the nearest point of the track jumps (inside curves).
#include "dem_writer.hpp"
#include "route_design.hpp"

#include "railodd/ingest/projection.hpp"

#include <vector>

namespace railodd::sample {

class Terrain {
public:
    explicit Terrain(const RouteDesign& design);

    // Ground elevation at local (x, y), m.
    double elevation(double x, double y) const;

    // Hill over the tunnel at main-line chainage s and lateral offset, m.
    double hill(double s, double offset) const;
    // Brook valley (negative) at local (x, y), m.
    double valley(double x, double y) const;
    static double undulation(double x, double y);

    static constexpr double hill_height = 52.0;
    static constexpr double valley_depth = 18.0;
    static constexpr double undulation_amplitude = 1.8;

private:
    struct Vertex {
        double s;
        double x;
        double y;
        double z; // designed track elevation
    };
    struct Foot {
        double s;
        double lateral; // signed distance, left of the track positive
        double distance;
    };
    Foot nearest(double x, double y) const;
    double smoothed_track_elevation(double x, double y) const;

    VerticalProfile profile_;
    Range tunnel_;
    std::vector<Vertex> line_;   // main line every 10 m: the ground needs no more
    std::vector<Vertex> coarse_; // every 50 m, for the smoothed elevation far out
    double brook_x_ = 0.0;       // valley axis: through the viaduct's centre ...
    double brook_y_ = 0.0;
    double brook_hdg_ = 0.0;     // ... in this direction
};

// Terrain elevation at every cell centre of the grid, row-major.
std::vector<float> sample_terrain(const Terrain& terrain, const DemGrid& grid,
                                  const ingest::LocalProjection& projection);

} // namespace railodd::sample
