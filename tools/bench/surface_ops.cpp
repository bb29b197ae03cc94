// Edge flip, edge split and edge collapse on a triangle surface: sxk::flip_edge / split_edge /
// collapse_edge against CGAL::Surface_mesh with CGAL::Euler operations and OpenMesh's TriMesh.
//
//   surface_ops [google-benchmark flags] [--edges=K] [--seed=S] MESH.ele
//
// Surface (untimed): the boundary of a TetGen mesh (the femur of tools/make-data, boundary
// triangles oriented outwards as faces of positive tets, vertices renumbered densely). The same
// vertex and triangle arrays build all three meshes, so vertex i is vertex i everywhere.
//
// Sequences (untimed, std::mt19937_64 with seed S), the same on all three sides:
//   flip      K random edges whose triangle pairs are pairwise disjoint, kept when all three
//             sides accept the flip (ours: flip_edge refuses an existing new edge, a collinear
//             triangle or a fold; OpenMesh: is_flip_ok). Timed: a round trip per edge (flip, then
//             flip the new edge back), so the mesh never drifts; counted as two flips.
//   split     K distinct random edges, split at their midpoints one after the other.
//   collapse  random edges whose closed vertex neighbourhoods are pairwise disjoint (so one
//             collapse cannot change another's link or geometry), kept when all three sides
//             accept them on a trial copy (ours: link condition and geometry; CGAL:
//             does_satisfy_link_condition; OpenMesh: is_collapse_ok). The kept vertex is
//             target(halfedge(e)) of CGAL's edge e (which CGAL's collapse keeps), on every side.
//   Split and collapse change the mesh: every iteration starts from a fresh copy (untimed).
//
// What each side does per operation (timed):
//   sxk       flip_edge(mesh, face): walk of the fan around c for an existing new edge c-d (both
//             ways round at once), exact collinearity and normal-alignment (fold) tests in
//             reference AND deformed positions (filtered: doubles with an error bound, exact
//             CGAL arithmetic when the bound cannot decide), then Mesh::replace_elements via
//             ProvenEdit (transaction checks, face reuse, anchors; no star walks). split_edge(mesh,
//             a, b): finds the edge's triangles by a walk of star(a) (the API takes vertex ids),
//             exact collinearity of the four children in both position sets, add_vertex with
//             attributes, replace_elements via ProvenEdit. collapse_edge(mesh, from, to): stars
//             of both ends (walked once), boundary rule, link condition on the two stars, exact
//             boundary, flatness and normal-turnover tests in both position sets, replace_elements
//             via ProvenEdit (the link condition proves what its star walks would check).
//   cgal      Euler::flip_edge(h) (no check at all: a precondition); Euler::split_edge(h) + two
//             Euler::split_face to triangulate + set the point; does_satisfy_link_condition(e) +
//             Euler::collapse_edge(e) (no geometric test; removed elements stay marked until
//             collect_garbage, which is not called).
//   openmesh  is_flip_ok(e) + flip(e); split(e, midpoint) (no check); is_collapse_ok(h) +
//             collapse(h) (topological tests; no geometric test). The garbage_collection()
//             OpenMesh needs to actually delete the collapsed elements runs once per batch,
//             untimed (since 2026-11-22; it was timed before): CGAL's collect_garbage is not
//             called at all, and compacting the arrays is a whole-mesh pass, not part of a
//             collapse. Ours frees the elements in the collapse itself (free lists), timed.
// Handles: CGAL and OpenMesh address edges by halfedge/edge handles resolved before timing; our
// flip takes a FaceId (updated from flip_edge's result), split and collapse take vertex ids.
//
// Counters: ops_per_s (CPU time; flips count two per round trip), ops, triangles.
#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "parse_option.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/traversal.hpp"
#include "tetgen_arrays.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using CgalVertex = CgalMesh::Vertex_index;
using CgalHalfedge = CgalMesh::Halfedge_index;

struct OpenMeshTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using OpenMeshMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

struct Options {
    std::size_t edges = 20000;
    std::uint64_t seed = 1;
    std::string ele;
};

struct Surface {
    std::vector<sxk::Point> points;
    std::vector<std::array<sxk::VertexId, 3>> triangles;
};

