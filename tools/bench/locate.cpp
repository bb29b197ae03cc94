// SpatialIndex (sxk/locate.hpp): locate latency at two sizes, and what keeping the index costs
// an edit.
//
//   locate [google-benchmark flags] [--queries=N] [--edits=K] [--seed=S]
//
// Meshes (untimed; tools/bench/unit_meshes.hpp): Kuhn cubes of n^3 unit cubes, n = 12 (10,368
// tets) and n = 55 (998,250 tets); planar grids of n^2 unit squares, n = 71 (10,082 triangles)
// and n = 708 (1,002,528 triangles); one SpatialIndex over the reference positions on each.
//
// Timed:
//   locate/<dim>/<size>/tree   index.locate(x) without a hint at N random points (the same
//                              cell-relative positions on both sizes): the rtree's path;
//   locate/<dim>/<size>/walk   index.locate(x, previous answer) along a random path of steps of
//                              0.3 cells: the walk's path;
//   edit/3d/large/<bare|watched|indexed>  split_edge(a, b, 0.5) of K random edges of the 1M cube,
//                              without a watcher, with one that does nothing (the kernel then
//                              logs and tells every net change: its share of the cost), and with
//                              the index attached (its events are part of the edit);
//   edit/2d/large/<bare|indexed>  flip_edge of K random interior edges of the 1M grid and the flip
//                              back (a round trip, so the mesh stays the same).
//   frame/3d/<size>/<bare|indexed>  a simulation's frame: move_vertices of every vertex's
//                              deformed position (one call), the cube bending back and forth by up
//                              to 0.2 cells, a period of 200 frames (at most 0.0063 cells a frame,
//                              a haptic loop's small steps), without an index and with one over the
//                              deformed positions (SpatialIndex::vertices_moved refits its trees);
//   locate/3d/large/deformed/<fresh|after-frames>  index.locate(x) without a hint over the
//                              deformed positions, at 20000 element centroids: on an index just
//                              built (tight boxes), and on the one 400 frames or more refitted
//                              (boxes with a margin): what the margin costs a query.
// Each call is timed on its own (steady_clock; Google Benchmark's manual time is their sum), so
// the counters give the distribution: p50_us, p99_us, mean_us.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "parse_option.hpp"
#include "sxk/locate.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/split_edge.hpp"
#include "unit_meshes.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Sizes {
    std::uint64_t queries = 20000, edits = 5000, seed = 1;
};

struct Case {
    std::string name;
    int dimension = 3;
    int n = 0;
    sxk::Mesh mesh{3, 3};
    std::unique_ptr<sxk::SpatialIndex> index;
    std::vector<sxk::Point> scattered, path;
};

// Per-call times in microseconds -> the distribution's counters.
void report(benchmark::State& state, std::vector<double>& us, std::size_t elements) {
    if (us.empty()) return;
    std::sort(us.begin(), us.end());
    double total = 0;
    for (const double t : us) total += t;
    state.counters["p50_us"] = us[us.size() / 2];
    state.counters["p99_us"] = us[us.size() * 99 / 100];
    state.counters["mean_us"] = total / static_cast<double>(us.size());
    state.counters["elements"] = static_cast<double>(elements);
}

void locate(benchmark::State& state, Case* c, bool walk) {
    const std::vector<sxk::Point>& points = walk ? c->path : c->scattered;
    std::vector<double> us;
    us.reserve(points.size());
    std::size_t next = 0, found = 0;
    sxk::ElementId hint = sxk::invalid_id;
    for (auto _ : state) {
        const sxk::Point& x = points[next];
        next = (next + 1) % points.size();
        const auto start = Clock::now();
        const sxk::Location location = c->index->locate(x, walk ? hint : sxk::ElementId{sxk::invalid_id});
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        state.SetIterationTime(seconds);
        us.push_back(seconds * 1e6);
        benchmark::DoNotOptimize(location);
        if (location.found()) {
            ++found;
            hint = location.element;
        }
    }
    if (found != us.size()) state.SkipWithError("a query point was not found");
    report(state, us, c->mesh.element_count());
}

// A random live element of the mesh.
sxk::ElementId random_element(const sxk::Mesh& mesh, std::mt19937_64& random) {
    auto t = static_cast<sxk::ElementId>(random() % mesh.element_capacity());
    while (!mesh.is_element(t)) t = static_cast<sxk::ElementId>((t + 1) % mesh.element_capacity());
    return t;
}

