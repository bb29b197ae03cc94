// The simplicial mesh: connectivity after Nienhuys' thesis chapter 7, plus geometry.
//
// Connectivity. An Element represents an oriented d-simplex and owns d+1 Face objects, one per
// (d-1)-simplex, stored in the order of the invariant
//
//   (7.1)  faces(t)[i] represents simplex(t).subn(i)
//   (7.2)  a face belongs to exactly the element that lists it
//   (7.3)  mate(f) is invalid_id (f on the boundary) or a face whose simplex is -simplex(f)
//   (7.4)  each d- and (d-1)-simplex is represented by one object only
//   (7.5)  the boundary map holds exactly the faces sigma with -sigma not a face of the mesh
//
// and validate() checks these plus face-connected vertex stars (the connectedness condition at
// the end of §7.3, which makes star(v) traversable from any element of it).
//
//          c                        Element <a,b,c> (positive: counter-clockwise)
//         / \                        faces[0] = +<b,c>   mate -> face <c,b> of the neighbour
//   f[1] /   \ f[0]                  faces[1] = -<a,c> = <c,a>
//       /  E  \       d              faces[2] = +<a,b>
//      a ----- b     /
//        f[2]  \    /                boundary: the faces whose mate is invalid_id, keyed in
//               \  /                 the boundary map by their simplex
//                ..
//
// Storage (docs/kernel.md "How it is stored"): elements and faces live in contiguous pools addressed by
// 32-bit ids with free lists; a Face stores only its element and its mate (8 bytes) and derives
// its simplex from (7.1). Identities: an ElementId/FaceId stays valid until the object is freed;
// change_elements keeps both element and face identities.
//
// Geometry. Every vertex has a reference position (the undeformed material) and a deformed
// position (the simulated shape; cuts act on it, thesis §3.2.2). Points always have three
// coordinates; in a planar mesh (ambient dimension 2) z is 0.
//
// Edits are transactions: replace_elements and change_elements check their arguments first and
// either complete or leave the mesh (and what watchers saw) exactly as it was, returning why.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/detail/boundary_map.hpp"
#include "sxk/detail/id_marks.hpp"
#include "sxk/detail/large_array.hpp"
#include "sxk/ids.hpp"
#include "sxk/outcome.hpp"
#include "sxk/simplex.hpp"
#include "sxk/watcher.hpp"

namespace sxk {

using Point = std::array<double, 3>;

class EditJournal;
namespace detail {
class EditLog;
class UndoLog;
struct ReplacePlan;

// One attribute's values: those of vertex (or element) i at [i * components, (i+1) * components).
// components == 0 marks a removed attribute (its id is not reused). Vertex and element
// attributes are two tables of these (core/src/attribute_table.hpp).
struct AttributeColumn {
    std::string name;
    int components = 0;
    std::vector<double> default_value;
    std::vector<double> values;
};
}  // namespace detail

// Identifies a vertex or element attribute of one mesh (Mesh::add_vertex_attribute,
// Mesh::add_element_attribute); the two kinds have ids of their own.
using AttributeId = std::uint32_t;

// One element's vertex substitution pi for change_elements: vertex j of the element's current
// canonical simplex becomes new_vertices[j].
struct ElementSubstitution {
    ElementId element = invalid_id;
    std::array<VertexId, 4> new_vertices{invalid_id, invalid_id, invalid_id, invalid_id};
};

// Labels of (d-1)-faces, as Medit "Triangles"/"Edges" references or Gmsh physical tags carry
// them, kept for faces on the boundary or on interfaces between materials and written back by
// the formats that have them. The key is Simplex(+1, sorted vertices) whatever the orientation
// of the face in the mesh or in the file: a label belongs to the vertex set, not to one side.
using FaceLabels = std::unordered_map<Simplex, int, SimplexHash>;

// Checks Mesh::move_vertices makes before moving, with the exact orientation predicates, in each
// position set the move writes, on every element around a moved vertex (where the topological
// dimension equals the ambient one; a triangle in space can only become flat: collinear).
struct MoveCheck {
    bool refuse_inverted = false;  // an element would be inverted
    bool refuse_flat = false;      // an element would be flat (orientation exactly zero)
};

// What Mesh::validate checks besides the connectivity invariants.
struct ValidateOptions {
    bool orientation = false;      // exact orientation in both position sets: inverted is invalid
    bool flat_is_invalid = false;  // with orientation: a flat element is invalid too
};

class SXK_API Mesh {
public:
    // topological_dimension: 2 (triangles) or 3 (tetrahedra); ambient_dimension: 2 or 3, at
    // least the topological one. Anything else throws std::invalid_argument.
    Mesh(int topological_dimension, int ambient_dimension);

