// Primary rays on the teapot (issue 5): Bézier clipping under Embree's BVH against Embree's own
// triangles, and against Bézier clipping without a BVH.
//
//   bezier_render [google-benchmark flags] [--size=N] [--alone_size=M] [--tolerance=R]
//                 [--max_triangles=T] TEAPOT.bpt
//
// Untimed, once: the teapot's 64 sextic triangular patches (read_bpt, to_triangular), the scene
// Scene::from_patches(patches) with default options, the camera frame(bounds, (1, -2, 1.2), z up)
// (the one of tests/plugins/bezier_mask_test.cpp), and the peer's triangles:
// tessellate(patches, segments) in Scene::from_triangles, segments = the count whose error is the
// tolerance below. segments_for_error measures the error of each count it tries, minutes at
// this tolerance, so it is asked at a coarse error e0 = 1e-4 x diagonal (s0 segments) and the
// count scaled by the law error ~ segments^-2 (uniform tessellation of smooth patches; s0 is
// already ~50): segments = ceil(s0 sqrt(e0 / tolerance)), error(segments) ~ e0 (s0/segments)^2.
//
// The peer's tessellation error is our verified hit tolerance, 1e-7 x the box diagonal (option
// --tolerance, relative to the diagonal): tests/plugins/bezier_mask_test.cpp checks that our
// hit/miss mask equals that of an exact reference to this tolerance. Our intersector's own
// criterion is tighter (a hit lies within ClippingOptions::distance_tolerance = 1e-10 x the
// patch's extent of the ray) but no tessellation can follow it: Embree's vertices are floats,
// whose resolution at the teapot's coordinates (about 3) is 2.4e-7, and the triangle count grows
// like 1/error. When the tessellation for the tolerance has more than T triangles (default 2^25:
// 4.6 GB peak for the whole program), the peer takes the finest within T and says so: it is then less
// accurate than ours, which favours the peer.
//
// Timed benchmarks (wall time: every one runs all cores through TBB, one task per image row):
//   clipping_embree/N   N x N primary rays, Scene::intersect on the patch scene (nearest hit)
//   triangles/N         the same rays, Scene::intersect on the triangle scene
//   clipping_embree/M   M x M rays on the patch scene again, for the comparison below
//   clipping_alone/M    M x M rays, each against every patch with intersect() (Bézier clipping,
//                       default ClippingOptions) after a test against the patch's control-point
//                       box (cheap, and what any user without a hierarchy would do); nearest hit
// Counters: rays_per_cpu_s (rays / CPU seconds of all threads of the process, median over the
// iterations: the figure, steady under the shared machine's load, where a preempted thread costs
// wall time but no CPU time), rays_per_s (rays / wall seconds, for information), hits, and for the
// scenes leaves (Embree primitives), tolerance (world units), segments (used), wanted_segments
// (for the tolerance, estimated as above), capped, peer_error (of the tessellation used, by the
// segments^-2 law), diagonal.
#include <benchmark/benchmark.h>

#include <time.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bezier_clipping.hpp"
#include "parse_option.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "render.hpp"
#include "triangular_patch.hpp"

namespace {

namespace bz = sxk::bezier;

struct Setup {
    std::vector<bz::TriangularPatch> patches;
    std::vector<bz::Box> patch_boxes;
    std::optional<bz::Scene> clipping, triangles;
    bz::Camera camera;
    double tolerance = 0;
    int wanted_segments = 0, segments = 0;
    double peer_error = 0;  // of the tessellation used, by the segments^-2 law
    bool capped = false;
};

// Traces size x size primary rays in parallel (rows as tasks); returns the number of hits.
std::uint64_t trace(const Setup& setup, int size, const std::function<bool(const bz::Ray&)>& hits) {
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(0, size), std::uint64_t{0},
        [&](const tbb::blocked_range<int>& rows, std::uint64_t count) {
            for (int y = rows.begin(); y != rows.end(); ++y)
                for (int x = 0; x < size; ++x) count += hits(bz::primary_ray(setup.camera, size, size, x, y));
            return count;
        },
        std::plus<std::uint64_t>());
}

double process_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

