// The planar cutters (issue 16, thesis chapter 5): per-movement latency on a 10k and a 1M-triangle
// mesh, and growth and smallest angle of Delaunay cutting against subdivision over 100 seeded random
// paths. Not a Google Benchmark: the figures are distributions over the movements of a cut.
//
//   delaunaycut PATH [--rate HZ]
//
// Latency: PATH (tests/data/paths/long-curve.path: a curve over a 19 x 19 window entering at the
// left side) is cut in the 71 x 71 grid (10,082 triangles) and the 708 x 708 grid (1,002,528), unit
// cells, the window at the middle of each mesh's left side: the same movements in mesh units, the
// larger mesh only larger. --rate HZ replays every movement as the steps a device sampling at HZ
// takes over the movement's time (default 1000: a haptic loop). Each method, 5 cuts on fresh copies.
//
// Random paths: 100 paths (seeds 1..100) of 120 movements on the 19 x 19 grid jittered by up to
// 0.15 and made Delaunay; each cut by both methods. Growth (triangles added) and the smallest angle
// after the cut, per method: their means, and the worst smallest angle.
//
// stdout: JSON lines (CONTRIBUTING.md "Benchmarks"); stderr: a table.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "percentile.hpp"
#include "planar_cut.hpp"
#include "svg_picture.hpp"
#include "sxk/generators.hpp"
#include "sxk/ops/make_delaunay_by_flips.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_path.hpp"

namespace {

using sxk::Mesh;
using sxk::Point;
using sxk::delaunaycut::Method;

constexpr int runs = 5;

void line(const std::string& name, const char* unit, double ours, double peer, const std::string& peer_name,
          const char* better) {
    std::printf("{\"name\": \"%s\", \"unit\": \"%s\", \"ours\": %.6g, \"peer\": %.6g, \"peer_name\": \"%s\", "
                "\"ratio\": %.4g, \"better\": \"%s\"}\n",
                name.c_str(), unit, ours, peer, peer_name.c_str(), peer != 0 ? ours / peer : 0.0, better);
}

Mesh grid(int cells) { return sxk::make_triangle_grid({cells, cells}).value(); }

struct Latency {
    double median = 0, p99 = 0, max = 0;
    std::size_t steps = 0;
};

// Every movement's time over `runs` cuts (the steps after the first, which only places the scalpel).
Latency latency(const Mesh& input, const std::vector<Point>& path, Method method) {
    std::vector<double> ms;
    for (int run = 0; run < runs; ++run) {
        Mesh mesh = input;
        sxk::delaunaycut::Options options;
        options.method = method;
        auto session = sxk::delaunaycut::PlanarCutSession::make(mesh, options);
        if (!session) {
            std::fprintf(stderr, "delaunaycut: %s\n", session.reason().c_str());
            std::exit(1);
        }
        for (std::size_t i = 0; i < path.size(); ++i) {
            const auto start = std::chrono::steady_clock::now();
            if (auto stepped = (*session)->cut(path[i]); !stepped) {
                std::fprintf(stderr, "delaunaycut: step %zu refused: %s\n", i, stepped.reason().c_str());
                std::exit(1);
            }
            const auto took = std::chrono::steady_clock::now() - start;
            const double t = std::chrono::duration<double, std::milli>(took).count();
            if (i > 0) ms.push_back(t);
        }
        (*session)->end();
    }
    return {percentile(ms, 0.5), percentile(ms, 0.99), *std::max_element(ms.begin(), ms.end()), ms.size() / runs};
}

Mesh random_mesh(std::mt19937_64& random, int cells) {
    Mesh mesh = grid(cells);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point p = mesh.deformed(v);
        const bool side_x = p[0] == 0 || p[0] == cells, side_y = p[1] == 0 || p[1] == cells;
        const Point moved{side_x ? p[0] : p[0] + jitter(random), side_y ? p[1] : p[1] + jitter(random), 0};
        mesh.set_reference(v, moved);
        mesh.set_deformed(v, moved);
    }
    (void)sxk::make_delaunay_by_flips(mesh);
    return mesh;
}