    // Copies connectivity, geometry, labels and vertex and element attributes; never watchers (a watcher watches one mesh).
    Mesh(const Mesh& other);
    Mesh& operator=(const Mesh& other);
    Mesh(Mesh&& other) noexcept;
    Mesh& operator=(Mesh&& other) noexcept;
    ~Mesh();

    int topological_dimension() const { return m_dimension; }
    int ambient_dimension() const { return m_ambient; }
    // d+1: vertices per element, faces per element.
    int element_vertex_count() const { return m_dimension + 1; }

    // ---- vertices and positions ---------------------------------------------------------------
    std::size_t vertex_count() const { return m_reference.size(); }
    // Adds a vertex with both positions; returns its id (ids are dense: 0, 1, 2, ...).
    VertexId add_vertex(const Point& reference, const Point& deformed);
    VertexId add_vertex(const Point& position) { return add_vertex(position, position); }
    const Point& reference(VertexId v) const { return m_reference[v]; }
    const Point& deformed(VertexId v) const { return m_deformed[v]; }
    // Gives vertices[i] the position points[i] in the sets `which`, and tells every watcher once
    // (Watcher::vertices_moved); inside an EditJournal step the old positions are kept for
    // rollback. Refuses (nothing moves, nobody is told) when the sizes differ, a vertex is
    // unknown or listed twice, a coordinate is not finite, a planar mesh (ambient dimension 2)
    // gets z != 0, or `check` finds an element that would be inverted or flat ("element 7 would
    // be inverted in the deformed positions", item = the element). An empty list does nothing.
    // Cost: O(moved vertices), plus their stars when checking.
    Outcome<Done> move_vertices(std::span<const VertexId> vertices, std::span<const Point> points,
                                PositionSet which, const MoveCheck& check = {});
    // Inside Watcher::vertices_moved: the elements with a corner among the moved vertices (their
    // stars; each once, in the order the stars are walked), found once per move for
    // move_vertices' check and every watcher that asks (the spatial index re-boxes them, a body
    // refreshes them) rather than by each: on a local solve's write they were half its cost,
    // found twice. Empty outside a move.
    std::span<const ElementId> elements_around_moved() const;
    // Star walks a move takes over. A caller that walks the stars of the vertices it is about to
    // move (a local solve gathers its region by their stars, then writes the region's positions)
    // walks them here: begin_star_walks() forgets earlier walks, walk_star(v) gives star(v) (as
    // sxk::star; valid until the next walk, empty for a vertex in no element) and remembers it.
    // While the mesh has not changed since but for moves (which change no star), a move of exactly
    // the vertices walked checks and tells their stars' union instead of walking them again: on
    // the femur those walks were a sixth of a needle step. Any other move walks as usual. Not for
    // concurrent readers: the walks are kept in the mesh.
    void begin_star_walks() const;
    std::span<const ElementId> walk_star(VertexId v) const;
    // One vertex, one set, no check. While neither a watcher nor an EditJournal step watches
    // the mesh this is the bulk path (a plain store: readers and generators set millions of
    // positions); otherwise it is move_vertices of one vertex, so nothing goes unobserved.
    // The point is stored as given (the caller keeps z == 0 in a planar mesh).
    void set_reference(VertexId v, const Point& p) {
        if (observed()) set_position(v, p, PositionSet::reference);
        else m_reference[v] = p;
    }
    void set_deformed(VertexId v, const Point& p) {
        if (observed()) set_position(v, p, PositionSet::deformed);
        else m_deformed[v] = p;
    }
    std::span<const Point> reference_positions() const { return m_reference; }
    std::span<const Point> deformed_positions() const { return m_deformed; }
    // Some element containing v, or invalid_id for a vertex in no element.
    ElementId vertex_element(VertexId v) const { return m_vertex_element[v]; }
    // The vertices in some element (vertex ids the edits left in none, as collapses leave theirs,
    // are not counted). O(1): kept with the anchors, so a tool's step may report it.
    std::size_t vertices_in_elements() const { return m_vertices_in_elements; }
    // sum weights[i] * position(vertices[i]) in both position sets, summed in input order (the
    // first term is weights[0] * p[0], so one vertex with weight 1 is copied bit for bit).
    // Sizes must match and every vertex exist; the splits use this to place their new vertex.
    std::pair<Point, Point> interpolated_positions(std::span<const VertexId> vertices,
                                                   std::span<const double> weights) const;
    // Adds a vertex at interpolated_positions(parents, weights) whose every vertex attribute is
    // the same combination of the parents' values (components summed in the same order). The
    // splits use it, so attributes follow subdivision. Refuses (nothing added) when the spans
    // are empty or of different sizes or a parent is not a vertex.
    Outcome<VertexId> add_interpolated_vertex(std::span<const VertexId> parents,
                                              std::span<const double> weights);
    // Removes the vertex vertex_count()-1 and its attribute values: the undo of add_vertex for
    // an edit that was refused after adding its vertex. Refuses (nothing changes) when the mesh
    // has no vertex or the last vertex is in an element (its anchor is set).
    Outcome<Done> remove_last_vertex();

