// Small meshes drawn by hand, shared by the kernel tests, and a state comparison for the
// transaction guarantee.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "sxk/generators.hpp"
#include "sxk/mesh.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {

// The seed of a randomised test: SXK_SEED if set, else a random one; printed as
// "[ seed     ] NAME SXK_SEED=S" and recorded as a test property, so that a failure replays.
inline std::uint64_t seed_for(const char* name) {
    std::uint64_t seed = std::random_device{}();
    if (const char* fixed = std::getenv("SXK_SEED")) seed = std::strtoull(fixed, nullptr, 10);
    std::cout << "[ seed     ] " << name << " SXK_SEED=" << seed << std::endl;
    ::testing::Test::RecordProperty("seed", std::to_string(seed));
    return seed;
}

// Similarity signature of a tetrahedron (reference positions): the six squared edge lengths,
// sorted, divided by the largest, rounded to 1e-7. Similar tetrahedra (mirror images included) have
// equal signatures: what the bisection tests count shapes by.
using ShapeSignature = std::array<long long, 6>;
inline ShapeSignature shape_signature(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    std::array<double, 6> lengths{};
    std::size_t next = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            const Point& a = mesh.reference(s.vertex(i));
            const Point& b = mesh.reference(s.vertex(j));
            lengths[next++] = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
        }
    std::sort(lengths.begin(), lengths.end());
    ShapeSignature signature{};
    for (std::size_t k = 0; k < 6; ++k) signature[k] = std::llround(lengths[k] / lengths[5] * 1e7);
    return signature;
}

//   d(3) ------- c(2)
//    |        /  |          two counter-clockwise triangles <0,1,2> and <0,2,3>
//    |   B  /    |          sharing the diagonal 0-2
//    |    /   A  |
//    |  /        |
//   a(0) ------- b(1)
inline Mesh unit_square() {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({1, 1, 0});
    mesh.add_vertex({0, 1, 0});
    const std::array<Simplex, 2> triangles{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})};
    EXPECT_TRUE(mesh.assign_elements(triangles).ok());
    return mesh;
}

// A planar n x n grid of unit squares, each split along its diagonal (2 n^2 triangles).
inline Mesh planar_grid(int n) {
    Mesh mesh(2, 2);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) mesh.add_vertex({double(i), double(j), 0});
    auto id = [n](int i, int j) { return VertexId(j * (n + 1) + i); };
    std::vector<Simplex> triangles;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            triangles.emplace_back(+1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            triangles.emplace_back(+1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    EXPECT_TRUE(mesh.assign_elements(triangles).ok());
    return mesh;
}

// A Kuhn (Freudenthal) cube mesh: n^3 unit cubes of 6 tetrahedra each, all sharing the cube's
// main diagonal (0,0,0)-(1,1,1) and positively oriented. n = 8 gives the thesis' 729-node,
// 3072-tetrahedron cube.
inline Mesh kuhn_cube(int n) {
    auto made = make_kuhn_cube(n);
    EXPECT_TRUE(made.ok()) << made.reason();
    Mesh mesh = std::move(made).value();
    // label each tetrahedron by its path (0..5), so that label-aware code sees six materials
    for (const ElementId t : elements(mesh)) mesh.set_label(t, static_cast<int>(t % 6));
    return mesh;
}

// Everything observable through the public interface, for "bit-identical after a refusal".
inline void expect_same_state(const Mesh& a, const Mesh& b) {
    ASSERT_EQ(a.vertex_count(), b.vertex_count());
    ASSERT_EQ(a.element_capacity(), b.element_capacity());
    ASSERT_EQ(a.face_capacity(), b.face_capacity());
    ASSERT_EQ(a.element_count(), b.element_count());
    for (VertexId v = 0; v < a.vertex_count(); ++v) {
        EXPECT_EQ(a.reference(v), b.reference(v));
        EXPECT_EQ(a.deformed(v), b.deformed(v));
        EXPECT_EQ(a.vertex_element(v), b.vertex_element(v));
    }
    for (ElementId t = 0; t < a.element_capacity(); ++t) {
        ASSERT_EQ(a.is_element(t), b.is_element(t));
        if (!a.is_element(t)) continue;
        EXPECT_EQ(a.simplex(t), b.simplex(t));
        EXPECT_EQ(a.label(t), b.label(t));
        for (int i = 0; i < a.element_vertex_count(); ++i) EXPECT_EQ(a.face(t, i), b.face(t, i));
    }
    for (FaceId f = 0; f < a.face_capacity(); ++f) {
        ASSERT_EQ(a.is_face(f), b.is_face(f));
        if (!a.is_face(f)) continue;
        EXPECT_EQ(a.face_element(f), b.face_element(f));
        EXPECT_EQ(a.mate(f), b.mate(f));
    }
    EXPECT_EQ(a.boundary_faces(), b.boundary_faces());
    EXPECT_EQ(a.face_labels(), b.face_labels());
    ASSERT_EQ(a.vertex_attributes(), b.vertex_attributes());
    for (const AttributeId x : a.vertex_attributes())
        for (VertexId v = 0; v < a.vertex_count(); ++v) {
            const auto p = a.vertex_attribute(x, v), q = b.vertex_attribute(x, v);
            EXPECT_TRUE(std::equal(p.begin(), p.end(), q.begin(), q.end())) << "vertex attribute " << x << " at " << v;
        }
    ASSERT_EQ(a.element_attributes(), b.element_attributes());
    for (const AttributeId x : a.element_attributes())
        for (ElementId t = 0; t < a.element_capacity(); ++t) {
            if (!a.is_element(t)) continue;
            const auto p = a.element_attribute(x, t), q = b.element_attribute(x, t);
            EXPECT_TRUE(std::equal(p.begin(), p.end(), q.begin(), q.end())) << "element attribute " << x << " at " << t;
        }
}

}  // namespace sxk::test

