// The operation driver shared by the operation fuzzer (fuzz/fuzz_ops.cpp) and the random
// operation property test (tests/ops/random_ops_test.cpp): a stream of choices (fuzzer bytes or
// a seeded generator) picks a start mesh and then one local operation after the other with its
// arguments, and the oracle checks every step (CONTRIBUTING.md "Tests": the fuzzers use the validator as their oracle).
//
// Oracle, after EVERY operation:
//   1. validate() is ok;
//   2. a refused operation left the mesh bit for bit as it was: a full snapshot (positions as
//      bit patterns, vertex anchors, every element slot with simplex, label and faces, every
//      face slot with element and mate, the boundary, face labels, vertex and element attribute
//      values)
//      compares equal to the one taken before;
//   3. after a successful operation every element is strictly positive by exact orientation in
//      both the reference and the deformed positions (triangles in space: not degenerate);
//   4. the vertex attribute "where", registered at the start as each vertex's reference
//      position, still is (within rounding) the reference position of every vertex: splits
//      interpolate attributes with the weights of the position, collapses to a point on the
//      edge interpolate along the edge, dissect copies;
//   5. the element attribute "box", stamped at the start of each step with every element's
//      reference bounding box, holds after a subdivision (splits, dissection, bisections,
//      refine-around) every element: a child takes its parent's values (replace_elements'
//      origins) and lies inside its parent.
// A broken rule comes back as a non-empty message naming the step and the operation.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "sxk/generators.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"
#include "sxk/ops/flip_44.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/make_delaunay_by_flips.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/split_element.hpp"
#include "sxk/ops/split_face.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"
// Operations written in parallel with this driver join when their headers exist.
#if __has_include("sxk/ops/remove_node.hpp")
#include "sxk/ops/remove_node.hpp"
#define SXK_OPS_DRIVER_HAS_REMOVE_NODE 1
#endif
#if __has_include("sxk/ops/bisect_edge.hpp")
#include "sxk/ops/bisect_edge.hpp"
#define SXK_OPS_DRIVER_HAS_BISECT_EDGE 1
#endif
#if __has_include("sxk/ops/refine_around.hpp")
#include "sxk/ops/refine_around.hpp"
#define SXK_OPS_DRIVER_HAS_REFINE_AROUND 1
#endif
#if __has_include("sxk/ops/refine_around_tetrahedra.hpp")
#include "sxk/ops/refine_around_tetrahedra.hpp"
#define SXK_OPS_DRIVER_HAS_REFINE_AROUND_TETRAHEDRA 1
#endif

namespace sxk::ops_driver {

// The choices: next() gives a value in [0, 256); `exhausted` turns true when a fuzzer input runs
// out (next() then gives 0). index(n) picks in [0, n) with one choice, or two when n > 256.
class Choices {
public:
    explicit Choices(std::function<int()> source) : m_source(std::move(source)) {}
    std::uint32_t next() {
        const int value = m_source();
        if (value < 0) {
            exhausted = true;
            return 0;
        }
        return static_cast<std::uint32_t>(value) & 0xffu;
    }
    std::uint32_t index(std::size_t n) {
        if (n == 0) return 0;
        std::uint32_t value = next();
        if (n > 256) value = value << 8 | next();
        return static_cast<std::uint32_t>(value % n);
    }
    bool exhausted = false;

private:
    std::function<int()> m_source;
};

// ---- snapshot ---------------------------------------------------------------------------------

struct Snapshot {
    std::vector<std::uint64_t> positions;  // bit patterns, reference then deformed per vertex
    std::vector<ElementId> anchors;
    std::vector<std::int64_t> elements;  // per slot: live, sign, vertices, label, faces, neighbours
    std::vector<std::uint32_t> faces;    // per slot: element id, mate face id
    std::vector<FaceId> boundary;
    FaceLabels face_labels;
    std::vector<std::uint64_t> attributes;
    bool operator==(const Snapshot&) const = default;
};

inline Snapshot snapshot(const Mesh& mesh) {
    Snapshot s;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        for (const double x : mesh.reference(v)) s.positions.push_back(std::bit_cast<std::uint64_t>(x));
        for (const double x : mesh.deformed(v)) s.positions.push_back(std::bit_cast<std::uint64_t>(x));
        s.anchors.push_back(mesh.vertex_element(v));
    }
    for (ElementId t = 0; t < mesh.element_capacity(); ++t) {
        s.elements.push_back(mesh.is_element(t));
        if (!mesh.is_element(t)) continue;
        const Simplex& tau = mesh.simplex(t);
        s.elements.push_back(tau.sign());
        for (const VertexId v : tau.vertices()) s.elements.push_back(v);
        s.elements.push_back(mesh.label(t));
        for (const FaceId f : mesh.faces(t)) s.elements.push_back(f);
        for (int i = 0; i < tau.count(); ++i) s.elements.push_back(mesh.neighbor(t, i));
    }
    for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
        s.faces.push_back(mesh.is_face(f) ? mesh.face_element(f) : ElementId{invalid_id});
        s.faces.push_back(mesh.is_face(f) ? mesh.mate(f) : FaceId{invalid_id});
    }
    s.boundary = mesh.boundary_faces();
    s.face_labels = mesh.face_labels();
    for (const AttributeId a : mesh.vertex_attributes()) {
        s.attributes.push_back(a);
        for (VertexId v = 0; v < mesh.vertex_count(); ++v)
            for (const double x : mesh.vertex_attribute(a, v))
                s.attributes.push_back(std::bit_cast<std::uint64_t>(x));
    }
    for (const AttributeId a : mesh.element_attributes()) {
        s.attributes.push_back(a);
        for (const ElementId t : elements(mesh))
            for (const double x : mesh.element_attribute(a, t))
                s.attributes.push_back(std::bit_cast<std::uint64_t>(x));
    }
    return s;
}