    // Drops every vertex that is in no element (what collapses and cuts leave behind), keeping
    // the order of the others, their positions, attributes and anchors, and renames the
    // vertices of elements, faces and face labels; element and face ids do not change. Returns
    // the old -> new map (invalid_id: dropped). Watchers are initialised again (every vertex id
    // may change). O(mesh): for writers and batch commands, not for a frame. Refused inside an
    // EditJournal step.
    Outcome<std::vector<VertexId>> compact_vertices();

    // ---- vertex attributes --------------------------------------------------------------------
    // Named per-vertex fields of `components` doubles each (temperature: 1, velocity: 3). Every
    // vertex has a value; add_vertex gives new vertices the attribute's default value,
    // add_interpolated_vertex (the splits) interpolates, and the operations document what their
    // new or moved vertices get (docs/kernel.md). Ids stay valid until the attribute is removed
    // and are not reused; copies of the mesh copy the attributes with their ids.
    //
    // Refuses (nothing changes) when the name is empty or already used, components < 1, or
    // `default_value` is neither empty (all zeros) nor of size `components`.
    Outcome<AttributeId> add_vertex_attribute(std::string name, int components,
                                              std::span<const double> default_value = {});
    // The id of the live attribute called `name`, or invalid_id.
    AttributeId find_vertex_attribute(std::string_view name) const;
    // Refuses when `attribute` is not a live attribute. Adding and removing attributes is
    // refused while an EditJournal step is open (a rollback restores values, not the schema).
    Outcome<Done> remove_vertex_attribute(AttributeId attribute);
    bool is_vertex_attribute(AttributeId attribute) const {
        return attribute < m_attributes.size() && m_attributes[attribute].components > 0;
    }
    // The live attributes, by increasing id.
    std::vector<AttributeId> vertex_attributes() const;
    // For a live attribute:
    const std::string& vertex_attribute_name(AttributeId attribute) const {
        return m_attributes[attribute].name;
    }
    int vertex_attribute_components(AttributeId attribute) const {
        return m_attributes[attribute].components;
    }
    std::span<const double> vertex_attribute_default(AttributeId attribute) const {
        return m_attributes[attribute].default_value;
    }
    // Sets the value of a live attribute at vertex v, kept for rollback inside an EditJournal
    // step. Refuses when the attribute or the vertex does not exist or the size is wrong.
    Outcome<Done> set_vertex_attribute(AttributeId attribute, VertexId v, std::span<const double> value);
    // The value of a live attribute at vertex v (v < vertex_count()): `components` doubles,
    // writable in place: the unobserved bulk path (an EditJournal does not see writes through
    // the span; use set_vertex_attribute inside a step). The span is invalidated by adding or
    // removing vertices.
    std::span<double> vertex_attribute(AttributeId attribute, VertexId v) {
        detail::AttributeColumn& a = m_attributes[attribute];
        const auto n = static_cast<std::size_t>(a.components);
        return {a.values.data() + v * n, n};
    }
    std::span<const double> vertex_attribute(AttributeId attribute, VertexId v) const {
        const detail::AttributeColumn& a = m_attributes[attribute];
        const auto n = static_cast<std::size_t>(a.components);
        return {a.values.data() + v * n, n};
    }

