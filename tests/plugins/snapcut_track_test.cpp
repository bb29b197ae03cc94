// Following the blade (plugins/snapcut/blade_track.hpp) against asking the spatial index along
// the whole blade every sweep (Options::follow_blade false), step by step, on random curved paths
// moved in small steps (where following pays), with vertices moved between steps as a simulation
// would: a few near the blade (their stars are looked at again) or all of them (the track starts
// over). Without snapping the two must cut exactly alike: the same mesh and the same marks after
// every step. With it the index also hands the selection elements that meet the sweep only where
// the snaps moved them (the track sees the mesh as the selection does, before the snaps), which
// may select an incision's face again and so change which labelled faces a later sweep retries:
// the two then must mark the same edges while they have cut alike. SXK_SEED replays a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <random>
#include <string>

#include "core/fixtures.hpp"
#include "snapcut_fixture.hpp"
#include "sxk/locate.hpp"
#include "sxk/quality.hpp"

namespace sxk::test {
namespace {

// How the body moves between steps.
enum class Moves { none, a_few, all };

// Moves `vertices` of both meshes by the same small random amount (deformed positions), unless
// an element would invert or flatten; whether both moved or both stayed (with snapping the two
// may have been cut differently while their counts agree).
bool move_both(Mesh& a, Mesh& b, const std::vector<VertexId>& vertices, double amount, std::mt19937_64& random) {
    std::uniform_real_distribution<double> offset(-amount, amount);
    std::vector<Point> to;
    for (const VertexId v : vertices) {
        Point p = a.deformed(v);
        for (double& x : p) x += offset(random);
        to.push_back(p);
    }
    const MoveCheck check{.refuse_inverted = true, .refuse_flat = true};
    const bool moved_a = static_cast<bool>(a.move_vertices(vertices, to, PositionSet::deformed, check));
    const bool moved_b = static_cast<bool>(b.move_vertices(vertices, to, PositionSet::deformed, check));
    return moved_a == moved_b;
}

// The same elements (ids and vertices) and vertex positions.
bool same_mesh(const Mesh& a, const Mesh& b) {
    if (a.vertex_count() != b.vertex_count() || a.element_capacity() != b.element_capacity()) return false;
    for (VertexId v = 0; v < a.vertex_count(); ++v)
        if (a.deformed(v) != b.deformed(v) || a.reference(v) != b.reference(v)) return false;
    for (ElementId t = 0; t < a.element_capacity(); ++t) {
        if (a.is_element(t) != b.is_element(t)) return false;
        if (a.is_element(t) && a.simplex(t) != b.simplex(t)) return false;
    }
    return true;
}

// The marks of the edges of `mesh`'s elements: (lower vertex, higher vertex, marked end, sweep),
// sorted.
std::vector<std::array<std::uint32_t, 4>> marks_of(const Mesh& mesh, const snapcut::CutMarks& marks) {
    std::vector<std::array<std::uint32_t, 4>> found;
    for (const ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j)
                if (const auto mark = marks.mark(s.vertex(i), s.vertex(j)))
                    found.push_back({s.vertex(i), s.vertex(j), mark->node, mark->sweep});
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

// `seed` (seed_for(name)) seeds the run.
void expect_same_cuts(const char* name, std::uint64_t seed, const Mesh& original, int paths, int steps, int substeps,
                      Moves moves) {
    std::mt19937_64 random(seed);
    const Box box = bounding_box(original);
    std::vector<ElementId> all = all_elements(original);
    const double h = mean_edge_length(original, Positions::deformed);
    std::size_t dissected = 0, taken = 0, compared = 0;
    for (int p = 0; p < paths; ++p) {
        Mesh followed = original, searched = original;
        snapcut::Options options;
        options.snap = random() % 4 != 0;
        auto following = snapcut::SnapCutSession::make(followed, options, {degeneracy_service()}).value();
        options.follow_blade = false;
        auto searching = snapcut::SnapCutSession::make(searched, options, {degeneracy_service()}).value();
        const Simplex inside = original.simplex(all[random() % all.size()]);
        Point through{};
        for (const VertexId v : inside.vertices())
            for (std::size_t k = 0; k < 3; ++k) through[k] += original.deformed(v)[k] / 4;
        const std::vector<snapcut::Scalpel> path = random_path(box, through, steps, random);
        const SpatialIndex index(followed, Positions::deformed);  // where the tip is, for the moves
        bool alike = true;  // the two meshes have been cut alike so far
        for (std::size_t i = 0; i < path.size(); ++i)
            for (int sub = 1; sub <= (i == 0 ? 1 : substeps); ++sub) {
                const snapcut::Scalpel scalpel =
                    i == 0 ? path[0] : snapcut::between(path[i - 1], path[i], double(sub) / substeps);
                const auto a = following->cut(scalpel);
                const auto b = searching->cut(scalpel);
                ASSERT_EQ(bool(a), bool(b)) << "seed " << seed << " path " << p << " step " << taken;
                ++taken;
                dissected += following->last_step().faces_dissected;
                const std::string where = "seed " + std::to_string(seed) + " path " + std::to_string(p) +
                                          " step " + std::to_string(taken) + (options.snap ? "" : " (no snapping)");
                alike = alike && same_mesh(followed, searched);
                ASSERT_TRUE(alike || options.snap) << where << ": the meshes differ";
                // cut alike so far: the same edges marked, by the same sweeps, at the same ends
                if (alike) {
                    ++compared;
                    const auto x = marks_of(followed, following->marks()), y = marks_of(searched, searching->marks());
                    std::vector<std::array<std::uint32_t, 4>> only_x, only_y;
                    std::set_difference(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(only_x));
                    std::set_difference(y.begin(), y.end(), x.begin(), x.end(), std::back_inserter(only_y));
                    ASSERT_TRUE(only_x.empty() && only_y.empty())
                        << where << ": marks only when following the blade " << ::testing::PrintToString(only_x)
                        << ", only when asking the index " << ::testing::PrintToString(only_y) << " (edge, marked end, sweep; "
                        << following->marks().sweeps().size() << " sweeps)";
                }
                if (!alike) continue;  // the bodies differ: they cannot be moved alike
                if (moves == Moves::a_few && followed.element_count() > 0) {
                    // the corners of a few elements the blade's tip is near
                    const Location at = index.locate(scalpel.tip);
                    if (at.found()) {
                        const Simplex s = followed.simplex(at.element);
                        alike = move_both(followed, searched, {s.vertices().begin(), s.vertices().end()}, 0.02 * h,
                                          random);
                    }
                } else if (moves == Moves::all) {
                    std::vector<VertexId> every;
                    for (VertexId v = 0; v < followed.vertex_count(); ++v)
                        if (followed.vertex_element(v) != invalid_id) every.push_back(v);
                    alike = move_both(followed, searched, every, 0.002 * h, random);
                }
            }
        if (!options.snap) expect_same_state(followed, searched);
        const auto valid = followed.validate({.orientation = true, .flat_is_invalid = true});
        ASSERT_TRUE(valid) << "seed " << seed << " path " << p << ": " << valid.reason();
        if (::testing::Test::HasFatalFailure()) return;
    }
    std::cout << "[ steps    ] " << name << ": " << taken << " steps, " << dissected << " faces dissected, "
              << compared << " steps on meshes still cut alike\n";
    EXPECT_GT(dissected, 0u);
}

void expect_same_cuts(const char* name, const Mesh& original, int paths, int steps, int substeps, Moves moves) {
    expect_same_cuts(name, seed_for(name), original, paths, steps, substeps, moves);
}

TEST(SnapCutTrack, FollowingTheBladeCutsAsTheIndexDoesOnTheCube) {
    expect_same_cuts("SnapCutTrack.Cube", make_kuhn_cube(8).value(), 6, 20, 8, Moves::none);
}

TEST(SnapCutTrack, FollowingTheBladeCutsAsTheIndexDoesOnRandomPoints) {
    const char* name = "SnapCutTrack.RandomPoints";
    const std::uint64_t seed = seed_for(name);
    expect_same_cuts(name, seed, make_delaunay(random_points(seed, 600)).value(), 6, 20, 8, Moves::none);
}

TEST(SnapCutTrack, VerticesMovedNearTheBladeAreLookedAtAgain) {
    expect_same_cuts("SnapCutTrack.AFewMoved", make_delaunay(cylinder_cloud(4, 13)).value(), 4, 20, 6, Moves::a_few);
}

TEST(SnapCutTrack, AFrameThatMovesEveryVertexStartsTheTrackOver) {
    expect_same_cuts("SnapCutTrack.AllMoved", make_kuhn_cube(8).value(), 3, 16, 4, Moves::all);
}

}  // namespace
}  // namespace sxk::test