// ---- checks -----------------------------------------------------------------------------------

// Empty, or the first element that is not strictly positive in one of the position sets.
inline std::string first_bad_element(const Mesh& mesh, std::span<const ElementId> which) {
    const bool surface = mesh.topological_dimension() < mesh.ambient_dimension();
    for (const ElementId t : which) {
        if (!mesh.is_element(t)) continue;
        for (const Positions p : {Positions::reference, Positions::deformed}) {
            const Sign s = element_orientation(mesh, t, p);
            if (surface ? s == Sign::zero : s != Sign::positive)
                return "element " + std::to_string(t) + " " + to_text(mesh.simplex(t)) + " is " +
                       (s == Sign::zero ? "flat" : "inverted") + " in the " +
                       (p == Positions::reference ? "reference" : "deformed") + " positions";
        }
    }
    return {};
}

inline std::vector<ElementId> live_elements(const Mesh& mesh) {
    std::vector<ElementId> all;
    for (const ElementId t : elements(mesh)) all.push_back(t);
    return all;
}

// Registers "where" = reference position on every vertex (checked by check_where).
inline void add_where(Mesh& mesh) {
    const AttributeId where = *mesh.add_vertex_attribute("where", 3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const auto value = mesh.vertex_attribute(where, v);
        std::copy(mesh.reference(v).begin(), mesh.reference(v).end(), value.begin());
    }
}

inline std::string check_where(const Mesh& mesh, VertexId from = 0) {
    const AttributeId where = mesh.find_vertex_attribute("where");
    if (where == invalid_id) return {};
    for (VertexId v = from; v < mesh.vertex_count(); ++v) {
        const auto value = mesh.vertex_attribute(where, v);
        for (std::size_t k = 0; k < 3; ++k)
            if (!(std::abs(value[k] - mesh.reference(v)[k]) <= 1e-9 * (1 + std::abs(mesh.reference(v)[k]))))
                return "attribute \"where\" of vertex " + std::to_string(v) + " is " +
                       std::to_string(value[k]) + ", its reference position " +
                       std::to_string(mesh.reference(v)[k]) + " (coordinate " + std::to_string(k) + ")";
    }
    return {};
}

// The reference bounding box of element t: min x, y, z, then max x, y, z.
inline std::array<double, 6> element_box(const Mesh& mesh, ElementId t) {
    std::array<double, 6> box{};
    const Simplex& tau = mesh.simplex(t);
    for (int j = 0; j < tau.count(); ++j)
        for (std::size_t k = 0; k < 3; ++k) {
            const double x = mesh.reference(tau.vertex(j))[k];
            box[k] = j == 0 ? x : std::min(box[k], x);
            box[k + 3] = j == 0 ? x : std::max(box[k + 3], x);
        }
    return box;
}