    // ---- element attributes -------------------------------------------------------------------
    // Named per-element fields of `components` doubles each: a solver's material parameters,
    // rest-shape data, a stiffness factor. Every element has a value. An element made by
    // replace_elements takes the values of its origin (the old element it comes from: a split
    // child its parent's; see replace_elements), assign_elements gives every element the default
    // value, and change_elements (dissection) keeps them with the element's identity. Values are
    // kept for rollback by set_element_attribute and by the edits. Ids and refusals as for
    // vertex attributes (add_vertex_attribute); element and vertex attributes are separate.
    Outcome<AttributeId> add_element_attribute(std::string name, int components,
                                               std::span<const double> default_value = {});
    AttributeId find_element_attribute(std::string_view name) const;
    Outcome<Done> remove_element_attribute(AttributeId attribute);
    bool is_element_attribute(AttributeId attribute) const {
        return attribute < m_element_attributes.size() && m_element_attributes[attribute].components > 0;
    }
    std::vector<AttributeId> element_attributes() const;
    const std::string& element_attribute_name(AttributeId attribute) const {
        return m_element_attributes[attribute].name;
    }
    int element_attribute_components(AttributeId attribute) const {
        return m_element_attributes[attribute].components;
    }
    std::span<const double> element_attribute_default(AttributeId attribute) const {
        return m_element_attributes[attribute].default_value;
    }
    // Kept for rollback inside an EditJournal step. Refuses when the attribute or the element
    // does not exist or the size is wrong.
    Outcome<Done> set_element_attribute(AttributeId attribute, ElementId t, std::span<const double> value);
    // The value of a live attribute at a live element t: writable in place, the unobserved bulk
    // path (use set_element_attribute inside a step). Invalidated by edits that add elements.
    std::span<double> element_attribute(AttributeId attribute, ElementId t) {
        detail::AttributeColumn& a = m_element_attributes[attribute];
        const auto n = static_cast<std::size_t>(a.components);
        return {a.values.data() + t * n, n};
    }
    std::span<const double> element_attribute(AttributeId attribute, ElementId t) const {
        const detail::AttributeColumn& a = m_element_attributes[attribute];
        const auto n = static_cast<std::size_t>(a.components);
        return {a.values.data() + t * n, n};
    }

    // ---- elements -----------------------------------------------------------------------------
    std::size_t element_count() const { return m_element_count; }
    // One past the largest element id ever handed out: iterate 0..capacity and skip dead ids.
    std::size_t element_capacity() const { return m_elements.size(); }
    bool is_element(ElementId t) const {
        return t < m_elements.size() && m_elements[t].simplex.count() != 0;
    }
    const Simplex& simplex(ElementId t) const { return m_elements[t].simplex; }
    FaceId face(ElementId t, int i) const { return m_elements[t].faces[static_cast<std::size_t>(i)]; }
    std::span<const FaceId> faces(ElementId t) const {
        return {m_elements[t].faces.data(), static_cast<std::size_t>(m_dimension + 1)};
    }
    int label(ElementId t) const { return m_elements[t].label; }
    // Kept for rollback inside an EditJournal step (labels have no watcher event).
    void set_label(ElementId t, int label) {
        if (m_undo != nullptr) note_element(t);
        m_elements[t].label = label;
        ++m_revision;
    }
    // The vertex of t not in face f (f must be a face of t).
    VertexId opposite_vertex(ElementId t, FaceId f) const;
    // The face of t not containing vertex v (v must be a vertex of t).
    FaceId opposite_face(ElementId t, VertexId v) const;
    // The neighbour of t across its i-th face, or invalid_id on the boundary: the element of
    // mate(face(t, i)), kept beside the faces so that walks pay one load per step.
    ElementId neighbor(ElementId t, int i) const {
        return m_elements[t].neighbors[static_cast<std::size_t>(i)];
    }

    // ---- faces --------------------------------------------------------------------------------
    std::size_t face_capacity() const { return m_faces.size(); }
    bool is_face(FaceId f) const { return f < m_faces.size() && m_faces[f].element != invalid_id; }
    ElementId face_element(FaceId f) const { return m_faces[f].element; }
    FaceId mate(FaceId f) const { return m_faces[f].mate; }
    // i such that faces(face_element(f))[i] == f.
    int face_slot(FaceId f) const;
    // simplex(face_element(f)).subn(face_slot(f)), by invariant 7.1.
    Simplex face_simplex(FaceId f) const;

    // ---- boundary -----------------------------------------------------------------------------
    std::size_t boundary_face_count() const { return m_boundary.size(); }
    // The boundary face representing exactly sigma (orientation included), or invalid_id.
    FaceId find_boundary_face(const Simplex& sigma) const;
    // The boundary face with sigma's vertices in either orientation (of sigma and -sigma at most
    // one is on the boundary), or invalid_id: one probe of the boundary map and no visit to the
    // pools, for callers to whom the orientation does not matter (face labels).
    FaceId find_boundary_face_unoriented(const Simplex& sigma) const { return m_boundary.find(sigma); }
    template <class Visit>  // visit(FaceId)
    void for_each_boundary_face(Visit&& visit) const {
        m_boundary.for_each([&](const detail::BoundaryMap::Key&, FaceId f) { visit(f); });
    }
    // Boundary faces sorted by id (deterministic order for writers and tests).
    std::vector<FaceId> boundary_faces() const;

