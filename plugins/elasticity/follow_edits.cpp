// ElasticBody following the edits of its mesh (elastic_body.hpp; watchers: thesis §7.4): the
// events record what changed, refresh() recomputes what they recorded.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "elastic_body.hpp"
#include "element_kernels.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::elasticity {
namespace {

// x in barycentric coordinates of the simplex s of dimension D (reference positions; corners
// beyond D get 0); nullopt when s is flat or x is outside it by more than a rounding error.
template <int D>
std::optional<std::array<double, 4>> inside(const Mesh& mesh, const Simplex& s, const Point& x) {
    // outside the simplex's box, widened far beyond the slack below: no factorisation (an edit of
    // an AMP closure removes tens of elements and adds tens of vertices, each tried against them)
    for (int k = 0; k < D; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        double low = mesh.reference(s.vertex(0))[kk], high = low;
        for (int j = 1; j <= D; ++j) {
            low = std::min(low, mesh.reference(s.vertex(j))[kk]);
            high = std::max(high, mesh.reference(s.vertex(j))[kk]);
        }
        const double margin = 1e-6 * (high - low) + 1e-12 * std::max(std::abs(low), std::abs(high));
        if (x[kk] < low - margin || x[kk] > high + margin) return std::nullopt;
    }
    const Point& origin = mesh.reference(s.vertex(D));
    const Eigen::FullPivLU<Eigen::Matrix<double, D, D>> lu(detail::edge_matrix<D>(mesh, s));
    if (!lu.isInvertible())
        return std::nullopt;
    Eigen::Matrix<double, D, 1> offset;
    for (int k = 0; k < D; ++k)
        offset[k] = x[static_cast<std::size_t>(k)] - origin[static_cast<std::size_t>(k)];
    const Eigen::Matrix<double, D, 1> w = lu.solve(offset);
    std::array<double, 4> b{};
    for (int j = 0; j < D; ++j)
        b[static_cast<std::size_t>(j)] = w[j];
    b[D] = 1 - w.sum();
    constexpr double slack = 1e-9;
    for (const double bj : b)
        if (!(bj >= -slack))
            return std::nullopt;
    return b;
}

std::optional<std::array<double, 4>> inside(const Mesh& mesh, const Simplex& s, const Point& x) {
    return s.count() == 4 ? inside<3>(mesh, s, x) : inside<2>(mesh, s, x);
}

}  // namespace

std::uint64_t ElasticBody::new_shape_revision() {
    static std::atomic<std::uint64_t> last{0};  // shared by all bodies: a revision never repeats
    return ++last;
}

void ElasticBody::heard_edit() {
    m_stale = true;
    m_shape_revision = new_shape_revision();
}

void ElasticBody::init(const Mesh& mesh) {
    m_mesh = &mesh;
    resize_vertices(mesh.vertex_count());
    std::fill(m_known.begin(), m_known.end(), 1);
    m_rebuild_all = true;
    m_dirty.clear();
    m_edit_removed.clear();
    m_edit_adding = false;
    heard_edit();
}

void ElasticBody::materials_changed() {
    m_rebuild_all = true;
    heard_edit();
}

void ElasticBody::element_removed(const Mesh&, ElementId, const Simplex& was) {
    if (m_edit_adding) {  // removals come first within an edit: this is the next edit
        m_edit_removed.clear();
        m_edit_adding = false;
    }
    m_edit_removed.push_back(was);
    heard_edit();
}

void ElasticBody::element_changed(const Mesh& mesh, ElementId element, const Simplex& was) {
    // the old shape holds the vertices a dissection copies (without marking a new edit: several
    // elements of one edit change in turn)
    m_edit_removed.push_back(was);
    take_element(mesh, element);
}

void ElasticBody::element_added(const Mesh& mesh, ElementId element) {
    m_edit_adding = true;
    take_element(mesh, element);
}

