#include "osm_xml.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace railodd::sample {

namespace {

std::string escape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
    return out;
}

// OSM stores coordinates in 1e-7 degree units; printing exactly that many
// decimals loses nothing a reader would keep.
std::string degrees(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7f", v);
    return buf;
}

void write_tags(std::string& out, const Tags& tags) {
    for (const auto& [k, v] : tags) {
        out += "    <tag k=\"" + escape(k) + "\" v=\"" + escape(v) + "\"/>\n";
    }
}

void write_bounds(std::string& out, const OsmData& data) {
    if (data.nodes.empty()) {
        return;
    }
    double min_lon = data.nodes.front().lon, max_lon = min_lon;
    double min_lat = data.nodes.front().lat, max_lat = min_lat;
    for (const auto& n : data.nodes) {
        min_lon = std::min(min_lon, n.lon);
        max_lon = std::max(max_lon, n.lon);
        min_lat = std::min(min_lat, n.lat);
        max_lat = std::max(max_lat, n.lat);
    }
    out += "  <bounds minlat=\"" + degrees(min_lat) + "\" minlon=\"" + degrees(min_lon) +
           "\" maxlat=\"" + degrees(max_lat) + "\" maxlon=\"" + degrees(max_lon) + "\"/>\n";
}

void write_node(std::string& out, const OsmNode& n) {
    out += "  <node id=\"" + std::to_string(n.id) + "\" version=\"1\" lat=\"" + degrees(n.lat) +
           "\" lon=\"" + degrees(n.lon) + "\"";
    if (n.tags.empty()) {
        out += "/>\n";
        return;
    }
    out += ">\n";
    write_tags(out, n.tags);
    out += "  </node>\n";
}

void write_way(std::string& out, const OsmWay& w) {
    out += "  <way id=\"" + std::to_string(w.id) + "\" version=\"1\">\n";
    for (const auto ref : w.nodes) {
        out += "    <nd ref=\"" + std::to_string(ref) + "\"/>\n";
    }
    write_tags(out, w.tags);
    out += "  </way>\n";
}

void write_relation(std::string& out, const OsmRelation& r) {
    out += "  <relation id=\"" + std::to_string(r.id) + "\" version=\"1\">\n";
    for (const auto& m : r.members) {
        out += "    <member type=\"" + m.type + "\" ref=\"" + std::to_string(m.ref) + "\" role=\"" +
               escape(m.role) + "\"/>\n";
    }
    write_tags(out, r.tags);
    out += "  </relation>\n";
}

} // namespace

std::string to_osm_xml(const OsmData& data) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<osm version=\"0.6\" generator=\"railodd sample\">\n";
    write_bounds(out, data);
    for (const auto& n : data.nodes) {
        write_node(out, n);
    }
    for (const auto& w : data.ways) {
        write_way(out, w);
    }
    for (const auto& r : data.relations) {
        write_relation(out, r);
    }
    out += "</osm>\n";
    return out;
}

} // namespace railodd::sample
