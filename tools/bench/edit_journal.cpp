// EditJournal cost (issue 13): a step of 100 kernel edits (50 flip_23 + flip_32 round trips on
// a Delaunay tetrahedralisation), run bare, recorded and committed, and recorded and rolled
// back, at two mesh sizes.
//
//   edit_journal [google-benchmark flags] [--small=N] [--large=N] [--seed=S]
//
// Setup (untimed): N random points in the unit cube, CGAL::Delaunay_triangulation_3<Epick>, the
// finite cells copied into an sxk::Mesh(3, 3) by assign_elements (vertex ids in CGAL's storage
// order, its spatial sort). 50 interior faces whose two tetrahedra share no tetrahedron with
// another drawn face and whose round trip succeeds are kept.
//
// Timed, per iteration (thread CPU time):
//   edits     the 50 round trips (100 edits: replace_elements twice per round trip), no journal
//   recorded  checkpoint, the same 100 edits, commit (history off: nothing kept)
//   rollback  checkpoint, the same 100 edits, rollback: the mesh is as before, ids included, so
//             the same faces serve the next iteration
// The figure of the issue is rollback / edits (the step and its undo against the edits alone;
// aim <= 2, i.e. checkpoint + rollback <= the edits), and each variant at the large size against
// the small one (a step costs what it touches, not the mesh: ratio ~1).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <random>
#include <unordered_set>
#include <vector>

#include "delaunay_3.hpp"
#include "parse_option.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"

namespace {

using sxk_bench::Delaunay;
using sxk_bench::Kernel;

constexpr std::size_t round_trips = 50;  // 100 edits

std::uint64_t small_points = 10000, large_points = 170000, seed = 1;

// 2-3 on `face`, then 3-2 on the new edge: the vertex sets of the two tetrahedra come back.
// Returns the restored face, or invalid_id when a flip was refused.
sxk::FaceId round_trip(sxk::Mesh& mesh, sxk::FaceId face) {
    const sxk::Simplex sigma = mesh.face_simplex(face);
    const auto three = sxk::flip_23(mesh, face);
    if (!three) return sxk::invalid_id;
    const sxk::FaceId entry = mesh.opposite_face((*three)[0], sigma.vertex(1));
    const auto two = sxk::flip_32(mesh, entry, mesh.face_simplex(entry).index(sigma.vertex(2)));
    if (!two) return sxk::invalid_id;
    const sxk::Simplex& kept = mesh.simplex((*two)[0]);
    for (int i = 0; i < 4; ++i)
        if (!sigma.contains(kept.vertex(i))) return mesh.face((*two)[0], i);
    return sxk::invalid_id;
}

struct Setup {
    std::unique_ptr<sxk::Mesh> mesh;
    std::vector<sxk::FaceId> faces;
};

Setup make_setup(std::uint64_t points) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<std::pair<Kernel::Point_3, std::uint32_t>> input;
    for (std::uint32_t i = 0; i < points; ++i) {
        const double x = coordinate(random), y = coordinate(random), z = coordinate(random);
        input.emplace_back(Kernel::Point_3(x, y, z), i);
    }
    Delaunay delaunay(input.begin(), input.end());
    Setup setup;
    setup.mesh = std::make_unique<sxk::Mesh>(3, 3);
    sxk::Mesh& mesh = *setup.mesh;
    for (const auto v : delaunay.finite_vertex_handles()) {
        v->info() = static_cast<std::uint32_t>(mesh.vertex_count());
        mesh.add_vertex({v->point().x(), v->point().y(), v->point().z()});
    }
    // CGAL's cells are positive in their listed order, which Simplex(+1, listed) represents
    std::vector<sxk::Simplex> simplexes;
    for (const auto c : delaunay.finite_cell_handles())
        simplexes.emplace_back(+1, std::initializer_list<sxk::VertexId>{c->vertex(0)->info(), c->vertex(1)->info(),
                                                                       c->vertex(2)->info(), c->vertex(3)->info()});
    if (!mesh.assign_elements(simplexes)) {
        std::fprintf(stderr, "edit_journal: assign_elements refused the Delaunay cells\n");
        std::exit(1);
    }
    // 50 faces with disjoint tetrahedra whose round trip succeeds
    std::unordered_set<sxk::ElementId> used;
    std::uniform_int_distribution<std::size_t> pick(0, mesh.element_capacity() - 1);
    while (setup.faces.size() < round_trips) {
        const auto t = static_cast<sxk::ElementId>(pick(random));
        const int i = static_cast<int>(random() % 4);
        const sxk::ElementId n = mesh.neighbor(t, i);
        if (n == sxk::invalid_id || used.count(t) || used.count(n)) continue;
        // the round trip's tetrahedra are t, n and their neighbours' faces only: keep away
        bool near = false;
        for (int j = 0; j < 4; ++j)
            near = near || used.count(mesh.neighbor(t, j)) || used.count(mesh.neighbor(n, j));
        if (near) continue;
        const sxk::FaceId f = mesh.face(t, i);
        const sxk::FaceId back = round_trip(mesh, f);
        if (back == sxk::invalid_id) continue;
        const sxk::ElementId a = mesh.face_element(back), b = mesh.face_element(mesh.mate(back));
        used.insert(a);
        used.insert(b);
        for (int j = 0; j < 4; ++j) {
            used.insert(mesh.neighbor(a, j));
            used.insert(mesh.neighbor(b, j));
        }
        setup.faces.push_back(back);
    }
    std::fprintf(stderr, "edit_journal: %llu points, %zu tets, %zu faces\n",
                 static_cast<unsigned long long>(points), mesh.element_count(), setup.faces.size());
    return setup;
}

