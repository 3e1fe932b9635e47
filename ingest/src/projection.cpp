#include "railodd/ingest/projection.hpp"

#include "railodd/util/errors.hpp"

#include <proj.h>

#include <cmath>
#include <cstdio>

namespace railodd::ingest {

namespace {

double round6(double v) { return std::round(v * 1e6) / 1e6; }

std::string tmerc_string(LonLat o) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "+proj=tmerc +lat_0=%.6f +lon_0=%.6f +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m",
                  o.lat, o.lon);
    return buf;
}

} // namespace

// One PROJ context per projection: PROJ contexts must not be shared between threads.
struct LocalProjection::Impl {
    PJ_CONTEXT* ctx = nullptr;
    PJ* pj = nullptr;
    ~Impl() {
        if (pj) proj_destroy(pj);
        if (ctx) proj_context_destroy(ctx);
    }
};

LocalProjection::LocalProjection(LonLat origin)
    : origin_{round6(origin.lon), round6(origin.lat)}, proj_string_(tmerc_string(origin_)),
      impl_(std::make_unique<Impl>()) {
    // Transverse Mercator is regular up to the pole itself.
    if (!(std::abs(origin_.lat) < 90.0) || !(std::abs(origin_.lon) <= 180.0)) {
        throw InputError("projection", "origin out of range: lon " + std::to_string(origin_.lon) +
                                           ", lat " + std::to_string(origin_.lat));
    }
    impl_->ctx = proj_context_create();
    impl_->pj = proj_create(impl_->ctx, proj_string_.c_str());
    if (!impl_->pj) {
        throw InputError("projection", "PROJ rejected '" + proj_string_ +
                                           "': " + proj_context_errno_string(impl_->ctx, proj_context_errno(impl_->ctx)));
    }
}

LocalProjection::~LocalProjection() = default;
LocalProjection::LocalProjection(LocalProjection&&) noexcept = default;
LocalProjection& LocalProjection::operator=(LocalProjection&&) noexcept = default;

XY LocalProjection::forward(LonLat p) const {
    PJ_COORD c = proj_coord(proj_torad(p.lon), proj_torad(p.lat), 0, 0);
    c = proj_trans(impl_->pj, PJ_FWD, c);
    return {c.xy.x, c.xy.y};
}

LonLat LocalProjection::inverse(XY p) const {
    PJ_COORD c = proj_coord(p.x, p.y, 0, 0);
    c = proj_trans(impl_->pj, PJ_INV, c);
    return {proj_todeg(c.lp.lam), proj_todeg(c.lp.phi)};
}

} // namespace railodd::ingest
