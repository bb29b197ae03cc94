// Property test of the snap cutter: seeded random scalpel paths (curved: the blade turns and
// tilts as it goes) on the thesis' cube, a Delaunay mesh of random points and the Delaunay
// cylinder; after every step the mesh is valid, with no element inverted or flat in either
// position set, and undoing every step gives back the input exactly. SXK_SEED replays a run.
// 10,980 steps in all (80 + 50 + 50 paths of 61 samples). The femur is cut in tests/real.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/fixtures.hpp"
#include "snapcut_fixture.hpp"

namespace sxk::test {
namespace {

using snapcut::Scalpel;

struct Box {
    Point low, high;
};

Box bounding_box(const Mesh& mesh) {
    Box box{mesh.reference(0), mesh.reference(0)};
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (std::size_t k = 0; k < 3; ++k) {
            box.low[k] = std::min(box.low[k], mesh.reference(v)[k]);
            box.high[k] = std::max(box.high[k], mesh.reference(v)[k]);
        }
    return box;
}

// A random curved path: the tip starts outside or inside the box, moves in small steps whose
// direction turns a little each time; the blade (length about the box's size) tilts as it goes.
std::vector<Scalpel> random_path(const Box& box, int steps, std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(0, 1), turn(-0.4, 0.4);
    double size = 0;
    Point centre;
    for (std::size_t k = 0; k < 3; ++k) {
        size = std::max(size, box.high[k] - box.low[k]);
        centre[k] = (box.low[k] + box.high[k]) / 2;
    }
    Point tip;
    for (std::size_t k = 0; k < 3; ++k) tip[k] = centre[k] + (unit(random) - 0.5) * 1.4 * size;
    double heading = 2 * std::numbers::pi * unit(random), tilt = 0.6 * (unit(random) - 0.5);
    const double step = size * (0.01 + 0.09 * unit(random));
    const double blade = size * (0.3 + 0.9 * unit(random));
    std::vector<Scalpel> path;
    for (int i = 0; i <= steps; ++i) {
        const Point up{std::sin(tilt) * std::cos(heading + std::numbers::pi / 2),
                       std::sin(tilt) * std::sin(heading + std::numbers::pi / 2), std::cos(tilt)};
        Scalpel scalpel{tip, tip};
        for (std::size_t k = 0; k < 3; ++k) scalpel.handle[k] += blade * up[k];
        path.push_back(scalpel);
        tip[0] += step * std::cos(heading);
        tip[1] += step * std::sin(heading);
        tip[2] += step * 0.3 * turn(random);
        heading += turn(random);
        tilt += 0.2 * turn(random);
    }
    return path;
}

void check_random_cuts(const char* name, const Mesh& original, int paths, int steps) {
    const std::uint64_t seed = seed_for(name);
    std::mt19937_64 random(seed);
    const Box box = bounding_box(original);
    std::size_t taken = 0, dissected = 0;
    for (int p = 0; p < paths; ++p) {
        Mesh mesh = original;
        snapcut::Options options;
        options.snap = random() % 4 != 0;
        options.remove_loose_pieces = random() % 3 == 0;
        auto session = snapcut::SnapCutSession::make(mesh, options, {degeneracy_service()}).value();
        for (const Scalpel& scalpel : random_path(box, steps, random)) {
            const auto stepped = session->cut(scalpel);
            ASSERT_TRUE(stepped) << "path " << p << " step " << taken << ": " << stepped.reason();
            ++taken;
            dissected += session->last_step().faces_dissected;
            const auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true});
            ASSERT_TRUE(valid) << "path " << p << ": " << valid.reason();
        }
        ASSERT_TRUE(session->cancel());
        expect_same_state(mesh, original);
        if (::testing::Test::HasFatalFailure()) return;
    }
    std::cout << "[ steps    ] " << name << ": " << taken << " steps, " << dissected << " faces dissected\n";
    EXPECT_GT(dissected, 0u);
}

TEST(SnapCutRandom, ThesisCube) { check_random_cuts("SnapCutRandom.ThesisCube", make_kuhn_cube(8).value(), 80, 60); }

TEST(SnapCutRandom, DelaunayOfRandomPoints) {
    std::mt19937_64 random(seed_for("SnapCutRandom.DelaunayOfRandomPoints/points"));
    std::uniform_real_distribution<double> coordinate(0, 1);
    std::vector<Point> points;
    for (int i = 0; i < 600; ++i) points.push_back({coordinate(random), coordinate(random), coordinate(random)});
    check_random_cuts("SnapCutRandom.DelaunayOfRandomPoints", make_delaunay(points).value(), 50, 60);
}

TEST(SnapCutRandom, DelaunayCylinder) {
    check_random_cuts("SnapCutRandom.DelaunayCylinder", make_delaunay(cylinder_cloud(4, 13)).value(), 50, 60);
}

}  // namespace
}  // namespace sxk::test