    // ---- building and editing -----------------------------------------------------------------
    // Room for this many vertices and elements (their faces and attributes too) before a pool is
    // copied to grow: a tool session takes half as much again when it begins (ToolSession). The
    // scratch that moves and star walks keep per vertex and element id is sized for the mesh as it
    // is, with room to double: the first move of a session would otherwise fill it inside a step
    // (about 20 ms on a million triangles, most of it the guest's first touch of fresh pages).
    void reserve(std::size_t vertices, std::size_t elements);

    // Builds the connectivity of an element-less mesh from a simplex soup in one pass (sorting
    // faces by vertex instead of going through the boundary map: the fast path for readers).
    // Refuses, naming the index of an offending simplex in `item`, when a simplex has the wrong
    // size, a repeated vertex or a vertex id >= vertex_count(), when two simplexes have the same
    // vertices, or when a face is shared by more than two elements or by two with the same
    // orientation (inconsistent orientation or non-manifold), or when the elements around a
    // vertex are not connected through faces (a pinched vertex: "star connectivity: ...", item =
    // an element of that star). Labels may be empty (all 0).
    // On refusal the mesh is unchanged. Watchers are initialised afterwards.
    Outcome<Done> assign_elements(std::span<const Simplex> simplexes, std::span<const int> labels = {});

    // The thesis' add-element, one simplex after the other, with no check beyond what the data
    // structure needs to stay addressable (sizes, distinct and known vertices, refused as above).
    // Duplicates, non-manifold faces and inconsistent orientations are built as they come and
    // leave an invalid structure that validate() then names (Fig. 7.8: not every invalid change
    // can be caught cheaply). `sxk validate` reads files this way to report what is wrong.
    Outcome<Done> assign_elements_unchecked(std::span<const Simplex> simplexes,
                                            std::span<const int> labels = {});

    // Thesis §7.3 replace-elements, with face reuse and the matched-pair optimisation: removes
    // `old_elements`, adds one element per new simplex. Faces whose simplex occurs both before
    // and after keep their FaceId. Returns the ids of the new elements in input order.
    //
    // Origins: new element i comes from old_elements[origins[i]] (a split child from its parent)
    // and takes that element's attribute values, and its label unless `labels` is given; with
    // `origins` empty every new element comes from old_elements[0]; with no old elements they
    // get the attributes' defaults and label 0. New elements get `labels[i]` when labels is not
    // empty.
    //
    // Refuses (mesh untouched) when: labels or origins have the wrong size or an origin is not
    // an index into old_elements; an old id is not an element or repeats; a new simplex has
    // the wrong size, a repeated vertex or an unknown vertex; two new simplexes have the same
    // vertices; a face occurs twice with the same orientation among the new simplexes; or a new
    // face already exists with the same orientation in an element that stays (invariant 7.4); or
    // the star of a vertex would no longer be face-connected (a pinched vertex).
    Outcome<std::vector<ElementId>> replace_elements(std::span<const ElementId> old_elements,
                                                     std::span<const Simplex> new_simplexes,
                                                     std::span<const int> labels = {},
                                                     std::span<const std::uint32_t> origins = {});
    // The same without the checks that walk vertex stars (a new face or element already in an
    // element that stays, invariant 7.4; pinched stars), for an operation that proved both from
    // its own checks. The proof is a token only ProvenEdit (core/src/mesh_checks.hpp, a private
    // header of the library's operations, which documents the obligations) can make.
    class StarChecksProof {
        StarChecksProof() = default;
        friend class ProvenEdit;
    };
    Outcome<std::vector<ElementId>> replace_elements(std::span<const ElementId> old_elements,
                                                     std::span<const Simplex> new_simplexes,
                                                     std::span<const int> labels,
                                                     std::span<const std::uint32_t> origins, StarChecksProof proof);

    // Thesis §7.3 change-elements: applies a vertex substitution per element, keeping every
    // element and face identity (Fig. 7.5). Refuses (mesh untouched) when an element is unknown
    // or repeats, a substituted simplex has a repeated or unknown vertex, two resulting elements
    // have the same vertices, a resulting face would exist twice with the same orientation, or
    // the star of a vertex would no longer be face-connected.
    Outcome<Done> change_elements(std::span<const ElementSubstitution> substitution);
    // The same without the checks that walk vertex stars, for an operation that proved them
    // (dissection: ProvenEdit::change, core/src/mesh_checks.hpp).
    Outcome<Done> change_elements(std::span<const ElementSubstitution> substitution, StarChecksProof proof);

