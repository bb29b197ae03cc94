// Static solves of an ElasticBody (elastic_body.hpp): the matrix-free linear conjugate gradient
// of thesis §2.4.1 and §3.1 and the nonlinear CG of §2.4.2 (for neo-Hookean bodies) with the
// constraints projected out (§6.6), and the assembled reference (Eigen's sparse matrix and its
// ConjugateGradient) that tests and benchmarks compare the linear one with.
#pragma once

#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "elastic_body.hpp"

namespace sxk::elasticity {

enum class StopCriterion {
    // ||r|| <= tolerance * ||f_ex|| (eq. 6.8, the thesis' chapters 3 and 4). Never met when the
    // loads are zero and only displacements are prescribed: use with_reactions then.
    external_force,
    // ||r|| <= tolerance * sqrt(||f_ex||^2 + ||f_react||^2) + E A rounding / sqrt(n) (eq. 6.9:
    // A = d H for a slab of thickness d in the plane, the 3D area term H^2 in space; H the body's
    // diameter, n the number of unknowns), f_react the forces that hold the constrained vertices.
    with_reactions,
};

struct SolveOptions {
    double tolerance = 1e-3;
    std::size_t max_iterations = 100000;
    StopCriterion stop = StopCriterion::with_reactions;
    double rounding = 1e-12;           // epsilon_round of eq. 6.9 (the thesis' needle runs: 1e-8)
    std::size_t recompute_every = 50;  // r = P(f - K u) afresh every so many steps (drift)
    // Nonlinear CG: the line search along d stops when |d . r(u + alpha d)| <= this times
    // |d . r(u)| (the thesis' epsilon_newton, §4.5: 0.1 worked best), or after
    // line_search_steps secant steps.
    double line_search_tolerance = 0.1;
    std::size_t line_search_steps = 20;
};

struct SolveReport {
    std::size_t iterations =
        0;  // CG steps (linear: matrix-vector products after the first residual)
    // passes over the elements (products or force evaluations), the first residual's included
    std::size_t evaluations = 0;
    bool converged = false;
    double residual = 0;          // ||r|| at the end (r projected onto the allowed motions)
    double threshold = 0;         // what ||r|| had to reach
    std::vector<double> history;  // ||r|| before each iteration and at the end
    double seconds = 0;           // in the solver (LinearRelaxation: in run, summed over its calls)
    double energy = 0;            // the potential energy at the end (ElasticBody::energy)
};

// Minimises the potential energy over the displacements the constraints allow, by linear CG
// from the body's current displacements (a warm start; constrained vertices keep their
// prescribed values). A body without any constrained vertex is refused (bad_argument): its
// stiffness matrix is singular. Not converging within max_iterations is not a refusal: the
// report says converged = false and the body holds the last iterate. Loads whose norm overflows,
// and a residual or threshold that is not finite at the end, are refused (bad_argument:
// detail::check_loads, detail::check_finite).
Outcome<SolveReport> solve_linear_cg(ElasticBody& body, const SolveOptions& options = {});

namespace detail {
// Whether |r| = `residual` meets `threshold`: both finite and |r| <= threshold. A comparison of
// infinities (inf <= inf) or with NaN proves nothing about the solution.
inline bool reached(double residual, double threshold) {
    return std::isfinite(residual) && std::isfinite(threshold) && residual <= threshold;
}
// The loads' norm `norm` (the whole body's, or a local solve's region's) is finite: prepare_solve's
// last check, refused as it says.
Outcome<Done> check_loads(double norm);
// A solve's arithmetic stayed finite: the report's residual and threshold are finite numbers.
// Otherwise the loads or the prescribed displacements were too large for doubles (K u or the
// reactions overflowed), and the displacements are not a solution: refused (bad_argument) with
// the iterations and both numbers.
Outcome<Done> check_finite(const SolveReport& report);

// What the linear and the nonlinear relaxation share: the body, the options, the report so far,
// and when they are done.
class Relaxation {
public:
    // Converged, out of iterations (max_iterations), or unable to progress.
    bool done() const;
    // Iterations, residual, threshold and history so far; the energy of the current displacements.
    SolveReport report() const;

protected:
    Relaxation(ElasticBody& body, const SolveOptions& options)
        : m_body(&body), m_options(options) {}
    // Not converged, not stalled, and iterations left: run() takes another step.
    bool may_continue() const {
        return !m_stalled && std::sqrt(m_rr) > m_report.threshold &&
               m_report.iterations < m_options.max_iterations;
    }
    // The end of a run() that began at `start`: the residual, converged and the time; converged.
    bool finish_run(std::chrono::steady_clock::time_point start);