namespace sxk::test {

// Counts every notification and keeps the set of boundary faces it believes in, so tests can
// check "exactly once per change" against the mesh's own boundary.
struct CountingWatcher : Watcher {
    int inits = 0, removed = 0, changed = 0, added = 0;
    int boundary_removed_count = 0, boundary_changed_count = 0, boundary_added_count = 0;
    std::vector<FaceId> boundary;  // sorted

    void init(const Mesh& mesh) override {
        ++inits;
        boundary = mesh.boundary_faces();
    }
    void element_removed(const Mesh&, ElementId, const Simplex&) override { ++removed; }
    void element_changed(const Mesh&, ElementId, const Simplex&) override { ++changed; }
    void element_added(const Mesh&, ElementId) override { ++added; }
    void boundary_removed(const Mesh&, FaceId f, const Simplex&) override {
        ++boundary_removed_count;
        auto it = std::find(boundary.begin(), boundary.end(), f);
        ASSERT_NE(it, boundary.end()) << "told twice that face " << f << " left the boundary";
        boundary.erase(it);
    }
    void boundary_changed(const Mesh&, FaceId, const Simplex&) override { ++boundary_changed_count; }
    void boundary_added(const Mesh&, FaceId f) override {
        ++boundary_added_count;
        ASSERT_EQ(std::find(boundary.begin(), boundary.end(), f), boundary.end())
            << "told twice that face " << f << " joined the boundary";
        boundary.push_back(f);
    }
    void reset_counts() {
        removed = changed = added = 0;
        boundary_removed_count = boundary_changed_count = boundary_added_count = 0;
    }
    void expect_in_step_with(const Mesh& mesh) {
        std::sort(boundary.begin(), boundary.end());
        EXPECT_EQ(boundary, mesh.boundary_faces());
    }
};

// Keeps its own copy of what the events say (live elements with their simplexes, boundary
// faces with theirs, positions) and checks each event against it: an element removed must be
// known with the simplex `was`, an element added must be new, and so on. expect_mirrors(mesh)
// then compares the copy with the mesh: together "every net change told exactly once".
struct MirrorWatcher : Watcher {
    std::map<ElementId, Simplex> elements;
    std::map<FaceId, Simplex> boundary;
    std::vector<Point> reference, deformed;
    int moves = 0;  // vertices_moved calls

