// Latency of one refine_around call on a small and a large mesh: whether the cost is local.
//
//   refine_latency [google-benchmark flags] [--calls=N] [--seed=S]
//
// Meshes (untimed): 3D Kuhn cubes of n^3 unit cubes (6 tetrahedra each): n = 12 (10,368 tets)
// and n = 55 (998,250 tets); 2D grids of n^2 unit squares (2 triangles each): n = 71 (10,082
// triangles) and n = 708 (1,002,528 triangles). Unit cells on both sizes, so a call with the same
// h does the same local work; only the mesh around it is larger.
//
// Timed, per iteration: ONE call, refine_around_tetrahedra(mesh, x, h) in 3D (the stateless
// longest-edge entry point) or refine_around(mesh, x, h) in 2D (no hint), at the next of N random
// points x (std::mt19937_64 with seed S, the same points in cell units on both sizes; kept
// 0.05 cells away from cell walls), h = 0.3 (3D) / 0.2 (2D). After every 50 calls the mesh is
// restored from a pristine copy (untimed), so refinements do not pile up in the small mesh, and
// room is reserved for the elements to come (untimed: growing a 1M-element pool copies it, a
// one-off cost that would otherwise be charged to the next call).
// Both entry points locate x themselves, by a walk from a start element (see their headers):
// that walk is part of the call and is the part that is not local. The cases ".../index" make the
// same calls with a SpatialIndex attached (sxk/locate.hpp): x is located by its rtree, and the
// index follows every bisection (its upkeep is part of the call).
//
// Counters: calls_per_s, elements (before refining), bisections per call.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "parse_option.hpp"
#include "unit_meshes.hpp"
#include "sxk/locate.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/predicates.hpp"

namespace {

constexpr int restore_every = 50;

struct Case {
    std::string name;
    int dimension;
    int n;
    sxk::Mesh pristine;
    std::vector<sxk::Point> points;
    bool indexed = false;  // locate x with a SpatialIndex attached to the mesh
};

// A fresh copy with room for the refinements to come: a copy's pools are exactly full, and
// the first edit after it would otherwise reallocate (copy) the whole pool inside the timing.
void restore(sxk::Mesh& mesh, const sxk::Mesh& pristine) {
    mesh = pristine;
    mesh.reserve(pristine.vertex_count() + 100000, pristine.element_count() + 400000);
}

void run(benchmark::State& state, Case* c) {
    sxk::Mesh mesh(c->dimension, c->dimension);
    // attached first: each restore (a copy assignment) rebuilds it, untimed
    std::optional<sxk::SpatialIndex> index;
    if (c->indexed) index.emplace(mesh);
    restore(mesh, c->pristine);
    std::size_t next = 0, bisections = 0, calls = 0;
    const double h = c->dimension == 3 ? 0.3 : 0.2;
    for (auto _ : state) {
        if (calls % restore_every == 0 && calls > 0) {
            state.PauseTiming();
            restore(mesh, c->pristine);
            state.ResumeTiming();
        }
        const sxk::Point& x = c->points[next];
        next = (next + 1) % c->points.size();
        ++calls;
        if (c->dimension == 3) {
            const auto refined = index ? sxk::refine_around_tetrahedra(mesh, x, h, *index)
                                       : sxk::refine_around_tetrahedra(mesh, x, h);
            if (!refined) {
                state.SkipWithError(("refine_around_tetrahedra refused: " + refined.reason()).c_str());
                return;
            }
            bisections += *refined;
        } else {
            const auto refined = index ? sxk::refine_around(mesh, x, h, *index) : sxk::refine_around(mesh, x, h);
            if (!refined) {
                state.SkipWithError(("refine_around refused: " + refined.reason()).c_str());
                return;
            }
            bisections += refined->bisections;
        }
    }
    state.counters["calls_per_s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["elements"] = static_cast<double>(c->pristine.element_count());
    state.counters["bisections_per_call"] =
        calls ? static_cast<double>(bisections) / static_cast<double>(calls) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::uint64_t calls = 500, seed = 1;
    for (int i = 1; i < argc; ++i)
        if (!sxk_bench::parse_option(argv[i], "calls", calls) && !sxk_bench::parse_option(argv[i], "seed", seed)) {
            std::fprintf(stderr, "usage: refine_latency [--benchmark_...] [--calls=N] [--seed=S]\n");
            return 2;
        }
    std::deque<Case> cases;
    cases.push_back({"3d/small", 3, 12, sxk_bench::kuhn_cube(12), {}});
    cases.push_back({"3d/large", 3, 55, sxk_bench::kuhn_cube(55), {}});
    cases.push_back({"2d/small", 2, 71, sxk_bench::grid(71), {}});
    cases.push_back({"2d/large", 2, 708, sxk_bench::grid(708), {}});
    for (std::size_t i = 0; i < 4; ++i) {  // the same calls locating with an index
        Case indexed{cases[i].name + "/index", cases[i].dimension, cases[i].n, cases[i].pristine, {}, true};
        cases.push_back(std::move(indexed));
    }
    for (Case& c : cases) {
        // the same points in cell units on both sizes: a random cell, a random point inside it
        std::mt19937_64 random(seed);
        std::uniform_int_distribution<int> cell(0, 11);  // cells of the small cube/grid region
        std::uniform_real_distribution<double> inside(0.05, 0.95);
        for (std::uint64_t k = 0; k < calls; ++k) {
            sxk::Point x{0, 0, 0};
            for (int axis = 0; axis < c.dimension; ++axis)
                x[static_cast<std::size_t>(axis)] = std::floor(cell(random) * c.n / 12.0) + inside(random);
            c.points.push_back(x);
        }
        benchmark::RegisterBenchmark(("refine/" + c.name).c_str(), run, &c)
            ->Unit(benchmark::kMicrosecond)
            ->Iterations(static_cast<benchmark::IterationCount>(calls));
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
