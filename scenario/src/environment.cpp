// Why these numbers: OpenSCENARIO describes the sun by its position and
// illuminance and the weather by physical quantities, while the taxonomy
// speaks of periods of the day and rail head conditions; each mapping below
// picks a representative physical value for the class.
#include "environment.hpp"

#include "attribute_values.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace railodd::scenario {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

struct Mapping {
    const char* element;
    const char* attribute;
};

constexpr std::array mappings{
    Mapping{"en.wx.rain", "intensity"},     Mapping{"en.wx.snow", "rate"},
    Mapping{"en.pt.fog", "visibility"},     Mapping{"en.pt.dust", "visibility"},
    Mapping{"en.pt.smoke", "visibility"},   Mapping{"en.il.time", "period"},
    Mapping{"en.il.time", "sun_elevation"}, Mapping{"en.il.cloud", "cover"},
    Mapping{"en.wx.wind", "speed"},         Mapping{"en.wx.temp", "air_temperature"},
    Mapping{"en.rs.head", "condition"},
};

double number(const std::string& value) {
    const auto v = parse_number(value);
    if (!v) {
        throw std::invalid_argument("'" + value + "' is not a number");
    }
    return *v;
}

// Sun elevation (deg), date and time, illuminance for a period of the day: a
// midsummer day at 50 deg N, the latitude of most of the shared extracts.
void period(Environment& env, const std::string& p) {
    struct Period {
        const char* name;
        const char* date_time;
        double elevation_deg;
        double azimuth_deg;
        double lux;
    };
    constexpr std::array periods{
        Period{"dawn", "2026-06-21T04:30:00", -3.0, 50.0, 400.0},
        Period{"day", "2026-06-21T13:00:00", 63.0, 180.0, 100000.0},
        Period{"dusk", "2026-06-21T21:45:00", -3.0, 310.0, 400.0},
        Period{"night", "2026-06-21T01:00:00", -16.0, 0.0, 0.1},
    };
    for (const auto& q : periods) {
        if (p == q.name) {
            env.date_time = q.date_time;
            env.sun_elevation_rad = q.elevation_deg * deg;
            env.sun_azimuth_rad = q.azimuth_deg * deg;
            env.sun_illuminance_lux = q.lux;
            return;
        }
    }
    throw std::invalid_argument("unknown period '" + p + "'");
}

// Friction relative to a dry rail head (adhesion ~0.3 dry; wet ~0.2, leaves
// and ice well under 0.1: the railway adhesion literature's usual figures).
double friction(const std::string& condition) {
    if (condition == "dry") return 1.0;
    if (condition == "damp") return 0.8;
    if (condition == "wet") return 0.65;
    if (condition == "snow") return 0.5;
    if (condition == "contaminated") return 0.5;
    if (condition == "leaf_film") return 0.25;
    if (condition == "ice") return 0.2;
    throw std::invalid_argument("unknown rail head condition '" + condition + "'");
}

} // namespace

bool environment_supports(const std::string& element_id, const std::string& attribute) {
    for (const auto& m : mappings) {
        if (element_id == m.element && attribute == m.attribute) {
            return true;
        }
    }
    return false;
}

std::string supported_perturbations() {
    std::string out;
    for (const auto& m : mappings) {
        out += (out.empty() ? "" : ", ") + std::string(m.element) + " " + m.attribute;
    }
    return out;
}

void apply_perturbation(Environment& env, const std::string& id, const std::string& attribute,
                        const std::string& value) {
    if (id == "en.wx.rain") {
        env.precipitation_intensity_mm_h = number(value);
        env.precipitation = env.precipitation_intensity_mm_h > 0.0 ? "rain" : "dry";
    } else if (id == "en.wx.snow") {
        // cm/h of snow to mm/h of water: fresh snow is about a tenth water.
        env.precipitation_intensity_mm_h = number(value);
        env.precipitation = env.precipitation_intensity_mm_h > 0.0 ? "snow" : "dry";
    } else if (id == "en.pt.fog" || id == "en.pt.dust" || id == "en.pt.smoke") {
        env.fog_visual_range_m = number(value);
    } else if (id == "en.il.time" && attribute == "period") {
        period(env, value);
    } else if (id == "en.il.time" && attribute == "sun_elevation") {
        env.sun_elevation_rad = number(value) * deg;
        env.sun_illuminance_lux = env.sun_elevation_rad > 0.0 ? 100000.0 * std::sin(env.sun_elevation_rad) : 1.0;
    } else if (id == "en.il.cloud") {
        env.fractional_cloud_cover = number(value) / 8.0;
    } else if (id == "en.wx.wind") {
        env.wind_speed_mps = number(value); // the taxonomy's unit is m/s
    } else if (id == "en.wx.temp") {
        env.air_temperature_c = number(value);
    } else if (id == "en.rs.head") {
        env.friction_scale = friction(value);
    } else {
        throw std::invalid_argument("no OpenSCENARIO mapping for " + id + " " + attribute);
    }
}

} // namespace railodd::scenario
