// Property test: long random sequences of kernel edits on 2D and 3D meshes. After every
// accepted edit validate() must pass and a watcher must stay in step; after every refused edit
// the state must be identical to before. The seed is printed; set SXK_SEED to replay one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <random>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;

ElementId random_element(const Mesh& mesh, std::mt19937_64& rng) {
    std::uniform_int_distribution<std::size_t> pick(0, mesh.element_capacity() - 1);
    for (;;) {
        const auto t = static_cast<ElementId>(pick(rng));
        if (mesh.is_element(t)) return t;
    }
}

// One random edit; returns whether it was accepted.
bool random_edit(Mesh& mesh, std::mt19937_64& rng) {
    const int k = mesh.element_vertex_count();
    const ElementId t = random_element(mesh, rng);
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: {  // flip across a random face: the 2-2 flip (2D) or 2-3 flip (3D), topology only
            const int slot = std::uniform_int_distribution<int>(0, k - 1)(rng);
            const ElementId n = mesh.neighbor(t, slot);
            if (n == invalid_id) return false;
            const VertexId other = mesh.opposite_vertex(n, mesh.mate(mesh.face(t, slot)));
            const Simplex face = mesh.simplex(t).subn(slot);
            std::vector<Simplex> created;
            for (VertexId x : face.vertices()) created.push_back(mesh.simplex(t).substituted(x, other));
            const std::array<ElementId, 2> old{t, n};
            return mesh.replace_elements(old, created).ok();
        }
        case 1: {  // remove an element and put it back
            const Simplex tau = mesh.simplex(t);
            const std::array<ElementId, 1> old{t};
            if (!mesh.replace_elements(old, {}).ok()) return false;
            const std::array<Simplex, 1> back{tau};
            return mesh.replace_elements({}, back).ok();
        }
        case 2: {  // replace an element by a copy of a neighbour: always refused
            const ElementId n = mesh.neighbor(t, std::uniform_int_distribution<int>(0, k - 1)(rng));
            if (n == invalid_id) return false;
            const std::array<ElementId, 1> old{t};
            const std::array<Simplex, 1> copy{mesh.simplex(n)};
            EXPECT_FALSE(mesh.replace_elements(old, copy).ok());
            return false;
        }
        case 3: {  // cut an element free with fresh vertices (change_elements), keep it
            ElementSubstitution s{t, {}};
            for (int j = 0; j < k; ++j) {
                const VertexId v = mesh.simplex(t).vertex(j);
                s.new_vertices[static_cast<std::size_t>(j)] = mesh.add_vertex(mesh.reference(v), mesh.deformed(v));
            }
            const std::array<ElementSubstitution, 1> cut{s};
            return mesh.change_elements(cut).ok();
        }
        default: {  // substitute one vertex by a random existing vertex: often refused
            ElementSubstitution s{t, {}};
            for (int j = 0; j < k; ++j) s.new_vertices[static_cast<std::size_t>(j)] = mesh.simplex(t).vertex(j);
            s.new_vertices[static_cast<std::size_t>(std::uniform_int_distribution<int>(0, k - 1)(rng))] =
                static_cast<VertexId>(std::uniform_int_distribution<std::size_t>(0, mesh.vertex_count() - 1)(rng));
            const std::array<ElementSubstitution, 1> change{s};
            return mesh.change_elements(change).ok();
        }
    }
}

void run_random_edits(Mesh mesh, int steps, const char* name) {
    std::mt19937_64 rng(test::seed_for(name));
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    int accepted = 0;
    for (int step = 0; step < steps; ++step) {
        const Mesh before = mesh;
        const std::size_t vertices = mesh.vertex_count();
        if (random_edit(mesh, rng)) {
            ++accepted;
            const auto verdict = mesh.validate();
            ASSERT_TRUE(verdict.ok()) << "step " << step << ": " << verdict.reason();
            watcher.expect_in_step_with(mesh);
        } else if (mesh.element_count() == before.element_count() && mesh.vertex_count() == vertices) {
            // refused (or a no-op that changed nothing): identical state
            expect_same_state(mesh, before);
            if (::testing::Test::HasFailure()) FAIL() << "state changed by a refused edit at step " << step;
        }
    }
    // vertices made for cuts that were refused stay as isolated vertices: still valid
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_GT(accepted, steps / 10);
}

TEST(RandomEdits, PlanarGrid) { run_random_edits(test::planar_grid(6), 20000, "PlanarGrid"); }

TEST(RandomEdits, KuhnCube) { run_random_edits(test::kuhn_cube(3), 20000, "KuhnCube"); }

TEST(RandomEdits, SurfaceIn3D) {
    // the boundary of a Kuhn cube as a triangle surface in space
    const Mesh solid = test::kuhn_cube(3);
    Mesh surface(2, 3);
    for (VertexId v = 0; v < solid.vertex_count(); ++v) surface.add_vertex(solid.reference(v));
    std::vector<Simplex> triangles;
    for (FaceId f : solid.boundary_faces()) triangles.push_back(solid.face_simplex(f));
    ASSERT_TRUE(surface.assign_elements(triangles).ok());
    ASSERT_TRUE(surface.validate().ok());
    EXPECT_EQ(surface.boundary_face_count(), 0u);  // closed surface
    run_random_edits(surface, 20000, "SurfaceIn3D");
}

}  // namespace
}  // namespace sxk
