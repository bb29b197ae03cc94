// ElasticBody: rest shapes, constraints and loads, and the matrix-free product (elastic_body.hpp).
#include "elastic_body.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "element_kernels.hpp"
#include "sxk/traversal.hpp"

namespace sxk::elasticity {
namespace {

bool finite(const Vector3& x) {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

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

Lame plane_stress_lame(const Material& material) {
    const Lame l = lame(material);
    return {l.mu, 2 * l.mu * l.lambda / (l.lambda + 2 * l.mu)};
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

Outcome<ElasticBody> ElasticBody::make(const Mesh& mesh, Material material, BodyOptions options) {
    const int dimension = mesh.topological_dimension();
    if (dimension != mesh.ambient_dimension() || dimension < 2)
        return Refusal{
            RefusalCode::wrong_dimension,
            "elasticity: the mesh has " + std::to_string(dimension) + "-dimensional elements in " +
                std::to_string(mesh.ambient_dimension()) +
                "-dimensional space; the body needs tetrahedra in space or triangles in the plane"};
    if (const std::string problem = detail::material_problem(material); !problem.empty())
        return Refusal{RefusalCode::bad_argument, "elasticity: " + problem};
    if (!(options.thickness > 0) || !std::isfinite(options.thickness))
        return Refusal{
            RefusalCode::bad_argument,
            "elasticity: the thickness " + text(options.thickness) + " is not positive and finite"};
    ElasticBody body;
    body.m_mesh = &mesh;
    body.m_material = material;
    body.m_options = options;
    body.m_dimension = dimension;
    body.init(mesh);
    if (auto fresh = body.refresh(); !fresh)
        return fresh.refusal();
    return body;
}

void ElasticBody::resize_vertices(std::size_t n) {
    const auto size = static_cast<Eigen::Index>(3 * n);
    const auto old = static_cast<Eigen::Index>(dof_count());
    // room to double, taken when they would grow (refresh_shapes: the rest shapes): a tool's
    // first new vertex would otherwise copy them inside its step
    if (m_freedom.capacity() < n) {
        m_freedom.reserve(2 * n);
        m_line.reserve(2 * n);
        m_known.reserve(2 * n);
    }
    m_freedom.resize(n, Freedom::free);
    m_line.resize(n, Vector3{0, 0, 0});
    m_known.resize(n, 0);
    if (size < old) {  // vertices dropped (a rollback): their entries are zero again
        m_u.segment(size, old - size).setZero();
        m_force.segment(size, old - size).setZero();
    }
    if (size > m_u.size()) {  // doubling: a split's vertex costs O(1) amortised, not a copy of all
        const Eigen::Index capacity = 2 * std::max(size, m_u.size());  // from the first size too
        const Eigen::Index was = m_u.size();
        m_u.conservativeResize(capacity);
        m_force.conservativeResize(capacity);
        m_u.tail(capacity - was).setZero();
        m_force.tail(capacity - was).setZero();
    }
}

Outcome<Done> ElasticBody::check_vertex(VertexId v, const char* what) const {
    if (v >= vertex_count() || v >= m_mesh->vertex_count() ||
        m_mesh->vertex_element(v) == invalid_id)
        return Refusal{RefusalCode::not_found, std::string("elasticity: ") + what + ": " +
                                                   std::to_string(v) +
                                                   " is not a vertex of an element"};
    return Done{};
}

Outcome<Done> ElasticBody::fix(VertexId v, Vector3 displacement) {
    if (auto ok = check_vertex(v, "fix"); !ok)
        return ok;
    if (!finite(displacement))
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: fix: the displacement is not finite"};
    m_freedom[v] = Freedom::fixed;
    if (m_dimension == 2)
        displacement[2] = 0;
    for (std::size_t k = 0; k < 3; ++k)
        m_u[static_cast<Eigen::Index>(3 * v + k)] = displacement[k];
    return Done{};
}

Outcome<Done> ElasticBody::constrain_to_line(VertexId v, Vector3 direction, Vector3 displacement) {
    if (auto ok = check_vertex(v, "constrain_to_line"); !ok)
        return ok;
    const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                    direction[2] * direction[2]);
    if (!(length > 0) || !std::isfinite(length) || !finite(displacement))
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: constrain_to_line: the direction is zero or not finite, or the "
                       "displacement not finite"};
    if (m_dimension == 2 && direction[2] != 0)
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: constrain_to_line: a planar body's line must lie in the plane "
                       "(direction z = 0)"};
    m_freedom[v] = Freedom::line;
    if (m_dimension == 2)
        displacement[2] = 0;
    m_line[v] = {direction[0] / length, direction[1] / length, direction[2] / length};
    for (std::size_t k = 0; k < 3; ++k)
        m_u[static_cast<Eigen::Index>(3 * v + k)] = displacement[k];
    return Done{};
}

Outcome<Done> ElasticBody::free(VertexId v) {
    if (auto ok = check_vertex(v, "free"); !ok)
        return ok;
    m_freedom[v] = Freedom::free;
    return Done{};
}

std::size_t ElasticBody::constrained_count() const {
    return static_cast<std::size_t>(std::count_if(m_freedom.begin(), m_freedom.end(),
                                                  [](Freedom f) { return f != Freedom::free; }));
}

Outcome<Done> ElasticBody::add_force(VertexId v, Vector3 force) {
    if (auto ok = check_vertex(v, "add_force"); !ok)
        return ok;
    if (!finite(force))
        return Refusal{RefusalCode::bad_argument, "elasticity: add_force: the force is not finite"};
    if (m_dimension == 2)
        force[2] = 0;
    for (std::size_t k = 0; k < 3; ++k)
        m_force[static_cast<Eigen::Index>(3 * v + k)] += force[k];
    return Done{};
}

Outcome<Done> ElasticBody::add_body_force(Vector3 per_volume) {
    if (!finite(per_volume))
        return Refusal{RefusalCode::bad_argument,
                       "elasticity: add_body_force: the force is not finite"};
    if (auto fresh = refresh(); !fresh)
        return fresh;
    if (m_dimension == 2)
        per_volume[2] = 0;
    const auto corner_count = static_cast<std::size_t>(m_dimension + 1);
    for (const ElementId t : m_elements) {
        const double part = m_rest[t].volume / static_cast<double>(corner_count);
        for (std::size_t j = 0; j < corner_count; ++j)
            for (std::size_t k = 0; k < 3; ++k)
                m_force[static_cast<Eigen::Index>(3 * m_corners[t][j] + k)] += part * per_volume[k];
    }
    return Done{};
}

void ElasticBody::clear_forces() {
    m_force.setZero();
}

template <int D, class Kernel>
bool ElasticBody::gather(const Eigen::Ref<const Eigen::VectorXd>& d, Eigen::VectorXd& out,
                         const Kernel& kernel) const {
    const std::size_t count = m_elements.size();
    constexpr std::size_t corner_count = D + 1;  // known to the compiler: the gather unrolls
    m_corner_forces.resize(12 * count);
    m_element_energy.resize(count);
    // vertices beyond d (a rollback dropped them and no refresh followed) read as at rest
    const std::size_t vertices = static_cast<std::size_t>(d.size()) / 3;
    std::atomic<bool> ok = true;
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, count, 1024), [&](const Range& r) {
        for (std::size_t e = r.begin(); e != r.end(); ++e) {
            const ElementId t = m_elements[e];
            double corners[12];
            for (std::size_t j = 0; j < corner_count; ++j) {
                const std::size_t v = m_corners[t][j];
                for (std::size_t k = 0; k < 3; ++k)
                    corners[3 * j + k] = v < vertices ? d[static_cast<Eigen::Index>(3 * v + k)] : 0;
            }
            if (!kernel(m_rest[t], corners, m_corner_forces.data() + 12 * e, m_element_energy[e]))
                ok.store(false, std::memory_order_relaxed);
        }
    });
    out.setZero(d.size());
    const std::size_t starred =
        std::min(m_star_begin.size() - 1, vertices);  // the vertices of the last refresh
    tbb::parallel_for(Range(0, starred, 4096), [&](const Range& r) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (std::uint32_t i = m_star_begin[v]; i < m_star_begin[v + 1]; ++i)
                sum += Eigen::Map<const Eigen::Vector3d>(m_corner_forces.data() +
                                                         3 * std::size_t{m_star[i]});
            out.segment<3>(3 * static_cast<Eigen::Index>(v)) = sum;
        }
    });
    return ok.load();
}

