// odd_profile.json: writing and reading the route's ODD profile (profile.hpp
// holds the format, profile_elements.cpp the elements' rows). Keys are
// written in a fixed order (ordered_json) and elements in the profile's
// order, so that two runs give identical files. `lonlat` is not part of the
// JSON: the geometry lives in odd_profile.geojson.
#include "railodd/odd/profile.hpp"

#include "json_read.hpp"
#include "profile_elements.hpp"
#include "profile_text.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/json_depth.hpp"

#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace railodd::odd {

namespace {

using ojson = nlohmann::ordered_json;

// Bumped when a key changes meaning. 2: elements as rows of a table; 1
// (still read): one object per element.
constexpr int format_version = 2;
namespace rows = profile_elements;
using namespace json_read;

} // namespace

void to_json(nlohmann::ordered_json& j, const MapPlace& p) {
    j = {{"road_id", p.road_id},
         {"s_start", p.s_start},
         {"s_end", p.s_end},
         {"track", p.track},
         {"chainage_start", p.chainage_start},
         {"chainage_end", p.chainage_end},
         {"point", p.point},
         {"osm_ids", p.osm_ids}};
}

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
    // The length to the millimetre too: the largest chainage of a route, rounded, stays within it.
    j["route"] = {{"description", profile.route},
                  {"length_m", rows::metres(profile.length_m)},
                  {"tracks", profile.tracks}};
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
    const rows::Kinds kinds = rows::kinds_of(profile.elements);
    ojson kind_list = ojson::array();
    for (const auto& [path, id] : kinds.list) {
        kind_list.push_back({path, id});
    }
    j["element_kinds"] = std::move(kind_list);
    j["element_columns"] = rows::columns();
    ojson elements = ojson::array();
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        elements.push_back(rows::row_json(profile.elements[i], kinds.of[i]));
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

void profile_text::write_json_head(const OddProfile& head, const rows::KindList& kinds, std::ostream& out) {
    OddProfile bare{head.taxonomy_name, head.taxonomy_version, head.taxonomy_file,
                    head.route, head.length_m, head.tracks, {}, {}, {}, false, {}};
    bare.along_route = head.along_route;
    ojson j = to_json(bare);
    out << "{\n";
    for (const char* key : {"railodd", "taxonomy", "route"}) {
        out << " \"" << key << "\": " << j[key].dump() << ",\n";
    }
    if (!head.track_ends.empty()) {
        out << " \"track_ends\": [\n";
        for (std::size_t i = 0; i < head.track_ends.size(); ++i) {
            out << "  " << track_end_json(head.track_ends[i]).dump() << (i + 1 < head.track_ends.size() ? ",\n" : "\n");
        }
        out << " ],\n";
    }
    out << " \"element_kinds\": [\n";
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        out << "  " << ojson::array({kinds[i].first, kinds[i].second}).dump() << (i + 1 < kinds.size() ? ",\n" : "\n");
    }
    out << " ],\n \"element_columns\": " << ojson(rows::columns()).dump() << ",\n";
    out << " \"elements\": [\n";
}

void profile_text::write_json_tail(const OddProfile& tail, std::ostream& out) {
    out << " ],\n \"unparsed\": [\n";
    for (std::size_t i = 0; i < tail.unparsed.size(); ++i) {
        const auto& u = tail.unparsed[i];
        out << "  " << ojson{{"osm_ids", u.osm_ids}, {"tag", u.tag}, {"value", u.value}, {"reason", u.reason}}.dump()
            << (i + 1 < tail.unparsed.size() ? ",\n" : "\n");
    }
    out << " ],\n \"summary\": " << (tail.summary.is_null() ? ojson::object() : tail.summary).dump(1) << "\n}\n";
}

// The same document as to_json(profile).dump(), written element by element:
// a whole network's profile (180,000 elements on Cologne) never exists as one
// JSON tree, and each element sits on its own line.
void write_json(const OddProfile& profile, std::ostream& out) {
    const rows::Kinds kinds = rows::kinds_of(profile.elements);
    profile_text::write_json_head(profile, kinds.list, out);
    std::string line;
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        line.assign(i > 0 ? ",\n  " : "  ");
        rows::append_row(line, profile.elements[i], kinds.of[i]);
        out << line;
    }
    out << (profile.elements.empty() ? "" : "\n");
    profile_text::write_json_tail(profile, out);
}

std::string to_json_text(const OddProfile& profile) {
    std::ostringstream out;
    write_json(profile, out);
    return std::move(out).str();
}

