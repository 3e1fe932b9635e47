// The <Environment> of the Init's EnvironmentAction: time of day, weather and
// the rail head condition. Values a declared parameter drives are written as
// "$Name" (parameter_names in concrete.hpp) where the target resolves it.
#include "xosc_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace railodd::scenario::xosc {

namespace {

// Cloud cover 0..1 as whole oktas (eighths of the sky).
int oktas(double fraction) { return static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 8.0)); }

// 1.2 and 1.3: fractionalCloudCover in oktas.
const char* fractional_cloud_cover(double fraction) {
    static constexpr std::array<const char*, 9> names = {
        "zeroOktas", "oneOktas", "twoOktas", "threeOktas", "fourOktas",
        "fiveOktas", "sixOktas", "sevenOktas", "eightOktas"};
    return names[static_cast<std::size_t>(oktas(fraction))];
}

// 1.1 has only the coarse cloudState.
const char* cloud_state(double fraction) {
    const int o = oktas(fraction);
    return o <= 2 ? "free" : o <= 5 ? "cloudy" : "overcast";
}

// OpenSCENARIO 1.0's precipitation intensity is a fraction [0..1], 1.1's is
// mm/h. log10(1 + mm/h) / log10(51) spreads the rain classes of the taxonomy
// over the fraction (light < 0.32, moderate < 0.55, violent from 50 mm/h at
// 1): ScenarioRunner makes it CARLA's precipitation in percent.
double precipitation_fraction(double mm_h) {
    return std::clamp(std::log10(1.0 + std::max(mm_h, 0.0)) / std::log10(51.0), 0.0, 1.0);
}

void write_precipitation(pugi::xml_node precipitation, const Context& cx) {
    const Environment& env = cx.scenario().environment;
    namespace pn = parameter_names;
    if (env.precipitation == "snow" && !cx.profile().snow) {
        const std::string reason = "CARLA has no snowfall (ScenarioRunner: \"CARLA does not support snow "
                                   "precipitation\"): the Precipitation is written dry";
        cx.drop(pn::precipitation_type, "string", env.precipitation, reason);
        cx.drop(pn::precipitation_intensity, "double", num(env.precipitation_intensity_mm_h), reason);
        attr(precipitation, "precipitationType", "dry");
        attr(precipitation, cx.rev_minor() < 1 ? "intensity" : "precipitationIntensity", 0.0);
        return;
    }
    attr(precipitation, "precipitationType", cx.value("Precipitation", pn::precipitation_type, env.precipitation));
    if (cx.rev_minor() < 1) {
        attr(precipitation, "intensity",
             cx.value("Precipitation", pn::precipitation_intensity,
                      precipitation_fraction(env.precipitation_intensity_mm_h)));
    } else {
        attr(precipitation, "precipitationIntensity",
             cx.value("Precipitation", pn::precipitation_intensity, env.precipitation_intensity_mm_h));
    }
}

// 1.0 has neither wind nor temperature: kept as parameters where the
// scenario sets them (a perturbation or degraded mode; the defaults say nothing).
void drop_for_1_0(const Context& cx) {
    const Environment& env = cx.scenario().environment;
    const Environment defaults;
    if (env.wind_speed_mps != defaults.wind_speed_mps) {
        cx.drop("WindSpeed", "double", num(env.wind_speed_mps),
                "OpenSCENARIO 1.0 has no Wind (ScenarioRunner sets CARLA's wind to 30 % whatever the scenario "
                "says); m/s");
    }
    if (env.air_temperature_c != defaults.air_temperature_c) {
        cx.drop("Temperature", "double", num(env.air_temperature_c + 273.15),
                "OpenSCENARIO 1.0 has no air temperature, CARLA's weather none; K");
    }
}

void write_weather(pugi::xml_node weather, const Context& cx) {
    const Environment& env = cx.scenario().environment;
    namespace pn = parameter_names;
    if (cx.rev_minor() >= 2) {
        attr(weather, "fractionalCloudCover",
             cx.value("Weather", pn::cloud_cover, fractional_cloud_cover(env.fractional_cloud_cover)));
    } else {
        // The CloudCover parameter holds an okta name, which cloudState does not accept.
        attr(weather, "cloudState", cloud_state(env.fractional_cloud_cover));
    }
    if (cx.rev_minor() >= 1) {
        attr(weather, "temperature", env.air_temperature_c + 273.15); // Kelvin
    }

    pugi::xml_node sun = weather.append_child("Sun");
    attr(sun, "azimuth", cx.value("Sun", pn::sun_azimuth, env.sun_azimuth_rad));
    attr(sun, "elevation", cx.value("Sun", pn::sun_elevation, env.sun_elevation_rad));
    if (cx.profile().sun_intensity_is_cloudiness) {
        // CARLA lights the scene by the sun's elevation; its cloudiness is
        // what ScenarioRunner reads from the intensity.
        attr(sun, "intensity", 1.0 - std::clamp(env.fractional_cloud_cover, 0.0, 1.0));
    } else {
        // 1.3 renamed the sun's illuminance (lux) from "intensity" to "illuminance".
        attr(sun, cx.rev_minor() >= 3 ? "illuminance" : "intensity", env.sun_illuminance_lux);
    }

    attr(weather.append_child("Fog"), "visualRange", cx.value("Fog", pn::fog_visual_range, env.fog_visual_range_m));
    write_precipitation(weather.append_child("Precipitation"), cx);

    if (cx.rev_minor() < 1) {
        drop_for_1_0(cx);
        return;
    }
    pugi::xml_node wind = weather.append_child("Wind");
    attr(wind, "direction", env.wind_direction_rad);
    attr(wind, "speed", env.wind_speed_mps);
}

} // namespace

void write_environment(pugi::xml_node environment_action, const Context& cx) {
    const Environment& env = cx.scenario().environment;
    pugi::xml_node e = environment_action.append_child("Environment");
    attr(e, "name", env.name);

    pugi::xml_node time = e.append_child("TimeOfDay");
    attr(time, "animation", "false");
    attr(time, "dateTime", cx.value("TimeOfDay", parameter_names::time_of_day, env.date_time));

    write_weather(e.append_child("Weather"), cx);

    attr(e.append_child("RoadCondition"), "frictionScaleFactor",
         cx.value("RoadCondition", parameter_names::friction_scale, env.friction_scale));
}

} // namespace railodd::scenario::xosc