void ElasticBody::multiply(const Eigen::Ref<const Eigen::VectorXd>& d, Eigen::VectorXd& out) const {
    // the linear kernels do not need the element energy (1/2 d^T K_t d)
    if (m_dimension == 3)
        gather<3>(d, out, [](const detail::RestShape& rest, const double* c, double* f, double&) {
            detail::linear_element_forces<3>(rest, c, f);
            return true;
        });
    else
        gather<2>(d, out, [](const detail::RestShape& rest, const double* c, double* f, double&) {
            detail::linear_element_forces<2>(rest, c, f);
            return true;
        });
}

bool ElasticBody::elastic_forces(const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::VectorXd& out) const {
    if (m_options.model == Model::linear) {
        multiply(u, out);
        return true;
    }
    if (m_dimension == 3)
        return gather<3>(u, out, detail::neo_hookean_forces<3>);
    return gather<2>(u, out, detail::neo_hookean_forces<2>);
}

bool ElasticBody::elastic_forces_at(std::span<const VertexId> vertices, std::vector<Vector3>& out) const {
    out.assign(vertices.size(), Vector3{0, 0, 0});
    const Mesh& mesh = *m_mesh;
    const std::size_t corner_count = static_cast<std::size_t>(m_dimension + 1);
    std::vector<ElementId> around;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const VertexId v = vertices[i];
        if (v >= vertex_count() || v >= mesh.vertex_count() || mesh.vertex_element(v) == invalid_id) continue;
        around.clear();
        collect_star(mesh, v, mesh.vertex_element(v), around);
        for (const ElementId t : around) {
            double corners[12] = {}, forces[12] = {}, energy = 0;
            std::size_t mine = corner_count;
            for (std::size_t j = 0; j < corner_count; ++j) {
                const VertexId w = m_corners[t][j];
                if (w == v) mine = j;
                for (std::size_t k = 0; k < 3; ++k) corners[3 * j + k] = m_u[static_cast<Eigen::Index>(3 * w + k)];
            }
            if (m_options.model == Model::linear) {
                if (m_dimension == 3)
                    detail::linear_element_forces<3>(m_rest[t], corners, forces);
                else
                    detail::linear_element_forces<2>(m_rest[t], corners, forces);
            } else if (!(m_dimension == 3 ? detail::neo_hookean_forces<3>(m_rest[t], corners, forces, energy)
                                          : detail::neo_hookean_forces<2>(m_rest[t], corners, forces, energy))) {
                return false;
            }
            for (std::size_t k = 0; k < 3 && mine < corner_count; ++k) out[i][k] += forces[3 * mine + k];
        }
    }
    return true;
}

