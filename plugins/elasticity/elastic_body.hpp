// Elasticity on a tetrahedral mesh in space or a triangle mesh in the plane (plane stress, thesis
// §6.3): the body, its material model (linear, §3.1, or compressible neo-Hookean, §4.3.3), its
// constraints and loads, the matrix-free product with its stiffness matrix and its elastic
// forces. The solvers are in solve.hpp.
//
//     auto body = sxk::elasticity::ElasticBody::make(mesh, {.young = 1e6, .poisson = 0.25});
//     body->fix(v);                        // u(v) = 0
//     body->add_force(w, {0, -1, 0});      // newtons
//     auto report = sxk::elasticity::solve_linear_cg(*body, {.tolerance = 1e-8});
//     body->displacement(w);               // metres
//
// Units are the caller's; the thesis' examples use SI (m, N, Pa). The body reads the mesh's
// reference positions as the rest shape and keeps its own state (displacements, loads,
// constraints) per vertex; it changes the mesh only when asked to show its solution
// (write_deformed).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sxk/mesh.hpp"
#include "sxk/plugins/elasticity.hpp"
#include "sxk/outcome.hpp"
#include "sxk/watcher.hpp"

namespace sxk::elasticity {

using Vector3 = std::array<double, 3>;

// An isotropic material. Young's modulus E > 0 and Poisson's ratio -1 < nu < 1/2.
struct Material {
    double young = 1e6;
    double poisson = 0.25;
};

// The Lamé parameters of eq. 3.2, T = 2 mu E + lambda trace(E) I.
struct Lame {
    double mu = 0;
    double lambda = 0;
};
Lame lame(const Material& material);

// The Lamé parameters of a thin slab in plane stress (thesis eq. 6.3): mu, and lambda replaced by
// 2 mu lambda / (lambda + 2 mu) = E nu / (1 - nu^2).
Lame plane_stress_lame(const Material& material);

// The material model of a body: Model (sxk/plugins/elasticity.hpp).

struct BodyOptions {
    Model model = Model::linear;
    // A triangle body's slab thickness (volume = area x thickness); ignored for tetrahedra.
    double thickness = 1;
};

namespace detail {
// What an element keeps of its rest shape: b_j = Z^-T e_j for corners j < D (the rows of Z^-1,
// Z = (z_0 - z_D, ..., z_{D-1} - z_D) as columns: the gradients of the corners' shape functions;
// b_D = -(b_0 + ... + b_{D-1})), and the volume (a triangle's: area x thickness;
// element_kernels.hpp).
struct RestShape {
    std::array<double, 9> gradient{};  // b_0 .. b_{D-1}, x y z each (a triangle's: z and b_2 zero)
    double volume = 0;
    Lame lame;  // the element's material (a triangle's: in plane stress)
};
// Empty, or why `material` is out of range ("Poisson's ratio 0.5 is not in (-1, 0.5)").
std::string material_problem(const Material& material);
}  // namespace detail

// Materials per element: an element attribute of this name with 2 components (Young's modulus,
// Poisson's ratio) gives each element its own; elements take the body's material otherwise (and
// when an attribute of this name has another number of components: it is not ours). Being an
// element attribute, it follows the edits: a split's children take their parent's material
// (Mesh::add_element_attribute), rollback restores it.
inline constexpr const char* material_attribute = "elasticity.material";

// What a vertex may do (thesis §6.6): move freely, stay at its prescribed displacement, or move
// along a line through its prescribed displacement. The solvers project residuals and search
// directions onto the allowed motions, so a constrained vertex keeps its constraint exactly.
enum class Freedom : std::uint8_t { free, fixed, line };

// The body of a tetrahedral mesh in space, or of a triangle mesh in the plane: a thin slab in
// plane stress (§6.3), whose vertices keep 3 unknowns with z held at 0 by project(), so that the
// solvers, the constraints and the loads are the same for both. To follow edits of the mesh, attach
// it as a watcher (mesh.add_watcher(body), or a ScopedWatcher) once it sits where it will stay: a
// body must not be moved or copied while attached. It then keeps its state in step with the mesh
// (thesis §7.4):
//
//   - added and changed elements get their rest shapes computed, and so do the elements around
//     a vertex whose reference position moved; the others keep theirs;
//   - a new vertex gets the displacement interpolated, in reference positions, from an element
//     the same edit removed or changed that holds it (a split's midpoint: the mean of its
//     edge's ends; a dissection's copy: its original's), else the mean of its neighbours';
//     it starts free and unloaded;
//   - vertices keep their constraints, loads and displacements by id; vertices that leave the
//     mesh (a rollback of added vertices) are dropped.
//
// The events only record; refresh() does the work, once, before the next solve (the solvers
// call it). A refresh after an edit costs the changed elements' rest shapes plus one pass over
// the element ids and stars, which a solve's every iteration costs anyway.
class ElasticBody : public Watcher {
public:
    // `material` is every element's, except where the mesh's material_attribute says otherwise.
    // Refuses a mesh that is neither tetrahedral in space nor triangular in the plane
    // (wrong_dimension), a material out of range or a thickness not positive and finite
    // (bad_argument; an element's material from the attribute: the element named), and an
    // element whose rest volume is not positive (would_flatten: its stiffness is undefined).
    static Outcome<ElasticBody> make(const Mesh& mesh, Material material, BodyOptions options = {});
    // The values of material_attribute were set anew (no event says so): every element's
    // material is read again at the next refresh.
    void materials_changed();
    // The largest Young's modulus of the elements (E of eq. 6.9), as of the last refresh.
    double largest_young() const { return m_largest_young; }

