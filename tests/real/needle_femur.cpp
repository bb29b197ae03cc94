// The needle in the femur (issue 17: 3D on the femur with conforming newest-vertex bisection): the
// femur of CGAL's data set tetrahedralised by TetGen -pq1.4 (tools/make-data: 212,936
// tetrahedra; z along the bone), a needle pushed along x through the shaft at z = 0.03, y = 0.065
// to its middle, refined to h_ref = 0.003 (about a quarter of a mean edge) by AMP's bisection (the
// femur is no Kuhn mesh). Geometry only: the femur's CG would be most of the time. Then: valid and
// conforming after every step, no element flat or inverted, the new shapes within AMP's bound,
// needle nodes along the shaft, and undoing every step gives the femur back exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/fixtures.hpp"
#include "needle.hpp"
#include "real/femur_data.hpp"
#include "sxk/io.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

TEST(NeedleFemur, ANeedleThroughTheShaftKeepsTheFemurValidAndUndoes) {
    const std::string femur = make_femur();
    ASSERT_FALSE(femur.empty()) << "tools/make-data femur failed";
    Mesh mesh = read_mesh(femur);
    const Mesh before = mesh;
    std::set<Simplex> original;
    for (const ElementId t : elements(mesh)) original.insert(mesh.simplex(t));
    needle::Options options;
    options.h_ref = 0.003;
    auto session = needle::NeedleSession::make(mesh, options);
    ASSERT_TRUE(session.ok()) << session.reason();
    std::size_t inside = 0;
    for (double x = -0.16; x <= -0.06 + 1e-12; x += 0.0025) {
        auto step = (*session)->move({{x - 0.2, 0.065, 0.03}, {x, 0.065, 0.03}});
        ASSERT_TRUE(step.ok()) << "x = " << x << ": " << step.reason();
        inside += step->tip_inside;
        const auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true});
        ASSERT_TRUE(valid.ok()) << "x = " << x << ": " << valid.reason();
    }
    EXPECT_GE(inside, 25u);
    EXPECT_GE((*session)->nodes().size(), 15u);
    for (const needle::NeedleNode& node : (*session)->nodes()) EXPECT_LE(std::hypot(node.perp[1], node.perp[2]), 0.01);
    // the refinement's shapes: AMP bisection keeps the descendants of an initial tetrahedron in a
    // bounded number of similarity classes (sxk/ops/tet_bisection.hpp: at most 69 measured)
    std::set<ShapeSignature> shapes;
    std::size_t kept = 0;
    for (const ElementId t : elements(mesh)) {
        if (original.count(mesh.simplex(t))) ++kept;
        else shapes.insert(shape_signature(mesh, t));
    }
    const std::size_t refined = before.element_count() - kept;
    std::printf("%zu tetrahedra -> %zu; %zu initial ones refined into %zu shapes\n", before.element_count(),
                mesh.element_count(), refined, shapes.size());
    EXPECT_GT(refined, 0u);
    EXPECT_LE(shapes.size(), 69 * refined);
    ASSERT_TRUE((*session)->cancel().ok());
    ASSERT_TRUE(mesh.validate().ok());
    expect_same_state(mesh, before);
}

}  // namespace
}  // namespace sxk::test