    // ---- checking -----------------------------------------------------------------------------
    // Checks invariants 7.1-7.5, that no element or face is represented twice, vertex anchors,
    // and face-connected vertex stars. Returns the first broken invariant in words, e.g.
    // "invariant 7.3 (mate): face 12 of element 4 ...". O(n) expected time.
    // With ValidateOptions::orientation also the geometry, after the connectivity: the exact
    // orientation of every element in the reference and then the deformed positions (where the
    // topological dimension equals the ambient one; a triangle surface in space has no
    // orientation to check). An inverted element is invalid ("element 7 is inverted in the
    // deformed positions"), a flat one (orientation exactly zero) only with flat_is_invalid
    // ("element 7 is flat in the reference positions"). The refusal's item is the element.
    Outcome<Done> validate(const ValidateOptions& options = {}) const;

    // ---- watchers -----------------------------------------------------------------------------
    // The watcher must outlive its registration; it is initialised at once.
    void add_watcher(Watcher& watcher);
    void remove_watcher(Watcher& watcher);

    // ---- labels -------------------------------------------------------------------------------
    // The labels of the (d-1)-faces; `face` is any orientation of the face (the key is its
    // sorted vertices). set/erase are kept for rollback inside an EditJournal step; the mutable
    // map is the unobserved bulk path for readers.
    std::optional<int> face_label(const Simplex& face) const;
    void set_face_label(const Simplex& face, int label);
    // True when the face had a label.
    bool erase_face_label(const Simplex& face);
    FaceLabels& face_labels() { return m_face_labels; }
    const FaceLabels& face_labels() const { return m_face_labels; }
    // Names of labels, as files carry them (Gmsh $PhysicalNames: dimension d for element labels,
    // d-1 for face labels). Metadata for writers: no edit reads or changes them, so they are
    // neither journaled nor watched; copies and renumberings keep them.
    struct LabelNames {
        std::map<int, std::string> elements;
        std::map<int, std::string> faces;
        bool empty() const { return elements.empty() && faces.empty(); }
    };
    LabelNames& label_names() { return m_label_names; }
    const LabelNames& label_names() const { return m_label_names; }

    // ---- revisions ----------------------------------------------------------------------------
    // Changes with every observed change of the mesh (edits, vertex additions and removals,
    // moves, labels, attribute values set through set_vertex_attribute and set_element_attribute,
    // adding and removing attributes); never repeats. An undo
    // history uses it to refuse undoing over changes made outside it.
    std::uint64_t revision() const { return m_revision; }

    // Bytes held by the connectivity, geometry and attribute arrays (capacity, not size).
    std::size_t memory_bytes() const;

private:
    struct ElementRecord {
        Simplex simplex;                // count() == 0: free; then faces[0] is the next free id
        std::array<FaceId, 4> faces{invalid_id, invalid_id, invalid_id, invalid_id};
        int label = 0;
        // neighbors[i] = face_element(mate(faces[i])) or invalid_id: derived from the faces
        // (validate checks it), stored because star walks and ring walks are memory-bound and
        // the derivation costs two more dependent loads from the face pool per step.
        std::array<ElementId, 4> neighbors{invalid_id, invalid_id, invalid_id, invalid_id};
    };
    struct FaceRecord {
        ElementId element = invalid_id;  // invalid_id: free; then mate is the next free id
        FaceId mate = invalid_id;
    };
    friend class EditJournal;
    friend class detail::UndoLog;
    // change_elements' body; proven == true skips the star walks, as for replace_elements_impl.
    Outcome<Done> change_elements_impl(std::span<const ElementSubstitution> substitution, bool proven);
    // replace_elements' body. proven == true skips the checks that walk vertex stars (a new
    // face or element already in an element that stays, invariant 7.4; pinched stars): only
    // with a StarChecksProof.
    Outcome<std::vector<ElementId>> replace_elements_impl(std::span<const ElementId> old_elements,
                                                          std::span<const Simplex> new_simplexes,
                                                          std::span<const int> labels,
                                                          std::span<const std::uint32_t> origins, bool proven);
    // Its phases after the checks, in this order (core/src/replace_elements.cpp): labels,
    // inherited attribute values, old vertices and neighbours read while the old elements exist;
    // the old faces detached and the old elements freed; new face pairs made mates; the new
    // elements allocated onto reused and paired faces; their attribute rows written; their other
    // faces mated across the boundary or put on it; their neighbour cache set.
    void read_before_removal(detail::ReplacePlan& plan) const;
    void remove_old_elements(detail::ReplacePlan& plan, detail::EditLog& log);
    void pair_new_faces(detail::ReplacePlan& plan, detail::EditLog& log);
    void add_new_elements(detail::ReplacePlan& plan, detail::EditLog& log);
    void give_inherited_attributes(const detail::ReplacePlan& plan);
    void add_remaining_faces(detail::ReplacePlan& plan, detail::EditLog& log);
    void link_new_elements(const detail::ReplacePlan& plan);
    // Grows every element attribute to the element pool's size, new slots at the default.
    void grow_element_attributes();

