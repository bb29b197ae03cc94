// The exact test a scalpel's sweep asks of the elements near it (triangle_meets_tetrahedron,
// sxk/predicates.hpp): ours by orientation signs against CGAL's do_intersect (the peer, which it
// replaced), on the same pairs in the same run.
//
//   sweep_tests MESH.ele [--sweeps N] [--seed S]
//
// Untimed: the mesh, a SpatialIndex over it, and N blade slivers through random elements'
// centroids (a blade a fifth of the mesh's box long in a random direction, moved by a twentieth
// of the mean edge across it: what a step at a haptic rate sweeps). Per sliver, three sets of
// elements: those whose closed simplex meets it (elements_hit_by_triangle), their neighbours
// across a face that it misses, and up to 200 others with a corner in its box (the kind of
// candidate the index's boxes give). Timed: each test over each set, best of 5 passes; both
// answers must agree pair by pair. Then the moved blade (a segment) against the first two sets:
// segment_meets_tetrahedron against CGAL's do_intersect and against the collinear triangle the
// snap cutter's blade track asked before.
// stdout: JSON lines (CONTRIBUTING.md "Benchmarks"); stderr: a summary.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "sxk/io.hpp"
#include "sxk/locate.hpp"
#include "sxk/predicates.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Clock = std::chrono::steady_clock;

K::Point_3 cgal(const sxk::Point& p) { return {p[0], p[1], p[2]}; }

struct TetrahedronPair {
    std::array<sxk::Point, 3> triangle;
    std::array<sxk::Point, 4> corners;
};

// Best of five passes, in ns per pair; `answers` gets the last pass's results.
template <class Test, class Pairs>
double time_per_pair(const Pairs& pairs, Test test, std::vector<char>& answers) {
    double best = 1e300;
    answers.assign(pairs.size(), 0);
    for (int pass = 0; pass < 5; ++pass) {
        const auto start = Clock::now();
        for (std::size_t i = 0; i < pairs.size(); ++i) answers[i] = test(pairs[i]) ? 1 : 0;
        best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - start).count());
    }
    return best / double(pairs.size());
}

