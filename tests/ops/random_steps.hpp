// What the property tests of edits (tests/ops/*_random_test.cpp) share: the driver's choices with
// a forced start mesh, and random checked vertex moves.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "../../fuzz/ops_driver.hpp"
#include "sxk/mesh.hpp"

namespace sxk::test {

// The driver's choices from a seeded generator, except the first after construction and after
// each restart(), which is `kind`: start_mesh's first choice, the kind of start mesh
// (fuzz/ops_driver.hpp).
class StartChoices {
public:
    StartChoices(std::mt19937_64& rng, std::uint32_t kind)
        : m_choices([this, &rng, kind]() -> int {
              if (m_forced) {
                  m_forced = false;
                  return static_cast<int>(kind);
              }
              return static_cast<int>(rng() & 0xff);
          }) {}
    StartChoices(const StartChoices&) = delete;
    StartChoices& operator=(const StartChoices&) = delete;
    ops_driver::Choices& choices() { return m_choices; }
    void restart() { m_forced = true; }

private:
    bool m_forced = true;
    ops_driver::Choices m_choices;
};

// Moves 1-3 random vertices by a small random offset, refusing inversions and flat elements
// (the driver's oracle wants every element strictly positive in both sets), and keeps the
// driver's "where" attribute on the reference position. Both position sets move alike, one
// move_vertices each (the deformed offset doubled where the driver doubled the deformed
// positions): make_delaunay_by_flips flips by one set only and may invert the other when the two
// are not similar (its header).
inline void random_move(Mesh& mesh, std::mt19937_64& rng) {
    if (mesh.vertex_count() == 0) return;
    std::uniform_int_distribution<VertexId> vertex(0, static_cast<VertexId>(mesh.vertex_count() - 1));
    std::uniform_real_distribution<double> offset(-0.05, 0.05);
    std::vector<VertexId> vertices;
    std::vector<Point> reference, deformed, old_reference;
    const int count = 1 + static_cast<int>(rng() % 3);
    for (int i = 0; i < count; ++i) {
        const VertexId v = vertex(rng);
        if (std::find(vertices.begin(), vertices.end(), v) != vertices.end()) continue;
        const double scale = mesh.deformed(v) == mesh.reference(v) ? 1 : 2;
        Point r = mesh.reference(v), d = mesh.deformed(v);
        for (std::size_t c = 0; c < static_cast<std::size_t>(mesh.ambient_dimension()); ++c) {
            const double delta = offset(rng);
            r[c] += delta;
            d[c] += scale * delta;
        }
        vertices.push_back(v);
        old_reference.push_back(mesh.reference(v));
        reference.push_back(r);
        deformed.push_back(d);
    }
    const MoveCheck check{true, true};
    if (!mesh.move_vertices(vertices, reference, PositionSet::reference, check).ok()) return;
    if (!mesh.move_vertices(vertices, deformed, PositionSet::deformed, check).ok()) {
        ASSERT_TRUE(mesh.move_vertices(vertices, old_reference, PositionSet::reference).ok());
        return;
    }
    const AttributeId where = mesh.find_vertex_attribute("where");
    if (where == invalid_id) return;
    for (const VertexId v : vertices) ASSERT_TRUE(mesh.set_vertex_attribute(where, v, mesh.reference(v)).ok());
}

}  // namespace sxk::test
