// solve_linear_cg: matrix-free linear CG with projected constraints (solve.hpp; thesis §2.4.1,
// §3.1 and §6.6), with what both relaxations share (detail::Relaxation) and solve(), the
// solver by model.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "solve.hpp"

namespace sxk::elasticity {

namespace {

// ||(I - P)(K u - f)||: the forces that hold the constrained vertices.
double reaction_norm(const ElasticBody& body, const Eigen::VectorXd& ku) {
    Eigen::VectorXd gradient = ku - body.forces();
    Eigen::VectorXd allowed = gradient;
    body.project(allowed);
    return (gradient - allowed).norm();
}

}  // namespace

namespace detail {

double stop_threshold(const ElasticBody& body, const SolveOptions& options,
                      const Eigen::VectorXd& ku) {
    const double external = body.forces().norm();
    const double reaction = options.stop == StopCriterion::external_force ? 0 : reaction_norm(body, ku);
    return threshold_of(body, options, external, reaction);
}

double threshold_of(const ElasticBody& body, const SolveOptions& options, double external, double reaction) {
    if (options.stop == StopCriterion::external_force)
        return options.tolerance * external;
    const double n = static_cast<double>(std::max<std::size_t>(body.dof_count(), 1));
    // the force scale E * area: d H for a slab of thickness d (eq. 6.9 as printed for 2D), H^2 in
    // space (the thesis' suggestion for 3D)
    const double h = body.diameter();
    const double area = body.dimension() == 2 ? body.thickness() * h : h * h;
    return options.tolerance * std::sqrt(external * external + reaction * reaction) +
           body.largest_young() * area * options.rounding / std::sqrt(n);
}

Outcome<Done> prepare_solve(ElasticBody& body) {
    if (body.constrained_count() == 0)
        return Refusal{
            RefusalCode::bad_argument,
            "elasticity: no vertex is constrained, so the body can move freely and its stiffness "
            "matrix is "
            "singular; fix at least three non-collinear vertices of every connected part"};
    if (auto fresh = body.refresh(); !fresh)
        return fresh;
    return check_loads(body.forces().norm());
}

Outcome<Done> check_loads(double norm) {
    if (std::isfinite(norm))
        return Done{};
    return Refusal{RefusalCode::bad_argument,
                   "elasticity: the loads are too large: their norm overflows a double, so no residual can be "
                   "measured against them; scale the loads, or the units, down"};
}

Outcome<Done> check_finite(const SolveReport& report) {
    if (std::isfinite(report.residual) && std::isfinite(report.threshold))
        return Done{};
    std::ostringstream why;
    why << "elasticity: the residual is not finite after " << report.iterations << " iterations (|r| = "
        << report.residual << ", needed " << report.threshold
        << "): the loads or the prescribed displacements are too large for double precision; scale them, or the "
           "units, down";
    return Refusal{RefusalCode::bad_argument, why.str()};
}

}  // namespace detail

Outcome<LinearRelaxation> LinearRelaxation::start(ElasticBody& body, const SolveOptions& options) {
    if (auto ready = detail::prepare_solve(body); !ready)
        return ready.refusal();
    LinearRelaxation relaxation(body, options);
    relaxation.residual();
    relaxation.m_rr = relaxation.m_r.squaredNorm();
    relaxation.m_report.history.push_back(std::sqrt(relaxation.m_rr));
    relaxation.m_d = relaxation.m_r;
    relaxation.run(0);  // residual and converged of the start
    return relaxation;
}

// r = P(f - K u): the steepest descent of the energy within the allowed motions; the reactions of
// eq. 6.9 change with u, so the threshold follows each fresh residual.
void LinearRelaxation::residual() {
    m_body->multiply(m_body->displacements(), m_ku);
    ++m_report.evaluations;
    m_r = m_body->forces() - m_ku;
    m_body->project(m_r);
    m_report.threshold = detail::stop_threshold(*m_body, m_options, m_ku);
}

bool LinearRelaxation::run(std::size_t iterations) {
    const auto start = std::chrono::steady_clock::now();
    auto multiply = [this](const Eigen::VectorXd& d, Eigen::VectorXd& q) {
        m_body->multiply(d, q);
        ++m_report.evaluations;
    };
    auto project = [this](Eigen::VectorXd& q) { m_body->project(q); };
    auto fresh = [this] { residual(); };
    for (std::size_t i = 0; i < iterations && may_continue(); ++i) {
        if (!detail::cg_iteration(m_body->displacements(), m_r, m_d, m_q, m_rr, m_report.iterations,
                                  m_options.recompute_every, multiply, project, fresh)) {
            m_stalled = true;  // d = 0 (exact solution), or K not positive on d
            break;
        }
        m_report.history.push_back(std::sqrt(m_rr));
    }
    return finish_run(start);
}

namespace detail {

bool Relaxation::finish_run(std::chrono::steady_clock::time_point start) {
    m_report.residual = std::sqrt(m_rr);
    m_report.converged = reached(m_report.residual, m_report.threshold);
    m_report.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return m_report.converged;
}

bool Relaxation::done() const {
    return m_report.converged || m_stalled || m_report.iterations >= m_options.max_iterations;
}

SolveReport Relaxation::report() const {
    SolveReport report = m_report;
    report.energy = m_body->energy();
    return report;
}

}  // namespace detail

Outcome<SolveReport> solve(ElasticBody& body, const SolveOptions& options) {
    return body.model() == Model::linear ? solve_linear_cg(body, options)
                                         : solve_nonlinear_cg(body, options);
}

Outcome<SolveReport> solve_linear_cg(ElasticBody& body, const SolveOptions& options) {
    return detail::solve_with<LinearRelaxation>(body, options);
}

}  // namespace sxk::elasticity