// The boundary of a TetGen mesh, through sxk::Mesh (untimed setup).
Surface boundary_of(const std::string& ele) {
    const sxk_bench::TetArrays arrays = sxk_bench::load_tetgen(ele);
    sxk::Mesh volume(3, 3);
    for (const auto& p : arrays.points) volume.add_vertex(p);
    std::vector<sxk::Simplex> tets;
    for (const auto& t : arrays.tets)
        tets.emplace_back(+1, std::initializer_list<sxk::VertexId>{t[0], t[1], t[2], t[3]});
    if (auto built = volume.assign_elements(tets); !built)
        throw std::runtime_error("assign_elements: " + built.reason());
    Surface surface;
    std::vector<sxk::VertexId> renumber(volume.vertex_count(), sxk::invalid_id);
    for (const sxk::FaceId f : volume.boundary_faces()) {
        const sxk::Simplex sigma = volume.face_simplex(f);
        std::array<sxk::VertexId, 3> v{sigma.vertex(0), sigma.vertex(1), sigma.vertex(2)};
        if (sigma.sign() < 0) std::swap(v[1], v[2]);
        for (sxk::VertexId& x : v) {
            if (renumber[x] == sxk::invalid_id) {
                renumber[x] = static_cast<sxk::VertexId>(surface.points.size());
                surface.points.push_back(volume.reference(x));
            }
            x = renumber[x];
        }
        surface.triangles.push_back(v);
    }
    return surface;
}

sxk::Mesh make_ours(const Surface& s) {
    sxk::Mesh mesh(2, 3);
    mesh.reserve(s.points.size(), s.triangles.size());
    for (const auto& p : s.points) mesh.add_vertex(p);
    std::vector<sxk::Simplex> triangles;
    for (const auto& t : s.triangles)
        triangles.emplace_back(+1, std::initializer_list<sxk::VertexId>{t[0], t[1], t[2]});
    if (auto built = mesh.assign_elements(triangles); !built)
        throw std::runtime_error("assign_elements: " + built.reason());
    return mesh;
}

CgalMesh make_cgal(const Surface& s) {
    CgalMesh mesh;
    for (const auto& p : s.points) mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
    for (const auto& t : s.triangles)
        if (mesh.add_face(CgalVertex(t[0]), CgalVertex(t[1]), CgalVertex(t[2])) == CgalMesh::null_face())
            throw std::runtime_error("Surface_mesh::add_face refused a triangle");
    return mesh;
}

OpenMeshMesh make_openmesh(const Surface& s) {
    OpenMeshMesh mesh;
    mesh.request_vertex_status();
    mesh.request_edge_status();
    mesh.request_face_status();
    mesh.request_halfedge_status();
    for (const auto& p : s.points) mesh.add_vertex(OpenMeshMesh::Point(p[0], p[1], p[2]));
    for (const auto& t : s.triangles)
        if (!mesh.add_face(OpenMesh::VertexHandle(static_cast<int>(t[0])),
                           OpenMesh::VertexHandle(static_cast<int>(t[1])),
                           OpenMesh::VertexHandle(static_cast<int>(t[2])))
                 .is_valid())
            throw std::runtime_error("OpenMesh add_face refused a triangle");
    return mesh;
}

// Our face representing the edge a-b, seen from the triangle that has it as a->b.
sxk::FaceId our_edge(const sxk::Mesh& mesh, sxk::VertexId a, sxk::VertexId b) {
    for (const sxk::ElementId t : sxk::star(mesh, a)) {
        const sxk::Simplex& tau = mesh.simplex(t);
        if (!tau.contains(b)) continue;
        for (int i = 0; i < 3; ++i)
            if (tau.vertex(i) != a && tau.vertex(i) != b) return mesh.face(t, i);
    }
    return sxk::invalid_id;
}

struct FlipEdge {
    sxk::FaceId ours;
    CgalHalfedge cgal;
    OpenMesh::EdgeHandle openmesh;
};
struct SplitEdge {
    sxk::VertexId a, b;
    CgalHalfedge cgal;
    OpenMesh::EdgeHandle openmesh;
};
struct CollapseEdge {
    sxk::VertexId from, to;
    CgalMesh::Edge_index cgal;
    OpenMesh::HalfedgeHandle openmesh;  // from -> to
};

