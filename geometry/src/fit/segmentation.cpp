#include "segmentation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace railodd::geometry::fit {

namespace {

// Prefix sums of weighted moments, so any knot range is fitted in O(1).
class Moments {
public:
    Moments(const std::vector<double>& s, const std::vector<double>& k) : s_(s) {
        const std::size_t n = s.size();
        acc_.assign(n + 1, {});
        for (std::size_t i = 0; i < n; ++i) {
            // Every knot weighs the same: knots sit at mapped nodes, so a long
            // interval means sparse data, not more evidence.
            const double w = 1.0;
            const double x = s[i] - s[0];
            Sums a = acc_[i];
            a.w += w;
            a.wx += w * x;
            a.wxx += w * x * x;
            a.wk += w * k[i];
            a.wkk += w * k[i] * k[i];
            a.wxk += w * x * k[i];
            acc_[i + 1] = a;
        }
    }

    struct Fit {
        double sse;
        double a; // value at range start
        double b; // value at range end
    };

    // Weighted SSE of the best constant, of zero, and of the best line over knots [i, j].
    Fit constant(std::size_t i, std::size_t j) const {
        const Sums d = diff(i, j);
        const double c = d.w > 0 ? d.wk / d.w : 0.0;
        return {std::max(0.0, d.wkk - c * d.wk), c, c};
    }
    Fit zero(std::size_t i, std::size_t j) const { return {diff(i, j).wkk, 0.0, 0.0}; }
    Fit linear(std::size_t i, std::size_t j) const {
        const Sums d = diff(i, j);
        const double det = d.w * d.wxx - d.wx * d.wx;
        if (std::abs(det) < 1e-12 * std::max(1.0, d.w * d.wxx)) {
            return constant(i, j);
        }
        const double slope = (d.w * d.wxk - d.wx * d.wk) / det;
        const double icpt = (d.wk - slope * d.wx) / d.w;
        const double sse = d.wkk - 2 * icpt * d.wk - 2 * slope * d.wxk + icpt * icpt * d.w +
                           2 * icpt * slope * d.wx + slope * slope * d.wxx;
        const double x0 = s_[i] - s_[0], x1 = s_[j] - s_[0];
        return {std::max(0.0, sse), icpt + slope * x0, icpt + slope * x1};
    }

private:
    struct Sums {
        double w = 0, wx = 0, wxx = 0, wk = 0, wkk = 0, wxk = 0;
    };
    Sums diff(std::size_t i, std::size_t j) const {
        const Sums& a = acc_[j + 1];
        const Sums& b = acc_[i];
        return {a.w - b.w, a.wx - b.wx, a.wxx - b.wxx, a.wk - b.wk, a.wkk - b.wkk, a.wxk - b.wxk};
    }
    const std::vector<double>& s_;
    std::vector<Sums> acc_;
};

// The residual sums of a line, an arc and a transition over every knot range
// [i, j]: they depend on neither the noise scale nor the penalty, so one
// table serves every segmentation of a window (candidate_structures runs 24).
class RangeTable {
public:
    RangeTable(const Moments& m, std::size_t n) : sse_(n * (n - 1) / 2) {
        for (std::size_t j = 1; j < n; ++j) {
            for (std::size_t i = 0; i < j; ++i) {
                sse_[at(i, j)] = {m.zero(i, j).sse, m.constant(i, j).sse, m.linear(i, j).sse};
            }
        }
    }
    const std::array<double, 3>& operator()(std::size_t i, std::size_t j) const { return sse_[at(i, j)]; }

private:
    static std::size_t at(std::size_t i, std::size_t j) { return j * (j - 1) / 2 + i; }
    std::vector<std::array<double, 3>> sse_;
};

struct Choice {
    double cost = std::numeric_limits<double>::infinity();
    std::size_t from = 0;
    PieceKind kind = PieceKind::line;
};

// The cheapest piece over a range, from its residual sums: fewer parameters
// win ties.
Choice best_piece(const std::array<double, 3>& sse, double scale, double penalty) {
    const double c_line = sse[0] * scale + 0 * penalty;
    const double c_arc = sse[1] * scale + 1 * penalty;
    const double c_ramp = sse[2] * scale + 2 * penalty;
    if (c_line <= c_arc && c_line <= c_ramp) {
        return {c_line, 0, PieceKind::line};
    }
    if (c_arc <= c_ramp) {
        return {c_arc, 0, PieceKind::arc};
    }
    return {c_ramp, 0, PieceKind::ramp};
}

Piece piece_over(const Moments& m, const std::vector<double>& s, std::size_t i, std::size_t j, PieceKind kind) {
    const double length = s[j] - s[i];
    if (kind == PieceKind::line) {
        return {PieceKind::line, length, 0.0, 0.0};
    }
    if (kind == PieceKind::arc) {
        const double c = m.constant(i, j).a;
        return {PieceKind::arc, length, c, c};
    }
    const auto lin = m.linear(i, j);
    return {PieceKind::ramp, length, lin.a, lin.b};
}

} // namespace

