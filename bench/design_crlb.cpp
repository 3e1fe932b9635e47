#include "design_crlb.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace railodd::bench {

namespace {

using geometry::Alignment;
using geometry::PrimitiveKind;

// The design as parameters: start x, y, hdg, every element's length, every
// arc's curvature. A transition runs between its neighbours' curvatures
// (zero beside a line, the design's value between two transitions).
class DesignParameters {
public:
    explicit DesignParameters(const Alignment& design) : design_(design) {
        values_ = {design.start.x, design.start.y, design.start.hdg};
        for (const auto& p : design.primitives) {
            values_.push_back(p.length);
        }
        for (std::size_t i = 0; i < design.primitives.size(); ++i) {
            if (design.primitives[i].kind == PrimitiveKind::arc) {
                arc_var_.push_back(values_.size());
                values_.push_back(design.primitives[i].curv_start);
            } else {
                arc_var_.push_back(0);
            }
        }
    }
    const std::vector<double>& values() const { return values_; }
    // Index of arc i's curvature among the parameters (primitive order).
    std::size_t arc_parameter(std::size_t primitive) const { return arc_var_[primitive]; }

    Alignment build(const std::vector<double>& v) const {
        Alignment a;
        a.start = {v[0], v[1], v[2], 0.0};
        const auto& q = design_.primitives;
        auto curvature_of = [&](std::size_t i, bool at_end) {
            if (q[i].kind == PrimitiveKind::arc) {
                return v[arc_var_[i]];
            }
            if (q[i].kind == PrimitiveKind::line) {
                return 0.0;
            }
            // A transition's end: its neighbour's, or the design's value
            // where the neighbour is a transition too.
            const bool has = at_end ? i + 1 < q.size() : i > 0;
            if (!has) {
                return at_end ? q[i].curv_end : q[i].curv_start;
            }
            const std::size_t j = at_end ? i + 1 : i - 1;
            if (q[j].kind == PrimitiveKind::arc) {
                return v[arc_var_[j]];
            }
            return at_end ? q[i].curv_end : q[i].curv_start;
        };
        for (std::size_t i = 0; i < q.size(); ++i) {
            const double l = v[3 + i];
            if (q[i].kind == PrimitiveKind::line) {
                a.primitives.push_back(geometry::make_line(l));
            } else if (q[i].kind == PrimitiveKind::arc) {
                a.primitives.push_back(geometry::make_arc(l, v[arc_var_[i]]));
            } else {
                a.primitives.push_back(geometry::make_spiral(l, curvature_of(i, false), curvature_of(i, true)));
            }
        }
        return a;
    }

private:
    const Alignment& design_;
    std::vector<double> values_;
    std::vector<std::size_t> arc_var_;
};

std::vector<double> offsets(const Alignment& a, const std::vector<geometry::Point>& nodes,
                            const std::vector<double>& near_s) {
    const geometry::IndexedAlignment ia(a, 2.0);
    std::vector<double> out;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        out.push_back(ia.project_within(nodes[i].x, nodes[i].y, near_s[i] - 30.0, near_s[i] + 30.0).offset);
    }
    return out;
}

} // namespace

std::vector<double> arc_curvature_bounds(const truth::TruthRoute& route, double sigma) {
    const DesignParameters dp(route.design);
    std::vector<geometry::Point> nodes;
    std::vector<double> near_s;
    const geometry::IndexedAlignment truth(route.design, 2.0);
    for (std::size_t i = 0; i < route.nodes.size(); ++i) {
        if (!route.outlier[i]) {
            nodes.push_back(route.nodes[i]);
            near_s.push_back(truth.project(route.nodes[i].x, route.nodes[i].y).s);
        }
    }
    const std::vector<double>& v0 = dp.values();
    // The first element's length slides with the start along its heading,
    // the last one's runs past the last node: neither changes an offset.
    std::vector<std::size_t> free;
    for (std::size_t k = 0; k < v0.size(); ++k) {
        if (k != 3 && k != 2 + route.design.primitives.size()) {
            free.push_back(k);
        }
    }
    Eigen::MatrixXd j(static_cast<long>(nodes.size()), static_cast<long>(free.size()));
    for (std::size_t c = 0; c < free.size(); ++c) {
        const std::size_t k = free[c];
        const bool curvature = k >= 3 + route.design.primitives.size();
        const double h = k < 2 ? 1e-3 : (k == 2 ? 1e-6 : (curvature ? 1e-8 : 1e-3));
        std::vector<double> plus = v0, minus = v0;
        plus[k] += h;
        minus[k] -= h;
        const std::vector<double> a = offsets(dp.build(plus), nodes, near_s);
        const std::vector<double> b = offsets(dp.build(minus), nodes, near_s);
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            j(static_cast<long>(i), static_cast<long>(c)) = (a[i] - b[i]) / (2 * h);
        }
    }
    const Eigen::MatrixXd info = j.transpose() * j / (sigma * sigma);
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(info);
    if (ldlt.info() != Eigen::Success) {
        return {};
    }
    const Eigen::MatrixXd cov = ldlt.solve(Eigen::MatrixXd::Identity(info.rows(), info.cols()));
    std::vector<double> out;
    double s = 0.0;
    std::size_t next_arc = 0;
    for (std::size_t i = 0; i < route.design.primitives.size() && next_arc < route.arcs.size(); ++i) {
        const auto& p = route.design.primitives[i];
        if (p.kind == PrimitiveKind::arc && std::abs(s - route.arcs[next_arc].s0) < 1e-6) {
            const auto it = std::find(free.begin(), free.end(), dp.arc_parameter(i));
            const long k = static_cast<long>(it - free.begin());
            out.push_back(std::sqrt(cov(k, k)) / std::abs(p.curv_start));
            ++next_arc;
        }
        s += p.length;
    }
    return out;
}

} // namespace railodd::bench
