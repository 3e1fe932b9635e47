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
class KmByClass {
public:
    KmByClass(const Taxonomy* taxonomy, const Kind& k, std::string name)
        : kind_(k), name_(std::move(name)), attribute_(taxonomy_attribute(taxonomy, k, name_)) {
        if (attribute_) {
            for (const auto& bin : attribute_->bins) {
                sums_.add(bin.label, 0.0); // every class listed, so that zero km shows as zero
            }
        }
    }
    void add(const TaggedElement& e) {
        if (!is(e, kind_)) {
            return;
        }
        const AttributeValue* v = e.find(name_);
        const double* number = v ? std::get_if<double>(v) : nullptr;
        std::string label = "unknown";
        if (number) {
            label = attribute_ ? classify(*attribute_, std::abs(*number)) : "";
            label = label.empty() ? "unclassified" : label;
        } else if (const AttributeValue* kind = e.find("kind"); kind && std::holds_alternative<std::string>(*kind)) {
            label = "kind: " + std::get<std::string>(*kind); // maxspeed=signals / none
        }
        sums_.add(label, range_m(e));
    }
    ojson json() const { return sums_.km_json(); }

private:
    Kind kind_;
    std::string name_;
    const Attribute* attribute_;
    ClassSums sums_;
};

// km per value of the enum attribute `name` of the elements of kind `k`:
// every taxonomy value listed in its order, then values it does not know.
class KmByValue {
public:
    KmByValue(const Taxonomy* taxonomy, const Kind& k, std::string name) : kind_(k), name_(std::move(name)) {
        if (const Attribute* attribute = taxonomy_attribute(taxonomy, k, name_)) {
            for (const auto& v : attribute->values) {
                sums_.add(v, 0.0);
            }
        }
    }
    void add(const TaggedElement& e) {
        if (is(e, kind_)) {
            const AttributeValue* v = e.find(name_);
            sums_.add(v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : "unknown", range_m(e));
        }
    }
    ojson json() const { return sums_.km_json(); }

private:
    Kind kind_;
    std::string name_;
    ClassSums sums_;
};

class CountBy {
public:
    CountBy(const Kind& k, std::string name) : kind_(k), name_(std::move(name)) {}
    void add(const TaggedElement& e) {
        if (is(e, kind_)) {
            const AttributeValue* v = e.find(name_);
            ++counts_[v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : "unknown"];
        }
    }
    ojson json() const {
        ojson j = ojson::object();
        for (const auto& [label, n] : counts_) {
            j[label] = n;
        }
        return j;
    }

private:
    Kind kind_;
    std::string name_;
    std::map<std::string, std::size_t> counts_; // sorted: deterministic
};

// A stretch written over several roads or tracks (a tunnel through a switch)
// is several elements with the same OSM ids: one feature.
class Count {
public:
    explicit Count(const Kind& k) : kind_(k) {}
    void add(const TaggedElement& e) {
        if (is(e, kind_)) {
            e.point || e.osm_ids.empty() ? ++points_ : (ranges_.insert(e.osm_ids), 0);
        }
    }
    std::size_t value() const { return points_ + ranges_.size(); }

private:
    Kind kind_;
    std::set<std::vector<std::string>> ranges_;
    std::size_t points_ = 0;
};

// A structure tagged as a point (no s-range on the map) still has its length
// attribute from the OSM way.
class Structures {
public:
    explicit Structures(const Kind& k) : kind_(k), count_(k) {}
    void add(const TaggedElement& e) {
        count_.add(e);
        if (is(e, kind_)) {
            const AttributeValue* length = e.find("length");
            metres_ += e.point && length && std::holds_alternative<double>(*length) ? std::get<double>(*length)
                                                                                    : range_m(e);
        }
    }
    ojson json() const { return {{"count", count_.value()}, {"length_km", km(metres_)}}; }

private:
    Kind kind_;
    Count count_;
    double metres_ = 0.0;
};

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

struct SummaryBuilder::State {
    explicit State(const Taxonomy* t)
        : curves(t, curve, "radius"), gradients(t, gradient, "gradient"), speeds(t, speed_limit, "maxspeed"),
          land(t, land_use, "kind") {}
    std::size_t elements = 0;
    KmByClass curves, gradients, speeds;
    KmByValue land;
    CountBy barriers{level_crossing, "barrier"}, signals{signal, "category"};
    Count footpaths{footpath_crossing}, stations{station}, halts{halt}, platforms{platform}, switches{switch_};
    Structures tunnels{tunnel}, bridges{bridge};
};

SummaryBuilder::SummaryBuilder(const Taxonomy* taxonomy) : state_(std::make_unique<State>(taxonomy)) {}

SummaryBuilder::~SummaryBuilder() = default;

void SummaryBuilder::add(const TaggedElement& e) {
    State& s = *state_;
    ++s.elements;
    s.curves.add(e);
    s.gradients.add(e);
    s.speeds.add(e);
    s.land.add(e);
    s.barriers.add(e);
    s.signals.add(e);
    for (Count* c : {&s.footpaths, &s.stations, &s.halts, &s.platforms, &s.switches}) {
        c->add(e);
    }
    s.tunnels.add(e);
    s.bridges.add(e);
}

nlohmann::ordered_json SummaryBuilder::json(const OddProfile& head) const {
    const State& s = *state_;
    ojson j;
    j["length_km"] = km(head.length_m);
    j["tracks"] = head.tracks;
    j["elements"] = s.elements;
    j["curve_km_by_radius"] = s.curves.json();
    j["gradient_km_by_class"] = s.gradients.json();
    j["speed_km_by_class"] = s.speeds.json();
    j["landuse_km_by_kind"] = s.land.json();
    j["level_crossings_by_barrier"] = s.barriers.json();
    j["footpath_crossings"] = s.footpaths.value();
    j["stations"] = s.stations.value();
    j["halts"] = s.halts.value();
    j["platforms"] = s.platforms.value();
    j["tunnels"] = s.tunnels.json();
    j["bridges"] = s.bridges.json();
    j["switches"] = s.switches.value();
    j["signals_by_category"] = s.signals.json();
    j["unparsed_values"] = head.unparsed.size();
    return j;
}

nlohmann::ordered_json summarize(const OddProfile& p, const Taxonomy* taxonomy) {
    SummaryBuilder b(taxonomy);
    for (const auto& e : p.elements) {
        b.add(e);
    }
    return b.json(p);
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