struct CurvatureDiagram::Tables {
    Tables(const std::vector<double>& s, const std::vector<double>& k) : moments(s, k), ranges(moments, s.size()) {}
    Moments moments;
    RangeTable ranges;
};

CurvatureDiagram::CurvatureDiagram(const std::vector<double>& s, const std::vector<double>& k) : s_(s) {
    if (s.size() >= 2) {
        tables_ = std::make_unique<Tables>(s, k);
    }
}

CurvatureDiagram::~CurvatureDiagram() = default;

std::vector<Piece> CurvatureDiagram::segment(const SegmentationOptions& options) const {
    const std::size_t n = s_.size();
    if (!tables_) {
        return {};
    }
    const double scale = 1.0 / (options.curvature_sigma * options.curvature_sigma);
    // best[j]: cheapest split of knots [0, j] with a piece ending at knot j.
    std::vector<Choice> best(n);
    best[0].cost = 0.0;
    for (std::size_t j = 1; j < n; ++j) {
        for (std::size_t i = 0; i < j; ++i) {
            Choice c = best_piece(tables_->ranges(i, j), scale, options.penalty);
            c.cost += best[i].cost + options.penalty; // each boundary's position is a parameter too
            if (c.cost < best[j].cost) {
                c.from = i;
                best[j] = c;
            }
        }
    }
    std::vector<Piece> pieces;
    for (std::size_t j = n - 1; j > 0; j = best[j].from) {
        pieces.push_back(piece_over(tables_->moments, s_, best[j].from, j, best[j].kind));
    }
    std::reverse(pieces.begin(), pieces.end());
    return pieces;
}

std::vector<Piece> segment_curvature(const std::vector<double>& s, const std::vector<double>& k,
                                     const SegmentationOptions& options) {
    return CurvatureDiagram(s, k).segment(options);
}

namespace {

// Moving average of the knot curvatures over +-3 knots.
std::vector<double> smoothed(const std::vector<double>& k) {
    std::vector<double> out(k.size());
    for (std::size_t i = 0; i < k.size(); ++i) {
        const std::size_t lo = i >= 3 ? i - 3 : 0, hi = std::min(k.size() - 1, i + 3);
        double sum = 0.0;
        for (std::size_t j = lo; j <= hi; ++j) {
            sum += k[j];
        }
        out[i] = sum / static_cast<double>(hi - lo + 1);
    }
    return out;
}

struct Run {
    std::size_t first, last; // knot indices
    int sign;
};

std::vector<Run> curved_runs(const std::vector<double>& s, const std::vector<double>& ks) {
    constexpr double straight = 5e-5; // below: radius over 20 km, a straight to any railway
    std::vector<Run> runs;
    for (std::size_t i = 0; i < ks.size(); ++i) {
        const int sign = ks[i] > straight ? 1 : ks[i] < -straight ? -1 : 0;
        if (sign == 0) {
            continue;
        }
        if (!runs.empty() && runs.back().sign == sign && s[i] - s[runs.back().last] < 60.0) {
            runs.back().last = i;
        } else {
            runs.push_back({i, i, sign});
        }
    }
    std::erase_if(runs, [&](const Run& r) { return s[r.last] - s[r.first] < 20.0; });
    return runs;
}

} // namespace

std::vector<Piece> template_structure(const std::vector<double>& s, const std::vector<double>& k) {
    std::vector<Piece> pieces;
    if (s.size() < 2) {
        return pieces;
    }
    const std::vector<Run> runs = curved_runs(s, smoothed(k));
    double at = s.front();
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const double a = s[runs[r].first], b = s[runs[r].last];
        double sum = 0.0;
        std::size_t n = 0;
        for (std::size_t i = runs[r].first; i <= runs[r].last; ++i) {
            sum += k[i];
            ++n;
        }
        const double kappa = sum / static_cast<double>(n);
        const bool joined = !pieces.empty() && pieces.back().kind == PieceKind::ramp && a - at < 1e-9;
        if (a - at > 1e-9) {
            pieces.push_back({PieceKind::line, a - at, 0.0, 0.0});
        }
        const double len = b - a;
        const double prev = joined ? pieces.back().curv_end : 0.0;
        pieces.push_back({PieceKind::ramp, 0.2 * len, prev, kappa});
        pieces.push_back({PieceKind::arc, 0.6 * len, kappa, kappa});
        pieces.push_back({PieceKind::ramp, 0.2 * len, kappa, 0.0});
        at = b;
    }
    if (s.back() - at > 1e-9) {
        pieces.push_back({PieceKind::line, s.back() - at, 0.0, 0.0});
    }
    return pieces;
}

} // namespace railodd::geometry::fit