void run(benchmark::State& state, const Setup* setup, int size, const std::function<bool(const bz::Ray&)>& hits) {
    std::vector<double> per_second, per_cpu_second;
    std::uint64_t found = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = process_cpu_seconds();
        found = trace(*setup, size, hits);
        const double cpu_seconds = process_cpu_seconds() - cpu_start;
        const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
        per_second.push_back(double(size) * size / seconds.count());
        per_cpu_second.push_back(double(size) * size / cpu_seconds);
    }
    state.counters["rays_per_s"] = median(per_second);
    state.counters["rays_per_cpu_s"] = median(per_cpu_second);
    state.counters["hits"] = double(found);
    state.counters["rays"] = double(size) * size;
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::uint64_t size = 1024, alone_size = 256, max_triangles = std::uint64_t{1} << 25;
    double relative_tolerance = 1e-7;
    std::string teapot_path;
    for (int i = 1; i < argc; ++i) {
        if (sxk_bench::parse_option(argv[i], "size", size) || sxk_bench::parse_option(argv[i], "alone_size", alone_size) ||
            sxk_bench::parse_option(argv[i], "max_triangles", max_triangles))
            continue;
        if (std::string(argv[i]).rfind("--tolerance=", 0) == 0) {
            relative_tolerance = std::strtod(argv[i] + std::strlen("--tolerance="), nullptr);
            continue;
        }
        if (std::string(argv[i]).rfind("--", 0) == 0 || !teapot_path.empty()) {
            teapot_path.clear();
            break;
        }
        teapot_path = argv[i];
    }
    if (teapot_path.empty() || size == 0 || alone_size == 0 || !(relative_tolerance > 0)) {
        std::fprintf(stderr,
                     "usage: bezier_render [--benchmark_...] [--size=N] [--alone_size=M] [--tolerance=R] "
                     "[--max_triangles=T] TEAPOT.bpt\n");
        return 2;
    }

    Setup setup;
    const auto setup_start = std::chrono::steady_clock::now();
    try {
        setup.patches = bz::to_triangular(bz::read_bpt(teapot_path));
        for (const bz::TriangularPatch& patch : setup.patches) setup.patch_boxes.push_back(bz::box_of(patch.control_points()));
        setup.clipping = bz::Scene::from_patches(setup.patches);
        setup.tolerance = relative_tolerance * setup.clipping->bounds().diagonal();
        setup.camera = bz::frame(setup.clipping->bounds(), {1, -2, 1.2}, {0, 0, 1});
        // segments_for_error measures every candidate count (minutes at the tolerance's ~1600
        // segments): measured at a coarse error, then scaled by the error's segments^-2 law
        const double coarse_error = 1e-4 * setup.clipping->bounds().diagonal();
        const int coarse_segments = bz::segments_for_error(setup.patches, coarse_error);
        setup.wanted_segments = static_cast<int>(std::ceil(coarse_segments * std::sqrt(coarse_error / setup.tolerance)));
        const auto within = static_cast<int>(std::sqrt(double(max_triangles) / double(setup.patches.size())));
        setup.capped = setup.wanted_segments > within;
        setup.segments = std::min(setup.wanted_segments, within);
        setup.peer_error = coarse_error * std::pow(double(coarse_segments) / setup.segments, 2);
        setup.triangles = bz::Scene::from_triangles(bz::tessellate(setup.patches, setup.segments));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bezier_render: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr,
                 "bezier_render: %zu patches, %zu leaves; tolerance %.3g (diagonal %.4g); tessellation: %d segments "
                 "wanted, %d used%s, %zu triangles, error %.3g; setup %.1f s\n",
                 setup.patches.size(), setup.clipping->leaf_count(), setup.tolerance,
                 setup.clipping->bounds().diagonal(), setup.wanted_segments, setup.segments,
                 setup.capped ? " (capped by --max_triangles)" : "", setup.triangles->leaf_count(), setup.peer_error,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count());

    const Setup* s = &setup;
    auto through_scene = [](const bz::Scene& scene) {
        return [&scene](const bz::Ray& ray) { return scene.intersect(ray).has_value(); };
    };
    auto alone = [s](const bz::Ray& ray) {
        bz::Ray nearest = ray;
        bool hit = false;
        for (std::size_t p = 0; p < s->patches.size(); ++p) {
            if (!bz::entry(nearest, s->patch_boxes[p])) continue;
            if (const auto found = bz::intersect(s->patches[p], nearest)) {
                hit = true;
                nearest.t_far = found->t;
            }
        }
        return hit;
    };
    auto add_scene_counters = [s](benchmark::State& state, const bz::Scene& scene) {
        state.counters["leaves"] = double(scene.leaf_count());
        state.counters["tolerance"] = s->tolerance;
        state.counters["segments"] = s->segments;
        state.counters["wanted_segments"] = s->wanted_segments;
        state.counters["capped"] = s->capped;
        state.counters["peer_error"] = s->peer_error;
        state.counters["diagonal"] = s->clipping->bounds().diagonal();
    };
    const int n = int(size), m = int(alone_size);
    benchmark::RegisterBenchmark(("clipping_embree/" + std::to_string(n)).c_str(), [=](benchmark::State& state) {
        run(state, s, n, through_scene(*s->clipping));
        add_scene_counters(state, *s->clipping);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark(("triangles/" + std::to_string(n)).c_str(), [=](benchmark::State& state) {
        run(state, s, n, through_scene(*s->triangles));
        add_scene_counters(state, *s->triangles);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    if (m != n)
        benchmark::RegisterBenchmark(("clipping_embree/" + std::to_string(m)).c_str(), [=](benchmark::State& state) {
            run(state, s, m, through_scene(*s->clipping));
        })->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark(("clipping_alone/" + std::to_string(m)).c_str(), [=](benchmark::State& state) {
        run(state, s, m, alone);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
