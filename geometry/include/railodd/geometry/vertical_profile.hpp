#pragma once
// The vertical profile of one track: elevations sampled along its alignment
// (from a DEM, from OSM `ele` tags, or none) smoothed into OpenDRIVE
// <elevation> cubics that are C1 continuous and have railway-like gradients.
#include "railodd/geometry/elevation_model.hpp"
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/ingest/projection.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace railodd::geometry {

// OpenDRIVE <elevation s a b c d>: z(ds) = a + b ds + c ds^2 + d ds^3 with
// ds = s' - s, valid from s to the next poly's s (the last to the end).
struct ElevationPoly {
    double s = 0.0;
    double a = 0.0;
    double b = 0.0;
    double c = 0.0;
    double d = 0.0;
};

// interpolated: no data on the track itself; cubic between the heights and
// grades of the vertices it joins (profile_ties.hpp).
enum class ElevationSource { dem, osm_ele, interpolated, flat };

const char* to_string(ElevationSource source);

struct SteepStretch {
    double s_start = 0.0;
    double s_end = 0.0;
    double gradient_permille = 0.0; // the steepest gradient inside, signed (+ rises with s)
};

struct VerticalProfile {
    std::vector<ElevationPoly> polys; // ascending s, first at s = 0
    ElevationSource source = ElevationSource::flat;
    double max_gradient_permille = 0.0; // max |dz/ds| over the whole profile
    std::vector<SteepStretch> steep;    // maximal stretches with |gradient| > ProfileOptions::steep_permille
    double rms_to_samples_m = 0.0;      // fit minus the elevations it kept (0 when flat)
    std::size_t samples_used = 0;       // elevations fitted (after dropping structures)
    std::size_t samples_rejected = 0;   // of those, approach samples the robust fit found off the track
};

struct ProfileInput {
    double length = 0.0;
    std::vector<double> s;               // ascending, in [0, length]
    std::vector<ingest::LonLat> lonlat;  // per sample
    std::vector<double> osm_ele;         // per sample, NaN where untagged; may be empty
    // Tunnel and bridge s-ranges: the DEM shows the ground above a tunnel or
    // below a bridge, not the track.
    std::vector<std::pair<double, double>> structures;
};

struct ProfileOptions {
    double knot_spacing_m = 100.0;
    // DEM samples this far beyond each tunnel portal / bridge abutment are
    // dropped too: mapped structure ends are a few metres off, and the
    // ground leaves the track right at them (see approach_m for further out).
    double structure_margin_m = 20.0;
    double steep_permille = 40.0;
    // Low-pass scale L of the smoothing spline: wavelengths are passed with
    // gain 1 / (1 + (2 pi L / wavelength)^4), halved at 2 pi L (~1.6 km by
    // default). SRTM noise of +-5-10 m over a few hundred metres would
    // otherwise read as gradients of tens of permille; railway grades change
    // over kilometres, and a change of grade of 12 permille (a vertical
    // curve of radius 15 km) is rounded off by about a metre.
    double smoothing_length_m = 250.0;
    // The DEM is the source only if it has a value for at least this share of
    // the samples outside structures; missing stretches are bridged like
    // tunnels.
    double min_dem_coverage = 0.9;
    // Approaches: DEM samples within this distance beyond a structure's
    // margin are fitted robustly (Huber, then Tukey's biweight), which drops
    // the ones far off the track, e.g. the ground rising over a portal's
    // cutting. Residuals are scaled by max(robust scale of all residuals,
    // robust_sigma_floor_m) and dropped beyond 4.7 times that. 0: off.
    double approach_m = 300.0;
    double robust_sigma_floor_m = 1.0;
};

// Fits the profile of one track. The source is the DEM if given and it
// covers the samples, else the OSM `ele` values where present (the fit
// interpolates between them; structures are not dropped, as `ele` is tagged
// on the track itself), else flat (z = 0). Samples inside structures (plus
// the margin) are dropped for the DEM and the smoothing spline bridges them
// with the smoothest (cubic) curve between the portals. Throws
// std::invalid_argument if the input's vectors disagree in size or s is not
// ascending within [0, length].
VerticalProfile fit_vertical_profile(const ProfileInput& input, const ElevationModel* dem,
                                     const ProfileOptions& options = {});

// Samples the alignment every step_m (and at its end), projecting each point
// to lon/lat; osm_ele is left empty for the caller to fill.
ProfileInput sample_alignment(const IndexedAlignment& alignment, const ingest::LocalProjection& projection,
                              double step_m, std::vector<std::pair<double, double>> structures);

// Elevation and gradient (dz/ds) of a profile at s: the last poly starting at
// or before s answers (the first one before the first poly's s). Empty: 0.
double elevation_at(const std::vector<ElevationPoly>& polys, double s);
double gradient_at(const std::vector<ElevationPoly>& polys, double s);

} // namespace railodd::geometry
