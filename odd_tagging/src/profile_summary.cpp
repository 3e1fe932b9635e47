// summarize() and summary_text() (profile_summary.hpp).
#include "railodd/odd/profile_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>

namespace railodd::odd {

namespace {

using ojson = nlohmann::ordered_json;

// The elements the summary speaks about, by stable id and by path (a profile
// written without ids still matches).
struct Kind {
    const char* id;
    const char* path;
};
constexpr Kind curve{"sc.geo.hz.curve", "Scenery/Track geometry/Horizontal/Curve"};
constexpr Kind gradient{"sc.geo.vt.gradient", "Scenery/Track geometry/Vertical/Gradient"};
constexpr Kind speed_limit{"op.speed.limit", "Operational Conditions/Speed/Speed limit"};
constexpr Kind level_crossing{"sc.xing.level", "Scenery/Crossings/Level crossing"};
constexpr Kind footpath_crossing{"sc.xing.foot", "Scenery/Crossings/Footpath crossing"};
constexpr Kind station{"sc.stn.station", "Scenery/Stations and stops/Station"};
constexpr Kind halt{"sc.stn.halt", "Scenery/Stations and stops/Halt"};
constexpr Kind platform{"sc.stn.platform", "Scenery/Stations and stops/Platform"};
constexpr Kind tunnel{"sc.str.tunnel", "Scenery/Structures/Tunnel"};
constexpr Kind bridge{"sc.str.bridge", "Scenery/Structures/Bridge"};
constexpr Kind switch_{"sc.lay.switch", "Scenery/Track layout/Switch"};
constexpr Kind signal{"sc.eqp.signal", "Scenery/Trackside equipment/Signal"};
constexpr Kind land_use{"sc.env.landuse", "Scenery/Surroundings/Land use"};

bool is(const TaggedElement& e, const Kind& k) { return e.element_id == k.id || e.element == k.path; }

double range_m(const TaggedElement& e) { return std::abs(e.s_end - e.s_start); }

double km(double metres) { return std::round(metres) / 1000.0; } // metre precision

const Attribute* taxonomy_attribute(const Taxonomy* taxonomy, const Kind& k, const std::string& name) {
    const Element* element = taxonomy ? taxonomy->find(k.path) : nullptr;
    if (!element && taxonomy) {
        element = taxonomy->find_id(k.id);
    }
    return element ? taxonomy->attribute(*element, name) : nullptr;
}

// Metres per class label, in first-seen order after the taxonomy's bins.
class ClassSums {
public:
    void add(const std::string& label, double metres) {
        for (auto& [l, m] : sums_) {
            if (l == label) {
                m += metres;
                return;
            }
        }
        sums_.emplace_back(label, metres);
    }
    ojson km_json() const {
        ojson j = ojson::object();
        for (const auto& [l, m] : sums_) {
            j[l] = km(m);
        }
        return j;
    }

private:
    std::vector<std::pair<std::string, double>> sums_;
};

// km per class of the number attribute `name` of the elements of kind `k`,
// classed by magnitude: a gradient's sign is its direction, not its class.
ojson km_by_class(const OddProfile& p, const Taxonomy* taxonomy, const Kind& k, const std::string& name) {
    const Attribute* attribute = taxonomy_attribute(taxonomy, k, name);
    ClassSums sums;
    if (attribute) {
        for (const auto& bin : attribute->bins) {
            sums.add(bin.label, 0.0); // every class listed, so that zero km shows as zero
        }
    }
    for (const auto& e : p.elements) {
        if (!is(e, k)) {
            continue;
        }
        const AttributeValue* v = e.find(name);
        const double* number = v ? std::get_if<double>(v) : nullptr;
        std::string label = "unknown";
        if (number) {
            label = attribute ? classify(*attribute, std::abs(*number)) : "";
            label = label.empty() ? "unclassified" : label;
        } else if (const AttributeValue* kind = e.find("kind"); kind && std::holds_alternative<std::string>(*kind)) {
            label = "kind: " + std::get<std::string>(*kind); // maxspeed=signals / none
        }
        sums.add(label, range_m(e));
    }
    return sums.km_json();
}

// km per value of the enum attribute `name` of the elements of kind `k`:
// every taxonomy value listed in its order, then values it does not know.
ojson km_by_value(const OddProfile& p, const Taxonomy* taxonomy, const Kind& k, const std::string& name) {
    const Attribute* attribute = taxonomy_attribute(taxonomy, k, name);
    ClassSums sums;
    if (attribute) {
        for (const auto& v : attribute->values) {
            sums.add(v, 0.0);
        }
    }
    for (const auto& e : p.elements) {
        if (is(e, k)) {
            const AttributeValue* v = e.find(name);
            sums.add(v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : "unknown", range_m(e));
        }
    }
    return sums.km_json();
}

ojson count_by(const OddProfile& p, const Kind& k, const std::string& name) {
    std::map<std::string, std::size_t> counts; // sorted: deterministic
    for (const auto& e : p.elements) {
        if (is(e, k)) {
            const AttributeValue* v = e.find(name);
            ++counts[v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : "unknown"];
        }
    }
    ojson j = ojson::object();
    for (const auto& [label, n] : counts) {
        j[label] = n;
    }
    return j;
}

// A stretch written over several roads or tracks (a tunnel through a switch)
// is several elements with the same OSM ids: one feature.
std::size_t count(const OddProfile& p, const Kind& k) {
    std::set<std::vector<std::string>> ranges;
    std::size_t points = 0;
    for (const auto& e : p.elements) {
        if (is(e, k)) {
            e.point || e.osm_ids.empty() ? ++points : (ranges.insert(e.osm_ids), 0);
        }
    }
    return points + ranges.size();
}

// A structure tagged as a point (no s-range on the map) still has its length
// attribute from the OSM way.
ojson structures(const OddProfile& p, const Kind& k) {
    const std::size_t n = count(p, k);
    double metres = 0.0;
    for (const auto& e : p.elements) {
        if (is(e, k)) {
            const AttributeValue* length = e.find("length");
            metres += e.point && length && std::holds_alternative<double>(*length) ? std::get<double>(*length)
                                                                                   : range_m(e);
        }
    }
    return {{"count", n}, {"length_km", km(metres)}};
}

// --- text ------------------------------------------------------------------

struct Row {
    std::string label; // indented by the caller
    std::string value; // "" for a section heading
};

std::string number_text(const ojson& v, const char* format) {
    if (!v.is_number()) {
        return v.dump();
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v.get<double>());
    return buf;
}

void add_table(std::vector<Row>& rows, const std::string& heading, const ojson& table, const char* format) {
    if (!table.is_object()) {
        return;
    }
    rows.push_back({heading, ""});
    if (table.empty()) {
        rows.push_back({"  (none)", ""});
    }
    for (const auto& [label, v] : table.items()) {
        rows.push_back({"  " + label, number_text(v, format)});
    }
}

void add_structure(std::vector<Row>& rows, const std::string& label, const ojson& s) {
    if (s.is_object() && s.contains("count") && s.contains("length_km")) {
        rows.push_back({label, number_text(s["count"], "%.0f") + "  " + number_text(s["length_km"], "%.2f") + " km"});
    }
}

std::string render(const std::vector<Row>& rows) {
    std::size_t label_width = 0;
    std::size_t value_width = 0;
    for (const auto& r : rows) {
        label_width = std::max(label_width, r.label.size());
        value_width = std::max(value_width, r.value.size());
    }
    std::string out;
    for (const auto& r : rows) {
        std::string line = r.label;
        if (!r.value.empty()) {
            line += std::string(label_width - r.label.size() + 2 + value_width - r.value.size(), ' ') + r.value;
        }
        out += line + "\n";
    }
    return out;
}

const ojson& field(const ojson& s, const char* key) {
    static const ojson null;
    return s.contains(key) ? s[key] : null;
}

} // namespace

nlohmann::ordered_json summarize(const OddProfile& p, const Taxonomy* taxonomy) {
    ojson j;
    j["length_km"] = km(p.length_m);
    j["tracks"] = p.tracks;
    j["elements"] = p.elements.size();
    j["curve_km_by_radius"] = km_by_class(p, taxonomy, curve, "radius");
    j["gradient_km_by_class"] = km_by_class(p, taxonomy, gradient, "gradient");
    j["speed_km_by_class"] = km_by_class(p, taxonomy, speed_limit, "maxspeed");
    j["landuse_km_by_kind"] = km_by_value(p, taxonomy, land_use, "kind");
    j["level_crossings_by_barrier"] = count_by(p, level_crossing, "barrier");
    j["footpath_crossings"] = count(p, footpath_crossing);
    j["stations"] = count(p, station);
    j["halts"] = count(p, halt);
    j["platforms"] = count(p, platform);
    j["tunnels"] = structures(p, tunnel);
    j["bridges"] = structures(p, bridge);
    j["switches"] = count(p, switch_);
    j["signals_by_category"] = count_by(p, signal, "category");
    j["unparsed_values"] = p.unparsed.size();
    return j;
}

std::string summary_text(const OddProfile& p, const Taxonomy* taxonomy) {
    ojson s = summarize(p, taxonomy);
    if (p.summary.is_object()) {
        for (const auto& [key, value] : p.summary.items()) {
            s[key] = value; // the tagger's numbers win: they may cover more than the elements
        }
    }
    std::string out = "route: " + (p.route.empty() ? std::string{"(no description)"} : p.route) + "\n";
    out += "taxonomy: " + p.taxonomy_name + " " + p.taxonomy_version +
           (taxonomy ? " (classes from " + taxonomy->source + ")" : std::string{" (no taxonomy file: stored summary)"}) +
           "\n";
    std::vector<Row> rows;
    rows.push_back({"length", number_text(field(s, "length_km"), "%.2f") + " km"});
    rows.push_back({"tracks", number_text(field(s, "tracks"), "%.0f")});
    rows.push_back({"tagged elements", number_text(field(s, "elements"), "%.0f")});
    add_table(rows, "curves by radius class (km)", field(s, "curve_km_by_radius"), "%.2f");
    add_table(rows, "gradients by class (km)", field(s, "gradient_km_by_class"), "%.2f");
    add_table(rows, "speed limits by class (km)", field(s, "speed_km_by_class"), "%.2f");
    add_table(rows, "land use by kind (km)", field(s, "landuse_km_by_kind"), "%.2f");
    add_table(rows, "level crossings by barrier", field(s, "level_crossings_by_barrier"), "%.0f");
    rows.push_back({"stations", number_text(field(s, "stations"), "%.0f")});
    rows.push_back({"halts", number_text(field(s, "halts"), "%.0f")});
    rows.push_back({"platforms", number_text(field(s, "platforms"), "%.0f")});
    add_structure(rows, "tunnels (count, length)", field(s, "tunnels"));
    add_structure(rows, "bridges (count, length)", field(s, "bridges"));
    rows.push_back({"switches", number_text(field(s, "switches"), "%.0f")});
    add_table(rows, "signals by category", field(s, "signals_by_category"), "%.0f");
    rows.push_back({"unparsed tag values", number_text(field(s, "unparsed_values"), "%.0f")});
    return out + render(rows);
}

} // namespace railodd::odd
