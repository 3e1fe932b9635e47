// The <Environment> of the Init's EnvironmentAction: time of day, weather and
// the rail head condition. Values a declared parameter drives are written as
// "$Name" (parameter_names in concrete.hpp).
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

void write_weather(pugi::xml_node weather, const Context& cx) {
    const Environment& env = cx.scenario().environment;
    if (cx.rev_minor() >= 2) {
        attr(weather, "fractionalCloudCover",
             cx.value(parameter_names::cloud_cover, fractional_cloud_cover(env.fractional_cloud_cover)));
    } else {
        // The CloudCover parameter holds an okta name, which cloudState does not accept.
        attr(weather, "cloudState", cloud_state(env.fractional_cloud_cover));
    }
    attr(weather, "temperature", env.air_temperature_c + 273.15); // Kelvin

    pugi::xml_node sun = weather.append_child("Sun");
    attr(sun, "azimuth", cx.value(parameter_names::sun_azimuth, env.sun_azimuth_rad));
    attr(sun, "elevation", cx.value(parameter_names::sun_elevation, env.sun_elevation_rad));
    // 1.3 renamed the sun's illuminance (lux) from "intensity" to "illuminance".
    attr(sun, cx.rev_minor() >= 3 ? "illuminance" : "intensity", env.sun_illuminance_lux);

    attr(weather.append_child("Fog"), "visualRange",
         cx.value(parameter_names::fog_visual_range, env.fog_visual_range_m));

    pugi::xml_node precipitation = weather.append_child("Precipitation");
    attr(precipitation, "precipitationType", cx.value(parameter_names::precipitation_type, env.precipitation));
    attr(precipitation, "precipitationIntensity",
         cx.value(parameter_names::precipitation_intensity, env.precipitation_intensity_mm_h));

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
    attr(time, "dateTime", cx.value(parameter_names::time_of_day, env.date_time));

    write_weather(e.append_child("Weather"), cx);

    attr(e.append_child("RoadCondition"), "frictionScaleFactor",
         cx.value(parameter_names::friction_scale, env.friction_scale));
}

} // namespace railodd::scenario::xosc
