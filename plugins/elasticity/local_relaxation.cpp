// LocalRelaxation: projected linear CG over the region around some seed vertices, the rest of the
// body held (local_relaxation.hpp).
#include "local_relaxation.hpp"

#include <chrono>
#include <cmath>

#include "element_kernels.hpp"
#include "sxk/traversal.hpp"

namespace sxk::elasticity {

void LocalRelaxation::gather(const ElasticBody& body, std::span<const VertexId> seeds, std::size_t max_vertices) {
    const Mesh& mesh = body.mesh();
    m_vertices.clear();
    m_elements.clear();
    m_element_corners.clear();
    // grown with the mesh, never cleared whole: unmark() resets what a solve marked
    if (m_local.size() < body.vertex_count()) m_local.resize(body.vertex_count(), none);
    if (m_taken.size() < mesh.element_capacity()) m_taken.resize(mesh.element_capacity(), 0);
    auto add = [&](VertexId v) {
        m_local[v] = static_cast<std::uint32_t>(m_vertices.size());
        m_vertices.push_back(v);
    };
    for (const VertexId v : seeds)
        if (v < body.vertex_count() && mesh.vertex_element(v) != invalid_id && m_local[v] == none) add(v);
    // ring by ring: each region vertex's star, once, gives the region's elements (its rows of K
    // are whole) and its neighbours, which join the region while it has room and the rim after
    bool open = m_vertices.size() < max_vertices;
    m_region = m_vertices.size();
    std::vector<ElementId> around;
    for (std::size_t head = 0; head < m_region; ++head) {
        const VertexId v = m_vertices[head];
        around.clear();
        collect_star(mesh, v, mesh.vertex_element(v), around);
        for (const ElementId t : around) {
            if (m_taken[t]) continue;
            m_taken[t] = 1;
            m_elements.push_back(t);
            std::array<std::uint32_t, 4> local{none, none, none, none};
            for (std::size_t j = 0; j < 4; ++j) {
                const VertexId w = body.corners(t)[j];
                if (w == invalid_id) continue;
                if (m_local[w] == none) {
                    add(w);
                    if (open) m_region = m_vertices.size();
                    open = open && m_vertices.size() < max_vertices;
                }
                local[j] = m_local[w];
            }
            m_element_corners.push_back(local);
        }
    }
}

void LocalRelaxation::unmark() {
    for (const VertexId v : m_vertices) m_local[v] = none;
    for (const ElementId t : m_elements) m_taken[t] = 0;
}

void LocalRelaxation::multiply(const ElasticBody& body, const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
    out.setZero(d.size());
    const std::size_t corner_count = static_cast<std::size_t>(m_dimension + 1);
    for (std::size_t e = 0; e < m_elements.size(); ++e) {
        const std::array<std::uint32_t, 4>& local = m_element_corners[e];
        double corners[12] = {}, forces[12] = {};
        for (std::size_t j = 0; j < corner_count; ++j)
            for (std::size_t k = 0; k < 3; ++k) corners[3 * j + k] = d[3 * local[j] + k];
        if (m_dimension == 3)
            detail::linear_element_forces<3>(body.rest_shape(m_elements[e]), corners, forces);
        else
            detail::linear_element_forces<2>(body.rest_shape(m_elements[e]), corners, forces);
        for (std::size_t j = 0; j < corner_count; ++j)
            for (std::size_t k = 0; k < 3; ++k) out[3 * local[j] + k] += forces[3 * j + k];
    }
}

void LocalRelaxation::project(const ElasticBody& body, Eigen::VectorXd& v) const {
    for (std::size_t i = 0; i < m_region; ++i)
        body.project_vertex(m_vertices[i], v.segment<3>(3 * static_cast<Eigen::Index>(i)));
    v.tail(3 * static_cast<Eigen::Index>(m_vertices.size() - m_region)).setZero();  // the rim is held
}

Outcome<LocalSolveReport> LocalRelaxation::solve(ElasticBody& body, std::span<const VertexId> seeds,
                                                 std::size_t max_vertices, const SolveOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (body.model() != Model::linear)
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: a local solve needs a linear body (a neo-Hookean body's forces are not K u): "
                       "relax the whole body"};
    if (auto fresh = body.refresh_shapes(); !fresh) return fresh.refusal();
    m_dimension = body.dimension();
    gather(body, seeds, max_vertices);
    struct Unmark {
        LocalRelaxation& local;
        ~Unmark() { local.unmark(); }
    } unmark_at_end{*this};
    LocalSolveReport report;
    report.region_vertices = m_region;
    report.rim_vertices = m_vertices.size() - m_region;
    report.elements = m_elements.size();
    SolveReport& solve = report.solve;
    if (m_region == 0) {
        solve.converged = true;
        return report;
    }

    const auto size = static_cast<Eigen::Index>(3 * m_vertices.size());
    const auto region = static_cast<Eigen::Index>(3 * m_region);
    Eigen::VectorXd u(size), f(size), ku, r, d, q;
    for (std::size_t i = 0; i < m_vertices.size(); ++i) {
        const auto at = static_cast<Eigen::Index>(3 * m_vertices[i]);
        u.segment<3>(3 * static_cast<Eigen::Index>(i)) = body.displacements().segment<3>(at);
        f.segment<3>(3 * static_cast<Eigen::Index>(i)) = body.forces().segment<3>(at);
    }
    const double external = f.head(region).norm();
    // r = P(f - K u) over the region, and the threshold of eq. 6.9 with its reactions
    auto residual = [&] {
        multiply(body, u, ku);
        ++solve.evaluations;
        r = f - ku;
        project(body, r);
        // (I - P)(K u - f) = (K u - f) + r
        const double reaction = (ku - f + r).head(region).norm();
        solve.threshold = detail::threshold_of(body, options, external, reaction);
    };
    residual();
    double rr = r.squaredNorm();
    solve.history.push_back(std::sqrt(rr));
    d = r;
    auto times_k = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
        multiply(body, x, out);
        ++solve.evaluations;
    };
    auto allowed = [&](Eigen::VectorXd& x) { project(body, x); };
    while (std::sqrt(rr) > solve.threshold && solve.iterations < options.max_iterations &&
           detail::cg_iteration(u, r, d, q, rr, solve.iterations, options.recompute_every, times_k, allowed,
                                residual))
        solve.history.push_back(std::sqrt(rr));
    solve.residual = std::sqrt(rr);
    solve.converged = solve.residual <= solve.threshold;
    auto body_u = body.displacements();
    for (std::size_t i = 0; i < m_region; ++i)
        body_u.segment<3>(3 * static_cast<Eigen::Index>(m_vertices[i])) =
            u.segment<3>(3 * static_cast<Eigen::Index>(i));
    solve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace sxk::elasticity
