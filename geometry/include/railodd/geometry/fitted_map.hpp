#pragma once
// The geometry stage's result, whole: the track and road graphs with their
// fitted alignments, the tracks' vertical profiles and cant, the features
// placed on them and the crossings. What the map builder (xodr::build_map)
// and the tagger (odd::tag_network) both take, beside the ingest result.
#include "railodd/geometry/cant.hpp"
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/vertical_profile.hpp"

#include <vector>

namespace railodd::geometry {

struct FittedMap {
    TrackGraph tracks;
    FittedNetwork fitted_tracks;
    std::vector<VerticalProfile> profiles;             // per track edge
    std::vector<std::vector<CantStretch>> cants;       // per track edge
    Attachment attachment;
    Crossings crossings;
    TrackGraph roads;
    FittedNetwork fitted_roads;
    // The fitted tracks indexed at 2 m, one per edge, where they were made
    // (to place the features): the map builder and the tagger use them
    // instead of indexing every track again. Empty where dropped (convert
    // drops them before tagging: a fifth of Cologne's peak).
    std::vector<IndexedAlignment> indexed;

    // The edge's prebuilt index, or null where there is none.
    const IndexedAlignment* indexed_edge(std::size_t edge) const {
        return indexed.size() == fitted_tracks.edges.size() ? &indexed[edge] : nullptr;
    }
};

} // namespace railodd::geometry
