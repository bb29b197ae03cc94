// Static solves of an ElasticBody (elastic_body.hpp): the matrix-free conjugate gradient of
// thesis §2.4.1 and §3.1 with the constraints projected out (§6.6), and the assembled reference
// (Eigen's sparse matrix and its ConjugateGradient) that tests and benchmarks compare it with.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "elastic_body.hpp"

namespace sxk::elasticity {

enum class StopCriterion {
    // ||r|| <= tolerance * ||f_ex|| (eq. 6.8, the thesis' chapters 3 and 4). Never met when the
    // loads are zero and only displacements are prescribed: use with_reactions then.
    external_force,
    // ||r|| <= tolerance * sqrt(||f_ex||^2 + ||f_react||^2) + E H^2 rounding / sqrt(n) (eq. 6.9
    // with the 3D area term H^2, H the body's diameter, n the number of unknowns), f_react the
    // forces that hold the constrained vertices.
    with_reactions,
};

struct SolveOptions {
    double tolerance = 1e-3;
    std::size_t max_iterations = 100000;
    StopCriterion stop = StopCriterion::with_reactions;
    double rounding = 1e-12;      // epsilon_round of eq. 6.9
    std::size_t recompute_every = 50;  // r = P(f - K u) afresh every so many steps (drift)
};

struct SolveReport {
    std::size_t iterations = 0;  // matrix-vector products after the first residual
    bool converged = false;
    double residual = 0;   // ||r|| at the end (r projected onto the allowed motions)
    double threshold = 0;  // what ||r|| had to reach
    std::vector<double> history;  // ||r|| before each iteration and at the end
    double seconds = 0;  // in the solver (LinearRelaxation: in run, summed over its calls)
    double energy = 0;  // 1/2 u^T K u - f^T u at the end
};

// Minimises the potential energy over the displacements the constraints allow, by linear CG
// from the body's current displacements (a warm start; constrained vertices keep their
// prescribed values). A body without any constrained vertex is refused (bad_argument): its
// stiffness matrix is singular. Not converging within max_iterations is not a refusal: the
// report says converged = false and the body holds the last iterate.
Outcome<SolveReport> solve_linear_cg(ElasticBody& body, const SolveOptions& options = {});

// The same CG a few iterations at a time, as the thesis interleaves relaxation with rendering
// (§3.3: "the course of the CG iteration is visualized during the simulation"): an application
// starts it, runs a bounded number of iterations per frame, shows the displacements in between
// (write_deformed), and starts again when loads, constraints or the mesh change (§3.3: "at every
// change in forces or boundary conditions, the CG iteration is restarted"). solve_linear_cg is
// start + run(max_iterations). The body must outlive the relaxation and must not be edited or
// re-constrained while it runs.
class LinearRelaxation {
public:
    // From the body's current displacements; refuses as solve_linear_cg.
    static Outcome<LinearRelaxation> start(ElasticBody& body, const SolveOptions& options = {});
    // At most `iterations` more CG iterations (none when done()); true when converged.
    bool run(std::size_t iterations);
    // Converged, out of iterations (max_iterations), or unable to progress.
    bool done() const;
    // Iterations, residual, threshold and history so far; the energy of the current displacements.
    SolveReport report() const;

private:
    LinearRelaxation(ElasticBody& body, const SolveOptions& options) : m_body(&body), m_options(options) {}
    void residual();

    ElasticBody* m_body;
    SolveOptions m_options;
    SolveReport m_report;
    Eigen::VectorXd m_ku, m_r, m_d, m_q;
    double m_rr = 0;
    bool m_stalled = false;
};

// K as an Eigen sparse matrix (3 rows and columns per vertex), summed from element_stiffness.
Eigen::SparseMatrix<double> assemble_stiffness(const ElasticBody& body);

// The same problem solved with the assembled K reduced to the allowed motions (B^T K B, B the
// basis of the free and line motions) and Eigen's ConjugateGradient (diagonal preconditioner),
// stopped at the same threshold as solve_linear_cg. The reference of the tests and the benchmarks.
Outcome<SolveReport> solve_assembled_cg(ElasticBody& body, const SolveOptions& options = {});

namespace detail {
// What both solvers check first: some vertex is constrained (else bad_argument: K is singular),
// and the body is in step with its mesh (ElasticBody::refresh).
Outcome<Done> prepare_solve(ElasticBody& body);
// The stop threshold of `options` in the current state, K u being `ku` (the reactions are
// computed only for the criterion that uses them).
double stop_threshold(const ElasticBody& body, const SolveOptions& options, const Eigen::VectorXd& ku);
}  // namespace detail

}  // namespace sxk::elasticity
