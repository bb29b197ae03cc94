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

namespace detail {

std::string material_problem(const Material& material) {
    if (!(material.young > 0) || !std::isfinite(material.young))
        return "Young's modulus " + text(material.young) + " is not positive and finite";
    if (!(material.poisson > -1 && material.poisson < 0.5))
        return "Poisson's ratio " + text(material.poisson) + " is not in (-1, 0.5)";
    return {};
}

}  // namespace detail

Outcome<ElasticBody> ElasticBody::make(const Mesh& mesh, Material material) {
    if (mesh.topological_dimension() != 3 || mesh.ambient_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "elasticity: the mesh has " + std::to_string(mesh.topological_dimension()) +
                           "-dimensional elements in " + std::to_string(mesh.ambient_dimension()) +
                           "-dimensional space; linear tetrahedra need a tetrahedral mesh in space"};
    if (const std::string problem = detail::material_problem(material); !problem.empty())
        return Refusal{RefusalCode::bad_argument, "elasticity: " + problem};
    ElasticBody body;
    body.m_mesh = &mesh;
    body.m_material = material;
    body.init(mesh);
    if (auto fresh = body.refresh(); !fresh) return fresh.refusal();
    return body;
}

void ElasticBody::resize_vertices(std::size_t n) {
    const auto size = static_cast<Eigen::Index>(3 * n);
    const Eigen::Index old = m_u.size();
    m_freedom.resize(n, Freedom::free);
    m_line.resize(n, Vector3{0, 0, 0});
    m_known.resize(n, 0);
    m_u.conservativeResize(size);
    m_force.conservativeResize(size);
    if (size > old) {
        m_u.tail(size - old).setZero();
        m_force.tail(size - old).setZero();
    }
}

Outcome<Done> ElasticBody::check_vertex(VertexId v, const char* what) const {
    if (v >= vertex_count() || v >= m_mesh->vertex_count() || m_mesh->vertex_element(v) == invalid_id)
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
    // vertices beyond d (a rollback dropped them and no refresh followed) read as at rest
    const std::size_t vertices = static_cast<std::size_t>(d.size()) / 3;
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, count, 1024), [&](const Range& r) {
        for (std::size_t e = r.begin(); e != r.end(); ++e) {
            const ElementId t = m_elements[e];
            double corners[12];
            for (std::size_t j = 0; j < 4; ++j) {
                const std::size_t v = m_corners[t][j];
                for (std::size_t k = 0; k < 3; ++k) corners[3 * j + k] = v < vertices ? d[static_cast<Eigen::Index>(3 * v + k)] : 0;
            }
            detail::linear_tetrahedron_forces(m_rest[t], corners, m_corner_forces.data() + 12 * e);
        }
    });
    out.setZero(d.size());
    const std::size_t starred = std::min(m_star_begin.size() - 1, vertices);  // the vertices of the last refresh
    tbb::parallel_for(Range(0, starred, 4096), [&](const Range& r) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (std::uint32_t i = m_star_begin[v]; i < m_star_begin[v + 1]; ++i)
                sum += Eigen::Map<const Eigen::Vector3d>(m_corner_forces.data() + 3 * std::size_t{m_star[i]});
            out.segment<3>(3 * static_cast<Eigen::Index>(v)) = sum;
        }
    });
}

void ElasticBody::project(Eigen::VectorXd& v) const {
    const std::size_t n = std::min(vertex_count(), static_cast<std::size_t>(v.size()) / 3);
    for (std::size_t i = 0; i < n; ++i) {
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
    Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
    if (!std::binary_search(m_elements.begin(), m_elements.end(), t)) return k;
    const detail::RestShape& rest = m_rest[t];
    for (int column = 0; column < 12; ++column) {
        double unit[12] = {};
        unit[column] = 1;
        detail::linear_tetrahedron_forces(rest, unit, k.col(column).data());
    }
    return k;
}

}  // namespace sxk::elasticity
