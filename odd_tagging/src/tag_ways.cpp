// Tags that OSM carries on the track ways themselves: gauge, electrification,
// speed limit, line usage, track service, preferred direction, train
// protection and train radio, over each
// way's stretch of the track. Values the parsers cannot read are recorded in
// the profile's `unparsed` list with the reason.
#include "tag_context.hpp"

#include "railodd/odd/tag_values.hpp"

namespace railodd::odd {

namespace {

void tag_gauge(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    const std::string text = ingest::tag_or(r.way->tags, "gauge");
    if (text.empty()) {
        return;
    }
    const auto g = parse_gauge(text);
    if (!g.ok()) {
        ctx.unparsed(ids, "gauge", text, g.problem);
        return;
    }
    ctx.tag("Scenery/Track geometry/Gauge", e, r.s0, r.s1, {{"gauge", g.value->front()}, {"dual_gauge", g.value->size() > 1}},
            ids, "osm");
}

void tag_electrification(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    const std::string text = ingest::tag_or(r.way->tags, "electrified");
    if (text.empty()) {
        return;
    }
    const auto el = parse_electrified(text);
    if (!el.ok()) {
        ctx.unparsed(ids, "electrified", text, el.problem);
        return;
    }
    std::vector<TaggedAttribute> attrs{{"system", std::string{to_string(el.value->front())}}};
    for (const char* key : {"voltage", "frequency"}) {
        const std::string v = ingest::tag_or(r.way->tags, key);
        if (v.empty()) {
            continue;
        }
        const auto parsed = std::string{key} == "voltage" ? parse_voltage(v) : parse_frequency(v);
        if (parsed.ok()) {
            attrs.push_back({key, parsed.value->front()});
        } else {
            ctx.unparsed(ids, key, v, parsed.problem);
        }
    }
    ctx.tag("Scenery/Trackside equipment/Electrification", e, r.s0, r.s1, attrs, ids, "osm");
}

void tag_speed(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    const std::string text = ingest::tag_or(r.way->tags, "maxspeed");
    if (text.empty()) {
        return;
    }
    const MaxSpeed m = parse_maxspeed(text);
    if (!m.ok()) {
        ctx.unparsed(ids, "maxspeed", text, m.problem);
        if (m.kind == SpeedLimitKind::unknown) {
            return;
        }
        ctx.tag("Operational Conditions/Speed/Speed limit", e, r.s0, r.s1, {{"kind", std::string{to_string(m.kind)}}}, ids,
                "osm");
        return;
    }
    ctx.tag("Operational Conditions/Speed/Speed limit", e, r.s0, r.s1,
            {{"maxspeed", *m.kmh}, {"kind", std::string{to_string(m.kind)}}}, ids, "osm");
}

void tag_usage(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    const std::string usage = ingest::tag_or(r.way->tags, "usage");
    if (!usage.empty()) {
        const auto u = parse_usage(usage);
        if (u.ok()) {
            ctx.tag("Operational Conditions/Usage/Line usage", e, r.s0, r.s1, {{"usage", std::string{to_string(*u.value)}}},
                    ids, "osm");
        } else {
            ctx.unparsed(ids, "usage", usage, u.problem);
        }
    }
    // No service tag: a running line (OSM's convention).
    const std::string service = ingest::tag_or(r.way->tags, "service");
    std::string value = "running";
    if (!service.empty()) {
        const auto s = parse_service(service);
        if (!s.ok()) {
            ctx.unparsed(ids, "service", service, s.problem);
            return;
        }
        value = to_string(*s.value);
    }
    ctx.tag("Operational Conditions/Usage/Track service", e, r.s0, r.s1, {{"service", value}}, ids,
            service.empty() ? "derived" : "osm");
}

void tag_direction(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    const std::string text = ingest::tag_or(r.way->tags, "railway:preferred_direction");
    if (text.empty()) {
        return;
    }
    const auto d = parse_preferred_direction(text);
    if (!d.ok()) {
        ctx.unparsed(ids, "railway:preferred_direction", text, d.problem);
        return;
    }
    ctx.tag("Operational Conditions/Direction/Preferred direction", e, r.s0, r.s1,
            {{"direction", std::string{to_string(*d.value)}}}, ids, "osm");
}

// Train protection systems mapped on the way (railway:etcs=<level>,
// railway:pzb=yes, ...): one element per system present.
void tag_train_protection(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    static const char* const systems[] = {"etcs", "lzb", "pzb", "atb", "tvm", "kvb"};
    for (const char* sys : systems) {
        const std::string v = ingest::tag_or(r.way->tags, std::string{"railway:"} + sys);
        if (v.empty() || v == "no") {
            continue;
        }
        std::vector<TaggedAttribute> attrs{{"system", std::string{sys}}};
        if (std::string{sys} == "etcs") {
            if (v == "0" || v == "1" || v == "2" || v == "3") {
                attrs.push_back({"etcs_level", v});
            } else if (v != "yes") {
                ctx.unparsed(ids, "railway:etcs", v, "not an ETCS level (0-3) or yes/no");
                continue;
            }
        } else if (v != "yes") {
            ctx.unparsed(ids, std::string{"railway:"} + sys, v, "expected yes or no");
            continue;
        }
        ctx.tag("Operational Conditions/Train control/Train protection", e, r.s0, r.s1, attrs, ids, "osm");
    }
}

// Train radio (railway:radio): one element per system; "no" is a stretch
// without radio (system none). Coverage is not mapped in OSM, so not claimed.
void tag_train_radio(TagContext& ctx, std::size_t e, const WayRange& r, const std::vector<std::string>& ids) {
    const std::string text = ingest::tag_or(r.way->tags, "railway:radio");
    if (text.empty()) {
        return;
    }
    const auto radio = parse_train_radio(text);
    if (!radio.ok()) {
        ctx.unparsed(ids, "railway:radio", text, radio.problem);
        return;
    }
    for (const TrainRadio system : *radio.value) {
        ctx.tag("Connectivity/Communication/Train radio", e, r.s0, r.s1, {{"system", std::string{to_string(system)}}},
                ids, "osm");
    }
}

} // namespace

void tag_way_attributes(TagContext& ctx) {
    for (std::size_t e = ctx.first(); e < ctx.last(); ++e) {
        for (const WayRange& r : ctx.ways(e)) {
            if (r.s1 - r.s0 <= 1e-6) {
                continue;
            }
            const std::vector<std::string> ids{"way:" + std::to_string(r.way->id)};
            tag_gauge(ctx, e, r, ids);
            tag_electrification(ctx, e, r, ids);
            tag_speed(ctx, e, r, ids);
            tag_usage(ctx, e, r, ids);
            tag_direction(ctx, e, r, ids);
            tag_train_protection(ctx, e, r, ids);
            tag_train_radio(ctx, e, r, ids);
        }
    }
}

} // namespace railodd::odd
