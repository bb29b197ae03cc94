// needle: the update rate of the needle's full loop (refine + intercept + solve + rearrange) in the
// setting of thesis Table 6.5, against the thesis' figures (a Pentium III at 1 GHz), and the step
// latency at the start against the end of a long insertion and on a coarse against a fine start
// mesh (issue 17), solving the whole body (table65, latency) or around the needle only (local:
// also on a start mesh of a million triangles, with and without far-field blocks, and what that
// costs in force and in the far field's lag). Prints one JSON line per figure (CONTRIBUTING.md
// "Benchmarks").
//
//   needle [--quick] [--local-vertices N] [table65] [latency] [local]
//       --quick: the speeds 3, 0.3 and 0.03 only; --local-vertices: the local solve's region
//       (default 300); parts named: only those (none: all)
//
// The thesis' automated insertion (§6.8.4): the slab 0.1 x 0.1 m (E = 34 kPa, nu = 0.34, 1 cm thick,
// fixed at x = 0.1), h_start = h3, the needle along y = 0.05 from the slab's edge to a depth of
// 70 mm, advanced a fixed amount per loop cycle, then cycled in place until nothing changes (no
// grip rearranged, no node slipping). Updates = loop cycles; rate = cycles / CPU time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <memory>
#include <span>
#include <utility>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "figure_line.hpp"
#include "needle.hpp"
#include "percentile.hpp"
#include "simulation.hpp"
#include "sxk/generators.hpp"

namespace {

using namespace sxk;

// the slab's body; `side` its width and height (the thesis': 0.1 m), fixed at x = side
std::vector<std::string> slab_body(double side) {
    return {"--fix",       "x>" + std::to_string(side - 1e-4), "--E",   "34e3", "--nu",       "0.34",
            "--thickness", "0.01",                              "--tol", "0.01", "--rounding", "1e-8"};
}

struct Run {
    double seconds = 0;
    std::size_t updates = 0;
    double iterations_mean = 0;
    std::size_t iterations_max = 0;
    std::vector<double> latency;  // per update, seconds, in order
    // the phases of each update (NeedleStepReport), and the step's time outside the loop (the
    // edit journal's step and the session's bookkeeping)
    std::vector<double> refine, intercept, solve, outside;
    std::vector<double> axial;  // the needle's force along its axis after each update, N
    std::size_t elements = 0, vertices = 0;
    // a local solve's: the largest displacement change a solve of the whole body makes after the
    // insertion, and the largest displacement then (m)
    double lag = 0, largest = 0;
};

// One automated insertion; h_start and h_ref as fractions of the 0.1 m slab (h_k = 0.1 / 2^k).
// `local`: Options::local_vertices (0: the whole body every step). `cells`: the start grid's
// cells per side (0: the thesis' 0.1 m slab; more: a larger slab of the same h_start, the needle
// entering at the middle of its side).
Run insert(int k_start, int k_ref, double speed, std::size_t local = 0, int cells = 0, std::size_t far = 0) {
    const double h_start = 0.1 / (1 << k_start), h_ref = 0.1 / (1 << k_ref);
    if (cells == 0) cells = 1 << k_start;
    const double side = cells * h_start, middle = 0.5 * side;
    Mesh mesh = *make_triangle_grid({cells, cells}, {h_start, h_start});
    auto made = elasticity::simulate(mesh, sxk::cli::body_options(slab_body(side)).value());
    std::unique_ptr<Simulation> simulation = std::move(*made);
    needle::Options options;
    options.h_ref = h_ref;
    options.local_vertices = local;
    options.far_vertices = far;
    auto begun = needle::NeedleSession::make(mesh, options, simulation.get());
    std::unique_ptr<needle::NeedleSession> session = std::move(*begun);
    Run run;
    const double step = speed * h_ref, depth = 0.07;
    auto cycle = [&](double x) {
        const auto start = std::chrono::steady_clock::now();
        auto report = session->move({{x - 0.1, middle, 0}, {x, middle, 0}});
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!report) {
            std::fprintf(stderr, "needle: refused: %s\n", report.reason().c_str());
            std::exit(1);
        }
        run.seconds += seconds;
        run.latency.push_back(seconds);
        run.refine.push_back(report->refine_seconds);
        run.intercept.push_back(report->intercept_seconds);
        run.solve.push_back(report->solve_seconds);
        run.outside.push_back(seconds - report->seconds);
        run.axial.push_back(report->axial_force);
        ++run.updates;
        run.iterations_mean += double(report->iterations);
        run.iterations_max = std::max(run.iterations_max, report->iterations);
        return *report;
    };
    double x = 0;
    cycle(x);
    while (x < depth) {
        x = std::min(x + step, depth);
        cycle(x);
    }
    for (int settle = 0; settle < 10000; ++settle) {
        const auto report = cycle(x);
        if (report.loosened + report.gripped == 0 && report.slip == 0) break;
    }
    run.iterations_mean /= double(run.updates);
    run.elements = mesh.element_count();
    run.vertices = mesh.vertices_in_elements();
    if (local > 0) {
        // what the held far field lags behind: the displacements against a solve of the whole body
        const std::size_t n = mesh.vertex_count();
        std::vector<Vector3> before(n);
        for (VertexId v = 0; v < n; ++v) before[v] = simulation->displacement(v);
        if (!simulation->relax(1000000)) std::exit(1);
        for (VertexId v = 0; v < n; ++v) {
            const Vector3 u = simulation->displacement(v);
            double change = 0, size = 0;
            for (int k = 0; k < 3; ++k) {
                change += (u[k] - before[v][k]) * (u[k] - before[v][k]);
                size += u[k] * u[k];
            }
            run.lag = std::max(run.lag, std::sqrt(change));
            run.largest = std::max(run.largest, std::sqrt(size));
        }
    }
    return run;
}

