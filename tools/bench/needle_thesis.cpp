// The needle's experiments of thesis §6.8 and §6.2, beside the thesis' figures (issue 17):
//
//   table61    error against the relaxation tolerance (h_start = h_ref = h7; against eps = 1e-8)
//   table62    CG iterations for h_start x h_ref (the static load, eps = 0.01)
//   table63    mean and maximum displacement error against the uniform h7 mesh, same runs
//   table64    error against insertion speed (h3/h6; against an insertion at 0.005 h_ref/update)
//   table66    conformance: a static load along a tilted line, needle nodes relocated or not (h3/h6),
//              against each other and against h7
//   nonlinear  §6.8.7: a needle inserted sideways into a slab fixed at the bottom, linear against
//              neo-Hookean (nu = 0, 0.01 h_ref/update): where the tip ends in the reference
//   size3d     §6.2: a 1 mm needle 70 mm into a 10 cm cube, as a line and as a surface of radius
//              0.5 mm: our mesh against the ~10^6 nodes of a uniform 1 mm mesh
//   fig614     Fig. 6.14: a needle of radius 1 mm into a 10 cm cube fixed at the bottom, refined
//              to h7, the whole body solved: the mesh's size against the thesis' ~30,000 elements
//
//   needle_thesis [NAME...]     (default: all)
//
// The slab (§6.8.1): 0.1 x 0.1 m, 1 cm thick, E = 34 kPa, nu = 0.34, fixed at x = 0.1; h_k = 0.1 m
// 2^-k; eps_round = 1e-8. The static load: the friction profile of Fig. 6.4 (needle.hpp Friction,
// our numbers: the figure has none) along y = 0.05 from x = 0 to the tip at x = 0.07, in +x, each
// node on the line loaded with the profile over its share. Errors in mm: the other solution
// interpolated at the reference solution's nodes (linear in each triangle).
//
// stdout: one JSON line per figure (CONTRIBUTING.md "Benchmarks"), the peer the thesis' figure;
// stderr: the tables.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "elastic_body.hpp"
#include "figure_line.hpp"
#include "friction.hpp"
#include "needle.hpp"
#include "shaft_refinement.hpp"
#include "simulation.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"
#include "sxk/locate.hpp"

namespace {

using namespace sxk;
using elasticity::ElasticBody;

double h(int k) { return 0.1 / double(1 << k); }

void line(const std::string& name, const char* unit, double ours, double thesis, const char* better) {
    print_figure(name, unit, ours, thesis, "thesis", better);
}

Mesh slab(int k_start) {
    const int cells = 1 << k_start;
    return *make_triangle_grid({cells, cells}, {h(k_start), h(k_start)});
}

// Refines `mesh` (at rest) along the segment [a, b] to size h_ref.
void refine_line(Mesh& mesh, const Point& a, const Point& b, double h_ref) {
    SpatialIndex reference(mesh, Positions::reference), deformed(mesh, Positions::deformed);
    auto refined = needle::refine_along(mesh, reference, deformed, a, b, h_ref, invalid_id);
    if (!refined) {
        std::fprintf(stderr, "needle_thesis: %s\n", refined.reason().c_str());
        std::exit(1);
    }
}

// A solution: the mesh and its displacements per vertex.
struct Solution {
    Mesh mesh{2, 2};
    std::vector<Point> u;
    std::size_t iterations = 0;
};

// The slab body of `mesh`, fixed at x = 0.1 (material: E = 34 kPa, nu, 1 cm).
std::unique_ptr<ElasticBody> slab_body(const Mesh& mesh, double poisson = 0.34,
                                       elasticity::Model model = elasticity::Model::linear) {
    auto made = ElasticBody::make(mesh, {.young = 34e3, .poisson = poisson}, {.model = model, .thickness = 0.01});
    auto body = std::make_unique<ElasticBody>(std::move(*made));
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.vertex_element(v) != invalid_id && mesh.reference(v)[0] >= 0.1 - 1e-12) (void)body->fix(v);
    return body;
}

