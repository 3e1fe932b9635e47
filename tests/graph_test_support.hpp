#pragma once
// Helpers shared by the track graph, crossing and attachment tests: every way
// segment lies in exactly one edge, inline OPL read through the OSM reader,
// and alignments standing in for fitted ones.
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace railodd::test {

inline ingest::IngestResult read_opl(const std::string& opl, ingest::IngestOptions options = {}) {
    return ingest::read_osm(write_file(scratch_dir() / "input.opl", opl), options);
}

// Lines through the polyline's nodes joined by 2 cm arcs: an Alignment cannot
// turn on the spot, and a stand-in for the fitted centreline is all tests need.
inline geometry::IndexedAlignment polyline_alignment(const std::vector<ingest::NodeRef>& nodes) {
    constexpr double joint = 0.02;
    geometry::Alignment a;
    const auto heading = [&](std::size_t i) {
        return std::atan2(nodes[i + 1].xy.y - nodes[i].xy.y, nodes[i + 1].xy.x - nodes[i].xy.x);
    };
    a.start = {nodes[0].xy.x, nodes[0].xy.y, heading(0), 0.0};
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
        const double len = std::hypot(nodes[i + 1].xy.x - nodes[i].xy.x, nodes[i + 1].xy.y - nodes[i].xy.y);
        const double trim = (i > 0 ? joint / 2 : 0.0) + (i + 2 < nodes.size() ? joint / 2 : 0.0);
        a.primitives.push_back(geometry::make_line(std::max(len - trim, 0.0)));
        if (i + 2 < nodes.size()) {
            const double turn = std::remainder(heading(i + 1) - heading(i), 2.0 * std::numbers::pi);
            a.primitives.push_back(geometry::make_arc(joint, turn / joint));
        }
    }
    return geometry::IndexedAlignment(a);
}

inline std::vector<geometry::IndexedAlignment> polyline_alignments(const geometry::TrackGraph& g) {
    std::vector<geometry::IndexedAlignment> out;
    for (const auto& e : g.edges) {
        out.push_back(polyline_alignment(e.nodes));
    }
    return out;
}

inline std::size_t way_segments(const std::vector<ingest::Way>& ways) {
    std::size_t n = 0;
    for (const auto& w : ways) {
        for (const auto& p : w.parts) {
            n += p.empty() ? 0 : p.size() - 1;
        }
    }
    return n;
}

inline std::size_t edge_segments(const geometry::TrackGraph& g) {
    std::size_t n = 0;
    for (const auto& e : g.edges) {
        n += e.nodes.size() - 1;
    }
    return n;
}

// Every directed way segment (in way direction) is covered by exactly one span
// segment, spans tile each edge without gaps, and edge ends are its vertices.
// Returns the first problem found, empty if none.
inline std::string check_conservation(const geometry::TrackGraph& g, const std::vector<ingest::Way>& ways) {
    using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>; // way, from node, to node
    std::map<Key, int> open;
    for (const auto& w : ways) {
        for (const auto& p : w.parts) {
            for (std::size_t i = 0; i + 1 < p.size(); ++i) {
                ++open[{w.id, p[i].id, p[i + 1].id}];
            }
        }
    }
    for (const auto& e : g.edges) {
        const std::string where = "edge " + std::to_string(e.id) + ": ";
        if (e.nodes.size() < 2 || e.ways.empty()) {
            return where + "fewer than two nodes or no span";
        }
        if (g.vertices.at(e.from).node_id != e.nodes.front().id || g.vertices.at(e.to).node_id != e.nodes.back().id) {
            return where + "ends are not its vertices";
        }
        std::size_t expect_first = 0;
        for (const auto& s : e.ways) {
            if (s.first != expect_first || s.last <= s.first || s.last >= e.nodes.size()) {
                return where + "spans do not tile the edge";
            }
            for (std::size_t k = s.first; k < s.last; ++k) {
                const auto a = e.nodes[k].id, b = e.nodes[k + 1].id;
                const Key key = s.reversed ? Key{s.way_id, b, a} : Key{s.way_id, a, b};
                if (--open[key] < 0) {
                    return where + "segment " + std::to_string(a) + "-" + std::to_string(b) + " of way " +
                           std::to_string(s.way_id) + " is not in the way or covered twice";
                }
            }
            expect_first = s.last;
        }
        if (expect_first != e.nodes.size() - 1) {
            return where + "spans end before the edge";
        }
    }
    for (const auto& [key, count] : open) {
        if (count != 0) {
            return "way " + std::to_string(std::get<0>(key)) + " segment " + std::to_string(std::get<1>(key)) + "-" +
                   std::to_string(std::get<2>(key)) + " is in no edge";
        }
    }
    return {};
}

} // namespace railodd::test
