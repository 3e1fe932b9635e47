#pragma once
// Attribute formatting shared by the OpenDRIVE serializer's files.
#include "railodd/xodr/model.hpp"

#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace railodd::xodr::xml {

// 15 significant digits: exact to well under a micrometre for coordinates of
// a few hundred kilometres, and locale-independent.
inline std::string num(double v) {
    if (v == 0.0 || std::abs(v) < 1e-300) {
        return "0"; // never "-0"
    }
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 15);
    return std::string(buf, r.ptr);
}

inline void attr(pugi::xml_node n, const char* name, const std::string& value) {
    n.append_attribute(name).set_value(value.c_str());
}

inline void attr(pugi::xml_node n, const char* name, const char* value) {
    n.append_attribute(name).set_value(value);
}

inline void attr(pugi::xml_node n, const char* name, double value) {
    attr(n, name, num(value));
}

inline void user_data(pugi::xml_node parent, const std::vector<UserData>& data) {
    for (const auto& d : data) {
        pugi::xml_node u = parent.append_child("userData");
        attr(u, "code", d.code);
        attr(u, "value", d.value);
    }
}

// Sections written by xml_sections.cpp.
void write_objects(pugi::xml_node road, const Road& r, Revision revision);
void write_signals(pugi::xml_node road, const Road& r, Revision revision);
void write_railroad(pugi::xml_node road, const Road& r);
void write_junction(pugi::xml_node root, const Junction& j, Revision revision);
void write_station(pugi::xml_node root, const Station& s);

} // namespace railodd::xodr::xml
