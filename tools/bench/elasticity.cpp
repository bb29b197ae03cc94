// The elasticity plug-in's matrix-free product against Eigen's assembled sparse matrix, and CG
// iterations per second on the thesis' 7986-element cube (issue 14).
//
//   elasticity [google-benchmark flags] [NAME=MESH.ele ...]   (without meshes: the cube only)
//
// Per mesh (untimed, once): read it, make an ElasticBody (E = 1e4, nu = 0.3), assemble K with
// assemble_stiffness (Eigen::SparseMatrix<double>, column-major: Eigen's product with it is
// serial), and a vector d of sines. Timed:
//   product/NAME/matrix_free/threads:T  body.multiply(d, out) in a TBB arena of T threads (1, 2)
//   product/NAME/eigen                  out = K * d
// and, on the thesis' cube (make_kuhn_cube(11): 1728 nodes, 7986 tetrahedra, nu = 1/4, back face
// z = 0 fixed, in-plane dilating forces on the side x = 1, ||r|| < 1e-3 ||f||: the first §3.3
// problem of tests/plugins/elasticity_thesis_test.cpp):
//   cube/matrix_free/threads:2  solve_linear_cg from rest
//   cube/eigen                  solve_assembled_cg from rest (assembly included: what a
//                               simulation that re-assembles after each edit pays)
// On the first mesh, the re-solve after a local edit (resolve/NAME/matrix_free and /eigen, 3
// iterations each: see resolve() below).
// Wall time (the products run on two threads). Counters: iterations and iterations_per_s
// (solves); nonzeros and matrix_bytes (K), body_bytes (what the matrix-free product keeps per
// element).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <exception>
#include <optional>
#include <random>
#include <vector>
#include <string>

#include <tbb/task_arena.h>

#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/split_edge.hpp"

namespace {

namespace el = sxk::elasticity;

struct Case {
    std::string name;
    sxk::Mesh mesh{3, 3};
    std::optional<el::ElasticBody> body;
    Eigen::SparseMatrix<double> k;
    Eigen::VectorXd d;
};

void counters(benchmark::State& state, const Case& c) {
    state.counters["elements"] = static_cast<double>(c.mesh.element_count());
    state.counters["nonzeros"] = static_cast<double>(c.k.nonZeros());
    state.counters["matrix_bytes"] = static_cast<double>(c.k.nonZeros() * (sizeof(double) + sizeof(int)) +
                                                         static_cast<std::size_t>(c.k.outerSize() + 1) * sizeof(int));
    // per element: its id (4 bytes), the rest shape (shape gradients, volume, Lame parameters:
    // sizeof(RestShape)), corners (16), 4 star entries (16), 12 corner forces (96); per vertex 4
    // (the star's start)
    state.counters["body_bytes"] = static_cast<double>(
        c.mesh.element_count() * (4 + sizeof(el::detail::RestShape) + 16 + 16 + 96) + c.mesh.vertex_count() * 4);
}

void matrix_free(benchmark::State& state, Case* c, int threads) {
    tbb::task_arena arena(threads);
    Eigen::VectorXd out;
    for (auto _ : state) {
        arena.execute([&] { c->body->multiply(c->d, out); });
        benchmark::DoNotOptimize(out.data());
    }
    counters(state, *c);
}

void eigen_product(benchmark::State& state, Case* c) {
    Eigen::VectorXd out(c->d.size());
    for (auto _ : state) {
        out.noalias() = c->k * c->d;
        benchmark::DoNotOptimize(out.data());
    }
    counters(state, *c);
}

// The §3.3 cube, loaded; displacements at rest.
el::ElasticBody thesis_cube(const sxk::Mesh& mesh) {
    auto body = el::ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.25});
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const sxk::Point& p = mesh.reference(v);
        if (p[2] == 0)
            (void)body->fix(v);
        else if (p[0] > 1 - 1e-12)
            (void)body->add_force(v, {0, p[1] - 0.5, p[2] - 0.5});
    }
    return std::move(*body);
}

void cube_solve(benchmark::State& state, const sxk::Mesh* mesh, bool assembled) {
    el::ElasticBody body = thesis_cube(*mesh);
    tbb::task_arena arena(2);
    const el::SolveOptions options{.tolerance = 1e-3, .stop = el::StopCriterion::external_force};
    std::size_t iterations = 0;
    for (auto _ : state) {
        body.displacements().setZero();
        arena.execute([&] {
            const auto report = assembled ? el::solve_assembled_cg(body, options) : el::solve_linear_cg(body, options);
            iterations = report->iterations;
        });
    }
    state.counters["iterations"] = static_cast<double>(iterations);
    state.counters["iterations_per_s"] =
        benchmark::Counter(static_cast<double>(iterations) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// ---- re-solve after a local edit ----------------------------------------------------------------

// The first mesh's load case: vertices within 5% of the lowest z fixed, a total force of 1e-3 E
// H^2 along x shared by those within 5% of the highest z (small displacements), E = 1e4, nu = 0.3.
void load_case(el::ElasticBody& body, const sxk::Mesh& mesh) {
    double low = INFINITY, high = -INFINITY;
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v) {
        low = std::min(low, mesh.reference(v)[2]);
        high = std::max(high, mesh.reference(v)[2]);
    }
    const double margin = 0.05 * (high - low);
    std::vector<sxk::VertexId> top;
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == sxk::invalid_id) continue;
        if (mesh.reference(v)[2] <= low + margin) (void)body.fix(v);
        else if (mesh.reference(v)[2] >= high - margin) top.push_back(v);
    }
    const double total = 1e-3 * 1e4 * body.diameter() * body.diameter();
    for (const sxk::VertexId v : top) (void)body.add_force(v, {total / static_cast<double>(top.size()), 0, 0});
}