struct Setup {
    Surface surface;
    sxk::Mesh ours{2, 3};
    CgalMesh cgal;
    OpenMeshMesh openmesh;
    std::vector<FlipEdge> flips;
    std::vector<SplitEdge> splits;
    std::vector<CollapseEdge> collapses;
};

// The face of our flip result representing the new edge (the one between the two triangles).
sxk::FaceId shared_face(const sxk::Mesh& mesh, const std::array<sxk::ElementId, 2>& pair) {
    for (int i = 0; i < 3; ++i) {
        const sxk::FaceId f = mesh.face(pair[0], i);
        const sxk::FaceId m = mesh.mate(f);
        if (m != sxk::invalid_id && mesh.face_element(m) == pair[1]) return f;
    }
    return sxk::invalid_id;
}

// Flips `face` and back; returns the face of the restored edge, or invalid_id. When the flip
// back is refused (the original pair folds more than the fold test allows: sharp features of the
// surface), the original is restored with topology_only and invalid_id returned.
sxk::FaceId our_flip_round_trip(sxk::Mesh& mesh, sxk::FaceId face) {
    const auto there = sxk::flip_edge(mesh, face);
    if (!there) return sxk::invalid_id;
    const sxk::FaceId diagonal = shared_face(mesh, *there);
    const auto back = sxk::flip_edge(mesh, diagonal);
    if (!back) {
        if (!sxk::flip_edge(mesh, diagonal, {.topology_only = true})) {
            std::fprintf(stderr, "surface_ops: could not undo a flip\n");
            std::exit(1);
        }
        return sxk::invalid_id;
    }
    return shared_face(mesh, *back);
}

bool openmesh_flip_round_trip(OpenMeshMesh& mesh, OpenMesh::EdgeHandle e) {
    if (!mesh.is_flip_ok(e)) return false;
    mesh.flip(e);
    if (!mesh.is_flip_ok(e)) return false;
    mesh.flip(e);
    return true;
}

void cgal_flip_round_trip(CgalMesh& mesh, CgalHalfedge h) {
    CGAL::Euler::flip_edge(h, mesh);
    CGAL::Euler::flip_edge(h, mesh);
}

void cgal_split(CgalMesh& mesh, CgalHalfedge h) {
    // h = a->b; afterwards hnew = a->m, next(hnew) = h = m->b; both quads get a diagonal at m
    const Kernel::Point_3 a = mesh.point(mesh.source(h));
    const Kernel::Point_3 b = mesh.point(mesh.target(h));
    const CgalHalfedge hnew = CGAL::Euler::split_edge(h, mesh);
    mesh.point(mesh.target(hnew)) = CGAL::midpoint(a, b);
    CGAL::Euler::split_face(hnew, mesh.next(h), mesh);
    const CgalHalfedge opposite = mesh.opposite(hnew);
    CGAL::Euler::split_face(mesh.opposite(h), mesh.next(opposite), mesh);
}

