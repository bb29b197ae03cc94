// solve_linear_cg: matrix-free linear CG with projected constraints (solve.hpp; thesis §2.4.1,
// §3.1 and §6.6).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "solve.hpp"

namespace sxk::elasticity {

namespace detail {

double reaction_norm(const ElasticBody& body, const Eigen::VectorXd& ku) {
    Eigen::VectorXd gradient = ku - body.forces();
    Eigen::VectorXd allowed = gradient;
    body.project(allowed);
    return (gradient - allowed).norm();
}

double stop_threshold(const ElasticBody& body, const SolveOptions& options, double reaction) {
    const double external = body.forces().norm();
    if (options.stop == StopCriterion::external_force) return options.tolerance * external;
    const double n = static_cast<double>(std::max<std::size_t>(body.dof_count(), 1));
    const double h = body.diameter();
    return options.tolerance * std::sqrt(external * external + reaction * reaction) +
           body.material().young * h * h * options.rounding / std::sqrt(n);
}

Outcome<Done> prepare_solve(ElasticBody& body) {
    if (body.constrained_count() == 0)
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: no vertex is constrained, so the body can move freely and its stiffness matrix is "
                       "singular; fix at least three non-collinear vertices of every connected part"};
    return body.refresh();
}

}  // namespace detail

Outcome<SolveReport> solve_linear_cg(ElasticBody& body, const SolveOptions& options) {
    if (auto ready = detail::prepare_solve(body); !ready) return ready.refusal();
    const auto start = std::chrono::steady_clock::now();
    SolveReport report;
    Eigen::VectorXd& u = body.displacements();
    Eigen::VectorXd ku, r, d, q;
    // r = P(f - K u): the steepest descent of the energy within the allowed motions; the
    // reactions of eq. 6.9 change with u, so the threshold follows each fresh residual
    auto residual = [&] {
        body.multiply(u, ku);
        r = body.forces() - ku;
        body.project(r);
        report.threshold = detail::stop_threshold(body, options, detail::reaction_norm(body, ku));
    };
    residual();
    double rr = r.squaredNorm();
    report.history.push_back(std::sqrt(rr));
    d = r;
    while (std::sqrt(rr) > report.threshold && report.iterations < options.max_iterations) {
        body.multiply(d, q);
        body.project(q);  // P K P: d is already in the allowed space
        const double dq = d.dot(q);
        if (!(dq > 0)) break;  // d = 0 (exact solution), or K not positive on d: no progress possible
        const double alpha = rr / dq;
        u += alpha * d;
        ++report.iterations;
        if (options.recompute_every > 0 && report.iterations % options.recompute_every == 0) {
            residual();
        } else {
            r -= alpha * q;
        }
        const double next = r.squaredNorm();
        d = r + (next / rr) * d;
        rr = next;
        report.history.push_back(std::sqrt(rr));
    }
    report.residual = std::sqrt(rr);
    report.converged = report.residual <= report.threshold;
    report.energy = body.energy();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace sxk::elasticity
