// A chain's Jacobian in state-space form (chain_system.hpp, residuals.hpp).
#include "chain_linearise.hpp"

#include "end_constraint.hpp"
#include "residual_rows.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

namespace {

// The rigid motion taking pose `from` to `to`, per unit of h, as a twist
// about `o`: a point q moves by (t_x - w q_y, t_y + w q_x), q from o.
Eigen::Vector3d twist(const Pose& from, const Pose& to, const Point2& o, double h) {
    const double w = to.hdg - from.hdg;
    return Eigen::Vector3d(w, to.x - from.x + w * (from.y - o.y), to.y - from.y - w * (from.x - o.x)) / h;
}

// A row's coefficients on the twist: the residual wt (p - c) . d of a
// point whose curve point c moves rigidly.
Eigen::Vector3d rigid_row(double wt, const Foot& f, double dx, double dy, const Point2& o) {
    const double qx = f.cx - o.x, qy = f.cy - o.y;
    return -wt * Eigen::Vector3d(dy * qx - dx * qy, dx, dy);
}

// Which parameter each length and curvature variable is.
struct Parameters {
    std::vector<long> length, variable;
};

Parameters parameters_of(const CurvatureModel& m, const ParameterMap& map, ChainJacobian& J) {
    Parameters out{std::vector<long>(m.segments(), -1), std::vector<long>(m.curv.size(), -1)};
    for (std::size_t i = 0; i < map.size(); ++i) {
        if (map.is_start(i)) {
            J.start[map.index(i)] = static_cast<long>(i);
        } else if (map.is_length(i)) {
            out.length[map.index(i)] = static_cast<long>(i);
        } else {
            out.variable[map.index(i)] = static_cast<long>(i);
        }
    }
    return out;
}

void fill_stages(const CurvatureModel& m, const ParameterMap& map, const Parameters& ps, ChainJacobian& J) {
    const auto var = [&](std::size_t k) { return m.knot_var[k] >= 0 ? ps.variable[static_cast<std::size_t>(m.knot_var[k])] : -1L; };
    J.first_curvature = var(0);
    J.stages.resize(m.segments());
    for (std::size_t s = 0; s < m.segments(); ++s) {
        ChainStage& st = J.stages[s];
        st.length = ps.length[s];
        st.carried = var(s);
        st.carried_on = st.carried >= 0 && var(s + 1) == st.carried;
        st.fresh = var(s + 1) >= 0 && var(s + 1) != st.carried ? var(s + 1) : -1;
        const auto ends = [&](long p) { return p >= 0 && map.influence(static_cast<std::size_t>(p)).second == s; };
        st.carried_ends = ends(st.carried);
        st.fresh_ends = ends(st.fresh);
    }
}

// The slot of parameter p in a row of stage s.
int slot_of(const ChainStage& st, long p) {
    return p == st.length ? chain_states : p == st.fresh ? chain_states + 1 : 3;
}

struct Rows {
    std::size_t pinned_first = 0, pinned_last = 0, transition = 0, guide = 0, knot = 0;
};

// The rows' layout (fill_residuals) and their parts on the state: the
// points' and pinned ends' rigid motion, the held knots' arc length.
Rows fill_rows(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet, const Point2& o,
               ChainJacobian& J) {
    const std::size_t n = feet.size(), segs = m.segments();
    Rows at;
    J.rows.assign(row_count(m, p), ChainRow{});
    const double w = 1.0 / p.opt.sigma_m;
    for (std::size_t i = 0; i < n; ++i) {
        const double wi = p.opt.point_scale.empty() ? w : w * p.opt.point_scale[i];
        J.rows[i].stage = feet[i].segment;
        J.rows[i].c.head<3>() = rigid_row(wi, feet[i], feet[i].nx, feet[i].ny, o);
    }
    std::size_t row = n;
    const auto along = [&](std::size_t i) {
        J.rows[row].stage = feet[i].segment;
        J.rows[row].c.head<3>() = rigid_row(w, feet[i], feet[i].tx, feet[i].ty, o);
        return row++;
    };
    at.pinned_first = p.opt.pin_first ? along(0) : 0;
    at.pinned_last = p.opt.pin_last ? along(n - 1) : 0;
    const auto block = [&](bool present, std::size_t count) {
        const std::size_t first = row;
        for (std::size_t k = 0; present && k < count; ++k) {
            J.rows[row++].stage = k;
        }
        return first;
    };
    at.transition = block(!p.opt.transition_prior.empty(), segs);
    at.guide = block(!p.opt.guide_weight.empty(), segs);
    at.knot = block(!p.opt.knot_weight.empty(), segs + 1);
    for (std::size_t k = 0; k < p.opt.knot_weight.size() && k <= segs; ++k) {
        J.rows[at.knot + k].c[4] = std::sqrt(std::max(0.0, p.opt.knot_weight[k]));
    }
    return at;
}

// Every parameter's own slot in the rows of its segments, by forward
// differences as the dense linearisation takes them, and the rigid motion
// it leaves beyond them (returned, per parameter).
std::vector<Eigen::Vector3d> fill_columns(const CurvatureModel& m, const ParameterMap& map, const Problem& p,
                                          const std::vector<Foot>& feet, const std::vector<Pose>& poses,
                                          const Eigen::VectorXd& r, const Rows& at, const Point2& o, ChainJacobian& J) {
    const std::vector<std::size_t> first_on = first_feet_on(feet, m.segments());
    const std::vector<double> base = map.get(m);
    std::vector<Pose> p2(poses.size());
    std::vector<Eigen::Vector3d> twists(map.size(), Eigen::Vector3d::Zero());
    CurvatureModel m2 = m;
    const double w = 1.0 / p.opt.sigma_m;
    for (std::size_t i = 0; i < map.size(); ++i) {
        if (map.is_start(i)) {
            twists[i] = J.start_twist.col(static_cast<long>(map.index(i)));
            continue;
        }
        const double h = map.difference_step(i);
        map.set_one(m2, i, base[i] + h);
        const auto [a, b] = map.influence(i);
        p2[a] = poses[a];
        for (std::size_t j = a; j <= b; ++j) {
            p2[j + 1] = evaluate(p2[j], m2.segment(j), m2.lengths[j]);
        }
        twists[i] = twist(poses[b + 1], p2[b + 1], o, h);
        const auto put = [&](std::size_t row, double value) {
            ChainRow& cr = J.rows[row];
            cr.c[slot_of(J.stages[cr.stage], static_cast<long>(i))] = (value - r[static_cast<long>(row)]) / h;
        };
        const auto moved = [&](std::size_t k, double wt, bool normal) {
            const Foot& f = feet[k];
            const Pose c = evaluate(p2[f.segment], m2.segment(f.segment), f.at_end ? m2.lengths[f.segment] : f.u);
            return wt * ((p.pts[k].x - c.x) * (normal ? f.nx : f.tx) + (p.pts[k].y - c.y) * (normal ? f.ny : f.ty));
        };
        for (std::size_t k = first_on[a]; k < first_on[b + 1]; ++k) {
            put(k, moved(k, p.opt.point_scale.empty() ? w : w * p.opt.point_scale[k], true));
        }
        if (p.opt.pin_first && feet.front().segment >= a && feet.front().segment <= b) {
            put(at.pinned_first, moved(0, w, false));
        }
        if (p.opt.pin_last && feet.back().segment >= a && feet.back().segment <= b) {
            put(at.pinned_last, moved(feet.size() - 1, w, false));
        }
        for (std::size_t j = a; j <= b; ++j) {
            if (!p.opt.transition_prior.empty()) {
                put(at.transition + j, transition_row(m2, p, j));
            }
            if (!p.opt.guide_weight.empty()) {
                put(at.guide + j, guide_row(m2, p, j));
            }
        }
        map.set_one(m2, i, base[i]);
    }
    return twists;
}

// The end gap's rows on the end state (twist about `origin`, curvature):
// the end pose moves rigidly with the twist.
void end_state_rows(const CurvatureModel& m, const Pose& end, const Point2& origin, Linearisation& lin) {
    const double ex = end.x - origin.x, ey = end.y - origin.y;
    lin.end_state = Eigen::MatrixXd::Zero(static_cast<long>(end_rows(m)), chain_states);
    lin.end_state.row(0) << -ey, 1, 0, 0, 0;
    lin.end_state.row(1) << ex, 0, 1, 0, 0;
    lin.end_state(2, 0) = end_heading_scale;
    if (lin.end_state.rows() == 4) {
        lin.end_state(3, 3) = end_curvature_scale;
    }
}

} // namespace

