// Connectivity build from a tetrahedron soup: sxk::Mesh against CGAL's tet_soup_to_c3t3.h.
//
//   build_connectivity [google-benchmark flags] NAME=MESH.ele [NAME=MESH.ele ...]
//
// For each TetGen mesh two benchmarks, "sxk/NAME" and "cgal/NAME", build the same soup:
//
//   sxk   timed: Mesh(3, 3); reserve(vertices, tets); add_vertex per node; assign_elements(soup)
//   cgal  timed: Triangulation tr; build_triangulation<Tr, true>(tr, points, cells, {}, handles)
//               (vertices, finite cells, one infinite cell per boundary face, all adjacencies;
//               `true` skips the final tds().is_valid() pass, the cheapest CGAL build there is)
//
// Both sides therefore insert the vertices and build element-to-element adjacency plus the
// boundary; neither validates afterwards. Untimed: reading the files, converting them to each
// side's input arrays (std::vector<sxk::Simplex> / std::vector<std::array<int, 5>>, 20 bytes per
// tet either way, and the point arrays), and destroying the result.
//
// Counters per benchmark:
//   tets_per_s              tets / CPU second of the timed part
//   peak_bytes_per_tet      high-water mark of heap bytes during the timed part, minus the bytes
//                           live before it (the inputs), per tet: the result plus temporaries
//   retained_bytes_per_tet  heap bytes still held by the result afterwards, per tet
//   allocations_per_tet     operator new calls during the timed part, per tet
//   boundary_faces          boundary triangles found (the same number on both sides, checked)
#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <array>
#include <cstdio>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "sxk/mesh.hpp"
#include "sxk/simplex.hpp"
#include "tetgen_arrays.hpp"

namespace {

// The triangulation Mesh_3 produces (Regular_triangulation_3 with Mesh_3's vertex and compact
// cell bases): what tet_soup_to_c3t3.h is written for and what a CGAL user would load into.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain>::type;
using CgalPoint = Triangulation::Point;
using SurfacePatch = Triangulation::Cell::Surface_patch_index;

struct Input {
    std::string name;
    std::size_t tets = 0;
    std::vector<sxk::Point> points;
    std::vector<sxk::Simplex> simplexes;
    std::vector<CgalPoint> cgal_points;
    std::vector<std::array<int, 5>> cgal_cells;     // 4 vertex ids + subdomain index
    std::optional<std::size_t> sxk_boundary_faces;  // set when the benchmark ran
    std::optional<std::size_t> cgal_boundary_faces;
};

Input make_input(const std::string& name, const sxk_bench::TetArrays& arrays) {
    Input input;
    input.name = name;
    input.tets = arrays.tets.size();
    input.points = arrays.points;
    input.simplexes.reserve(arrays.tets.size());
    input.cgal_points.reserve(arrays.points.size());
    input.cgal_cells.reserve(arrays.tets.size());
    for (const auto& p : arrays.points)
        input.cgal_points.emplace_back(p[0], p[1], p[2]);
    for (const auto& t : arrays.tets) {
        input.simplexes.emplace_back(+1,
                                     std::initializer_list<sxk::VertexId>{t[0], t[1], t[2], t[3]});
        input.cgal_cells.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]),
                                    static_cast<int>(t[2]), static_cast<int>(t[3]), 1});
    }
    return input;
}

struct Memory {
    std::size_t peak = 0;
    std::size_t retained = 0;
    std::size_t allocations = 0;
};

void set_counters(benchmark::State& state, const Input& input, const Memory& memory,
                  std::size_t boundary_faces) {
    const double tets = static_cast<double>(input.tets);
    state.counters["tets"] = tets;
    state.counters["tets_per_s"] =
        benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["peak_bytes_per_tet"] = static_cast<double>(memory.peak) / tets;
    state.counters["retained_bytes_per_tet"] = static_cast<double>(memory.retained) / tets;
    state.counters["allocations_per_tet"] = static_cast<double>(memory.allocations) / tets;
    state.counters["boundary_faces"] = static_cast<double>(boundary_faces);
}