// The static load of §6.8.1 on the nodes of the line y = 0.05, 0 <= x <= 0.07 (forces in +x).
void static_load(const Mesh& mesh, ElasticBody& body) {
    std::vector<needle::NeedleNode> nodes;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& x = mesh.reference(v);
        if (mesh.vertex_element(v) == invalid_id || x[1] != 0.05 || x[0] > 0.07 + 1e-12) continue;
        needle::NeedleNode node;
        node.vertex = v;
        node.along = x[0] - 0.07;
        nodes.push_back(node);
    }
    // shares reach the slab's edge at x = 0: the last node's share is half its spacing beyond it
    std::sort(nodes.begin(), nodes.end(), [](auto& a, auto& b) { return a.along > b.along; });
    const double spacing = nodes.size() > 1 ? nodes[nodes.size() - 2].along - nodes.back().along : 0.0;
    needle::share_thresholds(nodes, needle::Friction{}, spacing);
    for (const auto& node : nodes) (void)body.add_force(node.vertex, {node.threshold, 0, 0});
}

Solution solve_static(int k_start, int k_ref, double tolerance) {
    Solution s;
    s.mesh = slab(k_start);
    if (k_ref > k_start) refine_line(s.mesh, {0, 0.05, 0}, {0.07, 0.05, 0}, h(k_ref));
    auto body = slab_body(s.mesh);
    static_load(s.mesh, *body);
    auto report = elasticity::solve_linear_cg(*body, {.tolerance = tolerance, .rounding = 1e-8});
    s.iterations = report->iterations;
    for (VertexId v = 0; v < s.mesh.vertex_count(); ++v) {
        const auto d = body->displacement(v);
        s.u.push_back({d[0], d[1], d[2]});
    }
    return s;
}

// Mean and maximum |u_a - u_ref| in mm over the nodes of `reference`, u_a interpolated.
std::pair<double, double> errors(const Solution& a, const Solution& reference) {
    const SpatialIndex index(const_cast<Mesh&>(a.mesh), Positions::reference);
    double sum = 0, largest = 0;
    std::size_t n = 0;
    ElementId hint = invalid_id;
    for (VertexId v = 0; v < reference.mesh.vertex_count(); ++v) {
        if (reference.mesh.vertex_element(v) == invalid_id) continue;
        const Location at = index.locate(reference.mesh.reference(v), hint);
        if (!at.found()) continue;
        hint = at.element;
        const auto corners = a.mesh.simplex(at.element).vertices();
        Point u{0, 0, 0};
        for (std::size_t j = 0; j < corners.size(); ++j)
            for (int k = 0; k < 3; ++k) u[k] += at.barycentric[j] * a.u[corners[j]][k];
        const Point& r = reference.u[v];
        const double e = 1000 * std::hypot(u[0] - r[0], u[1] - r[1], u[2] - r[2]);
        sum += e;
        largest = std::max(largest, e);
        ++n;
    }
    return {sum / double(std::max<std::size_t>(n, 1)), largest};
}

void table61() {
    const Solution exact = solve_static(7, 7, 1e-8);
    const double thesis[][3] = {{0.3, 0.74, 2.98},   {0.1, 0.061, 0.18},     {0.03, 0.034, 0.083},
                                {0.01, 0.011, 0.022}, {0.003, 0.0038, 0.0096}, {0.001, 0.0008, 0.0021}};
    std::fprintf(stderr, "\nTable 6.1: error against the relaxation tolerance (h7 uniform, against eps = 1e-8: %zu "
                         "iterations)\n  eps     CG   mean mm   max mm | thesis mean  max\n",
                 exact.iterations);
    for (const auto& row : thesis) {
        const Solution s = solve_static(7, 7, row[0]);
        const auto [mean, largest] = errors(s, exact);
        std::fprintf(stderr, "  %-6g %4zu  %8.4f  %7.4f | %8.4f  %6.4f\n", row[0], s.iterations, mean, largest, row[1],
                     row[2]);
        line("needle Table 6.1 mean error at eps " + std::to_string(row[0]), "mm", mean, row[1], "lower");
    }
}

