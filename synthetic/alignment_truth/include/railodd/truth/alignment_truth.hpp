#pragma once
// Ground truth for the alignment fit: seeded railway alignments made by design
// rules (straights, transition curves sized for a design speed, arcs; reverse
// and compound curves), drawn as OpenStreetMap mappers draw them (nodes far
// apart on straights, close in curves, lateral scatter, a few outlier nodes),
// and the scores of a fitted centreline against the design it should recover.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/fit_alignment.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace railodd::truth {

// How far apart the mapped nodes are: as OSM mappers draw track (50-250 m
// on straights, 5-40 m in curves), densely (5-15 m everywhere, GPS-traced
// ways), sparsely (100-400 m on straights, 25-60 m in curves) or very
// sparsely (250-1,250 m on straights, 25-200 m in curves: a line mapped
// from a few points; issue 37 names no target for it, the sparse limit is
// applied). On straights every draw puts a node 2-15 m past each curve's
// start.
enum class Spacing { osm, dense, sparse, very_sparse };

// The spacing of a command line's name (osm, dense, sparse, very-sparse);
// nothing for any other name.
std::optional<Spacing> spacing_named(const std::string& name);
// Those names, comma-separated (for a usage message).
std::string spacing_names();

struct TruthOptions {
    double sigma_m = 0.3;            // lateral scatter of the mapped nodes
    Spacing spacing = Spacing::osm;
    double outlier_fraction = 0.01;  // nodes placed 3-10 m off the centreline
    double length_m = 8000.0;        // the design is at least this long
};

struct DesignArc {
    double s0 = 0.0, s1 = 0.0; // along the design
    double curvature = 0.0;    // signed, 1/m
};

struct TruthRoute {
    geometry::Alignment design;         // G2: lines, clothoids, arcs
    std::vector<DesignArc> arcs;        // the design's circular arcs
    std::vector<geometry::Point> nodes; // as mapped
    std::vector<bool> outlier;          // per node
    std::size_t sign_changes = 0;       // of the design's curvature (truth::sign_changes)
};

TruthRoute make_route(std::uint64_t seed, const TruthOptions& options);

struct TruthScore {
    double deviation_p50_m = 0.0; // distance of the true centreline (every 2 m) to the fit
    double deviation_p95_m = 0.0;
    double deviation_max_m = 0.0;
    double deviation_max_at_m = 0.0; // chainage of the true centreline where it is
    std::vector<double> radius_errors; // per design arc: |R_fit / R_true - 1| at the arc's middle
    std::size_t design_elements = 0;
    std::size_t fit_elements = 0;
    long spurious_sign_changes = 0; // fit's curvature sign changes beyond the design's
};

// Curvature sign changes along an alignment, sampled every 5 m; curvatures
// below 1/20,000 m count as straight.
std::size_t sign_changes(const geometry::Alignment& a);

TruthScore score(const TruthRoute& route, const geometry::Alignment& fit);

// Issue 37's limit on a route's largest deviation from the true centreline:
// 1 m up to 0.3 m of noise (1.5 m on sparse and very sparse nodes), 2.5 m
// at 1 m, 5 m at 2 m.
double deviation_limit(double sigma, Spacing spacing);

} // namespace railodd::truth