void ElasticBody::take_element(const Mesh& mesh, ElementId element) {
    heard_edit();
    m_dirty.push_back(element);
    if (mesh.vertex_count() > vertex_count())
        resize_vertices(mesh.vertex_count());
    const Simplex& s = mesh.simplex(element);
    for (int j = 0; j < s.count(); ++j)
        if (const VertexId v = s.vertex(j); !m_known[v])
            interpolate_new_vertex(mesh, v, s);
}

void ElasticBody::vertices_moved(const Mesh& mesh, std::span<const VertexId> /*vertices*/,
                                 PositionSet which) {
    if (!writes_reference(which))
        return;  // the deformed positions are ours to write, not a rest shape
    // the moved vertices' stars, found by the mesh once for every watcher
    const std::span<const ElementId> around = mesh.elements_around_moved();
    m_dirty.insert(m_dirty.end(), around.begin(), around.end());
    heard_edit();
}

void ElasticBody::interpolate_new_vertex(const Mesh& mesh, VertexId v, const Simplex& added) {
    const Point& x = mesh.reference(v);
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    bool found = false;
    for (const Simplex& was : m_edit_removed) {
        bool usable = true;  // every corner's displacement must be set already
        for (int j = 0; j < was.count(); ++j)
            usable = usable && was.vertex(j) < vertex_count() && m_known[was.vertex(j)];
        if (!usable)
            continue;
        if (const auto b = inside(mesh, was, x)) {
            for (int j = 0; j < was.count(); ++j)
                u += (*b)[static_cast<std::size_t>(j)] *
                     m_u.segment<3>(3 * static_cast<Eigen::Index>(was.vertex(j)));
            found = true;
            break;
        }
    }
    if (!found) {  // no element of the edit held it: the mean of the element's known corners
        int count = 0;
        for (int j = 0; j < added.count(); ++j)
            if (const VertexId w = added.vertex(j); w != v && m_known[w]) {
                u += m_u.segment<3>(3 * static_cast<Eigen::Index>(w));
                ++count;
            }
        if (count > 0)
            u /= count;
    }
    m_u.segment<3>(3 * static_cast<Eigen::Index>(v)) = u;
    m_known[v] = 1;
}

Outcome<Done> ElasticBody::refresh() {
    if (auto shapes = refresh_shapes(); !shapes)
        return shapes;
    if (m_stars_stale) {
        rebuild_elements_and_stars();
        // E of eq. 6.9 afresh (refresh_shapes only raises it): the stiffest live element's; the
        // body's without elements
        m_largest_young = m_elements.empty() ? m_material.young : 0;
        for (const ElementId t : m_elements)
            m_largest_young = std::max(m_largest_young, young_of(m_rest[t].lame));
        m_stars_stale = false;
    }
    return Done{};
}

double ElasticBody::young_of(const Lame& l) const {
    // 2 mu (1 + nu) = E; in plane stress nu = lambda / (lambda + 2 mu)
    const double nu = m_dimension == 3 ? l.lambda / (2 * (l.lambda + l.mu)) : l.lambda / (l.lambda + 2 * l.mu);
    return 2 * l.mu * (1 + nu);
}

