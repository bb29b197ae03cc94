// Small tetrahedral configurations and helpers shared by the flip_23 / flip_32 / flip_44 tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <utility>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {

// Two tetrahedra sharing the triangle 1,2,3 in z = 0, apex p = 0 above, q = 4 below; the
// segment 0-4 pierces the triangle at the origin, so the pair is strictly convex.
//
//                 0 (0,0,1)
//                /|\  p above, q below
//     (0,1,0) 2 / | \ 1 (1,0,0)        <1,2,3,0> and -<1,2,3,4>
//              \  |  /
//               3 (-1,-1,0)
//                 |
//                 4 (0,0,-1)
inline Mesh two_tets(Point q = {0, 0, -1}) {
    Mesh mesh(3, 3);
    mesh.add_vertex({0, 0, 1});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 0});
    mesh.add_vertex({-1, -1, 0});
    mesh.add_vertex(q);
    const std::array<Simplex, 2> two{Simplex(+1, {1, 2, 3, 0}), Simplex(-1, {1, 2, 3, 4})};
    EXPECT_TRUE(mesh.assign_elements(two).ok());
    return mesh;
}

// The interior face <1,2,3> of two_tets, seen from element 0.
inline FaceId shared_face(const Mesh& mesh) {
    return mesh.opposite_face(0, 0);
}

// An interior face whose simplex has the vertices of `vertices` (either side), or invalid_id.
inline FaceId interior_face_with(const Mesh& mesh, const Simplex& vertices) {
    FaceId found = invalid_id;
    for (FaceId f = 0; f < mesh.face_capacity(); ++f)
        if (mesh.is_face(f) && mesh.mate(f) != invalid_id && mesh.face_simplex(f).same_vertices(vertices))
            found = f;
    return found;
}

// An entry face and j such that face_simplex(entry).subn(j) is the edge u-w, or invalid_id.
inline std::pair<FaceId, int> edge_entry(const Mesh& mesh, VertexId u, VertexId w) {
    for (ElementId t : elements(mesh)) {
        const Simplex& tau = mesh.simplex(t);
        if (!tau.contains(u) || !tau.contains(w)) continue;
        for (int i = 0; i < 4; ++i) {
            if (tau.vertex(i) == u || tau.vertex(i) == w) continue;
            const FaceId f = mesh.face(t, i);
            const Simplex sigma = mesh.face_simplex(f);
            for (int j = 0; j < 3; ++j)
                if (sigma.vertex(j) != u && sigma.vertex(j) != w) return {f, j};
        }
    }
    return {invalid_id, 0};
}

// Sorted vertex sets of all elements (what a flip and its inverse must restore).
inline std::vector<std::array<VertexId, 4>> vertex_sets(const Mesh& mesh) {
    std::vector<std::array<VertexId, 4>> sets;
    for (ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        sets.push_back({s.vertex(0), s.vertex(1), s.vertex(2), s.vertex(3)});
    }
    std::sort(sets.begin(), sets.end());
    return sets;
}

inline bool all_positive(const Mesh& mesh) {
    for (ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::reference) != Sign::positive ||
            element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            return false;
    return true;
}

inline int interior_face_count(const Mesh& mesh) {
    int n = 0;
    for (FaceId f = 0; f < mesh.face_capacity(); ++f)
        if (mesh.is_face(f) && mesh.mate(f) != invalid_id) ++n;
    return n;
}

// A Kuhn cube of n^3 cells in one material, both position sets jittered independently (the
// reference by up to 0.08, the deformed by up to 0.15 per coordinate): exact grid degeneracies
// no longer refuse every flip, the two sets disagree on convexity, and every tetrahedron stays
// positive (the jitter is well below the unit edge), so the reference positions embed the mesh.
inline Mesh jittered_kuhn_cube(int n, std::mt19937_64& random) {
    Mesh mesh = kuhn_cube(n);
    for (ElementId t : elements(mesh)) mesh.set_label(t, 0);
    std::uniform_real_distribution<double> small(-0.08, 0.08), large(-0.15, 0.15);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        Point r = mesh.reference(v), d = mesh.reference(v);
        for (double& x : r) x += small(random);
        for (double& x : d) x += large(random);
        mesh.set_reference(v, r);
        mesh.set_deformed(v, d);
    }
    return mesh;
}

}  // namespace sxk::test