// Sets "box" (registered by start_mesh) to each element's bounding box where it differs, with
// the recorded setter (inside an EditJournal step the rollback puts the old values back).
inline void stamp_boxes(Mesh& mesh) {
    const AttributeId box = mesh.find_element_attribute("box");
    if (box == invalid_id) return;
    for (const ElementId t : elements(mesh)) {
        const std::array<double, 6> now = element_box(mesh, t);
        const auto held = mesh.element_attribute(box, t);
        if (!std::equal(now.begin(), now.end(), held.begin())) (void)mesh.set_element_attribute(box, t, now);
    }
}

// Empty, or the first element that does not lie in its "box" (within rounding).
inline std::string check_boxes(const Mesh& mesh) {
    const AttributeId box = mesh.find_element_attribute("box");
    if (box == invalid_id) return {};
    for (const ElementId t : elements(mesh)) {
        const std::array<double, 6> now = element_box(mesh, t);
        const auto held = mesh.element_attribute(box, t);
        for (std::size_t k = 0; k < 3; ++k) {
            const double slack = 1e-12 * (1 + std::abs(held[k]) + std::abs(held[k + 3]));
            if (now[k] < held[k] - slack || now[k + 3] > held[k + 3] + slack)
                return "element " + std::to_string(t) + " leaves the box it inherited along coordinate " +
                       std::to_string(k) + ": [" + std::to_string(now[k]) + ", " + std::to_string(now[k + 3]) +
                       "] in [" + std::to_string(held[k]) + ", " + std::to_string(held[k + 3]) + "]";
        }
    }
    return {};
}

// ---- start meshes -----------------------------------------------------------------------------

// Moves every interior vertex of a unit grid (coordinates strictly between 0 and the largest)
// by up to `jitter` per coordinate, keeping a move only if its star stays strictly positive.
inline void jitter_interior(Mesh& mesh, double jitter, Choices& choices) {
    double largest = 0;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (const double x : mesh.reference(v)) largest = std::max(largest, x);
    const auto dimensions = static_cast<std::size_t>(mesh.ambient_dimension());
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point p = mesh.reference(v);
        bool interior = true;
        for (std::size_t k = 0; k < dimensions; ++k) interior = interior && p[k] > 0 && p[k] < largest;
        if (!interior) continue;
        Point q = p;
        for (std::size_t k = 0; k < dimensions; ++k)
            q[k] += jitter * ((static_cast<double>(choices.next()) - 127.5) / 127.5);
        mesh.set_reference(v, q);
        mesh.set_deformed(v, q);
        const std::vector<ElementId> around = star(mesh, v);
        if (!first_bad_element(mesh, around).empty()) {
            mesh.set_reference(v, p);
            mesh.set_deformed(v, p);
        }
    }
}

// Planar n x n grid (two triangles per square), interior vertices jittered by up to `jitter`
// (choices decide), labels 1 on the left half and 0 on the right (two materials).
inline Mesh jittered_grid(int n, double jitter, Choices& choices) {
    Mesh mesh(2, 2);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            mesh.add_vertex({double(i), double(j), 0});
        }
    auto id = [n](int i, int j) { return VertexId(j * (n + 1) + i); };
    std::vector<Simplex> triangles;
    std::vector<int> labels;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            triangles.emplace_back(+1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            triangles.emplace_back(+1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            labels.push_back(2 * i < n ? 1 : 0);
            labels.push_back(2 * i < n ? 1 : 0);
        }
    (void)mesh.assign_elements(triangles, labels);
    jitter_interior(mesh, jitter, choices);
    return mesh;
}

// The closed surface of an octahedron in space, outward normals, scaled by `size`.
inline Mesh octahedron(double size) {
    Mesh mesh(2, 3);
    const std::array<Point, 6> corners{{{size, 0, 0}, {-size, 0, 0}, {0, size, 0}, {0, -size, 0},
                                        {0, 0, size}, {0, 0, -size}}};
    for (const Point& p : corners) mesh.add_vertex(p);
    // +x 0, -x 1, +y 2, -y 3, +z 4, -z 5; counter-clockwise seen from outside
    const std::vector<Simplex> triangles{
        Simplex(+1, {0, 2, 4}), Simplex(+1, {2, 1, 4}), Simplex(+1, {1, 3, 4}), Simplex(+1, {3, 0, 4}),
        Simplex(+1, {2, 0, 5}), Simplex(+1, {1, 2, 5}), Simplex(+1, {3, 1, 5}), Simplex(+1, {0, 3, 5})};
    std::vector<int> labels{0, 0, 0, 0, 1, 1, 1, 1};
    (void)mesh.assign_elements(triangles, labels);
    return mesh;
}

