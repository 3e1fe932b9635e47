// The lines of odd_profile.geojson and odd_profile.csv (profile_text.hpp;
// the formats are described in profile_files.hpp).
#include "json_text.hpp"
#include "profile_elements.hpp"
#include "profile_text.hpp"
#include "text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace railodd::odd {

namespace {

// 7 decimals of a degree are about 1 cm: finer digits are noise of the
// projection and only make the file larger and less diffable.
double degrees7(double v) { return std::round(v * 1e7) / 1e7; }

void append_position(std::string& out, const std::pair<double, double>& lonlat) {
    out += '[';
    json_text::number(out, degrees7(lonlat.first));
    out += ',';
    json_text::number(out, degrees7(lonlat.second));
    out += ']';
}

void append_geometry(std::string& out, const TaggedElement& e) {
    if (e.lonlat.empty()) {
        out += "null"; // RFC 7946 3.2: an unlocated feature has a null geometry
        return;
    }
    if (e.point || e.lonlat.size() == 1) {
        out += R"({"type":"Point","coordinates":)";
        append_position(out, e.lonlat.front());
        out += '}';
        return;
    }
    out += R"({"type":"LineString","coordinates":[)";
    for (std::size_t i = 0; i < e.lonlat.size(); ++i) {
        if (i > 0) {
            out += ',';
        }
        append_position(out, e.lonlat[i]);
    }
    out += "]}";
}

} // namespace

void profile_text::append_feature(std::string& out, const TaggedElement& e) {
    out += R"({"type":"Feature","geometry":)";
    append_geometry(out, e);
    out += R"(,"properties":{"odd_element":)";
    json_text::string(out, e.element);
    out += R"(,"element_id":)";
    json_text::string(out, e.element_id);
    out += R"(,"attributes":)";
    json_text::attributes(out, e.attributes);
    out += R"(,"road_id":)";
    json_text::string(out, e.road_id);
    out += R"(,"track":)";
    json_text::number(out, static_cast<unsigned long long>(e.track));
    const std::pair<const char*, double> numbers[] = {{R"(,"s_start":)", e.s_start},
                                                      {R"(,"s_end":)", e.s_end},
                                                      {R"(,"chainage_start":)", e.chainage_start},
                                                      {R"(,"chainage_end":)", e.chainage_end}};
    for (const auto& [key, value] : numbers) {
        out += key;
        json_text::number(out, profile_elements::metres(value)); // to the millimetre, as in odd_profile.json
    }
    out += R"(,"osm_ids":[)";
    for (std::size_t i = 0; i < e.osm_ids.size(); ++i) {
        out += i > 0 ? "," : "";
        json_text::string(out, e.osm_ids[i]);
    }
    out += R"(],"source":)";
    json_text::string(out, e.source);
    out += "}}";
}

namespace {

void append_value_text(std::string& out, const AttributeValue& value) {
    if (const auto* d = std::get_if<double>(&value)) {
        out += text::format(*d);
    } else if (const auto* b = std::get_if<bool>(&value)) {
        out += *b ? "true" : "false";
    } else {
        out += std::get<std::string>(value);
    }
}

// As printf's "%.3f" (to_chars with a precision is specified so).
void append_metres(std::string& out, double v) {
    char buf[48];
    const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 3);
    out.append(buf, res.ptr);
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

} // namespace

void profile_text::append_csv_header(std::string& out) {
    append_row(out, {"odd_element", "element_id", "road_id", "s_start", "s_end", "chainage_start", "chainage_end",
                     "track", "point", "attributes", "osm_ids", "source"});
}

// Fields appended in place, two buffers reused: a vector of strings per row
// made writing the Cologne network's 180,000 rows take half a second.
void profile_text::append_csv_row(std::string& row, std::string& field, const TaggedElement& e) {
    for (const std::string* text : {&e.element, &e.element_id, &e.road_id}) {
        append_field(row, *text);
        row += ',';
    }
    for (const double v : {e.s_start, e.s_end, e.chainage_start, e.chainage_end}) {
        append_metres(row, v);
        row += ',';
    }
    row += std::to_string(e.track);
    row += e.point ? ",true," : ",false,";
    field.clear();
    for (std::size_t i = 0; i < e.attributes.size(); ++i) {
        field += i > 0 ? ";" : "";
        field += e.attributes[i].name;
        field += '=';
        append_value_text(field, e.attributes[i].value);
    }
    append_field(row, field);
    row += ',';
    field.clear();
    for (std::size_t i = 0; i < e.osm_ids.size(); ++i) {
        field += i > 0 ? " " : "";
        field += e.osm_ids[i];
    }
    append_field(row, field);
    row += ',';
    append_field(row, e.source);
    row += "\r\n";
}

} // namespace railodd::odd