    ElasticBody* m_body;
    SolveOptions m_options;
    SolveReport m_report;
    double m_rr = 0;  // ||r||^2
    bool m_stalled = false;
};

// R::start, then R::run(max_iterations); the report's time is the whole solve's.
template <class R>
Outcome<SolveReport> solve_with(ElasticBody& body, const SolveOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    auto relaxation = R::start(body, options);
    if (!relaxation)
        return relaxation.refusal();
    relaxation->run(options.max_iterations);
    SolveReport report = relaxation->report();
    if (auto finite = check_finite(report); !finite)
        return finite.refusal();
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}
}  // namespace detail

// The same CG a few iterations at a time, as the thesis interleaves relaxation with rendering
// (§3.3: "the course of the CG iteration is visualized during the simulation"): an application
// starts it, runs a bounded number of iterations per frame, shows the displacements in between
// (write_deformed), and starts again when loads, constraints or the mesh change (§3.3: "at every
// change in forces or boundary conditions, the CG iteration is restarted"). solve_linear_cg is
// start + run(max_iterations). The body must outlive the relaxation and must not be edited or
// re-constrained while it runs.
class LinearRelaxation : public detail::Relaxation {
public:
    // From the body's current displacements; refuses as solve_linear_cg.
    static Outcome<LinearRelaxation> start(ElasticBody& body, const SolveOptions& options = {});
    // At most `iterations` more CG iterations (none when done()); true when converged.
    bool run(std::size_t iterations);

private:
    LinearRelaxation(ElasticBody& body, const SolveOptions& options) : Relaxation(body, options) {}
    void residual();

    Eigen::VectorXd m_ku, m_r, m_d, m_q;
};

// Minimises the potential energy of a body of any model (neo-Hookean: strain energy of eq. 4.6
// minus f^T u) by nonlinear CG (§2.4.2): Polak-Ribière directions (eq. 2.49) restarted when they
// stop descending, a secant line search on d . r (the thesis' Newton search without the tangent
// stiffness; the first step from the stiffness at rest), steps that would invert an element
// halved. When the starting displacements invert an element (a large prescribed displacement
// next to free vertices still at rest), it starts from the linear CG's answer instead. Refuses
// as solve_linear_cg, and with would_invert when even that inverts an element. For a linear body it
// finds what solve_linear_cg finds, in about twice the passes over the elements.
Outcome<SolveReport> solve_nonlinear_cg(ElasticBody& body, const SolveOptions& options = {});

// The same a few iterations at a time (see LinearRelaxation).
class NonlinearRelaxation : public detail::Relaxation {
public:
    static Outcome<NonlinearRelaxation> start(ElasticBody& body, const SolveOptions& options = {});
    bool run(std::size_t iterations);

private:
    NonlinearRelaxation(ElasticBody& body, const SolveOptions& options)
        : Relaxation(body, options) {}
    // r = P(f - g(u)) at u + alpha d; false when that inverts an element
    bool residual_at(double alpha, Eigen::VectorXd& r);
    double line_search();

