// odd_profile.json: writing and reading the route's ODD profile (profile.hpp
// holds the format). Keys are written in a fixed order (ordered_json) and
// elements in the profile's order, so that two runs give identical files.
// `lonlat` is not part of the JSON: the geometry lives in odd_profile.geojson.
#include "railodd/odd/profile.hpp"

#include "json_text.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/input_file.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace railodd::odd {

namespace {

using ojson = nlohmann::ordered_json;

// Bumped when a key changes meaning; readers refuse nothing yet (one version).
constexpr int format_version = 1;

ojson attribute_json(const AttributeValue& value) {
    return std::visit([](const auto& v) { return ojson(v); }, value);
}

ojson element_json(const TaggedElement& e) {
    ojson attrs = ojson::object();
    for (const auto& a : e.attributes) {
        attrs[a.name] = attribute_json(a.value);
    }
    ojson j;
    j["odd_element"] = e.element;
    j["id"] = e.element_id;
    j["attributes"] = std::move(attrs);
    j["road_id"] = e.road_id;
    j["s_start"] = e.s_start;
    j["s_end"] = e.s_end;
    j["track"] = e.track;
    j["chainage_start"] = e.chainage_start;
    j["chainage_end"] = e.chainage_end;
    j["point"] = e.point;
    j["osm_ids"] = e.osm_ids;
    j["source"] = e.source;
    if (e.reversed) {
        j["reversed"] = true;
    }
    return j;
}

// element_json(e).dump(), printed directly (json_text.hpp).
void append_element(std::string& out, const TaggedElement& e) {
    out += R"({"odd_element":)";
    json_text::string(out, e.element);
    out += R"(,"id":)";
    json_text::string(out, e.element_id);
    out += R"(,"attributes":)";
    json_text::attributes(out, e.attributes);
    out += R"(,"road_id":)";
    json_text::string(out, e.road_id);
    out += R"(,"s_start":)";
    json_text::number(out, e.s_start);
    out += R"(,"s_end":)";
    json_text::number(out, e.s_end);
    out += R"(,"track":)";
    json_text::number(out, static_cast<unsigned long long>(e.track));
    out += R"(,"chainage_start":)";
    json_text::number(out, e.chainage_start);
    out += R"(,"chainage_end":)";
    json_text::number(out, e.chainage_end);
    out += e.point ? R"(,"point":true,"osm_ids":[)" : R"(,"point":false,"osm_ids":[)";
    for (std::size_t i = 0; i < e.osm_ids.size(); ++i) {
        out += i > 0 ? "," : "";
        json_text::string(out, e.osm_ids[i]);
    }
    out += R"(],"source":)";
    json_text::string(out, e.source);
    out += e.reversed ? R"(,"reversed":true})" : "}";
}

// --- reading ---------------------------------------------------------------
// Every lookup names the key and where it was expected, so that a hand-edited
// file that lost a key is reported as "elements[3].s_start: missing".

template <class Json>
const Json& required(const Json& j, const std::string& key, const std::string& where) {
    if (!j.is_object()) {
        throw std::invalid_argument(where + ": expected an object");
    }
    const auto it = j.find(key);
    if (it == j.end()) {
        throw std::invalid_argument((where.empty() ? key : where + "." + key) + ": missing");
    }
    return *it;
}

template <class T, class Json>
T get(const Json& j, const std::string& key, const std::string& where) {
    const auto& v = required(j, key, where);
    if constexpr (std::is_same_v<T, std::size_t>) {
        // nlohmann would wrap -1 to 2^64-1 and cut 1.5 to 1: an index must be exact.
        if (!v.is_number_unsigned()) {
            throw std::invalid_argument((where.empty() ? key : where + "." + key) + ": expected a count, not " + v.dump());
        }
    }
    try {
        return v.template get<T>();
    } catch (const nlohmann::json::exception&) { // shared by both specialisations
        throw std::invalid_argument((where.empty() ? key : where + "." + key) + ": wrong type (" + v.type_name() + ")");
    }
}

template <class T, class Json>
T get_or(const Json& j, const std::string& key, const std::string& where, T fallback) {
    if (!j.is_object()) {
        throw std::invalid_argument((where.empty() ? "document" : where) + ": expected an object");
    }
    return j.contains(key) ? get<T>(j, key, where) : fallback;
}

template <class Json>
AttributeValue attribute_value(const Json& v, const std::string& where) {
    if (v.is_boolean()) {
        return v.template get<bool>();
    }
    if (v.is_number()) {
        return v.template get<double>();
    }
    if (v.is_string()) {
        return v.template get<std::string>();
    }
    throw std::invalid_argument(where + ": expected a number, string or bool (" + v.type_name() + ")");
}

template <class Json>
TaggedElement element_from_json(const Json& j, const std::string& where) {
    TaggedElement e;
    e.element = get<std::string>(j, "odd_element", where);
    e.element_id = get_or<std::string>(j, "id", where, "");
    if (j.contains("attributes")) {
        const auto& attrs = required(j, "attributes", where);
        if (!attrs.is_object()) {
            throw std::invalid_argument(where + ".attributes: expected an object");
        }
        for (const auto& [name, value] : attrs.items()) {
            e.attributes.push_back({name, attribute_value(value, where + ".attributes." + name)});
        }
    }
    e.road_id = get<std::string>(j, "road_id", where);
    e.s_start = get<double>(j, "s_start", where);
    e.s_end = get<double>(j, "s_end", where);
    e.track = get_or<std::size_t>(j, "track", where, 0);
    e.chainage_start = get_or<double>(j, "chainage_start", where, e.s_start);
    e.chainage_end = get_or<double>(j, "chainage_end", where, e.s_end);
    e.point = get_or<bool>(j, "point", where, false);
    e.osm_ids = get_or<std::vector<std::string>>(j, "osm_ids", where, {});
    e.source = get_or<std::string>(j, "source", where, "");
    e.reversed = get_or<bool>(j, "reversed", where, false);
    return e;
}

} // namespace

