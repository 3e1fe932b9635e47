#pragma once
// The check passes over a read document. Each adds findings and worst figures
// to one CheckResult through a Context; internal to xodr_check.
#include "model.hpp"

#include <string>
#include <vector>

namespace railodd::xodr_check {

class Context {
public:
    Context(const Document& doc, const Limits& limits, CheckResult& result)
        : doc(doc), limits(limits), result(result) {}

    void error(const std::string& object, const std::string& id, double s, const std::string& check,
               const std::string& message) {
        result.findings.push_back({Severity::error, object, id, s, check, message});
    }
    void warning(const std::string& object, const std::string& id, double s, const std::string& check,
                 const std::string& message) {
        result.findings.push_back({Severity::warning, object, id, s, check, message});
    }

    const Document& doc;
    const Limits& limits;
    CheckResult& result;
};

// "1.2345e-03 m > 1.0e-03 m": a measured value against its limit.
std::string measured(double value, double limit, const char* unit);

// "road 12 s=34.500"
std::string place(const std::string& object, const std::string& id, double s);

// One end of a road where it meets another road.
struct RoadEnd {
    const Road* road = nullptr;
    bool at_end = false; // false: the road's start (s = 0)
};

inline const char* end_name(bool at_end) { return at_end ? "end" : "start"; }

// "road 12 end"
inline std::string end_label(RoadEnd e) { return "road " + e.road->id + " " + end_name(e.at_end); }

// A road's predecessor or successor naming another road that exists, with a
// contactPoint of start or end (the links check reports the others).
struct RoadLink {
    const Road* road = nullptr; // the road holding the link
    bool at_end = false;        // successor (true) or predecessor (false)
    const Link* link = nullptr;
    const Road* other = nullptr;
    bool other_at_end = false; // the link's contactPoint
    RoadEnd mine() const { return {road, at_end}; }
    RoadEnd theirs() const { return {other, other_at_end}; }
};
std::vector<RoadLink> road_to_road_links(const Document& doc); // links.cpp

// The link of `road` at one of its ends.
inline const Link& link_at(const Road& road, bool at_end) { return at_end ? road.successor : road.predecessor; }

// The end of `incoming` that links to junction `j`; when both do (a loop), the
// one nearer `contact`. False when neither end links to the junction.
bool junction_end(const Road& incoming, const Junction& j, const Pose& contact, bool& at_end); // junctions.cpp

// Compares two road ends that should touch: position, heading (same direction
// when one is a start and the other an end, opposite otherwise) and, when both
// are rail roads, curvature. Findings go to `object` `id` with checks named
// `<prefix>_gap`, `<prefix>_heading`, `<prefix>_curvature`.
void compare_contact(Context& ctx, const std::string& object, const std::string& id, double s,
                     const std::string& prefix, RoadEnd a, RoadEnd b);

void check_plan_views(Context& ctx);   // planview.cpp
void check_elevations(Context& ctx);   // planview.cpp
void check_road_links(Context& ctx);   // links.cpp
void check_junctions(Context& ctx);    // junctions.cpp
void check_id_collisions(Context& ctx);        // id_collisions.cpp
void check_duplicate_connections(Context& ctx); // duplicate_connections.cpp
void check_contact_points(Context& ctx);       // contact_points.cpp
void check_elevation_links(Context& ctx);      // elevation_links.cpp
void check_rail_extensions(Context& ctx); // extensions.cpp

} // namespace railodd::xodr_check
