#pragma once
// Which way each fitted chain runs. OpenDRIVE readers follow lanes by lane
// id, not by contactPoint: CARLA continues a right lane, which runs along s,
// at the start of its road's successor, so a walk passes a link only where
// one road ends and the next starts (docs/xodr.md). Chains are reversed, as
// whole alignments, so that every movement between two chains runs end ->
// start where the network allows it. A wye or a balloon loop turns a train
// round: one link per such cycle cannot, and is counted.
#include "railodd/geometry/track_fit.hpp"

namespace railodd::geometry {

struct Orientation {
    std::size_t reversed_chains = 0;
    std::size_t reversing_links = 0; // movements left end -> end or start -> start
};

Orientation orient_chains(const TrackGraph& graph, FittedNetwork& net);

} // namespace railodd::geometry