double ElasticBody::strain_energy(const Eigen::Ref<const Eigen::VectorXd>& u) const {
    Eigen::VectorXd forces;
    if (m_options.model == Model::linear) {
        multiply(u, forces);
        return 0.5 * u.dot(forces);
    }
    if (!elastic_forces(u, forces))
        return std::numeric_limits<double>::infinity();
    // in element order, serially: the same sum on any number of threads
    double sum = 0;
    for (const double e : m_element_energy)
        sum += e;
    return sum;
}

void ElasticBody::project(Eigen::VectorXd& v) const {
    const std::size_t n = std::min(vertex_count(), static_cast<std::size_t>(v.size()) / 3);
    for (std::size_t i = 0; i < n; ++i)
        project_vertex(static_cast<VertexId>(i), v.segment<3>(3 * static_cast<Eigen::Index>(i)));
}

double ElasticBody::energy() const {
    return strain_energy(displacements()) - forces().dot(displacements());
}

Eigen::Matrix<double, 12, 12> ElasticBody::element_stiffness(ElementId t) const {
    Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
    if (!std::binary_search(m_elements.begin(), m_elements.end(), t))
        return k;
    const detail::RestShape& rest = m_rest[t];
    const int size = 3 * (m_dimension + 1);
    for (int column = 0; column < size; ++column) {
        double unit[12] = {};
        unit[column] = 1;
        if (m_dimension == 3)
            detail::linear_element_forces<3>(rest, unit, k.col(column).data());
        else
            detail::linear_element_forces<2>(rest, unit, k.col(column).data());
    }
    return k;
}

}  // namespace sxk::elasticity
