// Property test of the local operations (issue 3, "Property test"): more than 10^5 random
// operations - flips, splits, collapses, dissections, Lawson flipping, remove_node where it
// exists - on random planar meshes (a jittered grid; random points by element splits and Lawson
// flips), an octahedron surface in space and jittered Kuhn cubes of tetrahedra, two materials
// each. After every operation the oracle of the operation fuzzer (fuzz/ops_driver.hpp) checks:
// validate() ok; a refused operation left a bit-identical snapshot of the whole mesh; after a
// successful one every element is strictly positive by exact orientation in both position sets;
// the vertex attribute "where" (the reference position at the start) followed every new vertex.
// The seed is printed; SXK_SEED=<n> replays a run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "../../fuzz/ops_driver.hpp"
#include "core/fixtures.hpp"

namespace sxk {
namespace {

// Runs `operations` random operations on meshes of one kind (see ops_driver::start_mesh),
// starting a fresh mesh every `restart` operations (dissections shred a mesh over time).
// Returns how many operations of each name succeeded.
std::map<std::string, int> run(std::uint32_t kind, int operations, const char* name) {
    const std::uint64_t seed = test::seed_for(name);
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 rng(seed);
    bool forced = true;  // the first choice of each start mesh is its kind
    ops_driver::Choices choices([&]() -> int {
        if (forced) {
            forced = false;
            return static_cast<int>(kind);
        }
        return static_cast<int>(rng() & 0xff);
    });
    std::map<std::string, int> done;
    constexpr int restart = 2500;
    Mesh mesh(2, 2);
    for (int i = 0; i < operations; ++i) {
        if (i % restart == 0) {
            forced = true;
            mesh = ops_driver::start_mesh(choices, 6, 3);
            if (const auto valid = mesh.validate(); !valid.ok()) {
                ADD_FAILURE() << "start mesh: " << valid.reason();
                return done;
            }
            if (const std::string bad = ops_driver::first_bad_element(mesh, ops_driver::live_elements(mesh));
                !bad.empty()) {
                ADD_FAILURE() << "start mesh: " << bad;
                return done;
            }
        }
        const ops_driver::Step step = ops_driver::run_step(mesh, choices, 600);
        if (!step.finding.empty()) {
            ADD_FAILURE() << "operation " << i << ": " << step.finding;
            return done;
        }
        if (step.done) ++done[step.operation.substr(0, step.operation.find('('))];
    }
    EXPECT_TRUE(mesh.validate().ok());
    for (const auto& [operation, count] : done) std::cout << "[ done     ] " << operation << ": " << count << "\n";
    return done;
}

TEST(RandomOps, JitteredPlanarGrid) {
    const auto done = run(0, 30000, "RandomOps.JitteredPlanarGrid");
    for (const char* op : {"flip_edge", "split_edge", "split_element", "collapse_edge",
                           "collapse_edge to the midpoint", "dissect", "make_delaunay_by_flips"})
        EXPECT_GT(done.count(op) ? done.at(op) : 0, 0) << op;
}

TEST(RandomOps, PlanarRandomPoints) {
    const auto done = run(1, 20000, "RandomOps.PlanarRandomPoints");
    for (const char* op : {"flip_edge", "split_edge", "split_element", "collapse_edge"})
        EXPECT_GT(done.count(op) ? done.at(op) : 0, 0) << op;
}

TEST(RandomOps, OctahedronSurface) {
    const auto done = run(2, 20000, "RandomOps.OctahedronSurface");
    for (const char* op : {"flip_edge", "split_edge", "split_element", "collapse_edge", "dissect"})
        EXPECT_GT(done.count(op) ? done.at(op) : 0, 0) << op;
}

TEST(RandomOps, JitteredKuhnCube) {
    const auto done = run(3, 30000, "RandomOps.JitteredKuhnCube");
    for (const char* op : {"flip_23", "flip_32", "split_edge", "split_face", "split_element",
                           "collapse_edge", "collapse_edge to the midpoint", "dissect"})
        EXPECT_GT(done.count(op) ? done.at(op) : 0, 0) << op;
}

}  // namespace
}  // namespace sxk