const AttributeValue* TaggedElement::find(const std::string& attribute) const {
    for (const auto& a : attributes) {
        if (a.name == attribute) {
            return &a.value;
        }
    }
    return nullptr;
}

namespace {

ojson track_end_json(const TrackEnd& t) {
    return ojson::array({t.track, t.from_node, t.to_node, t.from_heading, t.to_heading});
}

template <class Json>
std::vector<TrackEnd> track_ends_from(const Json& list) {
    std::vector<TrackEnd> out;
    if (!list.is_array()) {
        throw std::invalid_argument("track_ends: expected an array");
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
        const auto& t = list[i];
        if (!t.is_array() || t.size() != 5 || !t[0].is_number_unsigned() || !t[1].is_number_integer() ||
            !t[2].is_number_integer() || !t[3].is_number() || !t[4].is_number()) {
            throw std::invalid_argument("track_ends[" + std::to_string(i) +
                                        "]: expected [track, from node, to node, from heading, to heading]");
        }
        out.push_back({t[0].template get<std::size_t>(), t[1].template get<std::int64_t>(),
                       t[2].template get<std::int64_t>(), t[3].template get<double>(), t[4].template get<double>()});
    }
    return out;
}

} // namespace

nlohmann::ordered_json to_json(const OddProfile& profile) {
    ojson j;
    j["railodd"] = {{"format", "odd_profile"}, {"format_version", format_version}};
    j["taxonomy"] = {{"name", profile.taxonomy_name},
                     {"version", profile.taxonomy_version},
                     {"file", profile.taxonomy_file}};
    j["route"] = {{"description", profile.route}, {"length_m", profile.length_m}, {"tracks", profile.tracks}};
    if (profile.along_route) {
        j["route"]["along_route"] = true;
    }
    if (!profile.track_ends.empty()) {
        ojson ends = ojson::array();
        for (const auto& t : profile.track_ends) {
            ends.push_back(track_end_json(t));
        }
        j["track_ends"] = std::move(ends);
    }
    ojson elements = ojson::array();
    for (const auto& e : profile.elements) {
        elements.push_back(element_json(e));
    }
    j["elements"] = std::move(elements);
    ojson unparsed = ojson::array();
    for (const auto& u : profile.unparsed) {
        unparsed.push_back({{"osm_ids", u.osm_ids}, {"tag", u.tag}, {"value", u.value}, {"reason", u.reason}});
    }
    j["unparsed"] = std::move(unparsed);
    j["summary"] = profile.summary.is_null() ? ojson::object() : profile.summary;
    return j;
}

