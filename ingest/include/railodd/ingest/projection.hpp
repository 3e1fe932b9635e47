#pragma once
// Local metric frame: a transverse Mercator projection centred on the selection,
// so coordinates stay small and scale error stays negligible over a route.
#include <memory>
#include <string>

namespace railodd::ingest {

struct LonLat {
    double lon = 0.0;
    double lat = 0.0;
};

struct XY {
    double x = 0.0; // metres east of the origin
    double y = 0.0; // metres north of the origin
};

class LocalProjection {
public:
    // Origin is rounded to 1e-6 degrees so the PROJ string is short and stable.
    explicit LocalProjection(LonLat origin);
    ~LocalProjection();
    LocalProjection(LocalProjection&&) noexcept;
    LocalProjection& operator=(LocalProjection&&) noexcept;
    LocalProjection(const LocalProjection&) = delete;
    LocalProjection& operator=(const LocalProjection&) = delete;

    XY forward(LonLat p) const;
    LonLat inverse(XY p) const;

    LonLat origin() const noexcept { return origin_; }
    // For OpenDRIVE's <geoReference>.
    const std::string& proj_string() const noexcept { return proj_string_; }

private:
    struct Impl;
    LonLat origin_;
    std::string proj_string_;
    std::unique_ptr<Impl> impl_;
};

} // namespace railodd::ingest
