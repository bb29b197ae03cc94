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
// Surface latency (§5.3): a line scalpel cuts the top of a Gaussian bell (height 10, width 8, unit
// cells) in the middle of a 72 x 72 (10,368 triangles) and a 708 x 708 grid (1,002,528): the same top,
// the larger surface only larger. An upright blade goes in by its tip, along a curve across the top
// and out again (a slit in the middle of the surface); then a level blade is swept through the top,
// which touches the flank, branches around the summit and annihilates behind it, crossing the slit
// twice; movements of a fifth of a cell (a blade moving 200 cells a second sampled at 1 kHz). 5 cuts
// on fresh copies.
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

#include "figure_line.hpp"
#include "percentile.hpp"
#include "planar_cut.hpp"
#include "surface_cut.hpp"
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
    print_figure(name, unit, ours, peer, peer_name, better);
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

// The surface cut's movements around the bell's top at (c, c): see the header.
std::vector<sxk::delaunaycut::Blade> bell_path(double c) {
    std::vector<sxk::delaunaycut::Blade> blades;
    constexpr double step = 0.2;
    auto upright = [&](double x, double y, double tip) {
        blades.push_back({{c + x, c + y, tip + 17}, {c + x, c + y, tip}});
    };
    for (double tip = 8; tip >= -2; tip -= 5 * step) upright(-20, -4 - 2 * std::sin(20.0 / 12), tip);  // the tip in
    for (double x = -20; x <= 20; x += step) upright(x, -4 + 2 * std::sin(x / 12), -2);                // along
    for (double tip = -2; tip <= 12; tip += 5 * step) upright(20, -4 + 2 * std::sin(20.0 / 12), tip);  // and out
    for (double x = 20; x >= -25; x -= 5 * step) upright(x, -3, 12);  // over the top, back
    for (double x = -25; x <= 20; x += step) blades.push_back({{c + x, c - 20, 6}, {c + x, c + 20, 6.2}});
    return blades;
}

struct SurfaceLatency {
    Latency latency;
    std::size_t branches = 0, annihilations = 0, growth = 0;
};

SurfaceLatency surface_latency(const Mesh& input, const std::vector<sxk::delaunaycut::Blade>& path) {
    std::vector<double> ms;
    SurfaceLatency result;
    for (int run = 0; run < runs; ++run) {
        Mesh mesh = input;
        auto session = sxk::delaunaycut::SurfaceCutSession::make(mesh, {});
        if (!session) {
            std::fprintf(stderr, "delaunaycut: %s\n", session.reason().c_str());
            std::exit(1);
        }
        result.branches = result.annihilations = 0;
        for (std::size_t i = 0; i < path.size(); ++i) {
            const auto start = std::chrono::steady_clock::now();
            if (auto stepped = (*session)->cut(path[i].handle, path[i].tip); !stepped) {
                std::fprintf(stderr, "delaunaycut: surface step %zu refused: %s\n", i, stepped.reason().c_str());
                std::exit(1);
            }
            const auto took = std::chrono::steady_clock::now() - start;
            if (i > 0) ms.push_back(std::chrono::duration<double, std::milli>(took).count());
            result.branches += (*session)->last_step().branches;
            result.annihilations += (*session)->last_step().annihilations;
        }
        (*session)->end();
        result.growth = mesh.element_count() - input.element_count();
    }
    result.latency = {percentile(ms, 0.5), percentile(ms, 0.99), *std::max_element(ms.begin(), ms.end()),
                      ms.size() / runs};
    return result;
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

    // ---- surface latency: the same cut of the bell's top in a 10k and a 1M surface -----------------
    std::array<SurfaceLatency, 2> surface;
    // 72 rather than 71 cells: the top at a vertex in both, so the surface around it is the same
    const std::array<int, 2> bell_sizes{72, 708};
    for (std::size_t k = 0; k < bell_sizes.size(); ++k) {
        const Mesh bell = sxk::make_gaussian_bell({bell_sizes[k], bell_sizes[k]}, {1.0, 1.0}, 10.0, 8.0).value();
        surface[k] = surface_latency(bell, bell_path(bell_sizes[k] / 2.0));
        std::fprintf(stderr, "%9zu-triangle bell, %zu movements: median %.4f ms, p99 %.4f ms, max %.3f ms "
                             "(%zu branches, %zu annihilations, +%zu triangles)\n",
                     bell.element_count(), surface[k].latency.steps, surface[k].latency.median, surface[k].latency.p99,
                     surface[k].latency.max, surface[k].branches, surface[k].annihilations, surface[k].growth);
    }
    line("delaunaycut/surface_latency/median", "ms", surface[1].latency.median, surface[0].latency.median,
         "10k triangles", "lower");
    line("delaunaycut/surface_latency/p99", "ms", surface[1].latency.p99, surface[0].latency.p99, "10k triangles",
         "lower");

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