    // Brings the body in step with the edits it heard (see above). Refuses (would_flatten, the
    // element named and the body still waiting for a refresh) when an edit left an element flat
    // at rest: remove it first (the degeneracy plug-in) - the thesis' reason for removing
    // degeneracies before relaxing. multiply, project and energy read the state of the last
    // refresh.
    Outcome<Done> refresh();
    bool needs_refresh() const { return m_stale || m_stars_stale; }
    // The part of refresh() a local solve needs (local_relaxation.hpp): the rest shapes and
    // corners of the edited elements and the new vertices' state, in time proportional to the
    // edit; the element list and the stars that multiply reads wait for the next refresh().
    // largest_young() only grows here. Refuses as refresh does.
    Outcome<Done> refresh_shapes();
    // Changes with every event the body hears but a move of the deformed positions (an element
    // added, removed or changed, a reference position moved, init, materials_changed), and takes no
    // value any other body had: while it stands, the rest shapes, the elements' corners and materials
    // and the vertices' stars are as they were. What a local solve keeps between solves is keyed to
    // it (local_relaxation.hpp).
    std::uint64_t shape_revision() const { return m_shape_revision; }

    void init(const Mesh& mesh) override;
    void element_removed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void element_changed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void element_added(const Mesh& mesh, ElementId element) override;
    void vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices,
                        PositionSet which) override;

    const Mesh& mesh() const { return *m_mesh; }
    // 3 (tetrahedra in space) or 2 (triangles in the plane).
    int dimension() const { return m_dimension; }
    Model model() const { return m_options.model; }
    double thickness() const { return m_options.thickness; }
    // The body's material: that of the elements the material attribute does not set.
    const Material& material() const { return m_material; }
    // Vertices of the body (the mesh's, as of the last event heard).
    std::size_t vertex_count() const { return m_freedom.size(); }
    // 3 per vertex, x y z (a planar body's z held at 0): the unknowns of the solvers.
    std::size_t dof_count() const { return 3 * vertex_count(); }

    // Constraints. fix: u(v) = displacement. constrain_to_line: u(v) = displacement + s * direction
    // for any s (direction not zero; it is normalised). free: no constraint (the default).
    // Refuse a vertex that is not in an element (not_found) and a zero or non-finite direction
    // (bad_argument; in a planar body also a line out of the plane). Setting a constraint sets
    // u(v) to the prescribed displacement. A planar body ignores the z of displacements and forces.
    Outcome<Done> fix(VertexId v, Vector3 displacement = {0, 0, 0});
    Outcome<Done> constrain_to_line(VertexId v, Vector3 direction,
                                    Vector3 displacement = {0, 0, 0});
    Outcome<Done> free(VertexId v);
    Freedom freedom(VertexId v) const { return m_freedom[v]; }
    // The unit direction of v's line constraint (zero for other vertices).
    Vector3 line_direction(VertexId v) const {
        return m_freedom[v] == Freedom::line ? m_line[v] : Vector3{0, 0, 0};
    }
    std::size_t constrained_count() const;