void line(const std::string& name, double ours, double peer, const char* peer_name) {
    std::printf("{\"name\":\"%s\",\"unit\":\"ns\",\"ours\":%.4g,\"peer\":%.4g,\"peer_name\":\"%s\",\"ratio\":%.4g,"
                "\"better\":\"lower\"}\n",
                name.c_str(), ours, peer, peer_name, ours / peer);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || std::string(argv[1]) == "--help") {
        std::fprintf(stderr, "usage: sweep_tests MESH.ele [--sweeps N] [--seed S]\n");
        return argc < 2 ? 2 : 0;
    }
    std::size_t sweeps = 200;
    std::uint64_t seed = 1;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--sweeps") sweeps = std::strtoull(argv[i + 1], nullptr, 10);
        else if (option == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 10);
        else {
            std::fprintf(stderr, "sweep_tests: unknown option '%s'\n", argv[i]);
            return 2;
        }
    }
    sxk::Mesh mesh = sxk::read_mesh(argv[1]);
    const sxk::SpatialIndex index(mesh, sxk::Positions::deformed);
    sxk::Point low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (std::size_t k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], mesh.deformed(v)[k]);
            high[k] = std::max(high[k], mesh.deformed(v)[k]);
        }
    const double blade = 0.2 * std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
    double edge_sum = 0;  // the mean edge length, from the first thousand elements
    std::size_t edge_count = 0;
    for (sxk::ElementId t = 0; t < std::min<std::size_t>(mesh.element_count(), 1000); ++t) {
        const auto s = mesh.simplex(t);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const auto& p = mesh.deformed(s.vertex(i));
                const auto& q = mesh.deformed(s.vertex(j));
                edge_sum += std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
                ++edge_count;
            }
    }
    const double move = edge_sum / double(edge_count) / 20;

    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss;
    std::uniform_int_distribution<std::size_t> element(0, mesh.element_count() - 1);
    auto unit = [&] {
        sxk::Point d{gauss(rng), gauss(rng), gauss(rng)};
        const double n = std::hypot(d[0], d[1], d[2]);
        for (double& x : d) x /= n;
        return d;
    };
    std::vector<TetrahedronPair> tetrahedra, misses, boxes;
    for (std::size_t k = 0; k < sweeps; ++k) {
        const auto s = mesh.simplex(sxk::ElementId(element(rng)));
        sxk::Point centre{};
        for (int j = 0; j < 4; ++j)
            for (std::size_t i = 0; i < 3; ++i) centre[i] += mesh.deformed(s.vertex(j))[i] / 4;
        const sxk::Point along = unit(), across = unit();
        sxk::Point handle{}, tip{}, moved{};
        for (std::size_t i = 0; i < 3; ++i) {
            handle[i] = centre[i] - blade / 2 * along[i];
            tip[i] = centre[i] + blade / 2 * along[i];
            moved[i] = tip[i] + move * across[i];
        }
        const std::array<sxk::Point, 3> triangle{handle, tip, moved};
        const auto hits = index.elements_hit_by_triangle(handle, tip, moved, sxk::TriangleHitsOf::elements).elements;
        for (const sxk::ElementId t : hits) {
            const auto e = mesh.simplex(t);
            TetrahedronPair pair{triangle, {}};
            for (int j = 0; j < 4; ++j) pair.corners[std::size_t(j)] = mesh.deformed(e.vertex(j));
            tetrahedra.push_back(pair);
        }
        // what the index's boxes give besides: elements with a corner in the sliver's box, up to
        // 200 per sliver (on a tilted blade its box holds a slab of the mesh)
        sxk::Point box_low = handle, box_high = handle;
        for (const sxk::Point& x : triangle)
            for (std::size_t i = 0; i < 3; ++i) {
                box_low[i] = std::min(box_low[i], x[i]);
                box_high[i] = std::max(box_high[i], x[i]);
            }
        std::size_t boxed = 0;
        for (const sxk::ElementId t : index.elements_with_vertex_in_box(box_low, box_high)) {
            if (std::binary_search(hits.begin(), hits.end(), t)) continue;
            if (++boxed > 200) break;
            const auto e = mesh.simplex(t);
            TetrahedronPair pair{triangle, {}};
            for (int i = 0; i < 4; ++i) pair.corners[std::size_t(i)] = mesh.deformed(e.vertex(i));
            boxes.push_back(pair);
        }
        // the near misses: the elements next to those (across a face) that the sliver does not meet
        for (const sxk::ElementId t : hits)
            for (int j = 0; j < 4; ++j) {
                const sxk::ElementId u = mesh.neighbor(t, j);
                if (u == sxk::invalid_id || std::binary_search(hits.begin(), hits.end(), u)) continue;
                const auto e = mesh.simplex(u);
                TetrahedronPair pair{triangle, {}};
                for (int i = 0; i < 4; ++i) pair.corners[std::size_t(i)] = mesh.deformed(e.vertex(i));
                misses.push_back(pair);
            }
    }

    std::vector<char> ours, peer;
    auto ours_test = [](const TetrahedronPair& p) {
        const auto& [a, b, c] = p.triangle;
        return sxk::triangle_meets_tetrahedron(a, b, c, p.corners[0], p.corners[1], p.corners[2], p.corners[3]);
    };
    auto peer_test = [](const TetrahedronPair& p) {
        return CGAL::do_intersect(K::Triangle_3(cgal(p.triangle[0]), cgal(p.triangle[1]), cgal(p.triangle[2])),
                                  K::Tetrahedron_3(cgal(p.corners[0]), cgal(p.corners[1]), cgal(p.corners[2]),
                                                   cgal(p.corners[3])));
    };
    std::array<double, 3> ours_tet{}, peer_tet{};
    const std::array<const std::vector<TetrahedronPair>*, 3> sets{&tetrahedra, &misses, &boxes};
    for (std::size_t k = 0; k < sets.size(); ++k) {
        ours_tet[k] = time_per_pair(*sets[k], ours_test, ours);
        peer_tet[k] = time_per_pair(*sets[k], peer_test, peer);
        if (ours != peer) {
            std::fprintf(stderr, "sweep_tests: triangle/tetrahedron answers differ from CGAL's\n");
            return 1;
        }
    }
    std::fprintf(stderr,
                 "sweep_tests: %zu tets, %zu slivers (blade %.3g, moved %.3g): %zu elements meeting them, %zu next "
                 "to those, %zu more in their boxes; ns per test, ours / CGAL: %.0f / %.0f meeting, %.0f / %.0f "
                 "next to them, %.0f / %.0f in the boxes\n",
                 mesh.element_count(), sweeps, blade, move, tetrahedra.size(), misses.size(), boxes.size(),
                 ours_tet[0], peer_tet[0], ours_tet[1], peer_tet[1], ours_tet[2], peer_tet[2]);
    // The moved blade (handle, moved) against the same elements: what the snap cutter's blade
    // track asks of every element a sweep met (segment_meets_tetrahedron), against CGAL's test and
    // against the collinear triangle (handle, moved, moved) the track asked before
    auto ours_segment = [](const TetrahedronPair& p) {
        return sxk::segment_meets_tetrahedron(p.triangle[0], p.triangle[2], p.corners[0], p.corners[1], p.corners[2],
                                              p.corners[3]);
    };
    auto peer_segment = [](const TetrahedronPair& p) {
        return CGAL::do_intersect(K::Segment_3(cgal(p.triangle[0]), cgal(p.triangle[2])),
                                  K::Tetrahedron_3(cgal(p.corners[0]), cgal(p.corners[1]), cgal(p.corners[2]),
                                                   cgal(p.corners[3])));
    };
    auto collinear_triangle = [](const TetrahedronPair& p) {
        return sxk::triangle_meets_tetrahedron(p.triangle[0], p.triangle[2], p.triangle[2], p.corners[0], p.corners[1],
                                               p.corners[2], p.corners[3]);
    };
    std::array<double, 2> ours_seg{}, peer_seg{}, collinear_seg{};
    std::vector<char> collinear;
    for (std::size_t k = 0; k < 2; ++k) {
        ours_seg[k] = time_per_pair(*sets[k], ours_segment, ours);
        peer_seg[k] = time_per_pair(*sets[k], peer_segment, peer);
        collinear_seg[k] = time_per_pair(*sets[k], collinear_triangle, collinear);
        if (ours != peer || collinear != peer) {
            std::fprintf(stderr, "sweep_tests: segment/tetrahedron answers differ from CGAL's\n");
            return 1;
        }
    }
    std::fprintf(stderr,
                 "sweep_tests: the moved blade, ns per test, ours / CGAL / a collinear triangle: %.0f / %.0f / %.0f "
                 "on the elements meeting the slivers, %.0f / %.0f / %.0f next to them\n",
                 ours_seg[0], peer_seg[0], collinear_seg[0], ours_seg[1], peer_seg[1], collinear_seg[1]);
    const char* tetrahedron_peer = "CGAL do_intersect(Triangle_3, Tetrahedron_3)";
    line("triangle meets tetrahedron (elements meeting a sliver)", ours_tet[0], peer_tet[0], tetrahedron_peer);
    line("triangle meets tetrahedron (their neighbours, missed)", ours_tet[1], peer_tet[1], tetrahedron_peer);
    line("triangle meets tetrahedron (in the sliver's box)", ours_tet[2], peer_tet[2], tetrahedron_peer);
    const char* segment_peer = "CGAL do_intersect(Segment_3, Tetrahedron_3)";
    line("segment meets tetrahedron (elements meeting a sliver)", ours_seg[0], peer_seg[0], segment_peer);
    line("segment meets tetrahedron (their neighbours, missed)", ours_seg[1], peer_seg[1], segment_peer);
    return 0;
}