void build_sxk(benchmark::State& state, Input* input) {
    Memory memory;
    std::size_t boundary_faces = 0;
    for (auto _ : state) {
        std::optional<sxk::Mesh> mesh;
        sxk_bench::reset_peak();
        const std::size_t before = sxk_bench::live_bytes();

        mesh.emplace(3, 3);
        mesh->reserve(input->points.size(), input->simplexes.size());
        for (const sxk::Point& p : input->points)
            mesh->add_vertex(p);
        const auto built = mesh->assign_elements(input->simplexes);

        state.PauseTiming();
        memory.peak = std::max(memory.peak, sxk_bench::peak_bytes() - before);
        memory.allocations = sxk_bench::allocation_count();
        memory.retained = sxk_bench::live_bytes() - before;
        if (!built) {
            state.SkipWithError(("assign_elements refused: " + built.reason()).c_str());
            break;
        }
        boundary_faces = mesh->boundary_face_count();
        mesh.reset();
        state.ResumeTiming();
    }
    if (!state.error_occurred())
        input->sxk_boundary_faces = boundary_faces;
    set_counters(state, *input, memory, boundary_faces);
}

void build_cgal(benchmark::State& state, Input* input) {
    const std::map<std::array<int, 3>, SurfacePatch> border_facets;  // none: no patch lookups
    Memory memory;
    std::size_t boundary_faces = 0;
    for (auto _ : state) {
        std::optional<Triangulation> tr;
        std::optional<std::vector<Triangulation::Vertex_handle>> handles;
        sxk_bench::reset_peak();
        const std::size_t before = sxk_bench::live_bytes();

        tr.emplace();
        handles.emplace();
        const bool built = CGAL::build_triangulation<Triangulation, true>(
            *tr, input->cgal_points, input->cgal_cells, border_facets, *handles);

        state.PauseTiming();
        memory.peak = std::max(memory.peak, sxk_bench::peak_bytes() - before);
        memory.allocations = sxk_bench::allocation_count();
        handles.reset();
        memory.retained = sxk_bench::live_bytes() - before;
        if (!built) {
            state.SkipWithError("CGAL::build_triangulation failed");
            break;
        }
        boundary_faces = tr->tds().number_of_cells() - tr->number_of_finite_cells();
        tr.reset();
        state.ResumeTiming();
    }
    if (!state.error_occurred())
        input->cgal_boundary_faces = boundary_faces;
    set_counters(state, *input, memory, boundary_faces);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::AddCustomContext("cgal_version", CGAL_VERSION_STR);
    if (argc < 2) {
        std::fprintf(
            stderr,
            "usage: build_connectivity [--benchmark_...] NAME=MESH.ele [NAME=MESH.ele ...]\n");
        return 2;
    }
    std::deque<Input> inputs;  // stable addresses for the registered benchmarks
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const auto equals = argument.find('=');
        if (equals == std::string::npos || equals == 0 || argument.rfind("--", 0) == 0) {
            std::fprintf(stderr, "build_connectivity: expected NAME=MESH.ele, got '%s'\n", argv[i]);
            return 2;
        }
        try {
            const auto arrays = sxk_bench::load_tetgen(argument.substr(equals + 1));
            inputs.push_back(make_input(argument.substr(0, equals), arrays));
        } catch (const std::exception& error) {
            std::fprintf(stderr, "build_connectivity: %s\n", error.what());
            return 2;
        }
    }
    for (Input& input : inputs) {
        benchmark::RegisterBenchmark(("sxk/" + input.name).c_str(), build_sxk, &input)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("cgal/" + input.name).c_str(), build_cgal, &input)
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    int status = 0;
    for (const Input& input : inputs) {
        if (input.sxk_boundary_faces && input.cgal_boundary_faces &&
            *input.sxk_boundary_faces != *input.cgal_boundary_faces) {
            std::fprintf(stderr,
                         "build_connectivity: %s: boundary faces differ (sxk %zu, CGAL %zu)\n",
                         input.name.c_str(), *input.sxk_boundary_faces, *input.cgal_boundary_faces);
            status = 1;
        }
    }
    return status;
}