    // External nodal forces; add_force accumulates. Refuse a vertex in no element (not_found) and
    // a non-finite force (bad_argument).
    Outcome<Done> add_force(VertexId v, Vector3 force);
    // Adds the weight of each element under a body force `per_volume` (gravity: density x
    // acceleration, N/m^3), an equal part at each corner: the consistent load of a uniform body
    // force on linear elements. A triangle's volume is its area x thickness. Brings the body in
    // step with its mesh first (refuses as refresh does) and refuses a non-finite force
    // (bad_argument). Like every load it stays on its vertices: after an edit, add it anew.
    Outcome<Done> add_body_force(Vector3 per_volume);
    void clear_forces();
    Vector3 force(VertexId v) const {
        return {m_force[3 * v], m_force[3 * v + 1], m_force[3 * v + 2]};
    }

    Vector3 displacement(VertexId v) const { return {m_u[3 * v], m_u[3 * v + 1], m_u[3 * v + 2]}; }
    // The unknowns, 3 per vertex: the solvers start from them (a warm start) and leave the
    // solution there. Writing them directly bypasses the constraints until the next solve. A view
    // of dof_count() entries into storage that grows by doubling, so that an edit adding a vertex
    // does not copy the body's arrays (a step of a tool on a large mesh would cost its size).
    using Values = Eigen::VectorBlock<Eigen::VectorXd>;
    using ConstValues = Eigen::VectorBlock<const Eigen::VectorXd>;
    Values displacements() { return m_u.head(static_cast<Eigen::Index>(dof_count())); }
    ConstValues displacements() const { return m_u.head(static_cast<Eigen::Index>(dof_count())); }
    ConstValues forces() const { return m_force.head(static_cast<Eigen::Index>(dof_count())); }

    // out = K d, K the stiffness matrix of the linear model (of a neo-Hookean body: its tangent
    // at rest), i.e. the linear elastic forces of displacements d with their sign reversed
    // (eq. 3.4 summed over the elements, eq. 3.5), without forming K; d and out have dof_count()
    // entries (the vertices of an edit not refreshed yet get 0). Elements in parallel (TBB), the
    // sums per vertex in a fixed order: the result does not depend on the number of threads.
    // One call at a time per body (it writes the body's scratch buffers; so do the two below).
    void multiply(const Eigen::Ref<const Eigen::VectorXd>& d, Eigen::VectorXd& out) const;
    // out = the gradient of the strain energy at displacements u, the elastic forces with their
    // sign reversed, in the body's model (linear: K u). False, out unspecified, when u inverts or
    // flattens an element (neo-Hookean only: its energy is infinite there).
    bool elastic_forces(const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::VectorXd& out) const;
    // The strain energy of displacements u in the body's model (linear: 1/2 u^T K u); infinity
    // when u inverts or flattens an element of a neo-Hookean body.
    double strain_energy(const Eigen::Ref<const Eigen::VectorXd>& u) const;
    // Projects v onto the motions the constraints allow (P_W of §6.6; a planar body's z is 0
    // everywhere), in place.
    void project(Eigen::VectorXd& v) const;
    // The same for vertex v's three entries x (a segment of such a vector, or a copy of one).
    void project_vertex(VertexId v, Eigen::Ref<Eigen::Vector3d> x) const {
        if (m_dimension == 2) x[2] = 0;
        if (m_freedom[v] == Freedom::fixed) {
            x.setZero();
        } else if (m_freedom[v] == Freedom::line) {
            const Eigen::Vector3d l(m_line[v][0], m_line[v][1], m_line[v][2]);
            x = l * l.dot(x);
        }
    }
    // Writes reference + u as the deformed positions of every vertex in an element, by one
    // Mesh::move_vertices (watchers such as a SpatialIndex over deformed positions hear one
    // vertices_moved; inside an EditJournal step the old positions are kept for rollback).
    // Refuses, writing nothing, when `mesh` is not the body's mesh (bad_argument) or an element
    // would be inverted or flat in the deformed positions (would_invert or would_flatten, the
    // element named): a solution that turns an element inside out is no shape to show or cut.
    Outcome<Done> write_deformed(Mesh& mesh) const;

    // The potential energy strain_energy(u) - f^T u of the current displacements.
    double energy() const;
    // The diameter of the rest shape (the diagonal of its bounding box): H of eq. 6.9.
    double diameter() const { return m_diameter; }