Setup& setup_of(std::uint64_t points) {
    static std::map<std::uint64_t, Setup> setups;
    auto it = setups.find(points);
    if (it == setups.end()) it = setups.emplace(points, make_setup(points)).first;
    return it->second;
}

void run_edits(sxk::Mesh& mesh, std::vector<sxk::FaceId>& faces) {
    for (sxk::FaceId& f : faces) {
        f = round_trip(mesh, f);
        if (f == sxk::invalid_id) {
            std::fprintf(stderr, "edit_journal: a round trip was refused\n");
            std::exit(1);
        }
    }
}

enum class Variant { edits, recorded, rollback };

void bench(benchmark::State& state, Variant variant, bool large) {
    Setup& setup = setup_of(large ? large_points : small_points);
    sxk::Mesh& mesh = *setup.mesh;
    sxk::EditJournal journal(mesh);
    journal.set_history_limit(0);
    std::size_t recorded = 0;
    for (auto _ : state) {
        if (variant == Variant::edits) {
            run_edits(mesh, setup.faces);
            continue;
        }
        std::vector<sxk::FaceId> faces = setup.faces;
        journal.checkpoint();
        run_edits(mesh, faces);
        recorded = journal.recorded();
        if (variant == Variant::recorded) {
            (void)journal.commit();
            setup.faces = faces;
        } else {
            (void)journal.rollback();  // the faces of before are valid again
        }
    }
    state.counters["edits"] = 2 * round_trips;
    state.counters["tets"] = static_cast<double>(mesh.element_count());
    state.counters["stores_recorded"] = static_cast<double>(recorded);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    for (int i = 1; i < argc; ++i)
        if (!sxk_bench::parse_option(argv[i], "small", small_points) &&
            !sxk_bench::parse_option(argv[i], "large", large_points) &&
            !sxk_bench::parse_option(argv[i], "seed", seed)) {
            std::fprintf(stderr, "edit_journal: unknown option %s\n", argv[i]);
            return 2;
        }
    for (const bool large : {false, true}) {
        const char* size = large ? "large" : "small";
        for (const auto& [variant, name] : {std::pair{Variant::edits, "edits"}, std::pair{Variant::recorded, "recorded"},
                                            std::pair{Variant::rollback, "rollback"}})
            benchmark::RegisterBenchmark((std::string(size) + "/" + name).c_str(),
                                         [variant = variant, large](benchmark::State& s) { bench(s, variant, large); })
                ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
