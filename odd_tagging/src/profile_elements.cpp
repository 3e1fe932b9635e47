// odd_profile.json's elements: rows of format 2, objects of format 1
// (profile_elements.hpp).
#include "profile_elements.hpp"

#include "json_read.hpp"
#include "json_text.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace railodd::odd::profile_elements {

namespace {

using ojson = nlohmann::ordered_json;
using namespace json_read;

// Chainage is written as null where it equals s (a whole-network profile's
// first road of each track), and flags only where set.
bool chainage_is_s(double chainage, double s) { return metres(chainage) == metres(s); }

ojson flags_json(const TaggedElement& e) {
    ojson flags = ojson::array();
    if (e.point) {
        flags.push_back("point");
    }
    if (e.reversed) {
        flags.push_back("reversed");
    }
    return flags;
}

} // namespace

double metres(double value) {
    return std::round(value * 1000.0) / 1000.0 + 0.0; // + 0.0: no "-0.0" in the file
}

const std::vector<std::string>& columns() {
    static const std::vector<std::string> c{"kind",           "track",         "road_id", "s_start",
                                            "s_end",          "chainage_start", "chainage_end", "source",
                                            "osm_ids",        "attributes",    "flags"};
    return c;
}

std::size_t KindIndex::of(const TaggedElement& e) {
    const auto [it, added] = index_.try_emplace(e.element + '\n' + e.element_id, list_.size());
    if (added) {
        list_.emplace_back(e.element, e.element_id);
    }
    return it->second;
}

Kinds kinds_of(const std::deque<TaggedElement>& elements) {
    KindIndex index;
    Kinds k;
    k.of.reserve(elements.size());
    for (const auto& e : elements) {
        k.of.push_back(index.of(e));
    }
    k.list = index.list();
    return k;
}

ojson row_json(const TaggedElement& e, std::size_t kind) {
    ojson attrs = ojson::object();
    for (const auto& a : e.attributes) {
        attrs[a.name] = std::visit([](const auto& v) { return ojson(v); }, a.value);
    }
    ojson row = ojson::array({kind, e.track, e.road_id, metres(e.s_start), metres(e.s_end)});
    row.push_back(chainage_is_s(e.chainage_start, e.s_start) ? ojson() : ojson(metres(e.chainage_start)));
    row.push_back(chainage_is_s(e.chainage_end, e.s_end) ? ojson() : ojson(metres(e.chainage_end)));
    row.push_back(e.source);
    row.push_back(e.osm_ids);
    row.push_back(std::move(attrs));
    if (e.point || e.reversed) {
        row.push_back(flags_json(e));
    }
    return row;
}

// row_json(e, kind).dump(), printed directly (json_text.hpp).
void append_row(std::string& out, const TaggedElement& e, std::size_t kind) {
    out += '[';
    json_text::number(out, static_cast<unsigned long long>(kind));
    out += ',';
    json_text::number(out, static_cast<unsigned long long>(e.track));
    out += ',';
    json_text::string(out, e.road_id);
    auto position = [&](double value) {
        out += ',';
        json_text::number(out, metres(value));
    };
    auto chainage = [&](double value, double s) {
        if (chainage_is_s(value, s)) {
            out += ",null";
        } else {
            position(value);
        }
    };
    position(e.s_start);
    position(e.s_end);
    chainage(e.chainage_start, e.s_start);
    chainage(e.chainage_end, e.s_end);
    out += ',';
    json_text::string(out, e.source);
    out += ",[";
    for (std::size_t i = 0; i < e.osm_ids.size(); ++i) {
        out += i > 0 ? "," : "";
        json_text::string(out, e.osm_ids[i]);
    }
    out += "],";
    json_text::attributes(out, e.attributes);
    if (e.point || e.reversed) {
        out += e.point && e.reversed ? R"(,["point","reversed"])" : e.point ? R"(,["point"])" : R"(,["reversed"])";
    }
    out += ']';
}

namespace {

template <class Json>
KindList kinds_of_list(const Json& list) {
    if (!list.is_array()) {
        throw std::invalid_argument("element_kinds: expected an array");
    }
    KindList out;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const auto& k = list[i];
        if (!k.is_array() || k.size() != 2 || !k[0].is_string() || !k[1].is_string()) {
            throw std::invalid_argument("element_kinds[" + std::to_string(i) + "]: expected [path, id]");
        }
        out.emplace_back(k[0].template get<std::string>(), k[1].template get<std::string>());
    }
    return out;
}