namespace {

// 1 for a file without the "railodd" header (written before it had one).
template <class Json>
int format_of(const Json& j) {
    if (!j.is_object() || !j.contains("railodd")) {
        return 1;
    }
    const auto& head = j["railodd"];
    if (get_or<std::string>(head, "format", "railodd", "odd_profile") != "odd_profile") {
        throw std::invalid_argument("railodd.format: expected \"odd_profile\", not " + head["format"].dump());
    }
    const auto& version = head.contains("format_version") ? head["format_version"] : Json(1);
    if (!version.is_number_integer() || version.template get<long long>() < 1 ||
        version.template get<long long>() > format_version) {
        throw std::invalid_argument("railodd.format_version: " + version.dump() +
                                    " is not a format this railodd reads (1 to " + std::to_string(format_version) + ")");
    }
    return static_cast<int>(version.template get<long long>());
}

// `streamed`: the elements read_profile took from the rows as they were
// parsed (the tree's "elements" is then empty).
template <class Json>
OddProfile profile_from(const Json& j, std::deque<TaggedElement>* streamed = nullptr) {
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
    const int format = format_of(j);
    if (streamed) {
        p.elements = std::move(*streamed);
    } else {
        p.elements = format == 1 ? rows::from_objects(j) : rows::from_rows(j);
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

namespace {

// read_profile's parser callback: each element becomes a TaggedElement as
// soon as the parser completes it and is dropped from the tree, so that a
// whole network's profile (170,000 elements on Cologne) never exists as one
// JSON tree. Only where the header, kinds and columns come before the
// elements, as railodd writes them; otherwise the tree is kept whole and read
// as profile_from_json reads it.
class ElementStream {
public:
    bool operator()(int depth, nlohmann::json::parse_event_t event, ojson& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (depth == 1 && event == Event::key) {
            key_ = parsed.template get<std::string>();
            if (streaming_ && (key_ == "railodd" || key_ == "element_kinds" || key_ == "element_columns")) {
                // The rows were read with the first one; the tree would take the last.
                throw std::invalid_argument(key_ + ": given again after the elements");
            }
            if (key_ == "elements") {
                streaming_ = ready();
                elements_.clear(); // a repeated key: the last one counts, as in the tree
                index_ = 0;
            }
            return true;
        }
        const bool done = event == Event::value || event == Event::object_end || event == Event::array_end;
        if (done && depth == 1 && key_ != "elements") {
            remember(parsed);
            return true;
        }
        if (done && depth == 2 && key_ == "elements" && streaming_) {
            const std::string where = "elements[" + std::to_string(index_++) + "]";
            elements_.push_back(*format_ == 1 ? rows::from_object(parsed, where)
                                              : rows::from_row(parsed, *kinds_, where));
            return false;
        }
        return true;
    }

    std::deque<TaggedElement>* streamed() { return streaming_ ? &elements_ : nullptr; }

private:
    void remember(const ojson& value) {
        try { // a malformed header, kinds or columns: not streamed, and refused by profile_from
            if (key_ == "railodd") {
                format_ = format_of(ojson{{"railodd", value}});
            } else if (key_ == "element_kinds") {
                kinds_ = rows::kinds_from(value);
            } else if (key_ == "element_columns") {
                rows::check_columns(value);
                columns_ok_ = true;
            }
        } catch (const std::invalid_argument&) {
            format_.reset();
        }
    }

    bool ready() const { return format_ && (*format_ == 1 || (kinds_ && columns_ok_)); }

    std::string key_;
    std::optional<int> format_;
    std::optional<rows::KindList> kinds_;
    bool columns_ok_ = false;
    bool streaming_ = false;
    std::size_t index_ = 0;
    std::deque<TaggedElement> elements_;
};

} // namespace

OddProfile read_profile(const std::filesystem::path& file) {
    const std::string text = read_input_file(file, "ODD profile");
    require_json_depth(text, file);
    // Parsed keeping key order: attributes and the summary's classes stay in
    // the order the tagger wrote them (the taxonomy's bin order).
    ElementStream stream;
    nlohmann::ordered_json j;
    try {
        j = nlohmann::ordered_json::parse(text, std::ref(stream));
        return profile_from(j, stream.streamed());
    } catch (const nlohmann::json::exception& e) { // parse errors, and out_of_range for 1e999
        throw InputError(file.string(), std::string{"invalid JSON: "} + e.what());
    } catch (const std::invalid_argument& e) {
        throw InputError(file.string(), std::string{"not an ODD profile: "} + e.what());
    }
}

} // namespace railodd::odd
