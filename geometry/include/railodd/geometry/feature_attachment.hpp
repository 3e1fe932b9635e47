#pragma once
// Railway features (signals, switches, level crossings, stations, platforms)
// placed on the track graph: which edge, how far along its alignment, and on
// which side.
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/ingest/types.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace railodd::geometry {

struct AttachedFeature {
    std::size_t feature = 0; // index into the features passed
    std::size_t edge = 0;
    double s = 0.0;        // along the edge's alignment
    double offset = 0.0;   // lateral, left of the edge direction positive
    double distance = 0.0; // from the alignment
    double s_start = 0.0;  // extent along the edge of an outline (platform); = s for points
    double s_end = 0.0;
    std::optional<std::size_t> vertex; // the feature's node is this topological vertex (a switch, an end)
};

struct Unattached {
    std::size_t feature = 0;
    std::string reason;
};

struct Attachment {
    std::vector<AttachedFeature> attached; // by feature index
    std::vector<Unattached> unattached;    // by feature index
};

// alignments[i] is the centreline of tracks.edges[i], normally starting at
// its first node; s and offset are measured along alignments[i] as given, so
// an alignment fitted against the edge's node order yields s from the edge's
// `to` end and mirrored offsets. A feature on a track node goes to the lowest-id edge through that
// node (at s = 0 or the end when the node is a vertex); any other goes to the
// edge whose alignment is nearest to its position (an outline's centroid),
// found through a spatial index of the edge polylines. Outlines get their
// s-range from projecting every outline node. Features farther than the limit
// (station_max_distance_m for kinds station and halt, which are often mapped
// at the building) are unattached, with the distance in the reason.
//
// Throws std::invalid_argument when alignments and edges differ in number.
Attachment attach_features(const TrackGraph& tracks, const std::vector<IndexedAlignment>& alignments,
                           const std::vector<ingest::Feature>& features, double max_distance_m,
                           double station_max_distance_m);

// One limit for every kind.
Attachment attach_features(const TrackGraph& tracks, const std::vector<IndexedAlignment>& alignments,
                           const std::vector<ingest::Feature>& features, double max_distance_m);

} // namespace railodd::geometry
