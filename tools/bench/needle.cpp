// needle: the update rate of the needle's full loop (refine + intercept + solve + rearrange) in the
// setting of thesis Table 6.5, against the thesis' figures (a Pentium III at 1 GHz), and the step
// latency at the start against the end of a long insertion and on a coarse against a fine start
// mesh (issue 17). Prints one JSON line per figure (CONTRIBUTING.md "Benchmarks").
//
//   needle [--quick]     --quick: the speeds 3, 0.3 and 0.03 only
//
// The thesis' automated insertion (§6.8.4): the slab 0.1 x 0.1 m (E = 34 kPa, nu = 0.34, 1 cm thick,
// fixed at x = 0.1), h_start = h3, the needle along y = 0.05 from the slab's edge to a depth of
// 70 mm, advanced a fixed amount per loop cycle, then cycled in place until nothing changes (no
// grip rearranged, no node slipping). Updates = loop cycles; rate = cycles / CPU time.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>
#include <utility>
#include <string>
#include <vector>

#include "figure_line.hpp"
#include "needle.hpp"
#include "percentile.hpp"
#include "simulation.hpp"
#include "sxk/generators.hpp"

namespace {

using namespace sxk;

const std::vector<std::string> slab_body{"--fix", "x>0.0999", "--E", "34e3", "--nu", "0.34", "--thickness", "0.01",
                                         "--tol", "0.01", "--rounding", "1e-8"};

struct Run {
    double seconds = 0;
    std::size_t updates = 0;
    double iterations_mean = 0;
    std::size_t iterations_max = 0;
    std::vector<double> latency;  // per update, seconds, in order
    std::size_t elements = 0, vertices = 0;
};

// One automated insertion; h_start and h_ref as fractions of the 0.1 m slab (h_k = 0.1 / 2^k).
Run insert(int k_start, int k_ref, double speed) {
    const double h_start = 0.1 / (1 << k_start), h_ref = 0.1 / (1 << k_ref);
    const int cells = 1 << k_start;
    Mesh mesh = *make_triangle_grid({cells, cells}, {h_start, h_start});
    auto made = elasticity::simulate(mesh, slab_body);
    std::unique_ptr<elasticity::Simulation> simulation = std::move(*made);
    needle::Options options;
    options.h_ref = h_ref;
    auto begun = needle::NeedleSession::make(mesh, options, simulation.get());
    std::unique_ptr<needle::NeedleSession> session = std::move(*begun);
    Run run;
    const double step = speed * h_ref, depth = 0.07;
    auto cycle = [&](double x) {
        const auto start = std::chrono::steady_clock::now();
        auto report = session->move({{x - 0.1, 0.05, 0}, {x, 0.05, 0}});
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!report) {
            std::fprintf(stderr, "needle: refused: %s\n", report.reason().c_str());
            std::exit(1);
        }
        run.seconds += seconds;
        run.latency.push_back(seconds);
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
    return run;
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
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    // Table 6.5 as printed
    const ThesisRow h6[] = {{3.00, 0.80, 157, 196.25, 11.81, 41}, {1.00, 0.90, 232, 257.78, 11.52, 62},
                            {0.30, 0.94, 308, 327.66, 10.87, 70}, {0.10, 1.07, 504, 471.03, 8.14, 61},
                            {0.03, 2.24, 1478, 659.82, 5.31, 57}, {0.01, 5.77, 4187, 725.65, 3.87, 51}};
    const ThesisRow h7[] = {{3.00, 2.46, 243, 98.78, 12.67, 57},  {1.00, 2.80, 401, 143.21, 10.88, 82},
                            {0.30, 3.15, 561, 178.10, 10.03, 66}, {0.10, 3.48, 1000, 287.36, 6.63, 67},
                            {0.03, 6.34, 2966, 467.82, 4.18, 53}, {0.01, 15.68, 8505, 542.41, 3.15, 48}};
    std::fprintf(stderr, "h_ref  speed  | ours: CPU s  updates      Hz  CG mean  max  tris | "
                         "thesis: s  updates   Hz   CG mean  max\n");
    const std::pair<int, std::span<const ThesisRow>> tables[] = {{6, h6}, {7, h7}};
    for (const auto& [k_ref, table] : tables) {
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
    {
        const Run run = insert(3, 6, 0.1);
        const std::size_t fifth = run.latency.size() / 5;
        const std::vector<double> first(run.latency.begin(), run.latency.begin() + fifth);
        const std::vector<double> last(run.latency.end() - fifth, run.latency.end());
        const double median_first = percentile(first, 0.5), median_last = percentile(last, 0.5);
        std::fprintf(stderr, "latency h3/h6 0.1 h_ref/update: first fifth median %.3f ms p99 %.3f ms, "
                             "last fifth median %.3f ms p99 %.3f ms\n",
                     1e3 * median_first, 1e3 * percentile(first, 0.99), 1e3 * median_last,
                     1e3 * percentile(last, 0.99));
        print_figure("needle step latency median, end of insertion vs start (h3/h6)", "ms", 1e3 * median_last,
              1e3 * median_first, "ourselves at the start", "lower");
        print_figure("needle step latency p99, end of insertion vs start (h3/h6)", "ms", 1e3 * percentile(last, 0.99),
              1e3 * percentile(first, 0.99), "ourselves at the start", "lower");
    }
    // a coarse against a fine start mesh, the same refinement around the needle
    {
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
    return 0;
}
