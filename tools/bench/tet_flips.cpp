// 2-3 / 3-2 flip round trips on a >= 1M-tet Delaunay mesh: sxk::flip_23 + flip_32 against
// CGAL's Triangulation_3::flip(Cell_handle, int) + flip(Cell_handle, int, int).
//
//   tet_flips [google-benchmark flags] [--points=N] [--faces=K] [--seed=S]
//
// Setup (untimed): N random points in the unit cube (std::mt19937_64 with seed S) are
// triangulated by CGAL::Delaunay_triangulation_3<Epick> (170,000 points give ~1.1M finite
// tets); the finite cells are copied into an sxk::Mesh(3, 3) by assign_elements (reference and
// deformed positions equal), in CGAL's cell storage order, with vertex ids in CGAL's vertex
// storage order (its spatial sort of the points), so that neither side's memory layout is
// better than the other's: an application numbers its mesh so too (sxk convert --reorder). Then K interior faces are drawn at random (a random finite cell
// and a random face of it) such that no tetrahedron belongs to two drawn faces, and each one is
// tried once on both sides: a face is kept only when BOTH sides complete the round trip
// (2-3 on the face, then 3-2 on the new edge, which restores the vertex sets of the two tets).
// Disagreements are counted and printed (with exact predicates on both sides they should not
// occur: for points in general position CGAL's positive orientations imply our checks).
//
// Timed, per iteration: one round trip on every kept face, in the same order on both sides
// ("sxk" and "cgal"). Because the drawn faces share no tetrahedron, a round trip never touches
// another drawn face's tetrahedra, so each side keeps its handle to the face up to date in O(1)
// after the round trip (ours: the face between the two tets flip_32 returns; CGAL: the facet
// opposite p in p->cell(), which the TDS's 3-2 flip sets to the surviving tetrahedron
// containing p) and the same sequence can be repeated any number of times.
//
// What each side checks per round trip:
//   sxk   flip_23: interior face, equal labels, edge pq not already in the mesh (star walk around
//         p), three exact orient3d tests in the reference AND three in the deformed positions;
//         then the bookkeeping of Mesh::replace_elements (face reuse: hull FaceIds survive;
//         boundary map, anchors, neighbour cache, watcher log); its star walks are proven
//         unnecessary by the flip's own checks (ProvenEdit). flip_32: the ring around pq
//         (cycle_around, boundary and degree 3), equal labels, triangle cde not already present
//         (star walk around c), 2 + 2 exact orient3d tests, replace_elements again.
//   sxk_embedded   the same with TetFlipOptions::reference_is_embedding: the two star walks
//         (edge pq, triangle cde) are skipped because the caller vouches for an embedding, which
//         with the orientation tests proves them absent; everything else as above.
//   cgal  flip(c, i): both cells finite, three orientation tests (Epick: filtered, exact);
//         flip(c, i, j): degree 3 by circulating around the edge, no infinite cell, two
//         orientation tests. No topological test (an embedded triangulation needs none) and one
//         set of positions. Preconditions are compiled out (Release, NDEBUG).
// Neither side has watchers attached.
//
// Counters: round_trips_per_s (CPU time), faces (K kept), tets, disagreements.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "delaunay_3.hpp"
#include "parse_option.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"
#include "sxk/predicates.hpp"
#include "sxk/simplex.hpp"

