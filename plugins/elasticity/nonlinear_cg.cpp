// solve_nonlinear_cg: nonlinear CG with projected constraints (solve.hpp; thesis §2.4.2, §4.4
// and §6.6).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "solve.hpp"

namespace sxk::elasticity {

Outcome<NonlinearRelaxation> NonlinearRelaxation::start(ElasticBody& body,
                                                        const SolveOptions& options) {
    if (auto ready = detail::prepare_solve(body); !ready)
        return ready.refusal();
    NonlinearRelaxation relaxation(body, options);
    if (!relaxation.residual_at(0, relaxation.m_r)) {
        // prescribed displacements that turn the elements next to them inside out while the
        // free vertices are still where they were: start from the linear answer, which spreads
        // them over the body (its passes over the elements are counted as this solve's)
        auto linear = LinearRelaxation::start(body, options);
        if (!linear)
            return linear.refusal();
        linear->run(options.max_iterations);
        relaxation.m_report.evaluations += linear->report().evaluations;
        if (!relaxation.residual_at(0, relaxation.m_r))
            return Refusal{
                RefusalCode::would_invert,
                "elasticity: the prescribed displacements invert an element even in the "
                "linear answer, where the neo-Hookean energy is infinite; prescribe them in "
                "smaller steps"};
    }
    relaxation.m_report.threshold = detail::stop_threshold(body, options, relaxation.m_g);
    relaxation.m_rr = relaxation.m_r.squaredNorm();
    relaxation.m_report.history.push_back(std::sqrt(relaxation.m_rr));
    relaxation.m_d = relaxation.m_r;
    relaxation.run(0);
    return relaxation;
}

bool NonlinearRelaxation::residual_at(double alpha, Eigen::VectorXd& r) {
    const auto u = std::as_const(*m_body).displacements();
    ++m_report.evaluations;
    if (alpha != 0)
        m_trial = u + alpha * m_d;
    if (!(alpha != 0 ? m_body->elastic_forces(m_trial, m_g) : m_body->elastic_forces(u, m_g)))
        return false;
    r = m_body->forces() - m_g;
    m_body->project(r);
    return true;
}

// alpha with d . r(u + alpha d) = 0, by secant steps from 0 and a first guess from the stiffness
// at rest; the residual there is left in m_q. 0 when no step along d lowers the energy.
double NonlinearRelaxation::line_search() {
    const double slope = m_d.dot(m_r);  // -dPi/dalpha at 0: positive along a descent direction
    m_body->multiply(m_d, m_q);
    ++m_report.evaluations;
    m_body->project(m_q);
    const double curvature = m_d.dot(m_q);
    if (!(slope > 0) || !(curvature > 0))
        return 0;
    double previous = 0, previous_slope = slope;
    double alpha = slope / curvature;
    // a step that inverts an element is halved until it does not
    for (int halving = 0; !residual_at(alpha, m_q); ++halving) {
        if (halving == 60)
            return 0;
        alpha /= 2;
    }
    double current_slope = m_d.dot(m_q);
    for (std::size_t step = 0; step < m_options.line_search_steps; ++step) {
        if (std::abs(current_slope) <= m_options.line_search_tolerance * slope)
            break;
        const double denominator = previous_slope - current_slope;
        double next =
            denominator != 0 ? alpha + current_slope * (alpha - previous) / denominator : 2 * alpha;
        // keep the bracket sensible: positive, and no wild jumps on a curved slope
        if (!(next > 0) || !std::isfinite(next))
            next = alpha / 2;
        next = std::min(next, 4 * alpha);
        previous = alpha;
        previous_slope = current_slope;
        alpha = next;
        for (int halving = 0; !residual_at(alpha, m_q); ++halving) {
            if (halving == 60)
                return 0;
            alpha = (alpha + previous) / 2;  // back towards the last step that did not invert
        }
        current_slope = m_d.dot(m_q);
    }
    return alpha;
}

bool NonlinearRelaxation::run(std::size_t iterations) {
    const auto start = std::chrono::steady_clock::now();
    auto u = m_body->displacements();
    for (std::size_t i = 0; i < iterations && may_continue(); ++i) {
        if (!(m_d.dot(m_r) > 0))
            m_d = m_r;  // not a descent direction: restart along the residual
        const double alpha = line_search();
        if (!(alpha > 0)) {
            m_stalled = true;
            break;
        }
        u += alpha * m_d;  // m_q holds r(u) now
        ++m_report.iterations;
        m_report.threshold = detail::stop_threshold(*m_body, m_options, m_g);
        const double next = m_q.squaredNorm();
        const double beta = std::max(0.0, (next - m_q.dot(m_r)) / m_rr);  // Polak-Ribière, eq. 2.49
        m_r.swap(m_q);
        m_d = m_r + beta * m_d;
        m_rr = next;
        m_report.history.push_back(std::sqrt(m_rr));
    }
    return finish_run(start);
}

Outcome<SolveReport> solve_nonlinear_cg(ElasticBody& body, const SolveOptions& options) {
    return detail::solve_with<NonlinearRelaxation>(body, options);
}

}  // namespace sxk::elasticity