Outcome<Done> ElasticBody::refresh_shapes() {
    if (!m_stale)
        return Done{};
    const Mesh& mesh = *m_mesh;
    if (mesh.vertex_count() != vertex_count())
        resize_vertices(mesh.vertex_count());  // a rollback may drop vertices
    // Room for the mesh to double, taken when the arrays would grow: their growth past the size
    // built would otherwise copy them whole inside a tool's step (the first cutting steps on the
    // femur took 52 and 76 ms, most of it copying 213k rest shapes and touching their new pages).
    // Address space only, until elements use it.
    if (m_rest.capacity() < mesh.element_capacity()) {
        m_rest.reserve(2 * mesh.element_capacity());
        m_corners.reserve(2 * mesh.element_capacity());
    }
    m_rest.resize(mesh.element_capacity());
    m_corners.resize(mesh.element_capacity());
    if (m_rebuild_all) {
        m_largest_young = 0;  // the materials may have changed: taken anew below
        m_dirty.clear();
        for (const ElementId t : sxk::elements(mesh))
            m_dirty.push_back(t);
    }
    std::sort(m_dirty.begin(), m_dirty.end());
    m_dirty.erase(std::unique(m_dirty.begin(), m_dirty.end()), m_dirty.end());
    AttributeId materials = mesh.find_element_attribute(material_attribute);
    if (materials != invalid_id && mesh.element_attribute_components(materials) != 2)
        materials = invalid_id;
    for (const ElementId t : m_dirty) {
        if (!mesh.is_element(t))
            continue;  // added, then removed again
        Material material = m_material;
        if (materials != invalid_id) {
            const std::span<const double> values = mesh.element_attribute(materials, t);
            material = {values[0], values[1]};
            if (const std::string problem = detail::material_problem(material); !problem.empty())
                return Refusal{RefusalCode::bad_argument,
                               "elasticity: element " + std::to_string(t) + " (" +
                                   material_attribute + "): " + problem,
                               t};
        }
        const Simplex& s = mesh.simplex(t);
        const detail::RestShape rest =
            m_dimension == 3 ? detail::rest_shape<3>(detail::edge_matrix<3>(mesh, s), thickness())
                             : detail::rest_shape<2>(detail::edge_matrix<2>(mesh, s), thickness());
        // flat by the exact predicate, or so thin that its volume rounds to zero in doubles (a
        // sliver of random moves did: exact orientation positive, determinant 0)
        const bool finite = std::all_of(rest.gradient.begin(), rest.gradient.end(),
                                        [](double g) { return std::isfinite(g); });
        if (!(rest.volume > 0) || !finite ||
            element_orientation(mesh, t, Positions::reference) == Sign::zero)
            return Refusal{RefusalCode::would_flatten,
                           "elasticity: element " + std::to_string(t) +
                               " is flat at rest (its stiffness is undefined)",
                           t};
        m_rest[t] = rest;
        m_rest[t].lame = m_dimension == 3 ? lame(material) : plane_stress_lame(material);
        m_corners[t].fill(invalid_id);
        for (int j = 0; j < s.count(); ++j)
            m_corners[t][static_cast<std::size_t>(j)] = s.vertex(j);
        m_largest_young = std::max(m_largest_young, young_of(m_rest[t].lame));
    }
    // the element list and the stars wait for the next refresh(): a local solve does not read them
    m_stars_stale = true;
    m_dirty.clear();
    m_edit_removed.clear();
    m_edit_adding = false;
    m_rebuild_all = false;
    m_stale = false;
    return Done{};
}

void ElasticBody::rebuild_elements_and_stars() {
    const Mesh& mesh = *m_mesh;
    const std::size_t n = vertex_count();
    m_elements.clear();
    for (const ElementId t : sxk::elements(mesh))
        m_elements.push_back(t);
    Vector3 low{}, high{};
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    m_star_begin.assign(n + 1, 0);
    const auto corner_count = static_cast<std::size_t>(m_dimension + 1);
    for (const ElementId t : m_elements)
        for (std::size_t j = 0; j < corner_count; ++j) {
            const VertexId v = m_corners[t][j];
            ++m_star_begin[v + 1];
            for (std::size_t k = 0; k < 3; ++k) {
                low[k] = std::min(low[k], mesh.reference(v)[k]);
                high[k] = std::max(high[k], mesh.reference(v)[k]);
            }
        }
    for (std::size_t v = 0; v < n; ++v)
        m_star_begin[v + 1] += m_star_begin[v];
    m_star.resize(m_star_begin[n]);
    std::vector<std::uint32_t> next(m_star_begin.begin(), m_star_begin.end() - 1);
    for (std::size_t e = 0; e < m_elements.size(); ++e)
        for (std::size_t j = 0; j < corner_count; ++j)
            m_star[next[m_corners[m_elements[e]][j]]++] = static_cast<std::uint32_t>(4 * e + j);
    m_diameter = m_elements.empty() ? 0
                                    : std::sqrt((high[0] - low[0]) * (high[0] - low[0]) +
                                                (high[1] - low[1]) * (high[1] - low[1]) +
                                                (high[2] - low[2]) * (high[2] - low[2]));
}

}  // namespace sxk::elasticity