    void init(const Mesh& mesh) override {
        elements.clear();
        boundary.clear();
        for (ElementId t : sxk::elements(mesh)) elements[t] = mesh.simplex(t);
        for (FaceId f : mesh.boundary_faces()) boundary[f] = mesh.face_simplex(f);
        reference.assign(mesh.reference_positions().begin(), mesh.reference_positions().end());
        deformed.assign(mesh.deformed_positions().begin(), mesh.deformed_positions().end());
    }
    void element_removed(const Mesh& mesh, ElementId t, const Simplex& was) override {
        grow(mesh);  // a rollback may have taken vertices away: ids past the count are forgotten
        const auto it = elements.find(t);
        ASSERT_NE(it, elements.end()) << "element " << t << " removed but not known";
        EXPECT_EQ(it->second, was) << "element " << t << " removed with another simplex";
        elements.erase(it);
    }
    void element_changed(const Mesh& mesh, ElementId t, const Simplex& was) override {
        const auto it = elements.find(t);
        ASSERT_NE(it, elements.end()) << "element " << t << " changed but not known";
        EXPECT_EQ(it->second, was) << "element " << t << " changed from another simplex";
        it->second = mesh.simplex(t);
    }
    void element_added(const Mesh& mesh, ElementId t) override {
        EXPECT_TRUE(elements.emplace(t, mesh.simplex(t)).second) << "element " << t << " added twice";
        grow(mesh);
    }
    void boundary_removed(const Mesh&, FaceId f, const Simplex& was) override {
        const auto it = boundary.find(f);
        ASSERT_NE(it, boundary.end()) << "face " << f << " left the boundary but was not on it";
        EXPECT_EQ(it->second, was);
        boundary.erase(it);
    }
    void boundary_changed(const Mesh& mesh, FaceId f, const Simplex& was) override {
        const auto it = boundary.find(f);
        ASSERT_NE(it, boundary.end()) << "boundary face " << f << " changed but not known";
        EXPECT_EQ(it->second, was);
        it->second = mesh.face_simplex(f);
    }
    void boundary_added(const Mesh& mesh, FaceId f) override {
        EXPECT_TRUE(boundary.emplace(f, mesh.face_simplex(f)).second) << "face " << f << " joined the boundary twice";
    }
    void vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices, PositionSet which) override {
        ++moves;
        grow(mesh);
        std::vector<VertexId> sorted(vertices.begin(), vertices.end());
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a vertex listed twice";
        // the elements around them, as the mesh finds them once for every watcher
        std::vector<ElementId> around;
        for (const VertexId v : vertices)
            if (mesh.vertex_element(v) != invalid_id) collect_star(mesh, v, mesh.vertex_element(v), around);
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        const std::span<const ElementId> found = mesh.elements_around_moved();
        std::vector<ElementId> told(found.begin(), found.end());
        std::sort(told.begin(), told.end());
        EXPECT_EQ(told, around) << "elements_around_moved is not the moved vertices' stars, each once";
        for (VertexId v : vertices) {
            if (writes_reference(which)) reference[v] = mesh.reference(v);
            if (writes_deformed(which)) deformed[v] = mesh.deformed(v);
        }
    }
    // Vertices have no event of their own: new ones are taken as the mesh has them, at every
    // element event, and ids past the vertex count are forgotten (a rollback took them away;
    // an undo or redo that puts vertices back tells them as moved, docs/kernel.md "Watchers").
    void grow(const Mesh& mesh) {
        for (std::size_t v = reference.size(); v < mesh.vertex_count(); ++v) {
            reference.push_back(mesh.reference(static_cast<VertexId>(v)));
            deformed.push_back(mesh.deformed(static_cast<VertexId>(v)));
        }
        reference.resize(mesh.vertex_count());
        deformed.resize(mesh.vertex_count());
    }
    void expect_mirrors(const Mesh& mesh) {
        std::map<ElementId, Simplex> live;
        for (ElementId t : sxk::elements(mesh)) live[t] = mesh.simplex(t);
        EXPECT_EQ(elements, live) << "the elements told differ from the mesh's";
        std::map<FaceId, Simplex> faces;
        for (FaceId f : mesh.boundary_faces()) faces[f] = mesh.face_simplex(f);
        EXPECT_EQ(boundary, faces) << "the boundary told differs from the mesh's";
        const std::size_t known = std::min<std::size_t>(reference.size(), mesh.vertex_count());
        for (std::size_t v = 0; v < known; ++v) {
            EXPECT_EQ(reference[v], mesh.reference(static_cast<VertexId>(v))) << "vertex " << v;
            EXPECT_EQ(deformed[v], mesh.deformed(static_cast<VertexId>(v))) << "vertex " << v;
        }
        grow(mesh);
    }
};

}  // namespace sxk::test