    ElementId allocate_element();
    void free_element(ElementId t);
    FaceId allocate_face();
    void free_face(FaceId f);
    // True when sigma (a face, or a whole element by its vertices) exists in an element not in
    // the sorted list `excluded`; walks the star of sigma's first vertex.
    bool has_face_outside(const Simplex& sigma, std::span<const ElementId> excluded) const;
    // Number of face-connected pieces star(v) would have after removing the sorted elements
    // `removed` and adding `added` (0 when v would be in no element). Walks star(v) once.
    std::size_t star_pieces_after(VertexId v, std::span<const ElementId> removed,
                                  std::span<const Simplex> added) const;
    // The refusal of an edit that would pinch one of the vertices `touched` (any order,
    // repeats allowed), or nothing.
    std::optional<Refusal> refuse_pinched_stars(std::vector<VertexId> touched,
                                                std::span<const ElementId> removed,
                                                std::span<const Simplex> added) const;
    // Recomputes neighbors[] of t from its faces' mates, and the entry of each mate's element
    // that points back (the edit primitives call it for every element whose faces they set).
    void link_neighbors(ElementId t);
    void link_neighbor(ElementId t, int i);  // the same for slot i only
    // f lost its mate (it is on the boundary now): its element's neighbour entry is cleared.
    void unlink_neighbor(FaceId f);
    // After an edit: vertices of the elements `added` (ids `added_ids`) get an anchor if theirs
    // no longer holds them; vertices of `old_vertices` that lost theirs take one of
    // `neighbours` (elements next to the edited ones) that contains them, or none.
    // `edited_sorted`: the ids the edit removed or substituted (sorted); other anchors hold.
    void repair_anchors(std::span<const Simplex> added, std::span<const ElementId> added_ids,
                        std::span<const VertexId> old_vertices,
                        std::span<const ElementId> neighbours,
                        std::span<const ElementId> edited_sorted);
    // ---- the EditJournal's record (core/src/undo_log.hpp), non-null only inside a step ------
    // True when a position store must be observed (watchers, or a step recording).
    bool observed() const { return m_undo != nullptr || !m_watchers.empty(); }
    void set_position(VertexId v, const Point& p, PositionSet which);
    // Each keeps the state that is about to change; the mesh calls them before every store into
    // its pools, anchors and boundary map while a step is open. An element or face is kept once
    // per stretch (m_noted).
    void note_element(ElementId t);
    void note_face(FaceId f);
    void note_anchor(VertexId v);
    void note_pools();  // free lists, counts and pool sizes, at the start of every edit
    // The boundary map's stores, recorded.
    void boundary_insert(const Simplex& sigma, FaceId f);
    void boundary_erase(const Simplex& sigma);
    // Writable records, recorded first (the edit primitives store through these).
    ElementRecord& element_for_write(ElementId t) {
        if (m_undo != nullptr) note_element(t);
        return m_elements[t];
    }
    FaceRecord& face_for_write(FaceId f) {
        if (m_undo != nullptr) note_face(f);
        return m_faces[f];
    }
    void set_anchor(VertexId v, ElementId t) {
        if (m_undo != nullptr) note_anchor(v);
        count_anchor(m_vertex_element[v], t);
        m_vertex_element[v] = t;
    }
    // Keeps vertices_in_elements() as a vertex's anchor goes from `was` to `now`.
    void count_anchor(ElementId was, ElementId now) {
        m_vertices_in_elements += std::size_t{now != invalid_id} - std::size_t{was != invalid_id};
    }
    // Recounts it after the anchors were set in bulk. O(vertices).
    void recount_anchors();
    // move_vertices' checks of a move (its vertices in range, its points finite): no vertex
    // listed twice and, as `check` asks, no element around them inverted or flat after it. The
    // elements around them are the caller's walks when they fit (walk_star).
    Outcome<Done> check_move(std::span<const VertexId> vertices, std::span<const Point> points, PositionSet which,
                             const MoveCheck& check);

