// odd_profile.geojson and odd_profile.csv (profile_outputs.hpp).
#include "railodd/odd/profile_outputs.hpp"

#include "text.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace railodd::odd {

namespace {

using ojson = nlohmann::ordered_json;

// 7 decimals of a degree are about 1 cm: finer digits are noise of the
// projection and only make the file larger and less diffable.
double degrees7(double v) { return std::round(v * 1e7) / 1e7; }

ojson position(const std::pair<double, double>& lonlat) {
    return ojson::array({degrees7(lonlat.first), degrees7(lonlat.second)});
}

ojson geometry(const TaggedElement& e) {
    if (e.lonlat.empty()) {
        return nullptr; // RFC 7946 3.2: an unlocated feature has a null geometry
    }
    if (e.point || e.lonlat.size() == 1) {
        return {{"type", "Point"}, {"coordinates", position(e.lonlat.front())}};
    }
    ojson coords = ojson::array();
    for (const auto& p : e.lonlat) {
        coords.push_back(position(p));
    }
    return {{"type", "LineString"}, {"coordinates", std::move(coords)}};
}

ojson feature(const TaggedElement& e) {
    ojson attrs = ojson::object();
    for (const auto& a : e.attributes) {
        attrs[a.name] = std::visit([](const auto& v) { return ojson(v); }, a.value);
    }
    ojson props;
    props["odd_element"] = e.element;
    props["element_id"] = e.element_id;
    props["attributes"] = std::move(attrs);
    props["road_id"] = e.road_id;
    props["track"] = e.track;
    props["s_start"] = e.s_start;
    props["s_end"] = e.s_end;
    props["chainage_start"] = e.chainage_start;
    props["chainage_end"] = e.chainage_end;
    props["osm_ids"] = e.osm_ids;
    props["source"] = e.source;
    return {{"type", "Feature"}, {"geometry", geometry(e)}, {"properties", std::move(props)}};
}

std::string value_text(const AttributeValue& value) {
    if (const auto* d = std::get_if<double>(&value)) {
        return text::format(*d);
    }
    if (const auto* b = std::get_if<bool>(&value)) {
        return *b ? "true" : "false";
    }
    return std::get<std::string>(value);
}

std::string metres(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

// RFC 4180 2.6/2.7: quote fields holding a separator, quote or line break and
// double the quotes inside.
void append_field(std::string& out, const std::string& field) {
    if (field.find_first_of(",\"\r\n") == std::string::npos) {
        out += field;
        return;
    }
    out += '"';
    for (char c : field) {
        if (c == '"') {
            out += '"';
        }
        out += c;
    }
    out += '"';
}

void append_row(std::string& out, const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i > 0) {
            out += ',';
        }
        append_field(out, fields[i]);
    }
    out += "\r\n";
}

std::string joined(const std::vector<std::string>& parts, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        s += (i > 0 ? sep : "") + parts[i];
    }
    return s;
}

} // namespace

// One feature per line: a whole route's profile stays a few MB, and diffs of
// two runs read element by element.
void write_geojson(const OddProfile& profile, std::ostream& out) {
    out << "{\"type\": \"FeatureCollection\", \"name\": \"odd_profile\", \"features\": [\n";
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        out << feature(profile.elements[i]).dump() << (i + 1 < profile.elements.size() ? ",\n" : "\n");
    }
    out << "]}\n";
}

std::string to_geojson(const OddProfile& profile) {
    std::ostringstream out;
    write_geojson(profile, out);
    return std::move(out).str();
}

void write_csv(const OddProfile& profile, std::ostream& out) {
    std::string row;
    append_row(row, {"odd_element", "element_id", "road_id", "s_start", "s_end", "chainage_start", "chainage_end",
                     "track", "point", "attributes", "osm_ids", "source"});
    out << row;
    for (const auto& e : profile.elements) {
        std::vector<std::string> attrs;
        for (const auto& a : e.attributes) {
            attrs.push_back(a.name + "=" + value_text(a.value));
        }
        row.clear();
        append_row(row, {e.element, e.element_id, e.road_id, metres(e.s_start), metres(e.s_end),
                         metres(e.chainage_start), metres(e.chainage_end), std::to_string(e.track),
                         e.point ? "true" : "false", joined(attrs, ";"), joined(e.osm_ids, " "), e.source});
        out << row;
    }
}

std::string to_csv(const OddProfile& profile) {
    std::ostringstream out;
    write_csv(profile, out);
    return std::move(out).str();
}

} // namespace railodd::odd
