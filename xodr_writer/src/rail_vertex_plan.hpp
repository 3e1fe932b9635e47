#pragma once
// How the edge ends at each track-graph vertex are joined in OpenDRIVE:
// which pairs of ends a train can pass between (movements: the ends meet
// with opposite headings and matching curvature, i.e. G2), and, at vertices
// with more than two ends, which ends are cut back to become a junction's
// connecting roads.
#include "railodd/geometry/vertex_legs.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace railodd::xodr {

using geometry::Leg;

struct VertexPlan {
    std::size_t vertex = 0;
    std::vector<Leg> legs;
    bool junction = false; // more than two ends: movements run through connecting roads
    // Leg index pairs; in a junction (uncut leg, cut leg), otherwise the two
    // legs of a direct link.
    std::vector<std::pair<std::size_t, std::size_t>> movements;
    std::vector<bool> cut;                                   // per leg
    std::vector<std::pair<std::size_t, std::string>> unlinked; // leg index, why no train passes there
};

using PlanTolerances = geometry::LegTolerances;

// One plan per vertex with at least two ends of written edges (written[e]).
std::vector<VertexPlan> plan_vertices(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                                      const std::vector<bool>& written, const PlanTolerances& tolerances = {});

} // namespace railodd::xodr
