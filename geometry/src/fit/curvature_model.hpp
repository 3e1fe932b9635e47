#pragma once
// A G2 alignment as a chain of segments whose curvature varies linearly
// between knots. A knot's curvature is either a shared variable or fixed; an
// arc is a segment whose two knots share one variable, a line one whose knots
// are fixed at zero, anything else a clothoid. Continuity of position, heading
// and curvature holds by construction, whatever the parameter values.
#include "railodd/geometry/alignment.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace railodd::geometry::fit {

struct CurvatureModel {
    Pose start;                     // x, y, hdg (curvature unused: knot 0 says it)
    bool start_free = true;         // x, y, hdg are parameters
    std::vector<double> lengths;    // one per segment
    std::vector<char> length_free;  // per segment
    std::vector<int> knot_var;      // per knot (segments + 1): index into curv, or -1: fixed
    std::vector<double> knot_fixed; // per knot: value where knot_var is -1
    std::vector<double> curv;       // the curvature variables

    std::size_t segments() const noexcept { return lengths.size(); }
    double knot_curvature(std::size_t k) const {
        return knot_var[k] >= 0 ? curv[static_cast<std::size_t>(knot_var[k])] : knot_fixed[k];
    }
    Primitive segment(std::size_t j) const;
    Alignment to_alignment() const;
    // Pose at the start of every segment, plus the end pose (segments + 1 entries).
    std::vector<Pose> knot_poses() const;

    // Adds a segment of `length` ending in a knot with the given variable / fixed value.
    void push_segment(double length, bool free_length, int end_var, double end_fixed = 0.0);
};

// The model's free parameters as one vector, in a fixed order: start (x, y,
// hdg) if free, free lengths, curvature variables.
class ParameterMap {
public:
    explicit ParameterMap(const CurvatureModel& model);
    std::size_t size() const noexcept { return slots_.size(); }
    std::vector<double> get(const CurvatureModel& model) const;
    void set(CurvatureModel& model, const std::vector<double>& values) const;
    void set_one(CurvatureModel& model, std::size_t i, double value) const;
    // Segments [first, last] whose shape parameter i changes; the start pose
    // parameters affect every segment rigidly and report (0, 0).
    std::pair<std::size_t, std::size_t> influence(std::size_t i) const { return slots_[i].range; }
    bool is_start(std::size_t i) const noexcept { return slots_[i].kind == Kind::start; }
    bool is_curvature(std::size_t i) const noexcept { return slots_[i].kind == Kind::curvature; }
    bool is_length(std::size_t i) const noexcept { return slots_[i].kind == Kind::length; }
    std::size_t index(std::size_t i) const noexcept { return slots_[i].index; }
    // The step a forward difference in parameter i takes: small against
    // what a curvature (1/m), a heading (rad) or a length or position (m)
    // moves, large against rounding.
    double difference_step(std::size_t i) const noexcept {
        return is_curvature(i) ? 1e-8 : is_start(i) && index(i) == 2 ? 1e-7 : 1e-5;
    }

private:
    enum class Kind { start, length, curvature };
    struct Slot {
        Kind kind;
        std::size_t index;
        std::pair<std::size_t, std::size_t> range;
    };
    std::vector<Slot> slots_;
};

} // namespace railodd::geometry::fit