    int m_dimension;
    int m_ambient;
    // the arrays that grow with the mesh: huge pages when large (sxk/detail/large_array.hpp)
    detail::LargeVector<Point> m_reference;
    detail::LargeVector<Point> m_deformed;
    detail::LargeVector<ElementId> m_vertex_element;
    std::size_t m_vertices_in_elements = 0;  // anchors that name an element
    detail::LargeVector<ElementRecord> m_elements;
    detail::LargeVector<FaceRecord> m_faces;
    ElementId m_free_element = invalid_id;
    FaceId m_free_face = invalid_id;
    std::size_t m_element_count = 0;
    detail::BoundaryMap m_boundary;
    FaceLabels m_face_labels;
    LabelNames m_label_names;
    std::vector<detail::AttributeColumn> m_attributes;          // vertex attributes
    std::vector<detail::AttributeColumn> m_element_attributes;  // sized to the element pool
    std::vector<Watcher*> m_watchers;
    EditJournal* m_journal = nullptr;   // the journal attached, not copied
    detail::UndoLog* m_undo = nullptr;  // its open step's record, not copied
    // The elements and faces the open step's record kept since its last checkpoint or rollback
    // (a stretch: no rollback can end inside one). A replay puts back the first state it kept of
    // each, so a second store into one in the same stretch needs no record of its own: an AMP
    // bisection stores into each new element once per face (docs/performance.md "A record per
    // element and stretch"). Not copied, a scratch.
    struct Noted {
        detail::IdMarks elements, faces;
    };
    Noted m_noted;
    void new_record_stretch();  // EditJournal, at each checkpoint and rollback
    std::uint64_t m_revision = 0;
    // the move being told (elements_around_moved), and the elements around it once found: not
    // copied, a scratch kept between moves. m_around_seen: the elements listed (each once without
    // a sort); m_move_slot: per vertex, its index in the move being checked, or none (the check's
    // positions without a search)
    std::span<const VertexId> m_moving;
    mutable std::vector<ElementId> m_around_moved;
    mutable bool m_around_moved_found = false;
    mutable detail::IdMarks m_around_seen;
    detail::LargeVector<std::uint32_t> m_move_slot;
    // the star walks since begin_star_walks() (walk_star), of the mesh at `revision`: the
    // vertices walked (how many, and each marked), their stars' union (each element marked), and
    // the last star walked
    struct StarWalks {
        bool open = false;
        std::uint64_t revision = 0;
        std::size_t walked = 0;
        detail::IdMarks vertices, elements;
        std::vector<ElementId> around, last;
    };
    mutable StarWalks m_walks;
    // the walks are of this mesh as it is, and of exactly `vertices` (each listed once)
    bool walked_exactly(std::span<const VertexId> vertices) const;
    // The scratch of moves and walks (m_move_slot, m_around_seen, m_walks' marks) for every vertex
    // and element id of the mesh as it is.
    void size_move_scratch();
    // A move's new revision. Walks current before it stay current: a move changes no star, so a
    // caller that gathers a region once and writes it frame after frame walks it once.
    void count_move();
    friend class MovingVertices;
};

// Attaches a watcher for the lifetime of the object, early returns and exceptions included.
class ScopedWatcher {
public:
    ScopedWatcher(Mesh& mesh, Watcher& watcher) : m_mesh(mesh), m_watcher(watcher) { mesh.add_watcher(watcher); }
    ~ScopedWatcher() { m_mesh.remove_watcher(m_watcher); }
    ScopedWatcher(const ScopedWatcher&) = delete;
    ScopedWatcher& operator=(const ScopedWatcher&) = delete;

private:
    Mesh& m_mesh;
    Watcher& m_watcher;
};

// Iterates the ids of live elements: for (ElementId t : elements(mesh)).
class ElementRange {
public:
    class Iterator {
    public:
        Iterator(const Mesh* mesh, ElementId t) : m_mesh(mesh), m_t(t) { skip(); }
        ElementId operator*() const { return m_t; }
        Iterator& operator++() {
            ++m_t;
            skip();
            return *this;
        }
        bool operator==(const Iterator& other) const { return m_t == other.m_t; }

    private:
        void skip() {
            while (m_t < m_mesh->element_capacity() && !m_mesh->is_element(m_t)) ++m_t;
        }
        const Mesh* m_mesh;
        ElementId m_t;
    };
    explicit ElementRange(const Mesh& mesh) : m_mesh(&mesh) {}
    Iterator begin() const { return {m_mesh, 0}; }
    Iterator end() const { return {m_mesh, static_cast<ElementId>(m_mesh->element_capacity())}; }

private:
    const Mesh* m_mesh;
};
inline ElementRange elements(const Mesh& mesh) { return ElementRange(mesh); }

}  // namespace sxk