void edit(benchmark::State& state, sxk::Mesh* mesh, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::vector<double> us;
    for (auto _ : state) {
        const sxk::ElementId t = random_element(*mesh, random);
        double seconds = 0;
        if (mesh->topological_dimension() == 3) {
            const sxk::Simplex& s = mesh->simplex(t);
            const int i = static_cast<int>(random() % 4), j = (i + 1 + static_cast<int>(random() % 3)) % 4;
            const sxk::VertexId a = s.vertex(i), b = s.vertex(j);
            const auto start = Clock::now();
            const auto split = sxk::split_edge(*mesh, a, b, 0.5);
            seconds = std::chrono::duration<double>(Clock::now() - start).count();
            if (!split) {
                state.SkipWithError(("split_edge refused: " + split.reason()).c_str());
                return;
            }
        } else {
            const int slot = static_cast<int>(random() % 3);
            if (mesh->neighbor(t, slot) == sxk::invalid_id) {
                state.SetIterationTime(1e-9);  // a boundary edge: not timed, not counted
                continue;
            }
            const auto start = Clock::now();
            const auto flipped = sxk::flip_edge(*mesh, mesh->face(t, slot));
            if (!flipped) {
                state.SkipWithError(("flip_edge refused: " + flipped.reason()).c_str());
                return;
            }
            // the new diagonal: the face of the first new triangle towards the second
            const auto [first, second] = *flipped;
            int back = 0;
            while (mesh->neighbor(first, back) != second) ++back;
            const auto restored = sxk::flip_edge(*mesh, mesh->face(first, back));
            seconds = std::chrono::duration<double>(Clock::now() - start).count();
            if (!restored) {
                state.SkipWithError(("flip_edge back refused: " + restored.reason()).c_str());
                return;
            }
        }
        state.SetIterationTime(seconds);
        us.push_back(seconds * 1e6);
    }
    report(state, us, mesh->element_count());
}

// A mesh whose deformed positions bend back and forth, frame after frame.
struct Bending {
    sxk::Mesh mesh{3, 3};
    std::vector<sxk::VertexId> all;
    std::vector<sxk::Point> at;
    int n = 0, frame = 0;
    std::unique_ptr<sxk::SpatialIndex> index;  // over the deformed positions, or none
    std::vector<sxk::Point> centroids;         // of random elements, deformed, for the queries

    // the next frame's deformed positions: z += 0.2 sin(2 pi frame / 200) sin(pi x / n)
    void next() {
        const double amplitude = 0.2 * std::sin(2 * std::numbers::pi * ++frame / 200.0);
        for (const sxk::VertexId v : all) {
            const sxk::Point& r = mesh.reference(v);
            at[v] = {r[0], r[1], r[2] + amplitude * std::sin(std::numbers::pi * r[0] / n)};
        }
    }
    void take_centroids(std::size_t count, std::uint64_t seed) {
        std::mt19937_64 random(seed);
        centroids.clear();
        for (std::size_t k = 0; k < count; ++k) {
            const sxk::Simplex& s = mesh.simplex(random_element(mesh, random));
            sxk::Point c{0, 0, 0};
            for (int j = 0; j < 4; ++j)
                for (std::size_t a = 0; a < 3; ++a) c[a] += mesh.deformed(s.vertex(j))[a] / 4;
            centroids.push_back(c);
        }
    }
};

void frames(benchmark::State& state, Bending* b) {
    std::vector<double> us;
    for (auto _ : state) {
        b->next();
        const auto start = Clock::now();
        const auto moved = b->mesh.move_vertices(b->all, b->at, sxk::PositionSet::deformed);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (!moved) {
            state.SkipWithError(("move_vertices refused: " + moved.reason()).c_str());
            return;
        }
        state.SetIterationTime(seconds);
        us.push_back(seconds * 1e6);
    }
    report(state, us, b->mesh.element_count());
}