    // The stiffness of one element: the 12 x 12 matrix K_t with K_t d_t = the element's share of
    // K d, vertices in the element's canonical order (for the assembled reference solver; a
    // triangle's fills the first 9 rows and columns); zero for an id that is not one of
    // elements().
    Eigen::Matrix<double, 12, 12> element_stiffness(ElementId t) const;
    // The live elements, in increasing id order (as of the last refresh).
    std::span<const ElementId> elements() const { return m_elements; }
    // Element t's rest shape and the vertices it was computed for, in that order (invalid_id
    // beyond the dimension), as of the last refresh_shapes: what a local solve multiplies with.
    const detail::RestShape& rest_shape(ElementId t) const { return m_rest[t]; }
    const std::array<VertexId, 4>& corners(ElementId t) const { return m_corners[t]; }

    // The elastic forces with their sign reversed (as elastic_forces) at `vertices` only, summed
    // over their stars: out gets 3 per vertex (0 for a vertex in no element). In time proportional
    // to the stars, not to the body; reads the state of the last refresh_shapes. False, out
    // unspecified, when the displacements invert an element of a neo-Hookean body there.
    bool elastic_forces_at(std::span<const VertexId> vertices, std::vector<Vector3>& out) const;
    // write_deformed for `vertices` only (the others keep their deformed positions): a local
    // solve's region. Refuses as write_deformed, writing nothing.
    Outcome<Done> write_deformed(Mesh& mesh, std::span<const VertexId> vertices) const;

private:
    ElasticBody() = default;
    Outcome<Done> check_vertex(VertexId v, const char* what) const;
    // The per-vertex arrays sized to n vertices (new ones free, unloaded, at rest, not known).
    void resize_vertices(std::size_t n);
    // An element an edit made or reshaped: its rest shape to compute at the next refresh, its
    // new corners' displacements now (follow_edits.cpp).
    void take_element(const Mesh& mesh, ElementId element);
    void interpolate_new_vertex(const Mesh& mesh, VertexId v, const Simplex& added);
    void rebuild_elements_and_stars();
    // E of a material given by its Lame parameters (in plane stress for a planar body)
    double young_of(const Lame& lame) const;
    // Calls kernel(rest shape, corner displacements, out, energy) for every element in parallel,
    // each writing 3 per corner into m_corner_forces (and its energy into m_element_energy), then
    // sums the corners per vertex into out; false when a kernel returned false. D: the body's
    // dimension.
    template <int D, class Kernel>
    bool gather(const Eigen::Ref<const Eigen::VectorXd>& d, Eigen::VectorXd& out, const Kernel& kernel) const;

    const Mesh* m_mesh = nullptr;
    Material m_material;
    BodyOptions m_options;
    int m_dimension = 3;
    double m_largest_young = 0;
    double m_diameter = 0;
    // the live elements in increasing id order, as of the last refresh
    std::vector<ElementId> m_elements;
    // per element id: the rest shape (element_kernels.hpp) and the vertices it was computed
    // for (the product reads them here, 16 bytes in a row, instead of the mesh's records)
    std::vector<detail::RestShape> m_rest;
    std::vector<std::array<VertexId, 4>> m_corners;
    // vertex v's (entry of m_elements * 4 + corner), at [m_star_begin[v], m_star_begin[v + 1])
    std::vector<std::uint32_t> m_star_begin, m_star;
    std::vector<Freedom> m_freedom;
    std::vector<Vector3> m_line;  // the unit direction of a line constraint
    // displacements and loads, 3 per vertex: dof_count() in use, zero beyond (the capacity)
    Eigen::VectorXd m_u, m_force;
    mutable std::vector<double>
        m_corner_forces;  // 12 per entry of m_elements (a triangle's: 9 used)
    mutable std::vector<double> m_element_energy;  // per entry of m_elements

    // what the events recorded for the next refresh
    void heard_edit();  // m_stale, and a new shape revision
    static std::uint64_t new_shape_revision();
    std::uint64_t m_shape_revision = new_shape_revision();
    bool m_stale = false;
    bool m_stars_stale = false;  // refresh_shapes ran since the last rebuild_elements_and_stars
    bool m_rebuild_all = false;      // init: every rest shape again
    std::vector<ElementId> m_dirty;  // rest shapes to compute
    std::vector<char> m_known;       // per vertex: its displacement is set
    std::vector<Simplex>
        m_edit_removed;          // the current edit's removed and changed elements, as they were
    bool m_edit_adding = false;  // the current edit reported an addition already
};

}  // namespace sxk::elasticity