struct Resolve {
    const Case* base = nullptr;
    Eigen::VectorXd solved;  // the base solution, tolerance 1e-6
};

// One iteration: a copy of the solved mesh and body (untimed), then, timed: split_edge of a random
// edge in the middle third of the mesh and the re-solve to 1e-6 - ours: the body attached as a
// watcher (rest shapes of the split's elements only) and the matrix-free CG from the previous
// solution; Eigen's: a body built afresh on the edited mesh (every rest shape), K assembled,
// ConjugateGradient from the same start (the previous solution, the new vertex interpolated).
void resolve(benchmark::State& state, Resolve* r, bool assembled) {
    std::mt19937_64 random(7);
    const el::SolveOptions options{.tolerance = 1e-6};
    std::size_t iterations = 0;
    for (auto _ : state) {
        state.PauseTiming();
        sxk::Mesh mesh = r->base->mesh;
        mesh.reserve(mesh.vertex_count() + 1, mesh.element_count() + 64);
        auto body = el::ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3});
        load_case(*body, mesh);
        body->displacements() = r->solved;
        mesh.add_watcher(*body);
        sxk::ElementId t = static_cast<sxk::ElementId>(random() % mesh.element_capacity());
        while (!mesh.is_element(t)) t = static_cast<sxk::ElementId>((t + 1) % mesh.element_capacity());
        const sxk::VertexId a = mesh.simplex(t).vertex(0), b = mesh.simplex(t).vertex(1);
        state.ResumeTiming();
        if (!sxk::split_edge(mesh, a, b, 0.5)) {
            state.SkipWithError("split_edge refused");
            return;
        }
        if (assembled) {
            auto fresh = el::ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3});
            load_case(*fresh, mesh);
            fresh->displacements() = body->displacements();  // the same start: previous + interpolated
            iterations = el::solve_assembled_cg(*fresh, options)->iterations;
        } else {
            iterations = el::solve_linear_cg(*body, options)->iterations;
        }
        state.PauseTiming();
        mesh.remove_watcher(*body);
        state.ResumeTiming();
    }
    state.counters["iterations"] = static_cast<double>(iterations);
}

const char* usage = "usage: elasticity [--benchmark_...] [NAME=MESH.ele...]\n";

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::deque<Case> cases;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const auto equals = argument.find('=');
        if (argument.rfind("--", 0) == 0 || equals == std::string::npos || equals == 0) {
            std::fputs(usage, stderr);
            return 2;
        }
        Case& c = cases.emplace_back();
        c.name = argument.substr(0, equals);
        try {
            c.mesh = sxk::read_mesh(argument.substr(equals + 1));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "elasticity: %s\n", e.what());
            return 1;
        }
        auto body = el::ElasticBody::make(c.mesh, {.young = 1e4, .poisson = 0.3});
        if (!body) {
            std::fprintf(stderr, "elasticity: %s: %s\n", c.name.c_str(), body.reason().c_str());
            return 1;
        }
        c.body.emplace(std::move(*body));
        c.k = el::assemble_stiffness(*c.body);
        c.d.resize(static_cast<Eigen::Index>(c.body->dof_count()));
        for (Eigen::Index j = 0; j < c.d.size(); ++j) c.d[j] = std::sin(0.37 * static_cast<double>(j));
        std::fprintf(stderr, "elasticity: %s: %zu tets, %zu vertices, K has %lld nonzeros\n", c.name.c_str(),
                     c.mesh.element_count(), c.mesh.vertex_count(), static_cast<long long>(c.k.nonZeros()));
    }
    for (Case& c : cases) {
        for (const int threads : {1, 2})
            benchmark::RegisterBenchmark(("product/" + c.name + "/matrix_free/threads:" + std::to_string(threads)).c_str(),
                                         matrix_free, &c, threads)
                ->UseRealTime()
                ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("product/" + c.name + "/eigen").c_str(), eigen_product, &c)
            ->UseRealTime()
            ->Unit(benchmark::kMicrosecond);
    }
    // the re-solve on the first mesh (the femur's small one in tools/bench/run)
    static Resolve resolve_case;
    if (!cases.empty()) {
        resolve_case.base = &cases.front();
        auto body = el::ElasticBody::make(cases.front().mesh, {.young = 1e4, .poisson = 0.3});
        load_case(*body, cases.front().mesh);
        const auto report = el::solve_linear_cg(*body, {.tolerance = 1e-6});
        std::fprintf(stderr, "elasticity: %s: base solve %zu iterations, %.2f s\n", cases.front().name.c_str(),
                     report->iterations, report->seconds);
        resolve_case.solved = body->displacements();
        for (const bool assembled : {false, true})
            benchmark::RegisterBenchmark(("resolve/" + cases.front().name + (assembled ? "/eigen" : "/matrix_free")).c_str(),
                                         resolve, &resolve_case, assembled)
                ->UseRealTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(3);
    }
    static const sxk::Mesh cube = *sxk::make_kuhn_cube(11, 1.0 / 11);
    benchmark::RegisterBenchmark("cube/matrix_free/threads:2", cube_solve, &cube, false)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("cube/eigen", cube_solve, &cube, true)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