std::unique_ptr<Setup> make_setup(const Options& options) {
    auto setup = std::make_unique<Setup>();
    setup->surface = boundary_of(options.ele);
    setup->ours = make_ours(setup->surface);
    setup->cgal = make_cgal(setup->surface);
    setup->openmesh = make_openmesh(setup->surface);
    std::fprintf(stderr, "surface_ops: %zu vertices, %zu triangles\n", setup->surface.points.size(),
                 setup->surface.triangles.size());

    // all edges once, as (a, b) with a->b the halfedge of some triangle
    std::vector<std::pair<sxk::VertexId, sxk::VertexId>> edges;
    for (const auto& t : setup->surface.triangles)
        for (int i = 0; i < 3; ++i) {
            const sxk::VertexId a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
            if (a < b) edges.emplace_back(a, b);
        }
    std::mt19937_64 random(options.seed);
    std::shuffle(edges.begin(), edges.end(), random);

    // flips: disjoint triangle pairs, accepted by all sides
    {
        std::vector<bool> used(setup->ours.element_capacity(), false);
        for (const auto& [a, b] : edges) {
            if (setup->flips.size() >= options.edges) break;
            const sxk::FaceId face = our_edge(setup->ours, a, b);
            const sxk::ElementId t0 = setup->ours.face_element(face);
            const sxk::ElementId t1 = setup->ours.face_element(setup->ours.mate(face));
            if (used[t0] || used[t1]) continue;
            used[t0] = used[t1] = true;
            const auto cgal = setup->cgal.halfedge(CgalVertex(a), CgalVertex(b));
            const auto openmesh = setup->openmesh.find_halfedge(OpenMesh::VertexHandle(static_cast<int>(a)),
                                                                 OpenMesh::VertexHandle(static_cast<int>(b)));
            const OpenMesh::EdgeHandle openmesh_edge = setup->openmesh.edge_handle(openmesh);
            // our flip first: it decides (and the trial restores the mesh on success)
            const sxk::FaceId next = our_flip_round_trip(setup->ours, face);
            if (next == sxk::invalid_id) continue;
            if (!openmesh_flip_round_trip(setup->openmesh, openmesh_edge)) continue;
            // CGAL checks nothing; our accepted flip proves the new edge did not exist
            cgal_flip_round_trip(setup->cgal, cgal);
            setup->flips.push_back({next, cgal, openmesh_edge});
        }
    }

    // splits: the first K edges
    for (std::size_t i = 0; i < edges.size() && setup->splits.size() < options.edges; ++i) {
        const auto [a, b] = edges[i];
        setup->splits.push_back(
            {a, b, setup->cgal.halfedge(CgalVertex(a), CgalVertex(b)),
             setup->openmesh.edge_handle(setup->openmesh.find_halfedge(
                 OpenMesh::VertexHandle(static_cast<int>(a)), OpenMesh::VertexHandle(static_cast<int>(b))))});
    }

    // collapses: disjoint closed neighbourhoods, accepted by all sides on trial copies
    {
        sxk::Mesh ours = setup->ours;
        CgalMesh cgal = setup->cgal;
        OpenMeshMesh openmesh = setup->openmesh;
        std::vector<bool> used(setup->surface.points.size(), false);
        auto ring = [&](sxk::VertexId v) {
            std::vector<sxk::VertexId> around{v};
            for (const sxk::ElementId t : sxk::star(setup->ours, v))
                for (const sxk::VertexId w : setup->ours.simplex(t).vertices()) around.push_back(w);
            return around;
        };
        for (const auto& [a, b] : edges) {
            if (setup->collapses.size() >= options.edges) break;
            std::vector<sxk::VertexId> around = ring(a);
            const std::vector<sxk::VertexId> around_b = ring(b);
            around.insert(around.end(), around_b.begin(), around_b.end());
            if (std::any_of(around.begin(), around.end(), [&](sxk::VertexId v) { return used[v]; }))
                continue;
            for (const sxk::VertexId v : around) used[v] = true;
            const auto cgal_edge = setup->cgal.edge(setup->cgal.halfedge(CgalVertex(a), CgalVertex(b)));
            const CgalHalfedge h = setup->cgal.halfedge(cgal_edge);
            const sxk::VertexId from = static_cast<sxk::VertexId>(setup->cgal.source(h));
            const sxk::VertexId to = static_cast<sxk::VertexId>(setup->cgal.target(h));
            const auto openmesh_h = setup->openmesh.find_halfedge(
                OpenMesh::VertexHandle(static_cast<int>(from)), OpenMesh::VertexHandle(static_cast<int>(to)));
            if (!sxk::collapse_edge(ours, from, to)) continue;
            if (!CGAL::Euler::does_satisfy_link_condition(cgal_edge, cgal)) {
                std::fprintf(stderr, "surface_ops: CGAL refused a collapse we made (setup aborted)\n");
                std::exit(1);
            }
            CGAL::Euler::collapse_edge(cgal_edge, cgal);
            if (!openmesh.is_collapse_ok(openmesh_h)) {
                std::fprintf(stderr, "surface_ops: OpenMesh refused a collapse we made (setup aborted)\n");
                std::exit(1);
            }
            openmesh.collapse(openmesh_h);
            setup->collapses.push_back({from, to, cgal_edge, openmesh_h});
        }
    }
    std::fprintf(stderr, "surface_ops: %zu flip edges, %zu split edges, %zu collapse edges\n",
                 setup->flips.size(), setup->splits.size(), setup->collapses.size());
    return setup;
}