void tables62_63() {
    const Solution exact = solve_static(7, 7, 1e-8);
    // thesis Tables 6.2 and 6.3, by (h_start, h_ref); -1: not in the table
    const std::map<std::pair<int, int>, std::array<double, 3>> thesis{
        {{1, 3}, {22, 0.34, 1.01}}, {{1, 4}, {34, 0.33, 0.88}}, {{1, 5}, {45, 0.33, 0.88}},
        {{1, 6}, {62, 0.30, 0.87}}, {{1, 7}, {84, 0.28, 0.87}}, {{2, 3}, {27, 0.26, 0.91}},
        {{2, 4}, {36, 0.24, 0.68}}, {{2, 5}, {46, 0.24, 0.61}}, {{2, 6}, {64, 0.21, 0.54}},
        {{2, 7}, {84, 0.20, 0.53}}, {{3, 3}, {46, 0.15, 0.66}}, {{3, 4}, {49, 0.13, 0.54}},
        {{3, 5}, {58, 0.13, 0.51}}, {{3, 6}, {73, 0.10, 0.29}}, {{3, 7}, {93, 0.08, 0.27}},
        {{4, 4}, {81, 0.09, 0.45}}, {{4, 5}, {86, 0.08, 0.43}}, {{4, 6}, {96, 0.04, 0.19}},
        {{4, 7}, {115, 0.03, 0.14}}, {{5, 5}, {204, 0.07, 0.41}}, {{5, 6}, {208, 0.03, 0.17}},
        {{5, 7}, {194, 0.00, 0.06}}, {{6, 6}, {278, 0.02, 0.16}}, {{6, 7}, {285, 0.00, 0.03}}};
    std::fprintf(stderr, "\nTables 6.2 and 6.3: the static load, eps = 0.01; CG iterations and the error [mm] "
                         "against the uniform h7 mesh (eps = 1e-8)\n"
                         "  start ref | triangles  CG  mean   max  | thesis CG  mean   max\n");
    for (const auto& [key, row] : thesis) {
        const auto [k_start, k_ref] = key;
        const Solution s = solve_static(k_start, k_ref, 0.01);
        const auto [mean, largest] = errors(s, exact);
        std::fprintf(stderr, "  h%d    h%d  | %9zu %4zu  %5.3f  %5.3f | %9.0f  %5.2f  %5.2f\n", k_start, k_ref,
                     s.mesh.element_count(), s.iterations, mean, largest, row[0], row[1], row[2]);
        const std::string at = " h" + std::to_string(k_start) + "/h" + std::to_string(k_ref);
        line("needle Table 6.2 CG iterations" + at, "iterations", double(s.iterations), row[0], "lower");
        line("needle Table 6.3 mean error" + at, "mm", mean, row[1], "lower");
    }
}

// The elasticity plug-in's simulation of `mesh` with `sxk deform`'s words; exits on a refusal.
std::unique_ptr<Simulation> body_of(Mesh& mesh, const std::vector<std::string>& words) {
    auto made = elasticity::simulate(mesh, sxk::cli::body_options(words).value());
    if (!made) {
        std::fprintf(stderr, "needle_thesis: %s\n", made.reason().c_str());
        std::exit(1);
    }
    return std::move(*made);
}

// An automated insertion (§6.8.4) into the slab along y = 0.05 at `speed` h_ref per update, then
// cycled in place until no grip changes and no node slips.
struct Inserted {
    Solution solution;
    std::size_t updates = 0;
    Point tip_reference{0, 0, 0};
    bool shown = true;  // every step's solution could be written (inverted nothing)
};