// Kuhn cube of n^3 cubes with 6 tetrahedra each (sxk::make_kuhn_cube); label 1 for the lower
// half, 0 above.
inline Mesh kuhn_cube(int n, double jitter, Choices& choices) {
    Mesh mesh = std::move(make_kuhn_cube(n)).value();
    const auto layer = static_cast<ElementId>(6 * n * n);  // elements per layer of cubes
    for (const ElementId t : elements(mesh)) mesh.set_label(t, 2 * static_cast<int>(t / layer) < n ? 1 : 0);
    jitter_interior(mesh, jitter, choices);
    return mesh;
}

// Doubles every deformed position (exactly), so that the two position sets differ while both
// stay positive: the ops must check and interpolate both.
inline void scale_deformed(Mesh& mesh) {
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        Point p = mesh.reference(v);
        for (double& x : p) x *= 2;
        mesh.set_deformed(v, p);
    }
}

// The start mesh chosen by one choice: 0 jittered planar grid, 1 planar random points (grid +
// split_element at random weights + Lawson flips), 2 octahedron surface, 3 Kuhn cube.
inline Mesh start_mesh(Choices& choices, int grid = 3, int cube = 2) {
    const std::uint32_t kind = choices.next() % 4;
    const bool scaled = choices.next() % 2 == 1;
    Mesh mesh(2, 2);
    if (kind == 0) {
        mesh = jittered_grid(grid, 0.3, choices);
    } else if (kind == 1) {
        mesh = jittered_grid(1, 0, choices);
        for (int i = 0; i < grid * grid; ++i) {
            const ElementId t = static_cast<ElementId>(choices.index(mesh.element_capacity()));
            std::array<double, 3> w{};
            for (double& x : w) x = 1 + choices.next();
            if (mesh.is_element(t)) (void)split_element(mesh, t, w);
        }
        (void)make_delaunay_by_flips(mesh);
    } else if (kind == 2) {
        mesh = octahedron(1);
    } else {
        mesh = kuhn_cube(cube, 0.25, choices);
    }
    if (scaled) scale_deformed(mesh);
    add_where(mesh);
    (void)mesh.add_element_attribute("box", 6);
    stamp_boxes(mesh);
    // face labels on the boundary (Medit/Gmsh references): 10 + a choice mod 3, so that ops
    // must carry them (validate() checks each names a face of the mesh)
    for (const FaceId f : mesh.boundary_faces())
        mesh.face_labels()[Simplex(+1, mesh.face_simplex(f).vertices())] = 10 + static_cast<int>(choices.next() % 3);
    return mesh;
}

// ---- one step ---------------------------------------------------------------------------------

struct Step {
    std::string operation;  // name and arguments, for messages
    bool done = false;      // the operation succeeded
    std::string finding;    // non-empty: the oracle failed
};

// A live element: an id in [0, capacity) moved on to the next live one (invalid_id if none).
inline ElementId pick_element(const Mesh& mesh, Choices& choices) {
    const std::size_t n = mesh.element_capacity();
    if (mesh.element_count() == 0) return invalid_id;
    ElementId t = choices.index(n);
    while (!mesh.is_element(t)) t = static_cast<ElementId>((t + 1) % n);
    return t;
}

inline std::string at(const char* name, std::initializer_list<std::uint64_t> args) {
    std::string text = std::string(name) + "(";
    bool first = true;
    for (const auto a : args) {
        text += (first ? "" : ", ") + std::to_string(a);
        first = false;
    }
    return text + ")";
}

inline constexpr int operation_kinds = 16;

