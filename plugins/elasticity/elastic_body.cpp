// ElasticBody: rest shapes, constraints and loads, and the matrix-free product (elastic_body.hpp).
#include "elastic_body.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "linear_tetrahedron.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::elasticity {
namespace {

bool finite(const Vector3& x) { return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]); }

std::string text(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

}  // namespace

Lame lame(const Material& material) {
    const double e = material.young, nu = material.poisson;
    return {e / (2 * (1 + nu)), e * nu / ((1 + nu) * (1 - 2 * nu))};
}

Outcome<ElasticBody> ElasticBody::make(const Mesh& mesh, Material material) {
    if (mesh.topological_dimension() != 3 || mesh.ambient_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "elasticity: the mesh has " + std::to_string(mesh.topological_dimension()) +
                           "-dimensional elements in " + std::to_string(mesh.ambient_dimension()) +
                           "-dimensional space; linear tetrahedra need a tetrahedral mesh in space"};
    if (!(material.young > 0) || !std::isfinite(material.young))
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: Young's modulus " + text(material.young) + " is not positive and finite"};
    if (!(material.poisson > -1 && material.poisson < 0.5))
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: Poisson's ratio " + text(material.poisson) + " is not in (-1, 0.5)"};
    ElasticBody body;
    body.m_mesh = &mesh;
    body.m_material = material;
    body.m_lame = lame(material);
    for (const ElementId t : sxk::elements(mesh)) body.m_elements.push_back(t);
    body.m_rest.resize(body.m_elements.size());
    body.m_corners.resize(body.m_elements.size());
    const std::size_t n = mesh.vertex_count();
    Vector3 low{}, high{};
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    body.m_star_begin.assign(n + 1, 0);
    for (std::size_t e = 0; e < body.m_elements.size(); ++e) {
        const ElementId t = body.m_elements[e];
        if (element_orientation(mesh, t, Positions::reference) == Sign::zero)
            return Refusal{RefusalCode::would_flatten,
                           "elasticity: element " + std::to_string(t) + " is flat at rest (its stiffness is undefined)"};
        const Simplex& s = mesh.simplex(t);
        Eigen::Matrix3d z;
        const Point& origin = mesh.reference(s.vertex(3));
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                z(k, j) = mesh.reference(s.vertex(j))[static_cast<std::size_t>(k)] - origin[static_cast<std::size_t>(k)];
        body.m_rest[e] = detail::rest_shape(z);
        for (int j = 0; j < 4; ++j) {
            const VertexId v = s.vertex(j);
            body.m_corners[e][static_cast<std::size_t>(j)] = v;
            ++body.m_star_begin[v + 1];
            for (std::size_t k = 0; k < 3; ++k) {
                low[k] = std::min(low[k], mesh.reference(v)[k]);
                high[k] = std::max(high[k], mesh.reference(v)[k]);
            }
        }
    }
    for (std::size_t v = 0; v < n; ++v) body.m_star_begin[v + 1] += body.m_star_begin[v];
    body.m_star.resize(body.m_star_begin[n]);
    std::vector<std::uint32_t> next(body.m_star_begin.begin(), body.m_star_begin.end() - 1);
    for (std::size_t e = 0; e < body.m_elements.size(); ++e)
        for (std::size_t j = 0; j < 4; ++j) body.m_star[next[body.m_corners[e][j]]++] = static_cast<std::uint32_t>(4 * e + j);
    if (!body.m_elements.empty())
        body.m_diameter = std::sqrt((high[0] - low[0]) * (high[0] - low[0]) + (high[1] - low[1]) * (high[1] - low[1]) +
                                    (high[2] - low[2]) * (high[2] - low[2]));
    body.m_freedom.assign(n, Freedom::free);
    body.m_line.assign(n, Vector3{0, 0, 0});
    body.m_u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(3 * n));
    body.m_force = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(3 * n));
    return body;
}

Outcome<Done> ElasticBody::check_vertex(VertexId v, const char* what) const {
    if (v >= vertex_count() || m_star_begin[v] == m_star_begin[v + 1])
        return Refusal{RefusalCode::not_found,
                       std::string("elasticity: ") + what + ": " + std::to_string(v) + " is not a vertex of an element"};
    return Done{};
}

