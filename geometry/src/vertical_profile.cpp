// Choosing the elevation source, dropping what is not track, and reporting
// the fit; the smoothing itself is in vertical/hermite_spline.
#include "railodd/geometry/vertical_profile.hpp"

#include "vertical/gradient_stats.hpp"
#include "vertical/hermite_spline.hpp"
#include "vertical/robust_fit.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace railodd::geometry {

namespace {

// Elevations the fit is made to.
struct Elevations {
    std::vector<double> s;
    std::vector<double> z;
    std::vector<bool> approach; // on a structure's approach: fitted robustly
};

void validate(const ProfileInput& in) {
    if (in.lonlat.size() != in.s.size() || (!in.osm_ele.empty() && in.osm_ele.size() != in.s.size())) {
        throw std::invalid_argument("vertical profile: s, lonlat and osm_ele differ in size");
    }
    if (!(in.length >= 0.0) || !std::isfinite(in.length)) {
        throw std::invalid_argument("vertical profile: length must be finite and >= 0");
    }
    for (std::size_t i = 0; i < in.s.size(); ++i) {
        if (!(in.s[i] >= 0.0 && in.s[i] <= in.length) || (i > 0 && in.s[i] < in.s[i - 1])) {
            throw std::invalid_argument("vertical profile: s[" + std::to_string(i) +
                                        "] is outside [0, length] or not ascending");
        }
    }
}

bool in_structure(double s, const ProfileInput& in, double margin) {
    return std::any_of(in.structures.begin(), in.structures.end(), [&](const auto& r) {
        return s >= std::min(r.first, r.second) - margin && s <= std::max(r.first, r.second) + margin;
    });
}

// nullopt unless the DEM answers for enough of the samples outside structures.
std::optional<Elevations> dem_elevations(const ProfileInput& in, const ElevationModel& dem,
                                         const ProfileOptions& o) {
    Elevations e;
    std::size_t considered = 0;
    for (std::size_t i = 0; i < in.s.size(); ++i) {
        if (in_structure(in.s[i], in, o.structure_margin_m)) {
            continue;
        }
        ++considered;
        if (const auto z = dem.sample(in.lonlat[i])) {
            e.s.push_back(in.s[i]);
            e.z.push_back(*z);
            e.approach.push_back(o.approach_m > 0.0 &&
                                 in_structure(in.s[i], in, o.structure_margin_m + o.approach_m));
        }
    }
    if (considered == 0 || e.s.empty() ||
        static_cast<double>(e.s.size()) < o.min_dem_coverage * static_cast<double>(considered)) {
        return std::nullopt;
    }
    return e;
}

std::optional<Elevations> osm_elevations(const ProfileInput& in) {
    Elevations e;
    for (std::size_t i = 0; i < in.osm_ele.size(); ++i) {
        if (std::isfinite(in.osm_ele[i])) {
            e.s.push_back(in.s[i]);
            e.z.push_back(in.osm_ele[i]);
            e.approach.push_back(false); // tagged on the track itself
        }
    }
    return e.s.empty() ? std::nullopt : std::optional<Elevations>{std::move(e)};
}

// Each datum weighs the metres of track it stands for (half the distance to
// its neighbours), capped at one knot spacing so the last datum before a
// tunnel does not pin the spline with the tunnel's whole length.
vertical::SplineData weighted(const Elevations& e, double cap) {
    vertical::SplineData d{e.s, e.z, {}};
    const std::size_t n = e.s.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double left = i > 0 ? e.s[i] - e.s[i - 1] : 0.0;
        const double right = i + 1 < n ? e.s[i + 1] - e.s[i] : 0.0;
        d.w.push_back(std::clamp(0.5 * (left + right), 1e-3, cap));
    }
    return d;
}

struct Smoothed {
    std::vector<ElevationPoly> polys;
    std::vector<double> weights; // robustness weight per elevation, 0 = rejected
};

Smoothed smooth(const Elevations& e, double length, const ProfileOptions& o) {
    if (!(length > 0.0) || !(e.s.back() > e.s.front())) {
        // One place, or no length: nothing to interpolate, the mean stands.
        double mean = 0.0;
        for (const double z : e.z) {
            mean += z;
        }
        return {{{0.0, mean / static_cast<double>(e.z.size()), 0.0, 0.0, 0.0}}, std::vector<double>(e.z.size(), 1.0)};
    }
    vertical::RobustOptions ro;
    ro.sigma_floor = o.robust_sigma_floor_m;
    auto fit = vertical::fit_robust(weighted(e, o.knot_spacing_m), e.approach, length, o.knot_spacing_m,
                                    o.smoothing_length_m, ro);
    return {vertical::to_polys(fit.knots), std::move(fit.weights)};
}

