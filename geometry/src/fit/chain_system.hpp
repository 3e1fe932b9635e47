#pragma once
// The Jacobian of a chain of clothoid segments in state-space form, and its
// damped normal equations solved in time linear in the segments.
//
// A parameter of segments [a, b] moves the points of those segments by its
// own derivative and every point beyond b rigidly: its rigid motion (a
// twist: rotation w and translation t, a point q moving by t + w x q) adds
// to the twist T all later segments carry. So a row of segment j depends
// on T_j, on the curvature variable at knot j, on the arc length S_j to
// knot j (held knots) and on the segment's own length and new end
// curvature: a linear-quadratic control problem with state (T, kappa, S)
// and two controls per segment, whose damped Gauss-Newton step a Riccati
// recursion solves exactly (Wright 1990, "Solution of discrete-time
// optimal control problems on parallel computers"). The dense normal
// equations cost the parameters cubed (a 512 km chain: 29 s of its 42 s
// fit).
#include <Eigen/Dense>

#include <array>
#include <vector>

namespace railodd::geometry::fit {

// A factored damped normal matrix A: solves A X = B.
class NormalMatrix {
public:
    virtual ~NormalMatrix() = default;
    virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const = 0;
};

class DenseNormal final : public NormalMatrix {
public:
    explicit DenseNormal(const Eigen::MatrixXd& A) : ldlt_(A) {}
    Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override {
        if (B.cols() == 1) {
            // By the vector solve: a matrix one is blocked otherwise and
            // rounds otherwise.
            const Eigen::VectorXd b = B.col(0);
            return Eigen::VectorXd(ldlt_.solve(b));
        }
        return ldlt_.solve(B);
    }

private:
    Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

// Slots of a row: the state (twist w, tx, ty; curvature variable at the
// segment's first knot; arc length to it), then the controls (the
// segment's length; the curvature variable new at its end knot).
constexpr int chain_states = 5;
constexpr int chain_controls = 2;
constexpr int chain_slots = chain_states + chain_controls;
using ChainRowCoefficients = Eigen::Matrix<double, chain_slots, 1>;

struct ChainRow {
    std::size_t stage = 0; // segment; segments() for a row of the end state only
    ChainRowCoefficients c = ChainRowCoefficients::Zero();
};

struct ChainStage {
    long length = -1;           // parameter index of the segment's length (-1: fixed)
    long fresh = -1;            // of the curvature variable new at its end knot
    long carried = -1;          // of the variable at its start knot (the state's curvature)
    bool carried_on = false;    // the end knot's variable is the start knot's
    bool carried_ends = false;  // the start knot's variable moves later segments only rigidly
    bool fresh_ends = false;    // likewise the new one (the chain's last segment)
    Eigen::Vector3d w_length = Eigen::Vector3d::Zero();
    Eigen::Vector3d w_carried = Eigen::Vector3d::Zero();
    Eigen::Vector3d w_fresh = Eigen::Vector3d::Zero();
};

struct ChainJacobian {
    std::size_t parameters = 0;
    std::vector<ChainStage> stages; // one per segment
    std::vector<ChainRow> rows;     // in the residual vector's order
    std::array<long, 3> start{-1, -1, -1};                  // start x, y, heading parameters
    Eigen::Matrix3d start_twist = Eigen::Matrix3d::Zero(); // their twists, a column each
    long first_curvature = -1;                              // the variable at knot 0

    std::size_t segments() const noexcept { return stages.size(); }
    bool start_free() const noexcept { return start[0] >= 0; }
};

// J^T J + D for a chain's Jacobian, D diagonal, factored by the Riccati
// recursion; J v and J^T y by one pass each.
class ChainSystem final : public NormalMatrix {
public:
    explicit ChainSystem(const ChainJacobian& j);
    // The diagonal of J^T J.
    const Eigen::VectorXd& diagonal() const noexcept { return diagonal_; }
    void factor(const Eigen::VectorXd& damping);
    Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override;
    Eigen::VectorXd times(const Eigen::VectorXd& v) const;
    Eigen::VectorXd transpose_times(const Eigen::VectorXd& y) const;

private:
    using State = Eigen::Matrix<double, chain_states, 1>;
    using StateMatrix = Eigen::Matrix<double, chain_states, chain_states>;
    using ControlGain = Eigen::Matrix<double, chain_controls, chain_states>;
    using Slots = Eigen::Matrix<double, chain_slots, chain_slots>;
    struct Step {
        StateMatrix A;
        Eigen::Matrix<double, chain_states, chain_controls> B;
        ControlGain K;                                   // u = K x + k
        Eigen::Matrix<double, chain_controls, chain_states> Qux;
        Eigen::LLT<Eigen::Matrix<double, chain_controls, chain_controls>> Quu;
    };

    void transitions();
    void diagonal_of_normal();
    Eigen::VectorXd solve_one(const Eigen::VectorXd& b) const;
    double damping_at(long parameter) const;

    const ChainJacobian& j_;
    std::vector<Slots> gram_; // per stage (segments + 1), the rows' J^T J over the slots
    std::vector<Step> steps_;
    Eigen::VectorXd diagonal_;
    Eigen::VectorXd damping_;
    Eigen::Matrix3d start_inverse_ = Eigen::Matrix3d::Identity();
    Eigen::LDLT<StateMatrix> initial_;
};

} // namespace railodd::geometry::fit