void set_counters(benchmark::State& state, const Setup& setup, std::size_t ops) {
    state.counters["ops_per_s"] =
        benchmark::Counter(static_cast<double>(ops), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["ops"] = static_cast<double>(ops);
    state.counters["triangles"] = static_cast<double>(setup.surface.triangles.size());
}

// ---- flip -------------------------------------------------------------------------------------
void flip_sxk(benchmark::State& state, Setup* setup) {
    for (auto _ : state)
        for (FlipEdge& e : setup->flips) {
            e.ours = our_flip_round_trip(setup->ours, e.ours);
            if (e.ours == sxk::invalid_id) {
                state.SkipWithError("sxk refused a flip it made during setup");
                return;
            }
        }
    set_counters(state, *setup, 2 * setup->flips.size());
}

void flip_cgal(benchmark::State& state, Setup* setup) {
    for (auto _ : state)
        for (const FlipEdge& e : setup->flips) cgal_flip_round_trip(setup->cgal, e.cgal);
    set_counters(state, *setup, 2 * setup->flips.size());
}

void flip_openmesh(benchmark::State& state, Setup* setup) {
    for (auto _ : state)
        for (const FlipEdge& e : setup->flips)
            if (!openmesh_flip_round_trip(setup->openmesh, e.openmesh)) {
                state.SkipWithError("OpenMesh refused a flip it made during setup");
                return;
            }
    set_counters(state, *setup, 2 * setup->flips.size());
}

// ---- split ------------------------------------------------------------------------------------
void split_sxk(benchmark::State& state, Setup* setup) {
    std::optional<sxk::Mesh> mesh;
    for (auto _ : state) {
        state.PauseTiming();
        mesh.reset();
        mesh.emplace(setup->ours);
        state.ResumeTiming();
        for (const SplitEdge& e : setup->splits)
            if (const auto split = sxk::split_edge(*mesh, e.a, e.b); !split) {
                state.SkipWithError(("sxk refused a split: " + split.reason()).c_str());
                return;
            }
    }
    if (const auto valid = mesh->validate(); !valid) state.SkipWithError(valid.reason().c_str());
    set_counters(state, *setup, setup->splits.size());
}

void split_cgal(benchmark::State& state, Setup* setup) {
    std::optional<CgalMesh> mesh;
    for (auto _ : state) {
        state.PauseTiming();
        mesh.reset();
        mesh.emplace(setup->cgal);
        state.ResumeTiming();
        for (const SplitEdge& e : setup->splits) cgal_split(*mesh, e.cgal);
    }
    if (!mesh->is_valid(false)) state.SkipWithError("Surface_mesh invalid after the splits");
    set_counters(state, *setup, setup->splits.size());
}

void split_openmesh(benchmark::State& state, Setup* setup) {
    std::unique_ptr<OpenMeshMesh> mesh;  // not std::optional: g++ 12 -Wmaybe-uninitialized
    for (auto _ : state) {
        state.PauseTiming();
        mesh.reset();
        mesh = std::make_unique<OpenMeshMesh>(setup->openmesh);
        state.ResumeTiming();
        for (const SplitEdge& e : setup->splits) {
            const OpenMesh::HalfedgeHandle h = mesh->halfedge_handle(e.openmesh, 0);
            const OpenMeshMesh::Point midpoint =
                (mesh->point(mesh->from_vertex_handle(h)) + mesh->point(mesh->to_vertex_handle(h))) * 0.5;
            mesh->split(e.openmesh, midpoint);
        }
    }
    set_counters(state, *setup, setup->splits.size());
}

// ---- collapse ---------------------------------------------------------------------------------
void collapse_sxk(benchmark::State& state, Setup* setup) {
    std::optional<sxk::Mesh> mesh;
    for (auto _ : state) {
        state.PauseTiming();
        mesh.reset();
        mesh.emplace(setup->ours);
        state.ResumeTiming();
        for (const CollapseEdge& e : setup->collapses)
            if (!sxk::collapse_edge(*mesh, e.from, e.to)) {
                state.SkipWithError("sxk refused a collapse it made during setup");
                return;
            }
    }
    if (const auto valid = mesh->validate(); !valid) state.SkipWithError(valid.reason().c_str());
    set_counters(state, *setup, setup->collapses.size());
}

void collapse_cgal(benchmark::State& state, Setup* setup) {
    std::optional<CgalMesh> mesh;
    for (auto _ : state) {
        state.PauseTiming();
        mesh.reset();
        mesh.emplace(setup->cgal);
        state.ResumeTiming();
        for (const CollapseEdge& e : setup->collapses) {
            if (!CGAL::Euler::does_satisfy_link_condition(e.cgal, *mesh)) {
                state.SkipWithError("CGAL refused a collapse it made during setup");
                return;
            }
            CGAL::Euler::collapse_edge(e.cgal, *mesh);
        }
    }
    if (!mesh->is_valid(false)) state.SkipWithError("Surface_mesh invalid after the collapses");
    set_counters(state, *setup, setup->collapses.size());
}

void collapse_openmesh(benchmark::State& state, Setup* setup) {
    std::unique_ptr<OpenMeshMesh> mesh;  // not std::optional: g++ 12 -Wmaybe-uninitialized
    for (auto _ : state) {
        state.PauseTiming();
        mesh.reset();
        mesh = std::make_unique<OpenMeshMesh>(setup->openmesh);
        state.ResumeTiming();
        for (const CollapseEdge& e : setup->collapses) {
            if (!mesh->is_collapse_ok(e.openmesh)) {
                state.SkipWithError("OpenMesh refused a collapse it made during setup");
                return;
            }
            mesh->collapse(e.openmesh);
        }
        // Untimed, like CGAL's collect_garbage (not called at all) and unlike our collapse,
        // which frees its elements at once: compacting the arrays is O(mesh), not per collapse.
        state.PauseTiming();
        mesh->garbage_collection();
        state.ResumeTiming();
    }
    set_counters(state, *setup, setup->collapses.size());
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::AddCustomContext("cgal_version", CGAL_VERSION_STR);
    benchmark::AddCustomContext("openmesh_version", "9.0");
    Options options;
    for (int i = 1; i < argc; ++i) {
        std::uint64_t value = 0;
        if (sxk_bench::parse_option(argv[i], "edges", value)) {
            options.edges = value;
        } else if (sxk_bench::parse_option(argv[i], "seed", value)) {
            options.seed = value;
        } else if (argv[i][0] != '-' && options.ele.empty()) {
            options.ele = argv[i];
        } else {
            options.ele.clear();
            break;
        }
    }
    if (options.ele.empty()) {
        std::fprintf(stderr, "usage: surface_ops [--benchmark_...] [--edges=K] [--seed=S] MESH.ele\n");
        return 2;
    }
    std::unique_ptr<Setup> setup;
    try {
        setup = make_setup(options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "surface_ops: %s\n", error.what());
        return 2;
    }
    benchmark::AddCustomContext("triangles", std::to_string(setup->surface.triangles.size()));
    const std::pair<const char*, void (*)(benchmark::State&, Setup*)> runs[] = {
        {"flip/sxk", flip_sxk},         {"flip/cgal", flip_cgal},
        {"flip/openmesh", flip_openmesh}, {"split/sxk", split_sxk},
        {"split/cgal", split_cgal},     {"split/openmesh", split_openmesh},
        {"collapse/sxk", collapse_sxk}, {"collapse/cgal", collapse_cgal},
        {"collapse/openmesh", collapse_openmesh}};
    for (const auto& [name, run] : runs)
        benchmark::RegisterBenchmark(name, run, setup.get())->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    int status = 0;
    if (const auto valid = setup->ours.validate(); !valid) {
        std::fprintf(stderr, "surface_ops: sxk mesh invalid after the flips: %s\n", valid.reason().c_str());
        status = 1;
    }
    if (!setup->cgal.is_valid(false)) {
        std::fprintf(stderr, "surface_ops: Surface_mesh invalid after the flips\n");
        status = 1;
    }
    return status;
}
