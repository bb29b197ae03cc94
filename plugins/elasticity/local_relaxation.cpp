// LocalRelaxation: projected linear CG over the region around some seed vertices, the rest of the
// body held (local_relaxation.hpp).
#include "local_relaxation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "element_kernels.hpp"

namespace sxk::elasticity {

void LocalRelaxation::reserve(const ElasticBody& body) {
    sxk::detail::grow_doubling(m_local, body.vertex_count(), none);
    sxk::detail::grow_doubling(m_element_index, body.mesh().element_capacity(), none);
}

void LocalRelaxation::gather(const ElasticBody& body, std::span<const VertexId> seeds, std::size_t max_vertices) {
    const Mesh& mesh = body.mesh();
    m_vertices.clear();
    m_elements.clear();
    m_element_corners.clear();
    m_star_start.clear();
    m_star.clear();
    // grown with the mesh, never cleared whole: unmark() resets what a gather marked
    reserve(body);
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
    // walked through the mesh, which keeps them for the region's write (Mesh::walk_star): the
    // write's check and the spatial index then need no walks of their own
    mesh.begin_star_walks();
    for (std::size_t head = 0; head < m_region; ++head) {
        const VertexId v = m_vertices[head];
        const std::span<const ElementId> around = mesh.walk_star(v);
        m_star_start.push_back(static_cast<std::uint32_t>(m_star.size()));
        for (const ElementId t : around) {
            if (m_element_index[t] != none) {
                m_star.push_back(m_element_index[t]);
                continue;
            }
            m_element_index[t] = static_cast<std::uint32_t>(m_elements.size());
            m_star.push_back(m_element_index[t]);
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
    m_star_start.push_back(static_cast<std::uint32_t>(m_star.size()));
}

// Row by row, the blocks of a row found through m_slot (a dense scratch over the local vertices,
// reset by the row's own columns): no sorting of triplets, and each row's blocks are contiguous.
// Why assembled: a local solve takes its 5-100 CG iterations on the same region, and the product
// from the blocks (a region vertex has ~15 neighbours in 3D, 9 multiplications each, against ~25
// elements of ~100 flops shared by 4 corners) costs 4.4 times fewer instructions than the
// element-by-element one on the femur and 2.9 times fewer on the slab; assembling costs what 2.5
// (3D) to 4 (2D) element-by-element products cost (callgrind, the needle's steps; docs/elasticity.md
// "Local relaxation"). The whole body keeps the element-by-element product ("Speed" there).
void LocalRelaxation::assemble(const ElasticBody& body) {
    m_row_start.assign(1, 0);
    m_columns.clear();
    m_blocks.clear();
    if (m_slot.size() < m_vertices.size()) m_slot.resize(m_vertices.size(), none);
    m_inverse_diagonal.resize(m_region);
    std::array<std::array<double, 9>, 4> row{};  // an element's blocks in the row being assembled
    for (std::size_t i = 0; i < m_region; ++i) {
        const std::size_t row_begin = m_columns.size();
        for (std::uint32_t s = m_star_start[i]; s < m_star_start[i + 1]; ++s) {
            const std::array<std::uint32_t, 4>& corners = m_element_corners[m_star[s]];
            const detail::RestShape& rest = body.rest_shape(m_elements[m_star[s]]);
            int j = 0;
            while (corners[static_cast<std::size_t>(j)] != i) ++j;
            if (m_dimension == 3)
                detail::linear_element_row<3>(rest, j, row);
            else
                detail::linear_element_row<2>(rest, j, row);
            for (std::size_t l = 0; l <= static_cast<std::size_t>(m_dimension); ++l) {
                const std::uint32_t column = corners[l];
                if (m_slot[column] == none) {
                    m_slot[column] = static_cast<std::uint32_t>(m_columns.size());
                    m_columns.push_back(column);
                    m_blocks.emplace_back();
                }
                std::array<double, 9>& sum = m_blocks[m_slot[column]];
                for (std::size_t k = 0; k < 9; ++k) sum[k] += row[l][k];  // 9: unrolled, and vectorised
            }
        }
        // block Jacobi: the row's diagonal block inverted (a triangle's in its plane); a block that
        // is not positive (no element of positive volume around the vertex) is left out (I)
        Eigen::Matrix3d diagonal = Eigen::Matrix3d::Identity();
        if (m_slot[i] != none)
            diagonal = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m_blocks[m_slot[i]].data());
        if (m_dimension == 2) diagonal(2, 2) = 1;
        m_inverse_diagonal[i] = Eigen::Matrix3d::Identity();
        if (diagonal.determinant() > 0) m_inverse_diagonal[i] = diagonal.inverse();
        for (std::size_t k = row_begin; k < m_columns.size(); ++k) m_slot[m_columns[k]] = none;
        m_row_start.push_back(m_columns.size());
    }
}

void LocalRelaxation::block_jacobi(const ElasticBody& body, const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
    z.setZero(r.size());
    for (std::size_t i = 0; i < m_region; ++i)
        z.segment<3>(3 * static_cast<Eigen::Index>(i)) =
            m_inverse_diagonal[i] * r.segment<3>(3 * static_cast<Eigen::Index>(i));
    project(body, z);
}

bool LocalRelaxation::made_for(const ElasticBody& body, std::span<const VertexId> seeds,
                               std::size_t max_vertices) const {
    return m_made.body == &body && m_made.shapes == body.shape_revision() && m_made.max_vertices == max_vertices &&
           std::equal(seeds.begin(), seeds.end(), m_made.seeds.begin(), m_made.seeds.end());
}

void LocalRelaxation::unmark() {
    for (const VertexId v : m_vertices) m_local[v] = none;
    for (const ElementId t : m_elements) m_element_index[t] = none;
}

void LocalRelaxation::multiply(const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
    out.setZero(d.size());
    // a triangle's blocks are zero outside their upper left 2 x 2 (linear_element_row)
    auto rows = [&]<int D>() {
        for (std::size_t i = 0; i < m_region; ++i) {
            double sum[3] = {0, 0, 0};
            for (std::size_t k = m_row_start[i]; k < m_row_start[i + 1]; ++k) {
                const double* block = m_blocks[k].data();
                const double* x = d.data() + 3 * static_cast<std::size_t>(m_columns[k]);
                for (int a = 0; a < D; ++a)
                    for (int c = 0; c < D; ++c) sum[a] += block[3 * a + c] * x[c];
            }
            for (int a = 0; a < D; ++a) out[3 * static_cast<Eigen::Index>(i) + a] = sum[a];
        }
    };
    if (m_dimension == 3)
        rows.template operator()<3>();
    else
        rows.template operator()<2>();
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
    LocalSolveReport report;
    report.kept = made_for(body, seeds, max_vertices);
    if (!report.kept) {
        m_made.body = nullptr;  // nothing kept until the region and its rows are whole again
        gather(body, seeds, max_vertices);
        unmark();  // only the gather reads the marks
        if (m_region > 0) assemble(body);
        m_made.seeds.assign(seeds.begin(), seeds.end());  // its capacity reused
        m_made.max_vertices = max_vertices;
        m_made.shapes = body.shape_revision();
        m_made.body = &body;
    }
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
    // resized, which allocates only when the size changes (a new region)
    Eigen::VectorXd &u = m_cg.u, &f = m_cg.f, &ku = m_cg.ku, &r = m_cg.r, &d = m_cg.d, &q = m_cg.q, &z = m_cg.z;
    u.resize(size);
    f.resize(size);
    z.resize(size);
    for (std::size_t i = 0; i < m_vertices.size(); ++i) {
        const auto at = static_cast<Eigen::Index>(3 * m_vertices[i]);
        u.segment<3>(3 * static_cast<Eigen::Index>(i)) = body.displacements().segment<3>(at);
        f.segment<3>(3 * static_cast<Eigen::Index>(i)) = body.forces().segment<3>(at);
    }
    const double external = f.head(region).norm();
    if (auto loads = detail::check_loads(external); !loads)  // as prepare_solve refuses the whole body's
        return loads.refusal();
    // r = P(f - K u) over the region, and the threshold of eq. 6.9 with its reactions
    auto residual = [&] {
        multiply(u, ku);
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
    auto times_k = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
        multiply(x, out);
        ++solve.evaluations;
    };
    auto allowed = [&](Eigen::VectorXd& x) { project(body, x); };
    auto precondition = [&](const Eigen::VectorXd& x) -> const Eigen::VectorXd& {
        block_jacobi(body, x, z);
        return z;
    };
    d = precondition(r);
    double rz = r.dot(d);
    while (std::sqrt(rr) > solve.threshold && solve.iterations < options.max_iterations &&
           detail::preconditioned_cg_iteration(u, r, d, q, rr, rz, solve.iterations, options.recompute_every, times_k,
                                               allowed, residual, precondition))
        solve.history.push_back(std::sqrt(rr));
    solve.residual = std::sqrt(rr);
    solve.converged = detail::reached(solve.residual, solve.threshold);
    if (auto finite = detail::check_finite(solve); !finite)
        return finite.refusal();  // the body keeps its displacements: these are not a solution
    auto body_u = body.displacements();
    for (std::size_t i = 0; i < m_region; ++i)
        body_u.segment<3>(3 * static_cast<Eigen::Index>(m_vertices[i])) =
            u.segment<3>(3 * static_cast<Eigen::Index>(i));
    solve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace sxk::elasticity