Inserted insert(int k_start, int k_ref, double speed, const std::vector<std::string>& body, Point from, Point to,
                double friction_scale = 1) {
    Inserted result;
    Mesh& mesh = result.solution.mesh;
    mesh = slab(k_start);
    std::unique_ptr<Simulation> simulation = body_of(mesh, body);
    needle::Options options;
    options.h_ref = h(k_ref);
    options.friction.shaft *= friction_scale;
    options.friction.tip *= friction_scale;
    auto begun = needle::NeedleSession::make(mesh, options, simulation.get());
    std::unique_ptr<needle::NeedleSession> session = std::move(*begun);
    const double length = std::hypot(to[0] - from[0], to[1] - from[1]);
    const double ax = (to[0] - from[0]) / length, ay = (to[1] - from[1]) / length;
    auto cycle = [&](double s) {
        const Point tip{from[0] + s * ax, from[1] + s * ay, 0};
        auto report = session->move({{tip[0] - 0.1 * ax, tip[1] - 0.1 * ay, 0}, tip});
        if (!report) {
            std::fprintf(stderr, "needle_thesis: refused: %s\n", report.reason().c_str());
            std::exit(1);
        }
        ++result.updates;
        result.shown = result.shown && report->shown;
        return *report;
    };
    double s = 0;
    cycle(s);
    while (s < length) cycle(s = std::min(s + speed * h(k_ref), length));
    for (int settle = 0; settle < 20000; ++settle) {
        const auto report = cycle(length);
        if (report.loosened + report.gripped == 0 && report.slip == 0) break;
    }
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const auto d = simulation->displacement(v);
        result.solution.u.push_back({d[0], d[1], d[2]});
    }
    // where the tip is in the reference: its deformed position located, mapped back
    const SpatialIndex deformed(mesh, Positions::deformed);
    const Location at = deformed.locate(to);
    if (at.found()) result.tip_reference = needle::reference_of(mesh, at);
    return result;
}

const std::vector<std::string> slab_words{"--fix", "x>0.0999", "--E", "34e3", "--nu", "0.34", "--thickness", "0.01",
                                          "--tol", "0.01", "--rounding", "1e-8"};

void table64() {
    const Inserted reference = insert(3, 6, 0.005, slab_words, {0, 0.05, 0}, {0.07, 0.05, 0});
    const double thesis[][3] = {{3.00, 0.62, 1.60}, {1.00, 0.68, 1.96}, {0.30, 0.15, 0.34},
                                {0.10, 0.18, 0.68}, {0.03, 0.36, 1.08}, {0.01, 0.07, 0.27}};
    std::fprintf(stderr, "\nTable 6.4: error against insertion speed (h3/h6, against 0.005 h_ref/update: %zu updates)\n"
                         "  speed  updates  mean mm  max mm | thesis mean  max\n",
                 reference.updates);
    for (const auto& row : thesis) {
        const Inserted run = insert(3, 6, row[0], slab_words, {0, 0.05, 0}, {0.07, 0.05, 0});
        const auto [mean, largest] = errors(run.solution, reference.solution);
        std::fprintf(stderr, "  %5.2f  %7zu  %7.3f  %6.3f | %8.2f  %5.2f\n", row[0], run.updates, mean, largest, row[1],
                     row[2]);
        char name[96];
        std::snprintf(name, sizeof name, "needle Table 6.4 mean error at %.2f h_ref per update", row[0]);
        line(name, "mm", mean, row[1], "lower");
    }
}

// The static load along a tilted line through needle nodes intercepted by a needle moved along it
// (geometry only), relocated or not; solved to eps = 1e-8.
Solution tilted(int k_start, int k_ref, bool relocate) {
    Solution s;
    s.mesh = slab(k_start);
    needle::Options options;
    options.h_ref = h(k_ref);
    options.relocate = relocate;
    const double angle = 0.25;  // radians; the thesis' Fig. 6.11 shows "an angled trajectory"
    const Point from{0, 0.035, 0};
    const double ax = std::cos(angle), ay = std::sin(angle), depth = 0.07;
    std::vector<needle::NeedleNode> nodes;
    {
        auto begun = needle::NeedleSession::make(s.mesh, options, nullptr);
        std::unique_ptr<needle::NeedleSession> session = std::move(*begun);
        for (double t = -0.005; t <= depth + 1e-12; t += 0.1 * h(k_ref)) {
            const Point tip{from[0] + t * ax, from[1] + t * ay, 0};
            (void)session->move({{tip[0] - 0.1 * ax, tip[1] - 0.1 * ay, 0}, tip});
        }
        nodes.assign(session->nodes().begin(), session->nodes().end());
        session->end();
    }
    auto body = slab_body(s.mesh);
    for (const auto& node : nodes) (void)body->add_force(node.vertex, {node.threshold * ax, node.threshold * ay, 0});
    auto report = elasticity::solve_linear_cg(*body, {.tolerance = 1e-8, .rounding = 1e-8});
    s.iterations = report->iterations;
    for (VertexId v = 0; v < s.mesh.vertex_count(); ++v) {
        const auto d = body->displacement(v);
        s.u.push_back({d[0], d[1], d[2]});
    }
    return s;
}

