#include "railodd/odd/tagger.hpp"

#include "tag_context.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace railodd::odd {

namespace {

std::string text_of(const AttributeValue& v) {
    if (const double* d = std::get_if<double>(&v)) {
        std::ostringstream os;
        os.precision(6);
        os << *d;
        return os.str();
    }
    if (const bool* b = std::get_if<bool>(&v)) {
        return *b ? "true" : "false";
    }
    return std::get<std::string>(v);
}

std::string class_of(const TaggedElement& t, const std::string& attribute) {
    const AttributeValue* v = t.find(attribute + "_class");
    return v ? text_of(*v) : "unclassified";
}

nlohmann::ordered_json summarize(const OddProfile& p) {
    nlohmann::ordered_json km_radius = nlohmann::ordered_json::object(), km_gradient = nlohmann::ordered_json::object(),
                           km_speed = nlohmann::ordered_json::object(), barriers = nlohmann::ordered_json::object(),
                           signals = nlohmann::ordered_json::object(), counts = nlohmann::ordered_json::object();
    double straight = 0.0, transition = 0.0;
    std::map<std::string, std::set<std::string>> structures; // path -> osm ids
    std::map<std::string, double> structure_m;
    for (const auto& t : p.elements) {
        const double km = (t.s_end - t.s_start) / 1000.0;
        const std::string leaf = t.element.substr(t.element.rfind('/') + 1);
        if (leaf == "Curve") {
            km_radius[class_of(t, "radius")] = km_radius.value(class_of(t, "radius"), 0.0) + km;
        } else if (leaf == "Straight") {
            straight += km;
        } else if (leaf == "Transition curve") {
            transition += km;
        } else if (leaf == "Gradient") {
            km_gradient[class_of(t, "gradient")] = km_gradient.value(class_of(t, "gradient"), 0.0) + km;
        } else if (leaf == "Speed limit") {
            km_speed[class_of(t, "maxspeed")] = km_speed.value(class_of(t, "maxspeed"), 0.0) + km;
        } else if (leaf == "Tunnel" || leaf == "Bridge") {
            structures[leaf].insert(t.osm_ids.begin(), t.osm_ids.end());
            structure_m[leaf] += t.s_end - t.s_start;
        }
        if (t.point) {
            counts[leaf] = counts.value(leaf, 0) + 1;
        }
        if (leaf == "Level crossing") {
            const AttributeValue* b = t.find("barrier");
            const std::string key = b ? text_of(*b) : "unknown";
            barriers[key] = barriers.value(key, 0) + 1;
        } else if (leaf == "Signal") {
            const AttributeValue* c = t.find("category");
            signals[text_of(*c)] = signals.value(text_of(*c), 0) + 1;
        }
    }
    nlohmann::ordered_json s;
    s["length_km"] = p.length_m / 1000.0;
    s["km_straight"] = straight;
    s["km_transition"] = transition;
    s["km_by_radius_class"] = km_radius;
    s["km_by_gradient_class"] = km_gradient;
    s["km_by_speed_class"] = km_speed;
    s["counts"] = counts;
    s["level_crossings_by_barrier"] = barriers;
    s["signals_by_category"] = signals;
    for (const char* leaf : {"Tunnel", "Bridge"}) {
        s[std::string{leaf} == "Tunnel" ? "tunnels" : "bridges"] = {{"count", structures[leaf].size()},
                                                                    {"length_m", structure_m[leaf]}};
    }
    s["unparsed_tag_values"] = p.unparsed.size();
    return s;
}

} // namespace

OddProfile tag_route(const TaggerInput& input, const Taxonomy& taxonomy) {
    OddProfile p;
    p.taxonomy_name = taxonomy.name;
    p.taxonomy_version = taxonomy.version;
    p.taxonomy_file = taxonomy.source;
    p.route = input.map_input.ingest.source + " (" + input.map_input.ingest.selection + ")";
    TagContext ctx(input, taxonomy, p);
    for (std::size_t e = 0; e < input.map_input.fitted_tracks.edges.size(); ++e) {
        if (ctx.written(e)) {
            p.length_m += ctx.alignment(e).length();
            ++p.tracks;
        }
    }
    // Scenery from the geometry, then from the ways' tags and the features;
    // operational conditions and connectivity come with the way and structure tags.
    tag_horizontal(ctx);
    tag_vertical_and_cant(ctx);
    tag_track_count(ctx);
    tag_way_attributes(ctx);
    tag_features(ctx);
    std::stable_sort(p.elements.begin(), p.elements.end(), [](const TaggedElement& a, const TaggedElement& b) {
        return std::tie(a.track, a.chainage_start, a.element, a.chainage_end) <
               std::tie(b.track, b.chainage_start, b.element, b.chainage_end);
    });
    p.summary = summarize(p);
    return p;
}

void add_odd_user_data(const OddProfile& profile, xodr::Map& map) {
    std::map<std::string, xodr::Road*> roads;
    for (auto& r : map.roads) {
        roads[r.id] = &r;
    }
    for (const auto& t : profile.elements) {
        const auto it = roads.find(t.road_id);
        if (it == roads.end()) {
            continue;
        }
        std::ostringstream v;
        v.precision(8);
        v << t.element_id << " s=" << t.s_start;
        if (!t.point) {
            v << '-' << t.s_end;
        }
        for (const auto& a : t.attributes) {
            v << ' ' << a.name << '=' << text_of(a.value);
        }
        it->second->user_data.push_back({"odd", v.str()});
    }
}

} // namespace railodd::odd
