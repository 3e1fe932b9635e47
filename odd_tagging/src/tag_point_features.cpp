// Features placed on the tracks by the geometry stage: stations, halts,
// platforms, signals, milestones and buffer stops.
#include "tag_context.hpp"

#include "railodd/odd/tag_values.hpp"

#include <array>

namespace railodd::odd {

namespace {

// Most significant first: a combined signal also carries main/distant keys.
constexpr std::array<const char*, 12> categories{
    "combined", "main", "distant", "shunting", "speed_limit", "speed_limit_distant",
    "crossing", "crossing_distant", "minor", "route", "stop", "train_protection"};

std::vector<TaggedAttribute> signal_attributes(const ingest::Feature& f) {
    for (const char* c : categories) {
        const std::string key = std::string{"railway:signal:"} + c;
        const std::string system = ingest::tag_or(f.tags, key);
        if (system.empty() || system == "no") {
            continue;
        }
        std::vector<TaggedAttribute> a{{"category", std::string{c}}, {"system", system}};
        const auto form = parse_signal_form(ingest::tag_or(f.tags, key + ":form"));
        if (form.ok()) {
            a.push_back({"form", std::string{to_string(*form.value)}});
        }
        return a;
    }
    return {{"category", std::string{"other"}}};
}

} // namespace

void tag_point_features(TagContext& ctx) {
    const auto& features = ctx.geo().ingest.features;
    for (const auto& at : ctx.geo().geometry.attachment.attached) {
        if (!ctx.in_batch(at.edge)) {
            continue;
        }
        const ingest::Feature& f = features[at.feature];
        const std::vector<std::string> ids{f.osm_type + ":" + std::to_string(f.id)};
        if (f.kind == "station") {
            ctx.tag("Scenery/Stations and stops/Station", at.edge, at.s, at.s, {}, ids, "osm");
        } else if (f.kind == "halt") {
            ctx.tag("Scenery/Stations and stops/Halt", at.edge, at.s, at.s, {}, ids, "osm");
        } else if (f.kind == "platform") {
            const double s0 = std::min(at.s_start, at.s_end), s1 = std::max(at.s_start, at.s_end);
            ctx.tag("Scenery/Stations and stops/Platform", at.edge, s0, s1,
                    {{"length", s1 - s0}, {"side", std::string{at.offset > 0 ? "left" : "right"}}}, ids, "osm+derived");
        } else if (f.kind == "signal") {
            ctx.tag("Scenery/Trackside equipment/Signal", at.edge, at.s, at.s, signal_attributes(f), ids, "osm");
        } else if (f.kind == "milestone") {
            const std::string text = ingest::tag_or(f.tags, "railway:position", ingest::tag_or(f.tags, "railway:position:exact"));
            const auto km = parse_railway_position(text);
            if (km.ok()) {
                ctx.tag("Scenery/Trackside equipment/Milestone", at.edge, at.s, at.s, {{"position", *km.value}}, ids, "osm");
            } else {
                ctx.unparsed(ids, "railway:position", text, km.problem);
            }
        } else if (f.kind == "buffer_stop") {
            ctx.tag("Scenery/Track layout/Buffer stop", at.edge, at.s, at.s, {{"type", std::string{"unknown"}}}, ids, "osm");
        }
    }
}

} // namespace railodd::odd