template <class Json>
void check_column_list(const Json& c) {
    if (!c.is_array() || c.size() != columns().size()) {
        throw std::invalid_argument("element_columns: expected the " + std::to_string(columns().size()) +
                                    " columns of format 2, not " + c.dump());
    }
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (!c[i].is_string() || c[i].template get<std::string>() != columns()[i]) {
            throw std::invalid_argument("element_columns[" + std::to_string(i) + "]: expected \"" + columns()[i] +
                                        "\", not " + c[i].dump());
        }
    }
}

template <class Json>
void read_flags(TaggedElement& e, const Json& flags, const std::string& where) {
    if (!flags.is_array()) {
        throw std::invalid_argument(where + ": expected an array of flags");
    }
    for (const auto& f : flags) {
        const std::string name = f.is_string() ? f.template get<std::string>() : f.dump();
        if (name != "point" && name != "reversed") {
            throw std::invalid_argument(where + ": unknown flag " + name + " (point, reversed)");
        }
        (name == "point" ? e.point : e.reversed) = true;
    }
}

template <class Json>
TaggedElement element_from_row(const Json& row, const KindList& kinds, const std::string& where) {
    const std::size_t n = columns().size();
    if (!row.is_array() || (row.size() != n && row.size() != n - 1)) {
        throw std::invalid_argument(where + ": expected a row of " + std::to_string(n - 1) + " or " +
                                    std::to_string(n) + " values (element_columns)");
    }
    auto column = [&](std::size_t i) { return where + "." + columns()[i]; };
    TaggedElement e;
    const auto kind = as<std::size_t>(row[0], column(0));
    if (kind >= kinds.size()) {
        throw std::invalid_argument(column(0) + ": " + std::to_string(kind) + " is not an index of element_kinds (" +
                                    std::to_string(kinds.size()) + " kinds)");
    }
    std::tie(e.element, e.element_id) = kinds[kind];
    e.track = as<std::size_t>(row[1], column(1));
    e.road_id = as<std::string>(row[2], column(2));
    e.s_start = as<double>(row[3], column(3));
    e.s_end = as<double>(row[4], column(4));
    e.chainage_start = row[5].is_null() ? e.s_start : as<double>(row[5], column(5));
    e.chainage_end = row[6].is_null() ? e.s_end : as<double>(row[6], column(6));
    e.source = as<std::string>(row[7], column(7));
    e.osm_ids = as<std::vector<std::string>>(row[8], column(8));
    e.attributes = attributes(row[9], column(9));
    if (row.size() == n) {
        read_flags(e, row[10], column(10));
    }
    return e;
}

template <class Json>
std::deque<TaggedElement> rows_of(const Json& doc) {
    const auto kinds = kinds_of_list(required(doc, "element_kinds", ""));
    check_column_list(required(doc, "element_columns", ""));
    const auto& rows = required(doc, "elements", "");
    if (!rows.is_array()) {
        throw std::invalid_argument("elements: expected an array");
    }
    std::deque<TaggedElement> out;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        out.push_back(element_from_row(rows[i], kinds, "elements[" + std::to_string(i) + "]"));
    }
    return out;
}

template <class Json>
TaggedElement element_from_object(const Json& j, const std::string& where) {
    TaggedElement e;
    e.element = get<std::string>(j, "odd_element", where);
    e.element_id = get_or<std::string>(j, "id", where, "");
    if (j.contains("attributes")) {
        e.attributes = attributes(j["attributes"], where + ".attributes");
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

template <class Json>
std::deque<TaggedElement> objects_of(const Json& doc) {
    const auto& elements = required(doc, "elements", "");
    if (!elements.is_array()) {
        throw std::invalid_argument("elements: expected an array");
    }
    std::deque<TaggedElement> out;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        out.push_back(element_from_object(elements[i], "elements[" + std::to_string(i) + "]"));
    }
    return out;
}

} // namespace

std::deque<TaggedElement> from_rows(const nlohmann::json& doc) { return rows_of(doc); }
std::deque<TaggedElement> from_rows(const nlohmann::ordered_json& doc) { return rows_of(doc); }
std::deque<TaggedElement> from_objects(const nlohmann::json& doc) { return objects_of(doc); }
std::deque<TaggedElement> from_objects(const nlohmann::ordered_json& doc) { return objects_of(doc); }

KindList kinds_from(const nlohmann::ordered_json& kinds) { return kinds_of_list(kinds); }
void check_columns(const nlohmann::ordered_json& columns) { check_column_list(columns); }
TaggedElement from_row(const nlohmann::ordered_json& row, const KindList& kinds, const std::string& where) {
    return element_from_row(row, kinds, where);
}
TaggedElement from_object(const nlohmann::ordered_json& element, const std::string& where) {
    return element_from_object(element, where);
}

} // namespace railodd::odd::profile_elements