void table66() {
    const Solution with = tilted(3, 6, true), without = tilted(3, 6, false), fine = tilted(7, 7, true);
    const auto between = errors(without, with), d_with = errors(with, fine), d_without = errors(without, fine);
    std::fprintf(stderr, "\nTable 6.6: conformance errors (h3/h6, a tilted line; against h7 with relocation)\n"
                         "                                          mean mm  max mm | thesis mean  max\n"
                         "  with relocation vs without              %7.3f  %6.3f | %8.3f  %5.2f\n"
                         "  discretization error with relocation    %7.3f  %6.3f | %8.3f  %5.2f\n"
                         "  discretization error without relocation %7.3f  %6.3f | %8.3f  %5.2f\n",
                 between.first, between.second, 0.019, 0.23, d_with.first, d_with.second, 0.094, 0.43, d_without.first,
                 d_without.second, 0.095, 0.37);
    line("needle Table 6.6 with vs without relocation, mean", "mm", between.first, 0.019, "lower");
    line("needle Table 6.6 discretization error with relocation, mean", "mm", d_with.first, 0.094, "lower");
    line("needle Table 6.6 discretization error without relocation, mean", "mm", d_without.first, 0.095, "lower");
}

void nonlinear() {
    // the slab fixed at the bottom, the needle in from the left side near the top, 70 mm
    std::fprintf(stderr, "\n6.8.7: sideways insertion, slab fixed at the bottom, nu = 0, h3/h6, 0.01 h_ref/update\n"
                         "  friction  linear tip (mm)        neo-Hookean tip (mm)    apart   linear s  nonlinear s\n");
    for (const double scale : {1.0, 2.0, 3.0}) {
        double seconds[2];
        Point tips[2];
        int i = 0;
        for (const char* material : {"linear", "neohookean"}) {
            const std::vector<std::string> words{"--fix",       "y<0.0001", "--E",   "34e3",     "--nu",     "0",
                                                 "--thickness", "0.01",     "--tol", "0.01",     "--rounding", "1e-8",
                                                 "--material",  material};
            const auto start = std::chrono::steady_clock::now();
            const Inserted run = insert(3, 6, 0.01, words, {0, 0.08, 0}, {0.07, 0.08, 0}, scale);
            seconds[i] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            tips[i++] = run.tip_reference;
            if (!run.shown) std::fprintf(stderr, "  (%s, friction x%g: a step's solution inverted an element)\n",
                                         material, scale);
        }
        const double apart = 1000 * std::hypot(tips[0][0] - tips[1][0], tips[0][1] - tips[1][1]);
        std::fprintf(stderr, "  x%-7g (%6.2f, %6.2f)       (%6.2f, %6.2f)        %5.2f   %7.1f  %10.1f\n", scale,
                     1000 * tips[0][0], 1000 * tips[0][1], 1000 * tips[1][0], 1000 * tips[1][1], apart, seconds[0],
                     seconds[1]);
        line("needle 6.8.7 tip reference positions apart, linear vs neo-Hookean, friction x" +
                 std::to_string(int(scale)),
             "mm", apart, 8.0, "higher");
    }
}

