// Degeneracy removal on a snapped mesh at two sizes: whether its cost is local (issue 4).
//
//   degeneracies [google-benchmark flags] [--iterations=N] [--whole_iterations=M]
//                NAME=MESH.ele [NAME=MESH.ele ...]
//
// Per TetGen mesh (untimed, once): read it (sxk::read_mesh), take the plane through the centre
// of its bounding box with normal (0.3, 1, 0.12) (the same plane relative to the box at every
// size, and the one tests/real/degeneracy_femur.cpp uses), and snap every vertex within h/3 of it
// onto it (snap_to_plane, h = the mesh's mean edge length): the snapped mesh.
//
// Two benchmarks per mesh, N iterations (default 10) and M iterations (default 2):
//   local/NAME  timed: remove_degeneracies(mesh, elements_around(mesh, moved)), the stars of the
//               moved vertices as candidates: what an application does after a snap cut
//   whole/NAME  timed: remove_degeneracies(mesh), every element looked at (for information; on
//               TetGen's femur it also finds the mesher's own degenerates, away from the plane)
// Untimed per iteration: a fresh copy of the snapped mesh, and room reserved for the elements
// to come (a copy's pools are exactly full: the first edit would otherwise copy a whole pool,
// a one-off charged to the removal; refine_latency does the same).
//
// Counters (from the last iteration; every iteration does the same work):
//   found              degenerates on the first list
//   removed            found - remaining
//   cut_free           elements cut free (cracks)
//   peeled             flat elements removed from the boundary (no crack)
//   us_per_degenerate  thread CPU time of the timed call per removed degenerate (median over the
//                      iterations): the figure compared across sizes
//   elements           tetrahedra of the mesh before snapping
//   candidates         elements around the snapped vertices (what the local variant looks at)
#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <exception>
#include <string>
#include <vector>

#include "parse_option.hpp"
#include "remove_degeneracies.hpp"
#include "snap_to_plane.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"
#include "sxk/quality.hpp"

namespace {

namespace dg = sxk::degeneracy;

struct Case {
    std::string name;
    std::size_t elements = 0;  // before snapping
    sxk::Mesh snapped{3, 3};
    std::vector<sxk::VertexId> moved;
    std::size_t candidates = 0;
};

double thread_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void run(benchmark::State& state, Case* c, bool local) {
    sxk::Mesh mesh(3, 3);
    std::vector<double> us_per_degenerate;
    dg::Report last;
    for (auto _ : state) {
        state.PauseTiming();
        mesh = c->snapped;
        mesh.reserve(mesh.vertex_count() + 100000, mesh.element_count() + 400000);
        state.ResumeTiming();
        const double start = thread_cpu_seconds();
        auto removed = local ? dg::remove_degeneracies(mesh, dg::elements_around(mesh, c->moved))
                             : dg::remove_degeneracies(mesh);
        const double seconds = thread_cpu_seconds() - start;
        if (!removed) {
            state.SkipWithError(("remove_degeneracies refused: " + removed.reason()).c_str());
            return;
        }
        last = std::move(removed).value();
        const std::size_t count = last.found - last.remaining;
        if (count == 0) {
            state.SkipWithError("no degenerate removed");
            return;
        }
        us_per_degenerate.push_back(1e6 * seconds / static_cast<double>(count));
    }
    std::sort(us_per_degenerate.begin(), us_per_degenerate.end());
    state.counters["found"] = static_cast<double>(last.found);
    state.counters["removed"] = static_cast<double>(last.found - last.remaining);
    state.counters["cut_free"] = static_cast<double>(last.cut_free);
    state.counters["peeled"] = static_cast<double>(last.peeled);
    state.counters["us_per_degenerate"] =
        us_per_degenerate.empty() ? 0.0 : us_per_degenerate[us_per_degenerate.size() / 2];
    state.counters["elements"] = static_cast<double>(c->elements);
    state.counters["candidates"] = static_cast<double>(c->candidates);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::uint64_t iterations = 10, whole_iterations = 2;
    std::deque<Case> cases;
    for (int i = 1; i < argc; ++i) {
        if (sxk_bench::parse_option(argv[i], "iterations", iterations) ||
            sxk_bench::parse_option(argv[i], "whole_iterations", whole_iterations))
            continue;
        const std::string argument = argv[i];
        const auto equals = argument.find('=');
        if (argument.rfind("--", 0) == 0 || equals == std::string::npos || equals == 0) {
            std::fprintf(stderr,
                         "usage: degeneracies [--benchmark_...] [--iterations=N] "
                         "[--whole_iterations=M] NAME=MESH.ele...\n");
            return 2;
        }
        Case& c = cases.emplace_back();
        c.name = argument.substr(0, equals);
        try {
            c.snapped = sxk::read_mesh(argument.substr(equals + 1));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "degeneracies: %s\n", e.what());
            return 1;
        }
        c.elements = c.snapped.element_count();
        const dg::SnapReport snap =
            dg::snap_to_plane(c.snapped, dg::plane_through_centre(c.snapped, {0.3, 1, 0.12}),
                              sxk::mean_edge_length(c.snapped) / 3);
        c.moved = snap.moved;
        c.candidates = dg::elements_around(c.snapped, c.moved).size();
        std::fprintf(
            stderr, "degeneracies: %s: %zu tets, h = %.4g, %zu vertices snapped, %zu refused\n",
            c.name.c_str(), c.elements, snap.mean_edge_length, snap.moved.size(), snap.refused);
    }
    if (cases.empty()) {
        std::fprintf(stderr,
                     "usage: degeneracies [--benchmark_...] [--iterations=N] "
                     "[--whole_iterations=M] NAME=MESH.ele...\n");
        return 2;
    }
    for (Case& c : cases) {
        benchmark::RegisterBenchmark(("local/" + c.name).c_str(), run, &c, true)
            ->Unit(benchmark::kMicrosecond)
            ->Iterations(static_cast<benchmark::IterationCount>(iterations));
        benchmark::RegisterBenchmark(("whole/" + c.name).c_str(), run, &c, false)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(static_cast<benchmark::IterationCount>(whole_iterations));
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
