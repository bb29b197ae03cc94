// Random local operations on a real mesh: the femur of CGAL's data set tetrahedralised by
// TetGen (tools/make-data, as in io_femur.cpp), 47,733 nodes and 212,936 tetrahedra. A few
// thousand splits (edge, face, element), 2-3 and 3-2 flips and collapses (plain and to the
// midpoint) at random places; validate() every 400 operations and at the end.
//
// The whole-mesh checks of the property test (tests/ops/random_ops_test.cpp) cost O(n) per
// operation, too much for 213k tetrahedra. Every operation here acts inside the star of the
// vertices of one element t (flips of a face or an edge of t, splits of t or its edges and
// faces, collapses of an edge of t): each element it removes or adds contains a vertex of t.
// So, per operation:
//   - a refusal must leave a LOCAL snapshot bit-identical: the counts and capacities of the
//     whole mesh, every element of those stars (simplex, label, face ids, and each face's
//     element and mate) and the positions and anchors of their vertices;
//   - a success must leave every element of those stars (and of the new vertex) strictly
//     positive by exact orient3d in both position sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "real/femur_data.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/split_element.hpp"
#include "sxk/ops/split_face.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"
#include "core/fixtures.hpp"

namespace sxk {
namespace {

using test::make_femur;

// The elements of the stars of `vertices` (those still in an element), sorted, no repeats.
std::vector<ElementId> region(const Mesh& mesh, std::span<const VertexId> vertices) {
    std::vector<ElementId> all;
    for (const VertexId v : vertices)
        if (v < mesh.vertex_count() && mesh.vertex_element(v) != invalid_id)
            for (const ElementId t : star(mesh, v)) all.push_back(t);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

std::vector<std::uint64_t> local_snapshot(const Mesh& mesh, std::span<const ElementId> around) {
    std::vector<std::uint64_t> s{mesh.vertex_count(), mesh.element_count(), mesh.element_capacity(),
                                 mesh.face_capacity(), mesh.boundary_face_count()};
    for (const ElementId t : around) {
        s.push_back(t);
        s.push_back(mesh.is_element(t));
        if (!mesh.is_element(t)) continue;
        const Simplex& tau = mesh.simplex(t);
        s.push_back(static_cast<std::uint64_t>(tau.sign() + 1));
        for (const VertexId v : tau.vertices()) {
            s.push_back(v);
            s.push_back(mesh.vertex_element(v));
            for (const double x : mesh.reference(v)) s.push_back(std::bit_cast<std::uint64_t>(x));
            for (const double x : mesh.deformed(v)) s.push_back(std::bit_cast<std::uint64_t>(x));
        }
        s.push_back(static_cast<std::uint64_t>(mesh.label(t)));
        for (const FaceId f : mesh.faces(t)) {
            s.push_back(f);
            s.push_back(mesh.face_element(f));
            s.push_back(mesh.mate(f));
        }
    }
    return s;
}

TEST(OpsFemur, RandomLocalOperations) {
    const std::string ele = make_femur();
    ASSERT_FALSE(ele.empty()) << "tools/make-data femur failed";
    ASSERT_TRUE(std::filesystem::exists(ele)) << ele;
    Mesh mesh = read_mesh(ele);
    ASSERT_EQ(mesh.element_count(), 212936u);
    ASSERT_TRUE(mesh.validate().ok());

    const std::uint64_t seed = test::seed_for("OpsFemur.RandomLocalOperations");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 rng(seed);
    auto uniform = [&](double low, double high) {
        return std::uniform_real_distribution<double>(low, high)(rng);
    };
    std::map<std::string, int> done, refused;
    constexpr int operations = 4000;
    for (int i = 0; i < operations; ++i) {
        ElementId t = static_cast<ElementId>(rng() % mesh.element_capacity());
        while (!mesh.is_element(t)) t = static_cast<ElementId>((t + 1) % mesh.element_capacity());
        const Simplex tau = mesh.simplex(t);
        const std::vector<ElementId> around = region(mesh, tau.vertices());
        const auto before = local_snapshot(mesh, around);
        const auto vertices_before = mesh.vertex_count();
        const int slot = static_cast<int>(rng() % 4);
        const FaceId f = mesh.face(t, slot);
        const VertexId a = tau.vertex(slot), b = tau.vertex((slot + 1 + static_cast<int>(rng() % 3)) % 4);
        std::string name;
        bool ok = false;
        std::string reason;
        auto record = [&](auto&& outcome) {
            ok = outcome.ok();
            if (!ok) reason = outcome.reason();
        };
        switch (rng() % 8) {
        case 0: name = "split_edge"; record(split_edge(mesh, a, b, uniform(0.2, 0.8))); break;
        case 1: name = "split_face"; record(split_face(mesh, f, {uniform(1, 2), uniform(1, 2), uniform(1, 2)})); break;
        case 2: name = "split_element"; record(split_element(mesh, t)); break;
        case 3:
        case 4: name = "flip_23"; record(flip_23(mesh, f)); break;
        case 5: name = "flip_32"; record(flip_32(mesh, f, static_cast<int>(rng() % 3))); break;
        case 6: name = "collapse_edge"; record(collapse_edge(mesh, a, b)); break;
        default: {
            name = "collapse_edge to the midpoint";
            Point r{}, g{};
            for (std::size_t k = 0; k < 3; ++k) {
                r[k] = 0.5 * (mesh.reference(a)[k] + mesh.reference(b)[k]);
                g[k] = 0.5 * (mesh.deformed(a)[k] + mesh.deformed(b)[k]);
            }
            record(collapse_edge(mesh, a, b, r, g));
        }
        }
        if (!ok) {
            ++refused[name];
            ASSERT_FALSE(reason.empty()) << name;
            ASSERT_EQ(local_snapshot(mesh, around), before)
                << "operation " << i << ": " << name << " refused (" << reason << ") but changed the mesh";
        } else {
            ++done[name];
            std::vector<VertexId> touched(tau.vertices().begin(), tau.vertices().end());
            if (mesh.vertex_count() > vertices_before) touched.push_back(static_cast<VertexId>(vertices_before));
            for (const ElementId u : region(mesh, touched))
                for (const Positions p : {Positions::reference, Positions::deformed})
                    ASSERT_EQ(element_orientation(mesh, u, p), Sign::positive)
                        << "operation " << i << ": " << name << " left element " << u << " "
                        << mesh.simplex(u) << " not positive";
        }
        if (i % 400 == 399) {
            const auto valid = mesh.validate();
            ASSERT_TRUE(valid.ok()) << "after operation " << i << " (" << name << "): " << valid.reason();
        }
    }
    const auto valid = mesh.validate();
    EXPECT_TRUE(valid.ok()) << valid.reason();
    for (const auto& [name, count] : done)
        std::cout << "[ done     ] " << name << ": " << count << " (refused " << refused[name] << ")\n";
    // every kind of operation did happen somewhere on the femur
    for (const char* op : {"split_edge", "split_face", "split_element", "flip_23", "flip_32", "collapse_edge",
                           "collapse_edge to the midpoint"})
        EXPECT_GT(done[op], 0) << op;
}

}  // namespace
}  // namespace sxk