    Eigen::VectorXd m_r, m_d, m_trial, m_g, m_q;
};

// The solver of the body's model: solve_linear_cg for linear bodies, solve_nonlinear_cg else.
Outcome<SolveReport> solve(ElasticBody& body, const SolveOptions& options = {});

// K as an Eigen sparse matrix (3 rows and columns per vertex), summed from element_stiffness.
Eigen::SparseMatrix<double> assemble_stiffness(const ElasticBody& body);

// The same problem solved with the assembled K reduced to the allowed motions (B^T K B, B the
// basis of the free and line motions) and Eigen's ConjugateGradient (diagonal preconditioner),
// stopped at the same threshold as solve_linear_cg. The reference of the tests and the benchmarks.
Outcome<SolveReport> solve_assembled_cg(ElasticBody& body, const SolveOptions& options = {});

namespace detail {
// One iteration of projected, preconditioned linear CG (thesis §2.4.1 with the constraints of
// §6.6), shared by LinearRelaxation (the whole body, unpreconditioned: cg_iteration below) and
// LocalRelaxation (a region, block Jacobi): u the unknowns, r = P(f - K u) the residual, d the
// direction (in the allowed space), rr = |r|^2, rz = r^T z with z = precondition(r) (a reference
// to z, in the allowed space: P M^-1 P r; r itself for none). multiply(d, q) sets q = K d,
// project(q) projects q in place, residual() recomputes r afresh (every recompute_every
// iterations, against drift). False, nothing changed, when d^T K d is not positive (d = 0, or K
// not positive on d): no progress is possible.
template <class Unknowns, class Multiply, class Project, class Residual, class Precondition>
bool preconditioned_cg_iteration(Unknowns&& u, Eigen::VectorXd& r, Eigen::VectorXd& d, Eigen::VectorXd& q,
                                 double& rr, double& rz, std::size_t& iterations, std::size_t recompute_every,
                                 const Multiply& multiply, const Project& project, const Residual& residual,
                                 const Precondition& precondition) {
    multiply(d, q);
    project(q);  // P K P: d is already in the allowed space
    const double dq = d.dot(q);
    if (!(dq > 0)) return false;
    const double alpha = rz / dq;
    u += alpha * d;
    ++iterations;
    if (recompute_every > 0 && iterations % recompute_every == 0)
        residual();
    else
        r -= alpha * q;
    rr = r.squaredNorm();
    const Eigen::VectorXd& z = precondition(r);
    const double next = &z == &r ? rr : r.dot(z);
    d = z + (next / rz) * d;
    rz = next;
    return true;
}

// The same without a preconditioner (z = r, rz = rr).
template <class Unknowns, class Multiply, class Project, class Residual>
bool cg_iteration(Unknowns&& u, Eigen::VectorXd& r, Eigen::VectorXd& d, Eigen::VectorXd& q, double& rr,
                  std::size_t& iterations, std::size_t recompute_every, const Multiply& multiply,
                  const Project& project, const Residual& residual) {
    double rz = rr;
    return preconditioned_cg_iteration(u, r, d, q, rr, rz, iterations, recompute_every, multiply, project, residual,
                                       [](const Eigen::VectorXd& x) -> const Eigen::VectorXd& { return x; });
}

// What both solvers check first: some vertex is constrained (else bad_argument: K is singular),
// the body is in step with its mesh (ElasticBody::refresh), and the loads have a finite norm
// (else bad_argument: a load of 1e200 shared by 81 vertices is finite at every vertex, but |f|
// overflows, the stop threshold is inf, and "|r| <= threshold" held at once with |r| = inf:
// issue 47 saw "CG: 0 iterations, |r| inf <= inf" and the input written back unchanged).
Outcome<Done> prepare_solve(ElasticBody& body);
// The stop threshold of `options` in the current state, the elastic forces (K u) being `ku` (the
// reactions are computed only for the criterion that uses them).
double stop_threshold(const ElasticBody& body, const SolveOptions& options,
                      const Eigen::VectorXd& ku);
// The same from the norms of the loads and of the reactions (a local solve's, over its region).
double threshold_of(const ElasticBody& body, const SolveOptions& options, double external, double reaction);
}  // namespace detail

}  // namespace sxk::elasticity