Outcome<Done> ElasticBody::fix(VertexId v, Vector3 displacement) {
    if (auto ok = check_vertex(v, "fix"); !ok) return ok;
    if (!finite(displacement)) return Refusal{RefusalCode::bad_argument, "elasticity: fix: the displacement is not finite"};
    m_freedom[v] = Freedom::fixed;
    for (std::size_t k = 0; k < 3; ++k) m_u[static_cast<Eigen::Index>(3 * v + k)] = displacement[k];
    return Done{};
}

Outcome<Done> ElasticBody::constrain_to_line(VertexId v, Vector3 direction, Vector3 displacement) {
    if (auto ok = check_vertex(v, "constrain_to_line"); !ok) return ok;
    const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
    if (!(length > 0) || !std::isfinite(length) || !finite(displacement))
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: constrain_to_line: the direction is zero or not finite, or the displacement not finite"};
    m_freedom[v] = Freedom::line;
    m_line[v] = {direction[0] / length, direction[1] / length, direction[2] / length};
    for (std::size_t k = 0; k < 3; ++k) m_u[static_cast<Eigen::Index>(3 * v + k)] = displacement[k];
    return Done{};
}

Outcome<Done> ElasticBody::free(VertexId v) {
    if (auto ok = check_vertex(v, "free"); !ok) return ok;
    m_freedom[v] = Freedom::free;
    return Done{};
}

std::size_t ElasticBody::constrained_count() const {
    return static_cast<std::size_t>(std::count_if(m_freedom.begin(), m_freedom.end(), [](Freedom f) { return f != Freedom::free; }));
}

Outcome<Done> ElasticBody::add_force(VertexId v, Vector3 force) {
    if (auto ok = check_vertex(v, "add_force"); !ok) return ok;
    if (!finite(force)) return Refusal{RefusalCode::bad_argument, "elasticity: add_force: the force is not finite"};
    for (std::size_t k = 0; k < 3; ++k) m_force[static_cast<Eigen::Index>(3 * v + k)] += force[k];
    return Done{};
}

void ElasticBody::clear_forces() { m_force.setZero(); }

void ElasticBody::multiply(const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
    const std::size_t count = m_elements.size();
    m_corner_forces.resize(12 * count);
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, count, 1024), [&](const Range& r) {
        for (std::size_t e = r.begin(); e != r.end(); ++e) {
            double corners[12];
            for (std::size_t j = 0; j < 4; ++j) {
                const double* dj = d.data() + 3 * std::size_t{m_corners[e][j]};
                for (std::size_t k = 0; k < 3; ++k) corners[3 * j + k] = dj[k];
            }
            detail::linear_tetrahedron_forces(m_rest[e], m_lame, corners, m_corner_forces.data() + 12 * e);
        }
    });
    out.resize(d.size());
    tbb::parallel_for(Range(0, vertex_count(), 4096), [&](const Range& r) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (std::uint32_t i = m_star_begin[v]; i < m_star_begin[v + 1]; ++i)
                sum += Eigen::Map<const Eigen::Vector3d>(m_corner_forces.data() + 3 * std::size_t{m_star[i]});
            out.segment<3>(3 * static_cast<Eigen::Index>(v)) = sum;
        }
    });
}

void ElasticBody::project(Eigen::VectorXd& v) const {
    for (std::size_t i = 0; i < vertex_count(); ++i) {
        if (m_freedom[i] == Freedom::free) continue;
        auto x = v.segment<3>(3 * static_cast<Eigen::Index>(i));
        if (m_freedom[i] == Freedom::fixed) {
            x.setZero();
        } else {
            const Eigen::Vector3d l(m_line[i][0], m_line[i][1], m_line[i][2]);
            x = l * l.dot(x);
        }
    }
}

double ElasticBody::energy() const {
    Eigen::VectorXd ku;
    multiply(m_u, ku);
    return 0.5 * m_u.dot(ku) - m_force.dot(m_u);
}

Eigen::Matrix<double, 12, 12> ElasticBody::element_stiffness(ElementId t) const {
    const auto at = std::lower_bound(m_elements.begin(), m_elements.end(), t);
    Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
    if (at == m_elements.end() || *at != t) return k;
    const detail::RestShape& rest = m_rest[static_cast<std::size_t>(at - m_elements.begin())];
    for (int column = 0; column < 12; ++column) {
        double unit[12] = {};
        unit[column] = 1;
        detail::linear_tetrahedron_forces(rest, m_lame, unit, k.col(column).data());
    }
    return k;
}

}  // namespace sxk::elasticity