void size3d() {
    // a needle of 1 mm diameter, 10 cm cube: h_ref = 1 mm, start 8 cells (12.5 mm), 70 mm deep near
    // the centre; first a line (the nodes of the faces the tip enters), then the needle as a surface
    // of radius 0.5 mm (§6.2: "the mesh must include elements with a size comparable to the needle
    // diameter" to represent it; Options::radius)
    for (const double radius : {0.0, 0.0005}) {
        Mesh cube = *make_kuhn_cube(8, 0.0125);
        needle::Options options;
        options.h_ref = 0.001;
        options.radius = radius;
        auto begun = needle::NeedleSession::make(cube, options, nullptr);
        std::unique_ptr<needle::NeedleSession> session = std::move(*begun);
        const auto start = std::chrono::steady_clock::now();
        for (double x = -0.005; x <= 0.07 + 1e-12; x += 0.0005)
            (void)session->move({{x - 0.1, 0.0503, 0.0497}, {x, 0.0503, 0.0497}});
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double uniform = std::pow(0.1 / 0.001 + 1, 3);
        const std::string needle = radius > 0 ? "a needle of radius 0.5 mm" : "a line";
        std::fprintf(stderr,
                     "\n6.2: a 1 mm needle 70 mm into a 10 cm cube, %s: %zu vertices, %zu tetrahedra, %zu needle "
                     "nodes after %zu steps (%.2f s, geometry only); a uniform 1 mm mesh has %.0f vertices: %.0fx "
                     "smaller\n",
                     needle.c_str(), cube.vertices_in_elements(), cube.element_count(), session->nodes().size(),
                     session->steps(), seconds, uniform, uniform / double(cube.vertices_in_elements()));
        line("needle 6.2 vertices after a 70 mm insertion (1 mm needle, 10 cm cube" +
                 std::string(radius > 0 ? ", radius 0.5 mm" : "") + ") vs a uniform 1 mm mesh",
             "vertices", double(cube.vertices_in_elements()), uniform, "lower");
    }
}

void fig614() {
    // Fig. 6.14: a needle of radius 1 mm from the left into a 10 cm cube fixed at the bottom, linear
    // material (the slab's E and nu; the figure gives none), refined around the needle to h7 (the
    // thesis: "Figure 6.14 corresponds to refinement to h7. The simulation has approximately
    // 30,000 elements"); ours 70 mm deep in 180 updates of 0.4 mm, the whole body solved each.
    // Against the same insertion with a line for a needle.
    const std::vector<std::string> words{"--fix", "z<0.0001", "--E", "34e3", "--nu", "0.34", "--tol", "0.01"};
    std::fprintf(stderr, "\nFig. 6.14: a needle into a 10 cm cube fixed at the bottom, h3/h7, linear, whole body\n"
                         "  radius    tetrahedra  vertices  needle nodes  CG iterations  CPU s  axial force (N)\n");
    for (const double radius : {0.0, 0.001}) {
        Mesh cube = *make_kuhn_cube(8, 0.0125);
        std::unique_ptr<Simulation> simulation = body_of(cube, words);
        needle::Options options;
        options.h_ref = h(7);
        options.radius = radius;
        auto begun = needle::NeedleSession::make(cube, options, simulation.get());
        std::unique_ptr<needle::NeedleSession> session = std::move(*begun);
        std::size_t iterations = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k <= 180; ++k) {
            const double x = -0.002 + 0.072 * k / 180;
            auto report = session->move({{x - 0.1, 0.0503, 0.0497}, {x, 0.0503, 0.0497}});
            if (!report) {
                std::fprintf(stderr, "needle_thesis: refused: %s\n", report.reason().c_str());
                std::exit(1);
            }
            iterations += report->iterations;
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "  %4.1f mm  %10zu  %8zu  %12zu  %13zu  %5.1f  %15.3f\n", 1000 * radius,
                     cube.element_count(), cube.vertices_in_elements(), session->nodes().size(), iterations, seconds,
                     session->last_step().axial_force);
        if (radius > 0)
            line("needle Fig. 6.14 tetrahedra after a 70 mm insertion of a 1 mm radius needle, refined to h7", "elements",
                 double(cube.element_count()), 30000, "lower");
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::map<std::string, std::function<void()>> experiments{
        {"table61", table61}, {"table62", tables62_63}, {"table63", tables62_63}, {"table64", table64},
        {"table66", table66}, {"nonlinear", nonlinear}, {"size3d", size3d}, {"fig614", fig614}};
    std::vector<std::string> names(argv + 1, argv + argc);
    if (names.empty()) names = {"table61", "table62", "table64", "table66", "nonlinear", "size3d", "fig614"};
    for (const std::string& name : names) {
        const auto found = experiments.find(name);
        if (found == experiments.end()) {
            std::fprintf(stderr, "needle_thesis: unknown experiment '%s'\n", name.c_str());
            return 2;
        }
        found->second();
    }
    return 0;
}