// The step latency at the end of an insertion against its start: the last fifth of the updates
// against the first, median and p99 (on stderr, and as figures named with `what` and `setting`).
void end_against_start(const Run& run, const std::string& what, const std::string& setting) {
    const std::size_t fifth = run.latency.size() / 5;
    const std::vector<double> first(run.latency.begin(), run.latency.begin() + fifth);
    const std::vector<double> last(run.latency.end() - fifth, run.latency.end());
    std::fprintf(stderr,
                 "latency %s%s, 0.1 h_ref/update: first fifth median %.3f ms p99 %.3f ms, last fifth median %.3f ms "
                 "p99 %.3f ms\n",
                 what.c_str(), setting.c_str(), 1e3 * percentile(first, 0.5), 1e3 * percentile(first, 0.99),
                 1e3 * percentile(last, 0.5), 1e3 * percentile(last, 0.99));
    for (const auto& [name, q] : {std::pair{"median", 0.5}, std::pair{"p99", 0.99}})
        print_figure("needle step latency " + std::string(name) + ", " + what + "end of insertion vs start (" +
                         setting + ")",
                     "ms", 1e3 * percentile(last, q), 1e3 * percentile(first, q), "ourselves at the start", "lower");
}

struct ThesisRow {
    double speed;
    double seconds;
    int rearrangements;
    double hz, cg_mean;
    int cg_max;
};

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    std::size_t local_vertices = 300;
    std::vector<std::string> parts;  // none named: all
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (std::strcmp(argv[i], "--local-vertices") == 0 && i + 1 < argc)
            local_vertices = std::stoul(argv[++i]);
        else
            parts.emplace_back(argv[i]);
    auto want = [&](const char* part) {
        return parts.empty() || std::find(parts.begin(), parts.end(), part) != parts.end();
    };
    // Table 6.5 as printed
    const ThesisRow h6[] = {{3.00, 0.80, 157, 196.25, 11.81, 41}, {1.00, 0.90, 232, 257.78, 11.52, 62},
                            {0.30, 0.94, 308, 327.66, 10.87, 70}, {0.10, 1.07, 504, 471.03, 8.14, 61},
                            {0.03, 2.24, 1478, 659.82, 5.31, 57}, {0.01, 5.77, 4187, 725.65, 3.87, 51}};
    const ThesisRow h7[] = {{3.00, 2.46, 243, 98.78, 12.67, 57},  {1.00, 2.80, 401, 143.21, 10.88, 82},
                            {0.30, 3.15, 561, 178.10, 10.03, 66}, {0.10, 3.48, 1000, 287.36, 6.63, 67},
                            {0.03, 6.34, 2966, 467.82, 4.18, 53}, {0.01, 15.68, 8505, 542.41, 3.15, 48}};
    if (want("table65")) std::fprintf(stderr, "h_ref  speed  | ours: CPU s  updates      Hz  CG mean  max  tris | "
                         "thesis: s  updates   Hz   CG mean  max\n");
    const std::pair<int, std::span<const ThesisRow>> tables[] = {{6, h6}, {7, h7}};
    for (const auto& [k_ref, table] : tables) {
        if (!want("table65")) break;
        for (const ThesisRow& row : table) {
            if (quick && row.speed != 3.0 && row.speed != 0.3 && row.speed != 0.03) continue;
            const Run run = insert(3, k_ref, row.speed);
            const double hz = double(run.updates) / run.seconds;
            std::fprintf(stderr,
                         "h%d  %5.2f  |  %9.3f  %7zu  %6.0f  %7.2f  %3zu  %5zu | %9.2f  %7d  %4.0f  %7.2f  %3d\n",
                         k_ref, row.speed, run.seconds, run.updates, hz, run.iterations_mean, run.iterations_max,
                         run.elements, row.seconds, row.rearrangements, row.hz, row.cg_mean, row.cg_max);
            char name[128];
            std::snprintf(name, sizeof name, "needle update rate h3/h%d at %.2f h_ref per update", k_ref, row.speed);
            print_figure(name, "Hz", hz, row.hz, "thesis Table 6.5 (Pentium III 1 GHz)", "higher");
        }
    }
    // latency at the start against the end of a long insertion (0.1 h_ref per update, h3/h6): the
    // first and the last fifth of the advancing updates
    if (want("latency")) end_against_start(insert(3, 6, 0.1), "", "h3/h6");
    // a coarse against a fine start mesh, the same refinement around the needle
    if (want("latency")) {
        const Run coarse = insert(3, 6, 0.1), fine = insert(5, 6, 0.1);
        std::fprintf(stderr, "latency h_ref h6, 0.1 h_ref/update: start h3 median %.3f ms p99 %.3f ms (%zu triangles), "
                             "start h5 median %.3f ms p99 %.3f ms (%zu triangles)\n",
                     1e3 * percentile(coarse.latency, 0.5), 1e3 * percentile(coarse.latency, 0.99), coarse.elements,
                     1e3 * percentile(fine.latency, 0.5), 1e3 * percentile(fine.latency, 0.99), fine.elements);
        print_figure("needle step latency median, start mesh h5 vs h3 (h_ref h6)", "ms",
                     1e3 * percentile(fine.latency, 0.5), 1e3 * percentile(coarse.latency, 0.5),
                     "ourselves on the h3 start mesh", "lower");
        print_figure("needle step latency p99, start mesh h5 vs h3 (h_ref h6)", "ms",
                     1e3 * percentile(fine.latency, 0.99), 1e3 * percentile(coarse.latency, 0.99),
                     "ourselves on the h3 start mesh", "lower");
    }
    // the same with the solve confined to the needle's surroundings (Options::local_vertices, 300
    // vertices: more than the whole h3 mesh after the refinement) on the coarse and the fine start mesh
    // and on start meshes of more than a million triangles: the h5 grid over a slab 720 cells wide
    // (22.5 times the thesis' slab: the needle's surroundings as on h5, only the body larger) and the
    // h3 grid 720 cells wide (90 times: as on h3); what it gives up: the needle's force against the
    // whole body's solve on the h5 mesh, and the far field's lag
    if (want("local")) {
        struct Case {
            const char* name;
            int k_start, cells;
            std::size_t far, local;
        };
        // the last two: a region of half as many vertices, which the h3 mesh holds too (at N = 300
        // the h3 mesh, about 200 vertices after the refinement, is smaller than the region)
        const std::size_t half = local_vertices / 2;
        const Case cases[] = {{"h3", 3, 0, 0, local_vertices},
                              {"h5", 5, 0, 0, local_vertices},
                              {"h3, 720 x 720 cells", 3, 720, 0, local_vertices},
                              {"h5, far field blocks", 5, 0, local_vertices, local_vertices},
                              {"h3, 720 x 720 cells, far field blocks", 3, 720, local_vertices, local_vertices},
                              {"h3, half the region", 3, 0, 0, half},
                              {"h5, half the region", 5, 0, 0, half},
                              {"h5, 720 x 720 cells", 5, 720, 0, local_vertices}};
        std::vector<double> median(std::size(cases)), p99(std::size(cases));
        std::vector<Run> runs(std::size(cases));
        for (std::size_t i = 0; i < std::size(cases); ++i) {
            const Run& run = runs[i] =
                insert(cases[i].k_start, 6, 0.1, cases[i].local, cases[i].cells, cases[i].far);
            median[i] = 1e3 * percentile(run.latency, 0.5);
            p99[i] = 1e3 * percentile(run.latency, 0.99);
            std::fprintf(stderr,
                         "local %zu, h_ref h6, 0.1 h_ref/update, start %s: median %.3f ms p99 %.3f ms (%zu triangles, "
                         "CG mean %.1f max %zu); far field lags by %.3g mm (largest displacement %.3g mm)\n",
                         cases[i].local, cases[i].name, median[i], p99[i], run.elements, run.iterations_mean,
                         run.iterations_max, 1e3 * run.lag, 1e3 * run.largest);
            std::fprintf(stderr,
                         "  median / p99 ms: refine %.3f / %.3f, intercept %.3f / %.3f, solve %.3f / %.3f, "
                         "outside the loop %.3f / %.3f\n",
                         1e3 * percentile(run.refine, 0.5), 1e3 * percentile(run.refine, 0.99),
                         1e3 * percentile(run.intercept, 0.5), 1e3 * percentile(run.intercept, 0.99),
                         1e3 * percentile(run.solve, 0.5), 1e3 * percentile(run.solve, 0.99),
                         1e3 * percentile(run.outside, 0.5), 1e3 * percentile(run.outside, 0.99));
            // what sets the p99: the slowest updates and their phases
            std::vector<std::size_t> order(run.latency.size());
            for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
            const std::size_t shown = std::min<std::size_t>(5, order.size());
            std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(shown), order.end(),
                              [&](std::size_t a, std::size_t b) { return run.latency[a] > run.latency[b]; });
            std::fprintf(stderr, "  slowest updates (ms: refine + intercept + solve + outside):");
            for (std::size_t k = 0; k < shown; ++k) {
                const std::size_t u = order[k];
                std::fprintf(stderr, " #%zu %.2f (%.2f+%.2f+%.2f+%.2f)", u, 1e3 * run.latency[u], 1e3 * run.refine[u],
                             1e3 * run.intercept[u], 1e3 * run.solve[u], 1e3 * run.outside[u]);
            }
            std::fprintf(stderr, "\n");
        }
        // the start against the end of the insertion, as above, with the local solve (h5)
        end_against_start(runs[1], "local solve, ", "h5/h6");
        const Run whole = insert(5, 6, 0.1);
        double deviation = 0, largest = 0;
        for (const int i : {1, 3, 6}) {
            const std::size_t count = std::min(whole.axial.size(), runs[i].axial.size());
            double most = 0;
            largest = 0;
            for (std::size_t k = 0; k < count; ++k) {
                most = std::max(most, std::abs(runs[i].axial[k] - whole.axial[k]));
                largest = std::max(largest, std::abs(whole.axial[k]));
            }
            if (i == 1) deviation = most;
            std::fprintf(stderr,
                         "%s: the needle's axial force against the whole body's: largest difference %.4f N of %.4f N "
                         "(%.1f%%) over %zu updates; at the end %.4f N against %.4f N\n",
                         cases[i].name, most, largest, 100 * most / largest, count, runs[i].axial.back(),
                         whole.axial.back());
        }
        print_figure("needle step latency median, local solve, start mesh h5 vs h3 (h_ref h6)", "ms", median[1],
                     median[0], "ourselves on the h3 start mesh", "lower");
        print_figure("needle step latency p99, local solve, start mesh h5 vs h3 (h_ref h6)", "ms", p99[1], p99[0],
                     "ourselves on the h3 start mesh", "lower");
        print_figure("needle step latency median, local solve, half the region, start mesh h5 vs h3 (h_ref h6)", "ms",
                     median[6], median[5], "ourselves on the h3 start mesh", "lower");
        print_figure("needle step latency p99, local solve, half the region, start mesh h5 vs h3 (h_ref h6)", "ms",
                     p99[6], p99[5], "ourselves on the h3 start mesh", "lower");
        // the same start mesh, only the body larger: what the mesh's size costs a step
        print_figure("needle step latency median, local solve, 1M-triangle h5 grid vs h5 (h_ref h6)", "ms",
                     median[7], median[1], "ourselves on the h5 start mesh", "lower");
        print_figure("needle step latency p99, local solve, 1M-triangle h5 grid vs h5 (h_ref h6)", "ms", p99[7],
                     p99[1], "ourselves on the h5 start mesh", "lower");
        // a coarser start mesh too: the region of 300 reaches further out over coarser triangles
        print_figure("needle step latency median, local solve, 1M-triangle h3 grid vs h5 (h_ref h6)", "ms",
                     median[2], median[1], "ourselves on the h5 start mesh", "lower");
        print_figure("needle step latency p99, local solve, 1M-triangle h3 grid vs h5 (h_ref h6)", "ms", p99[2],
                     p99[1], "ourselves on the h5 start mesh", "lower");
        print_figure("needle step latency median, local solve, 1M-triangle h3 grid vs h3 (h_ref h6)", "ms",
                     median[2], median[0], "ourselves on the h3 start mesh", "lower");
        print_figure("needle step latency p99, local solve, 1M-triangle h3 grid vs h3 (h_ref h6)", "ms", p99[2],
                     p99[0], "ourselves on the h3 start mesh", "lower");
        print_figure("needle axial force, local solve vs whole body, largest difference over the insertion (h5)",
                     "N", deviation, largest, "the whole body's largest force", "lower");
        print_figure("needle far-field lag after a local insertion (h5)", "mm", 1e3 * runs[1].lag,
                     1e3 * runs[1].largest, "the largest displacement", "lower");
        print_figure("needle far-field lag after a local insertion with far-field blocks (h5)", "mm",
                     1e3 * runs[3].lag, 1e3 * runs[3].largest, "the largest displacement", "lower");
        print_figure("needle step latency median, local solve and far-field blocks, h5 vs h3", "ms", median[3],
                     median[0], "ourselves on the h3 start mesh (local only)", "lower");
        print_figure("needle step latency median, local solve and far-field blocks, 1M vs h3", "ms", median[4],
                     median[0], "ourselves on the h3 start mesh (local only)", "lower");
    }
    return 0;
}