std::vector<Point> random_path(std::mt19937_64& random, double side, std::size_t samples) {
    std::uniform_real_distribution<double> unit(0, 1);
    const double angle = 2 * sxk::pi * unit(random);
    Point p{side / 2 - 0.7 * side * std::cos(angle), side / 2 - 0.7 * side * std::sin(angle), 0};
    double heading = angle + (unit(random) - 0.5);
    std::vector<Point> path{p};
    while (path.size() < samples) {
        heading += 0.6 * (unit(random) - 0.5);
        const double step = 0.05 + 0.3 * unit(random);
        p = {p[0] + step * std::cos(heading), p[1] + step * std::sin(heading), 0};
        path.push_back(p);
    }
    return path;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: delaunaycut PATH [--rate HZ]\n");
        return 2;
    }
    double rate = 1000;
    for (int i = 2; i + 1 < argc; i += 2)
        if (std::string(argv[i]) == "--rate") rate = std::atof(argv[i + 1]);
    const std::array<int, 1> columns{2};
    const sxk::ToolPath recorded = sxk::read_tool_path(argv[1], columns);

    // ---- latency: the same movements in the middle of the left side of a 10k and a 1M mesh -------
    const std::array<int, 2> sizes{71, 708};
    std::array<Latency, 2> delaunay, subdivision;
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        const Mesh mesh = grid(sizes[k]);
        const double lift = sizes[k] / 2.0 - 9.5;  // the 19 x 19 window's place
        std::vector<Point> path;
        for (std::size_t i = 0; i < recorded.samples.size(); ++i) {
            const auto& s = recorded.samples[i];
            const Point p{s.values[0], s.values[1] + lift, 0};
            if (i > 0) {
                const Point& q = path.back();
                const auto& before = recorded.samples[i - 1];
                const auto pieces = std::max<long>(1, std::lround((s.time - before.time) * rate));
                for (long j = 1; j < pieces; ++j) {
                    const double f = static_cast<double>(j) / static_cast<double>(pieces);
                    path.push_back({q[0] + f * (p[0] - q[0]), q[1] + f * (p[1] - q[1]), 0});
                }
            }
            path.push_back(p);
        }
        delaunay[k] = latency(mesh, path, Method::delaunay);
        subdivision[k] = latency(mesh, path, Method::subdivision);
        std::fprintf(stderr, "%9zu triangles, %zu movements: Delaunay median %.4f ms, p99 %.4f ms, max %.3f ms; "
                             "subdivision median %.4f ms, p99 %.4f ms, max %.3f ms\n",
                     mesh.element_count(), delaunay[k].steps, delaunay[k].median, delaunay[k].p99, delaunay[k].max,
                     subdivision[k].median, subdivision[k].p99, subdivision[k].max);
    }
    line("delaunaycut/latency/delaunay/median", "ms", delaunay[1].median, delaunay[0].median, "10k triangles", "lower");
    line("delaunaycut/latency/delaunay/p99", "ms", delaunay[1].p99, delaunay[0].p99, "10k triangles", "lower");
    line("delaunaycut/latency/subdivision/median", "ms", subdivision[1].median, subdivision[0].median, "10k triangles",
         "lower");
    line("delaunaycut/latency/subdivision/p99", "ms", subdivision[1].p99, subdivision[0].p99, "10k triangles", "lower");

    // ---- random paths: growth and smallest angle, Delaunay against subdivision --------------------
    constexpr int paths = 100;
    std::array<double, 2> growth{}, angle{};
    std::array<double, 2> worst{180, 180};
    for (int seed = 1; seed <= paths; ++seed) {
        std::mt19937_64 random(static_cast<std::uint64_t>(seed));
        const Mesh mesh = random_mesh(random, 19);
        const std::vector<Point> path = random_path(random, 19, 121);
        for (const Method method : {Method::delaunay, Method::subdivision}) {
            const auto m = static_cast<std::size_t>(method == Method::subdivision);
            Mesh cut = mesh;
            sxk::delaunaycut::Options options;
            options.method = method;
            auto session = sxk::delaunaycut::PlanarCutSession::make(cut, options);
            for (const Point& p : path)
                if (!(*session)->cut(p)) return 1;
            (*session)->end();
            growth[m] += (static_cast<double>(cut.element_count()) - static_cast<double>(mesh.element_count())) / paths;
            const auto angles = sxk::delaunaycut::triangle_angle_degrees(cut);
            const double smallest = *std::min_element(angles.smallest.begin(), angles.smallest.end());
            angle[m] += smallest / paths;
            worst[m] = std::min(worst[m], smallest);
        }
    }
    std::fprintf(stderr, "100 random paths on the jittered 19 x 19 grid (722 triangles): growth %.1f (Delaunay) vs "
                         "%.1f "
                         "(subdivision); smallest angle mean %.2f vs %.2f degrees, worst %.2f vs %.3f\n",
                 growth[0], growth[1], angle[0], angle[1], worst[0], worst[1]);
    line("delaunaycut/random/growth", "triangles", growth[0], growth[1], "subdivision", "lower");
    line("delaunaycut/random/smallest_angle/mean", "degrees", angle[0], angle[1], "subdivision", "higher");
    line("delaunaycut/random/smallest_angle/worst", "degrees", worst[0], worst[1], "subdivision", "higher");
    return 0;
}