// `fresh`: on an index built now over the same positions; otherwise on the one the frames
// refitted (after 400 frames at least: the runs may come in any order).
void locate_deformed(benchmark::State& state, Bending* b, std::uint64_t seed, bool fresh) {
    while (!fresh && b->frame < 400) {
        b->next();
        if (!b->mesh.move_vertices(b->all, b->at, sxk::PositionSet::deformed)) {
            state.SkipWithError("move_vertices refused");
            return;
        }
    }
    const std::unique_ptr<sxk::SpatialIndex> built =
        fresh ? std::make_unique<sxk::SpatialIndex>(b->mesh, sxk::Positions::deformed) : nullptr;
    const sxk::SpatialIndex& index = fresh ? *built : *b->index;
    b->take_centroids(20000, seed);
    std::vector<double> us;
    std::size_t next = 0, found = 0;
    for (auto _ : state) {
        const sxk::Point& x = b->centroids[next];
        next = (next + 1) % b->centroids.size();
        const auto start = Clock::now();
        const sxk::Location location = index.locate(x);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        state.SetIterationTime(seconds);
        us.push_back(seconds * 1e6);
        benchmark::DoNotOptimize(location);
        found += location.found() ? 1 : 0;
    }
    if (found != us.size()) state.SkipWithError("a centroid was not found");
    report(state, us, b->mesh.element_count());
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    Sizes sizes;
    for (int i = 1; i < argc; ++i)
        if (!sxk_bench::parse_option(argv[i], "queries", sizes.queries) &&
            !sxk_bench::parse_option(argv[i], "edits", sizes.edits) &&
            !sxk_bench::parse_option(argv[i], "seed", sizes.seed)) {
            std::fprintf(stderr, "usage: locate [--benchmark_...] [--queries=N] [--edits=K] [--seed=S]\n");
            return 2;
        }
    std::deque<Case> cases;
    for (const auto& [name, dimension, n] :
         {std::tuple{"3d/small", 3, 12}, std::tuple{"3d/large", 3, 55}, std::tuple{"2d/small", 2, 71},
          std::tuple{"2d/large", 2, 708}}) {
        Case& c = cases.emplace_back();
        c.name = name;
        c.dimension = dimension;
        c.n = n;
        c.mesh = dimension == 3 ? sxk_bench::kuhn_cube(n) : sxk_bench::grid(n);
        c.index = std::make_unique<sxk::SpatialIndex>(c.mesh);
        // the same points in cell units on both sizes: a random cell of a 12^d block spread over
        // the mesh, a random point inside it; and a path of steps of 0.3 cells from the middle
        std::mt19937_64 random(sizes.seed);
        std::uniform_int_distribution<int> cell(0, 11);
        std::uniform_real_distribution<double> inside(0.05, 0.95), step(-0.3, 0.3);
        sxk::Point at{0, 0, 0};
        for (int axis = 0; axis < dimension; ++axis) at[static_cast<std::size_t>(axis)] = 0.5 * n + 0.5;
        for (std::uint64_t k = 0; k < sizes.queries; ++k) {
            sxk::Point x{0, 0, 0};
            for (int axis = 0; axis < dimension; ++axis) {
                const auto a = static_cast<std::size_t>(axis);
                x[a] = std::floor(cell(random) * n / 12.0) + inside(random);
                at[a] = std::clamp(at[a] + step(random), 0.05, n - 0.05);
            }
            c.scattered.push_back(x);
            c.path.push_back(at);
        }
        for (const bool walk : {false, true})
            benchmark::RegisterBenchmark(("locate/" + c.name + (walk ? "/walk" : "/tree")).c_str(), locate, &c, walk)
                ->UseManualTime()
                ->Unit(benchmark::kMicrosecond)
                ->Iterations(static_cast<benchmark::IterationCount>(sizes.queries));
    }
    // the edits: the indexed large meshes above, bare copies of them, and watched copies
    std::deque<sxk::Mesh> copies;
    sxk::Watcher nobody;  // hears every event and does nothing
    for (Case& c : cases) {
        if (c.name.find("large") == std::string::npos) continue;
        sxk::Mesh& bare = copies.emplace_back(c.mesh);
        sxk::Mesh& watched = copies.emplace_back(c.mesh);
        watched.add_watcher(nobody);
        const std::string dim = c.name.substr(0, 2);
        for (const auto& [kind, mesh] :
             {std::pair{"bare", &bare}, std::pair{"watched", &watched}, std::pair{"indexed", &c.mesh}})
            benchmark::RegisterBenchmark(("edit/" + dim + "/large/" + kind).c_str(), edit, mesh, sizes.seed)
                ->UseManualTime()
                ->Unit(benchmark::kMicrosecond)
                ->Iterations(static_cast<benchmark::IterationCount>(sizes.edits));
    }
    // a simulation's frames: bare and indexed copies of each cube, bent the same way
    std::deque<Bending> bent;
    for (const auto& [size, n] : {std::pair{"small", 12}, std::pair{"large", 55}})
        for (const bool indexed : {false, true}) {
            Bending& b = bent.emplace_back();
            b.mesh = sxk_bench::kuhn_cube(n);
            b.n = n;
            for (sxk::VertexId v = 0; v < b.mesh.vertex_count(); ++v) b.all.push_back(v);
            b.at.resize(b.all.size());
            if (indexed) b.index = std::make_unique<sxk::SpatialIndex>(b.mesh, sxk::Positions::deformed);
            const std::string name = std::string("frame/3d/") + size + (indexed ? "/indexed" : "/bare");
            benchmark::RegisterBenchmark(name.c_str(), frames, &b)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(400);
            if (indexed && n == 55)
                for (const bool fresh : {true, false})
                    benchmark::RegisterBenchmark(fresh ? "locate/3d/large/deformed/fresh"
                                                       : "locate/3d/large/deformed/after-frames",
                                                 locate_deformed, &b, sizes.seed, fresh)
                        ->UseManualTime()
                        ->Unit(benchmark::kMicrosecond)
                        ->Iterations(static_cast<benchmark::IterationCount>(sizes.queries));
        }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