// Over the elevations the fit kept.
double rms(const std::vector<ElevationPoly>& polys, const Elevations& e, const std::vector<double>& weights) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < e.s.size(); ++i) {
        if (weights[i] > 0.0) {
            const double r = elevation_at(polys, e.s[i]) - e.z[i];
            sum += r * r;
            ++n;
        }
    }
    return n == 0 ? 0.0 : std::sqrt(sum / static_cast<double>(n));
}

std::size_t poly_at(const std::vector<ElevationPoly>& polys, double s) {
    const auto it = std::upper_bound(polys.begin(), polys.end(), s,
                                     [](double v, const ElevationPoly& p) { return v < p.s; });
    return it == polys.begin() ? 0 : static_cast<std::size_t>(it - polys.begin()) - 1;
}

} // namespace

const char* to_string(ElevationSource source) {
    switch (source) {
    case ElevationSource::dem:
        return "dem";
    case ElevationSource::osm_ele:
        return "osm_ele";
    case ElevationSource::interpolated:
        return "interpolated";
    case ElevationSource::flat:
        return "flat";
    }
    return "flat";
}

VerticalProfile fit_vertical_profile(const ProfileInput& input, const ElevationModel* dem,
                                     const ProfileOptions& options) {
    validate(input);
    VerticalProfile p;
    std::optional<Elevations> e;
    if (dem && (e = dem_elevations(input, *dem, options))) {
        p.source = ElevationSource::dem;
    } else if ((e = osm_elevations(input))) {
        p.source = ElevationSource::osm_ele;
    }
    if (!e) {
        p.source = ElevationSource::flat;
        p.polys = {{0.0, 0.0, 0.0, 0.0, 0.0}};
        return p;
    }
    auto smoothed = smooth(*e, input.length, options);
    p.polys = std::move(smoothed.polys);
    p.samples_used = e->s.size();
    p.samples_rejected = static_cast<std::size_t>(
        std::count_if(smoothed.weights.begin(), smoothed.weights.end(), [](double w) { return w == 0.0; }));
    p.rms_to_samples_m = rms(p.polys, *e, smoothed.weights);
    p.max_gradient_permille = 1000.0 * vertical::max_abs_gradient(p.polys, input.length);
    p.steep = vertical::steep_stretches(p.polys, input.length, options.steep_permille / 1000.0);
    return p;
}

ProfileInput sample_alignment(const IndexedAlignment& alignment, const ingest::LocalProjection& projection,
                              double step_m, std::vector<std::pair<double, double>> structures) {
    if (!(step_m > 0.0) || !std::isfinite(step_m)) {
        throw std::invalid_argument("sample_alignment: step must be positive, got " + std::to_string(step_m));
    }
    ProfileInput in;
    in.length = alignment.length();
    in.structures = std::move(structures);
    const auto n = std::max<long>(1, std::lround(std::ceil(in.length / step_m)));
    for (long i = 0; i <= n; ++i) {
        // The last step may be short: samples stay step_m apart and end exactly at the end.
        const double s = std::min(static_cast<double>(i) * step_m, in.length);
        const Pose q = alignment.evaluate(s);
        in.s.push_back(s);
        in.lonlat.push_back(projection.inverse({q.x, q.y}));
        if (s >= in.length) {
            break;
        }
    }
    return in;
}

double elevation_at(const std::vector<ElevationPoly>& polys, double s) {
    if (polys.empty()) {
        return 0.0;
    }
    const ElevationPoly& p = polys[poly_at(polys, s)];
    const double ds = std::max(0.0, s - p.s);
    return p.a + ds * (p.b + ds * (p.c + ds * p.d));
}

double gradient_at(const std::vector<ElevationPoly>& polys, double s) {
    if (polys.empty()) {
        return 0.0;
    }
    const ElevationPoly& p = polys[poly_at(polys, s)];
    const double ds = std::max(0.0, s - p.s);
    return p.b + ds * (2.0 * p.c + 3.0 * ds * p.d);
}

} // namespace railodd::geometry