namespace {

using sxk_bench::Delaunay;
using sxk_bench::Kernel;
using CellHandle = Delaunay::Cell_handle;
using VertexHandle = Delaunay::Vertex_handle;

struct Options {
    std::size_t points = 170000;
    std::size_t faces = 100000;
    std::uint64_t seed = 1;
};

// One drawn face, as each side addresses it.
struct OurFace {
    sxk::FaceId face;
};
struct CgalFace {
    CellHandle cell;
    int index;
};

struct Setup {
    Delaunay delaunay;
    std::optional<sxk::Mesh> mesh;
    std::vector<OurFace> ours;
    std::vector<CgalFace> cgal;
    std::size_t tets = 0;
    std::size_t attempts = 0;
    std::size_t disagreements = 0;
};

// Our round trip on `face`; returns the face to use next time, or invalid_id when a flip was
// refused (reason in *why).
sxk::FaceId our_round_trip(sxk::Mesh& mesh, sxk::FaceId face, const sxk::TetFlipOptions& options,
                           std::string* why) {
    const sxk::Simplex sigma = mesh.face_simplex(face);
    const auto three = sxk::flip_23(mesh, face, options);
    if (!three) {
        if (why) *why = three.reason();
        return sxk::invalid_id;
    }
    // (*three)[0] is simplex(t0) with a = sigma.vertex(0) replaced by q: it holds p, q, b, c; its
    // face opposite b holds p, q, c, and the edge pq is that face without c.
    const sxk::ElementId first = (*three)[0];
    const sxk::FaceId entry = mesh.opposite_face(first, sigma.vertex(1));
    const int j = mesh.face_simplex(entry).index(sigma.vertex(2));
    const auto two = sxk::flip_32(mesh, entry, j, options);
    if (!two) {
        if (why) *why = two.reason();
        return sxk::invalid_id;
    }
    // (*two)[0] = <abc, min(p,q)>: the restored face abc is opposite that vertex
    const sxk::Simplex& kept = mesh.simplex((*two)[0]);
    for (int i = 0; i < 4; ++i) {
        const sxk::VertexId v = kept.vertex(i);
        if (v != sigma.vertex(0) && v != sigma.vertex(1) && v != sigma.vertex(2))
            return mesh.face((*two)[0], i);
    }
    return sxk::invalid_id;
}

// CGAL's round trip on facet (cell, index); false when a flip was refused. On success `face`
// is updated to the restored facet.
bool cgal_round_trip(Delaunay& delaunay, CgalFace& face) {
    const CellHandle c = face.cell;
    const int i = face.index;
    const VertexHandle p = c->vertex(i);
    if (!delaunay.flip(c, i)) return false;
    // TDS flip_really keeps c and replaces its vertex (i+3)&3 by q: c holds the new edge pq
    if (!delaunay.flip(c, i, (i + 3) & 3)) return false;
    // the 3-2 flip deletes c and makes p->cell() the surviving tet <abc, p>
    face.cell = p->cell();
    face.index = face.cell->index(p);
    return true;
}

sxk::FaceId find_our_face(const sxk::Mesh& mesh, std::array<sxk::VertexId, 4> apex_and_face) {
    // the element of apex p containing the face: walk p's anchor star
    const sxk::VertexId p = apex_and_face[0];
    std::vector<sxk::ElementId> seen{mesh.vertex_element(p)};
    for (std::size_t next = 0; next < seen.size(); ++next) {
        const sxk::ElementId t = seen[next];
        const sxk::Simplex& tau = mesh.simplex(t);
        if (tau.contains(apex_and_face[1]) && tau.contains(apex_and_face[2]) &&
            tau.contains(apex_and_face[3]))
            return mesh.opposite_face(t, p);
        for (int i = 0; i < 4; ++i) {
            if (tau.vertex(i) == p) continue;
            const sxk::ElementId n = mesh.neighbor(t, i);
            if (n != sxk::invalid_id && std::find(seen.begin(), seen.end(), n) == seen.end())
                seen.push_back(n);
        }
    }
    return sxk::invalid_id;
}

std::unique_ptr<Setup> make_setup(const Options& options) {
    auto setup = std::make_unique<Setup>();
    std::mt19937_64 random(options.seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<std::pair<Kernel::Point_3, std::uint32_t>> points;
    points.reserve(options.points);
    for (std::size_t i = 0; i < options.points; ++i) {
        const double x = coordinate(random), y = coordinate(random), z = coordinate(random);
        points.emplace_back(Kernel::Point_3(x, y, z), static_cast<std::uint32_t>(i));
    }
    std::fprintf(stderr, "tet_flips: Delaunay of %zu points (seed %llu)\n", options.points,
                 static_cast<unsigned long long>(options.seed));
    setup->delaunay.insert(points.begin(), points.end());

    std::vector<CellHandle> cells;
    std::vector<sxk::Simplex> simplexes;
    cells.reserve(setup->delaunay.number_of_finite_cells());
    simplexes.reserve(setup->delaunay.number_of_finite_cells());
    sxk::Mesh& mesh = setup->mesh.emplace(3, 3);
    mesh.reserve(options.points, setup->delaunay.number_of_finite_cells());
    // our vertex ids follow CGAL's vertex storage order, which is its spatial sort (Hilbert
    // order) of the input: points close in space are close in memory on both sides
    for (const VertexHandle v : setup->delaunay.finite_vertex_handles()) {
        v->info() = static_cast<std::uint32_t>(mesh.vertex_count());
        mesh.add_vertex({v->point().x(), v->point().y(), v->point().z()});
    }
    for (const CellHandle c : setup->delaunay.finite_cell_handles()) {
        cells.push_back(c);
        std::array<sxk::VertexId, 4> v{};
        for (int i = 0; i < 4; ++i) v[static_cast<std::size_t>(i)] = c->vertex(i)->info();
        // CGAL cells are positively oriented; take the sign from our own predicate anyway
        const sxk::Sign s = sxk::orient3d(mesh.reference(v[0]), mesh.reference(v[1]),
                                          mesh.reference(v[2]), mesh.reference(v[3]));
        simplexes.emplace_back(s == sxk::Sign::negative ? -1 : +1,
                               std::initializer_list<sxk::VertexId>{v[0], v[1], v[2], v[3]});
    }
    setup->tets = simplexes.size();
    if (const auto built = mesh.assign_elements(simplexes); !built) {
        std::fprintf(stderr, "tet_flips: assign_elements refused: %s\n", built.reason().c_str());
        std::exit(1);
    }
    std::fprintf(stderr, "tet_flips: %zu tets, %zu boundary faces\n", setup->tets,
                 mesh.boundary_face_count());

    // Draw faces whose tet pairs are pairwise disjoint; try each once on both sides.
    std::unordered_set<CellHandle> used;
    std::uniform_int_distribution<std::size_t> pick_cell(0, cells.size() - 1);
    std::uniform_int_distribution<int> pick_face(0, 3);
    const std::size_t max_attempts = options.faces * 20;
    while (setup->ours.size() < options.faces && setup->attempts < max_attempts) {
        const CellHandle c = cells[pick_cell(random)];
        const int i = pick_face(random);
        const CellHandle n = c->neighbor(i);
        if (used.count(c) || used.count(n) || setup->delaunay.is_infinite(n)) continue;
        ++setup->attempts;
        used.insert(c);
        used.insert(n);
        const sxk::VertexId p = c->vertex(i)->info();
        std::array<sxk::VertexId, 4> key{p, 0, 0, 0};
        for (int k = 1; k <= 3; ++k)
            key[static_cast<std::size_t>(k)] = c->vertex((i + k) & 3)->info();
        const sxk::FaceId ours = find_our_face(mesh, key);
        if (ours == sxk::invalid_id || mesh.mate(ours) == sxk::invalid_id) {
            std::fprintf(stderr, "tet_flips: face of cell not found in the sxk mesh\n");
            std::exit(1);
        }
        CgalFace theirs{c, i};
        const bool cgal_ok = cgal_round_trip(setup->delaunay, theirs);
        std::string why;
        const sxk::FaceId next = our_round_trip(mesh, ours, {}, &why);
        const bool ours_ok = next != sxk::invalid_id;
        if (cgal_ok != ours_ok) {
            ++setup->disagreements;
            if (setup->disagreements <= 5)
                std::fprintf(stderr, "tet_flips: disagreement (CGAL %s, sxk %s%s)\n",
                             cgal_ok ? "flipped" : "refused", ours_ok ? "flipped" : "refused: ",
                             why.c_str());
        }
        if (cgal_ok && ours_ok) {
            setup->ours.push_back({next});
            setup->cgal.push_back(theirs);
        }
    }
    std::fprintf(stderr,
                 "tet_flips: %zu faces kept of %zu tried (%zu disagreements)\n",
                 setup->ours.size(), setup->attempts, setup->disagreements);
    return setup;
}

void set_counters(benchmark::State& state, const Setup& setup) {
    const double faces = static_cast<double>(setup.ours.size());
    state.counters["round_trips_per_s"] =
        benchmark::Counter(faces, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["faces"] = faces;
    state.counters["tets"] = static_cast<double>(setup.tets);
    state.counters["disagreements"] = static_cast<double>(setup.disagreements);
}

void run_sxk(benchmark::State& state, Setup* setup, sxk::TetFlipOptions options) {
    sxk::Mesh& mesh = *setup->mesh;
    for (auto _ : state) {
        for (OurFace& face : setup->ours) {
            face.face = our_round_trip(mesh, face.face, options, nullptr);
            if (face.face == sxk::invalid_id) {
                state.SkipWithError("sxk refused a round trip it made during setup");
                return;
            }
        }
    }
    set_counters(state, *setup);
}

void run_cgal(benchmark::State& state, Setup* setup) {
    for (auto _ : state) {
        for (CgalFace& face : setup->cgal)
            if (!cgal_round_trip(setup->delaunay, face)) {
                state.SkipWithError("CGAL refused a round trip it made during setup");
                return;
            }
    }
    set_counters(state, *setup);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::AddCustomContext("cgal_version", CGAL_VERSION_STR);
    Options options;
    for (int i = 1; i < argc; ++i) {
        std::uint64_t value = 0;
        if (sxk_bench::parse_option(argv[i], "points", value)) {
            options.points = value;
        } else if (sxk_bench::parse_option(argv[i], "faces", value)) {
            options.faces = value;
        } else if (sxk_bench::parse_option(argv[i], "seed", value)) {
            options.seed = value;
        } else {
            std::fprintf(stderr, "usage: tet_flips [--benchmark_...] [--points=N] [--faces=K] "
                                 "[--seed=S]\n");
            return 2;
        }
    }
    const std::unique_ptr<Setup> setup = make_setup(options);
    benchmark::AddCustomContext("tets", std::to_string(setup->tets));
    benchmark::RegisterBenchmark("sxk/round_trip", run_sxk, setup.get(), sxk::TetFlipOptions{})
        ->Unit(benchmark::kMillisecond);
    sxk::TetFlipOptions embedded;
    embedded.reference_is_embedding = true;
    benchmark::RegisterBenchmark("sxk_embedded/round_trip", run_sxk, setup.get(), embedded)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("cgal/round_trip", run_cgal, setup.get())->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    int status = 0;
    if (const auto valid = setup->mesh->validate(); !valid) {
        std::fprintf(stderr, "tet_flips: sxk mesh invalid afterwards: %s\n", valid.reason().c_str());
        status = 1;
    }
    if (setup->mesh->element_count() != setup->delaunay.number_of_finite_cells()) {
        std::fprintf(stderr, "tet_flips: element counts differ afterwards (sxk %zu, CGAL %zu)\n",
                     setup->mesh->element_count(), setup->delaunay.number_of_finite_cells());
        status = 1;
    }
    return status;
}