// The same document as to_json(profile).dump(), written element by element:
// a whole network's profile (180,000 elements on Cologne) never exists as one
// JSON tree, and each element sits on its own line.
void write_json(const OddProfile& profile, std::ostream& out) {
    OddProfile bare{profile.taxonomy_name, profile.taxonomy_version, profile.taxonomy_file,
                    profile.route, profile.length_m, profile.tracks, {}, {}, {}, false, {}};
    bare.along_route = profile.along_route;
    ojson head = to_json(bare);
    out << "{\n";
    for (const char* key : {"railodd", "taxonomy", "route"}) {
        out << " \"" << key << "\": " << head[key].dump() << ",\n";
    }
    if (!profile.track_ends.empty()) {
        out << " \"track_ends\": [\n";
        for (std::size_t i = 0; i < profile.track_ends.size(); ++i) {
            out << "  " << track_end_json(profile.track_ends[i]).dump()
                << (i + 1 < profile.track_ends.size() ? ",\n" : "\n");
        }
        out << " ],\n";
    }
    out << " \"elements\": [\n";
    std::string line;
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        line.assign("  ");
        append_element(line, profile.elements[i]);
        line += i + 1 < profile.elements.size() ? ",\n" : "\n";
        out << line;
    }
    out << " ],\n \"unparsed\": [\n";
    for (std::size_t i = 0; i < profile.unparsed.size(); ++i) {
        const auto& u = profile.unparsed[i];
        out << "  " << ojson{{"osm_ids", u.osm_ids}, {"tag", u.tag}, {"value", u.value}, {"reason", u.reason}}.dump()
            << (i + 1 < profile.unparsed.size() ? ",\n" : "\n");
    }
    out << " ],\n \"summary\": " << (profile.summary.is_null() ? ojson::object() : profile.summary).dump(1) << "\n}\n";
}

std::string to_json_text(const OddProfile& profile) {
    std::ostringstream out;
    write_json(profile, out);
    return std::move(out).str();
}

namespace {

template <class Json>
OddProfile profile_from(const Json& j) {
    OddProfile p;
    const auto& taxonomy = required(j, "taxonomy", "");
    p.taxonomy_name = get_or<std::string>(taxonomy, "name", "taxonomy", "");
    p.taxonomy_version = get_or<std::string>(taxonomy, "version", "taxonomy", "");
    p.taxonomy_file = get_or<std::string>(taxonomy, "file", "taxonomy", "");
    const auto& route = required(j, "route", "");
    p.route = get_or<std::string>(route, "description", "route", "");
    p.length_m = get<double>(route, "length_m", "route");
    p.tracks = get_or<std::size_t>(route, "tracks", "route", 0);
    p.along_route = get_or<bool>(route, "along_route", "route", false);
    if (j.contains("track_ends")) {
        p.track_ends = track_ends_from(j["track_ends"]);
    }
    const auto& elements = required(j, "elements", "");
    if (!elements.is_array()) {
        throw std::invalid_argument("elements: expected an array");
    }
    for (std::size_t i = 0; i < elements.size(); ++i) {
        p.elements.push_back(element_from_json(elements[i], "elements[" + std::to_string(i) + "]"));
    }
    if (j.contains("unparsed")) {
        const auto& unparsed = j["unparsed"];
        if (!unparsed.is_array()) {
            throw std::invalid_argument("unparsed: expected an array");
        }
        for (std::size_t i = 0; i < unparsed.size(); ++i) {
            const std::string where = "unparsed[" + std::to_string(i) + "]";
            p.unparsed.push_back({get_or<std::vector<std::string>>(unparsed[i], "osm_ids", where, {}),
                                  get_or<std::string>(unparsed[i], "tag", where, ""),
                                  get_or<std::string>(unparsed[i], "value", where, ""),
                                  get_or<std::string>(unparsed[i], "reason", where, "")});
        }
    }
    if (j.contains("summary")) {
        if (!j["summary"].is_object()) {
            throw std::invalid_argument("summary: expected an object");
        }
        p.summary = nlohmann::ordered_json(j["summary"]);
    }
    return p;
}

} // namespace

OddProfile profile_from_json(const nlohmann::json& j) { return profile_from(j); }

OddProfile profile_from_json(const nlohmann::ordered_json& j) { return profile_from(j); }

OddProfile read_profile(const std::filesystem::path& file) {
    const std::string text = read_input_file(file, "ODD profile");
    // Parsed keeping key order: attributes and the summary's classes stay in
    // the order the tagger wrote them (the taxonomy's bin order).
    nlohmann::ordered_json j;
    try {
        j = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::exception& e) { // parse errors, and out_of_range for 1e999
        throw InputError(file.string(), std::string{"invalid JSON: "} + e.what());
    }
    try {
        return profile_from_json(j);
    } catch (const std::invalid_argument& e) {
        throw InputError(file.string(), std::string{"not an ODD profile: "} + e.what());
    }
}

} // namespace railodd::odd