bool chain_form(const CurvatureModel& m, const Problem& p) {
    if (!p.opt.chain_solve || p.opt.kink_sigma > 0 || p.opt.ridge_sigma > 0 || m.segments() == 0) {
        return false;
    }
    // Every variable on one run of consecutive knots: only then does one
    // curvature cross each knot.
    for (std::size_t k = 2; k < m.knot_var.size(); ++k) {
        const int v = m.knot_var[k];
        if (v >= 0 && v != m.knot_var[k - 1] &&
            std::find(m.knot_var.begin(), m.knot_var.begin() + static_cast<long>(k) - 1, v) !=
                m.knot_var.begin() + static_cast<long>(k) - 1) {
            return false;
        }
    }
    return true;
}

void chain_linearise(const CurvatureModel& m, const ParameterMap& map, const Problem& p, const std::vector<Foot>& feet,
                     const std::vector<Pose>& poses, Linearisation& lin) {
    ChainJacobian J;
    J.parameters = map.size();
    const Point2 o{poses.front().x, poses.front().y};
    const Parameters ps = parameters_of(m, map, J);
    fill_stages(m, map, ps, J);
    // Start x and y move the curve, its heading turns it about the start.
    J.start_twist << 0, 0, 1, 1, 0, 0, 0, 1, 0;
    const Rows at = fill_rows(m, p, feet, o, J);
    const std::vector<Eigen::Vector3d> twists = fill_columns(m, map, p, feet, poses, lin.r, at, o, J);
    for (ChainStage& st : J.stages) {
        const auto of = [&](long q) { return q >= 0 ? twists[static_cast<std::size_t>(q)] : Eigen::Vector3d::Zero().eval(); };
        st.w_length = of(st.length);
        st.w_carried = of(st.carried);
        st.w_fresh = of(st.fresh);
    }
    if (p.opt.end) {
        end_state_rows(m, poses.back(), o, lin);
        const long last_var = m.knot_var.back() >= 0 ? ps.variable[static_cast<std::size_t>(m.knot_var.back())] : -1;
        lin.C = Eigen::MatrixXd::Zero(lin.c.size(), static_cast<long>(map.size()));
        for (std::size_t i = 0; i < map.size(); ++i) {
            Eigen::Matrix<double, chain_states, 1> y;
            y << twists[i], static_cast<long>(i) == last_var ? 1.0 : 0.0, 0.0;
            lin.C.col(static_cast<long>(i)) = lin.end_state * y;
        }
    }
    lin.chain = std::move(J);
}

} // namespace railodd::geometry::fit
