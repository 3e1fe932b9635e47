// The map's geoReference to WGS84. Any CRS PROJ understands is accepted (a
// railodd map has a local transverse Mercator; other writers use EPSG codes
// or WKT), so the page draws maps from other tools too.
#include "parts.hpp"

#include "railodd/util/errors.hpp"

#include <proj.h>

namespace railodd::report::detail {

struct GeoFrame::Impl {
    PJ_CONTEXT* ctx = nullptr;
    PJ* pj = nullptr;
    ~Impl() {
        if (pj) proj_destroy(pj);
        if (ctx) proj_context_destroy(ctx);
    }
};

namespace {

// A bare "+proj=..." string names a CRS only with +type=crs.
std::string as_crs(const std::string& s) {
    if (s.rfind("+proj", 0) == 0 && s.find("+type=crs") == std::string::npos) {
        return s + " +type=crs";
    }
    return s;
}

} // namespace

GeoFrame::GeoFrame(const std::string& proj_string, const std::string& file) : impl_(std::make_unique<Impl>()) {
    if (proj_string.empty()) {
        throw InputError(file, "has no <geoReference>: the map cannot be placed on the earth");
    }
    impl_->ctx = proj_context_create();
    PJ* raw = proj_create_crs_to_crs(impl_->ctx, as_crs(proj_string).c_str(), "EPSG:4326", nullptr);
    if (raw) {
        impl_->pj = proj_normalize_for_visualization(impl_->ctx, raw); // lon, lat order
        proj_destroy(raw);
    }
    if (!impl_->pj) {
        throw InputError(file, "PROJ cannot use its <geoReference> '" + proj_string + "': " +
                                   proj_context_errno_string(impl_->ctx, proj_context_errno(impl_->ctx)));
    }
}

GeoFrame::~GeoFrame() = default;

LonLat GeoFrame::to_lonlat(double x, double y) const {
    PJ_COORD c = proj_trans(impl_->pj, PJ_FWD, proj_coord(x, y, 0, 0));
    return {c.xy.x, c.xy.y};
}

void GeoFrame::to_local(LonLat p, double& x, double& y) const {
    PJ_COORD c = proj_trans(impl_->pj, PJ_INV, proj_coord(p.lon, p.lat, 0, 0));
    x = c.xy.x;
    y = c.xy.y;
}

} // namespace railodd::report::detail
