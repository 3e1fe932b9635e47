#pragma once
// The check passes over a read document. Each adds findings and worst figures
// to one CheckResult through a Context; internal to xodr_check.
#include "model.hpp"

#include <string>

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
void check_rail_extensions(Context& ctx); // extensions.cpp

} // namespace railodd::xodr_check
