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
// Wall time (the products run on two threads). Counters: iterations and iterations_per_s
// (solves); nonzeros and matrix_bytes (K), body_bytes (what the matrix-free product keeps per
// element).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <exception>
#include <optional>
#include <string>

#include <tbb/task_arena.h>

#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"

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
    // per element: its id (4 bytes), shape gradients and volume (80), corners (16), 4 star
    // entries (16), 12 corner forces (96); per vertex 4 (the star's start)
    state.counters["body_bytes"] =
        static_cast<double>(c.mesh.element_count() * (4 + 80 + 16 + 16 + 96) + c.mesh.vertex_count() * 4);
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