// Picks one operation with its arguments and runs it; `max_elements` bounds the growth (splits
// are skipped above it). `check_all` checks orientation of every element; otherwise only the
// elements the operation returned or changed (validate() still runs on the whole mesh).
inline Step run_step(Mesh& mesh, Choices& choices, std::size_t max_elements) {
    Step step;
    stamp_boxes(mesh);
    const Snapshot before = snapshot(mesh);
    const std::size_t vertices_before = mesh.vertex_count();
    const int d = mesh.topological_dimension();
    const int kind = static_cast<int>(choices.next() % operation_kinds);
    const ElementId t = pick_element(mesh, choices);
    if (t == invalid_id) return step;
    const int slot = static_cast<int>(choices.next() % static_cast<std::uint32_t>(d + 1));
    const FaceId f = mesh.face(t, slot);
    const Simplex tau = mesh.simplex(t);
    const bool may_grow = mesh.element_count() < max_elements;
    std::string reason;
    auto record = [&](auto&& outcome) {
        step.done = outcome.ok();
        if (!step.done) reason = outcome.reason();
    };
    switch (kind) {
    case 0:
        step.operation = at("flip_edge", {f});
        record(flip_edge(mesh, f));
        break;
    case 1:
        step.operation = at("flip_23", {f});
        record(flip_23(mesh, f));
        break;
    case 2: {
        const int j = static_cast<int>(choices.next() % 3);
        step.operation = at("flip_32", {f, static_cast<std::uint64_t>(j)});
        record(flip_32(mesh, f, j));
        break;
    }
    case 3: {
        const int j = static_cast<int>(choices.next() % 3);
        const int diagonal = static_cast<int>(choices.next() % 2);
        step.operation = at("flip_44", {f, static_cast<std::uint64_t>(j), static_cast<std::uint64_t>(diagonal)});
        record(flip_44(mesh, f, j, diagonal));
        break;
    }
    case 4: {
        if (!may_grow) return step;
        const VertexId a = tau.vertex(slot), b = tau.vertex((slot + 1 + static_cast<int>(choices.next() % static_cast<std::uint32_t>(d))) % (d + 1));
        const double s = (1.0 + choices.next()) / 257.0;
        step.operation = at("split_edge", {a, b}) + " at " + std::to_string(s);
        record(split_edge(mesh, a, b, s));
        break;
    }
    case 5: {
        if (!may_grow) return step;
        std::array<double, 3> w{};
        for (double& x : w) x = 1.0 + choices.next();
        step.operation = at("split_face", {f});
        record(split_face(mesh, f, w));
        break;
    }
    case 6: {
        if (!may_grow) return step;
        std::vector<double> w(static_cast<std::size_t>(d + 1));
        for (double& x : w) x = 1.0 + choices.next();
        step.operation = at("split_element", {t});
        record(split_element(mesh, t, w));
        break;
    }
    case 7:
    case 8: {
        const VertexId from = tau.vertex(slot);
        const VertexId to = tau.vertex((slot + 1 + static_cast<int>(choices.next() % static_cast<std::uint32_t>(d))) % (d + 1));
        if (kind == 7) {
            step.operation = at("collapse_edge", {from, to});
            record(collapse_edge(mesh, from, to));
        } else {
            Point r{}, g{};
            for (std::size_t k = 0; k < 3; ++k) {
                r[k] = 0.5 * (mesh.reference(from)[k] + mesh.reference(to)[k]);
                g[k] = 0.5 * (mesh.deformed(from)[k] + mesh.deformed(to)[k]);
            }
            step.operation = at("collapse_edge to the midpoint", {from, to});
            record(collapse_edge(mesh, from, to, r, g));
        }
        break;
    }
    case 9: {
        std::vector<Simplex> cut{mesh.face_simplex(f)};
        const std::uint32_t more = choices.next() % 3;
        for (std::uint32_t i = 0; i < more; ++i) {
            const ElementId u = pick_element(mesh, choices);
            const FaceId g = mesh.face(u, static_cast<int>(choices.next() % static_cast<std::uint32_t>(d + 1)));
            // a face of C counts with its mate: either orientation
            cut.push_back(choices.next() % 2 ? mesh.face_simplex(g) : mesh.face_simplex(g).mate());
        }
        step.operation = "dissect(" + std::to_string(cut.size()) + " faces from " + to_text(cut[0]) + ")";
        record(dissect(mesh, cut));
        break;
    }
    case 10:
        step.operation = "make_delaunay_by_flips";
        record(make_delaunay_by_flips(mesh, choices.next() % 2 ? Positions::reference : Positions::deformed));
        break;
    case 11: {
#ifdef SXK_OPS_DRIVER_HAS_REMOVE_NODE
        const VertexId v = tau.vertex(slot);
        step.operation = at("remove_node", {v});
        record(remove_node(mesh, v, choices.next() % 2 ? Positions::reference : Positions::deformed));
#endif
        break;
    }
    case 12: {
#ifdef SXK_OPS_DRIVER_HAS_BISECT_EDGE
        if (!may_grow) return step;
        const VertexId a = tau.vertex(slot), b = tau.vertex((slot + 1) % (d + 1));
        step.operation = at("bisect_edge", {a, b});
        record(bisect_edge(mesh, a, b));
#endif
        break;
    }
    case 13: {
        // one refinement can add hundreds of elements: only on meshes at most half the bound
        if (2 * mesh.element_count() >= max_elements) return step;
        // a point inside element t (reference positions) and a size of 1/4 to 1 grid cells
        Point x{0, 0, 0};
        double total = 0;
        std::array<double, 4> w{};
        for (int j = 0; j <= d; ++j) total += w[static_cast<std::size_t>(j)] = 1.0 + choices.next();
        for (int j = 0; j <= d; ++j)
            for (std::size_t k = 0; k < 3; ++k)
                x[k] += w[static_cast<std::size_t>(j)] / total * mesh.reference(tau.vertex(j))[k];
        const double h = 0.25 + choices.next() / 340.0;
        const std::string where = "(" + std::to_string(x[0]) + ", " + std::to_string(x[1]) + ", " +
                                  std::to_string(x[2]) + "; h = " + std::to_string(h) + ")";
        if (d == 2) {
#ifdef SXK_OPS_DRIVER_HAS_REFINE_AROUND
            step.operation = "refine_around" + where;
            record(refine_around(mesh, x, h, choices.next() % 2 ? t : ElementId{invalid_id}));
#endif
        } else {
#ifdef SXK_OPS_DRIVER_HAS_REFINE_AROUND_TETRAHEDRA
            step.operation = "refine_around_tetrahedra" + where;
            record(refine_around_tetrahedra(mesh, x, h));
#endif
        }
        break;
    }
    case 14: {
        // an element (and, half the time, a neighbour): refused when it would pinch a star; not
        // on small meshes, which removals would empty (the tests write their meshes)
        if (mesh.element_count() < 12) return step;
        std::vector<ElementId> doomed{t};
        if (choices.next() % 2 && mesh.neighbor(t, slot) != invalid_id) doomed.push_back(mesh.neighbor(t, slot));
        step.operation = at("remove_elements", {t});
        record(remove_elements(mesh, doomed));
        break;
    }
    default: {
        // arguments out of range or degenerate: every op must refuse and touch nothing
        const std::uint32_t which = choices.next() % 6;
        const auto nv = static_cast<VertexId>(mesh.vertex_count());
        const auto nf = static_cast<FaceId>(mesh.face_capacity());
        const auto ne = static_cast<ElementId>(mesh.element_capacity());
        const std::array<double, 3> zero{0, 1, 1};
        const std::array<Simplex, 1> wrong{Simplex(+1, {0, 1})};
        step.operation = "bad arguments " + std::to_string(which);
        if (which == 0) record(split_edge(mesh, nv, 0));
        else if (which == 1) record(flip_edge(mesh, nf + 1));
        else if (which == 2) record(collapse_edge(mesh, tau.vertex(0), tau.vertex(0)));
        else if (which == 3) record(split_element(mesh, ne));
        else if (which == 4) record(split_face(mesh, f, zero));
        else if (d == 3) record(dissect(mesh, wrong));
        else record(split_edge(mesh, tau.vertex(0), tau.vertex(1), 1.0));
        if (step.done) step.finding = step.operation + " succeeded";
        return step;
    }
    }
    if (step.operation.empty()) return step;
    if (const auto valid = mesh.validate(); !valid.ok()) {
        step.finding = step.operation + (step.done ? " (done)" : " (refused: " + reason + ")") +
                       " left an invalid mesh: " + valid.reason();
        return step;
    }
    if (!step.done) {
        if (reason.empty()) step.finding = step.operation + " refused without a reason";
        else if (!(snapshot(mesh) == before))
            step.finding = step.operation + " refused (" + reason + ") but changed the mesh";
        return step;
    }
    if (std::string bad = first_bad_element(mesh, live_elements(mesh)); !bad.empty()) {
        step.finding = step.operation + " made " + bad;
        return step;
    }
    if (std::string bad = check_where(mesh, kind == 8 ? 0 : static_cast<VertexId>(vertices_before)); !bad.empty()) {
        step.finding = step.operation + ": " + bad;
        return step;
    }
    const bool subdivision = kind == 4 || kind == 5 || kind == 6 || kind == 9 || kind == 12 || kind == 13;
    if (std::string bad = subdivision ? check_boxes(mesh) : std::string(); !bad.empty())
        step.finding = step.operation + ": " + bad;
    return step;
}

}  // namespace sxk::ops_driver
