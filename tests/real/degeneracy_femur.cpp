// Degeneracy removal on a snapped real mesh (issue 4): the femur of CGAL's data set
// tetrahedralised by TetGen -pq1.4 (tools/make-data, as in ops_femur.cpp), 47,733 nodes and
// 212,936 tetrahedra, snapped onto a plane along the bone (snapped_femur.hpp); then
// remove_degeneracies.
//
// TetGen's femur has degenerates of its own before any snapping (about 30 needles at the
// boundary, aspect ratio down to 0.0027): the whole-mesh run removes them too, the run on the
// stars of the moved vertices leaves those outside alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "real/femur_data.hpp"
#include "real/snapped_femur.hpp"
#include "remove_degeneracies.hpp"
#include "snap_to_plane.hpp"
#include "sxk/io.hpp"
#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"

namespace sxk::degeneracy {
namespace {

using test::make_femur;

bool below(const Mesh& mesh, ElementId t, double threshold) {
    return aspect_ratio(element_points(mesh, t, Positions::reference)) < threshold;
}

std::size_t count_below(const Mesh& mesh, double threshold) {
    std::size_t n = 0;
    for (const ElementId t : elements(mesh))
        n += below(mesh, t, threshold);
    return n;
}

std::size_t count_not_strictly_positive(const Mesh& mesh) {
    std::size_t n = 0;
    for (const ElementId t : elements(mesh))
        n += element_orientation(mesh, t, Positions::reference) != Sign::positive ||
             element_orientation(mesh, t, Positions::deformed) != Sign::positive;
    return n;
}

void print(const char* name, const Report& report) {
    std::printf(
        "[ figures  ] %s: found %zu, remaining %zu, cut free %zu, peeled %zu, collapses %zu, "
        "splits %zu, "
        "flips %zu, elements %zu -> %zu, vertices %zu -> %zu, passes %zu\n",
        name, report.found, report.remaining, report.cut_free, report.peeled, report.collapses,
        report.splits, report.flips, report.elements_before, report.elements_after,
        report.vertices_before, report.vertices_after, report.passes.size());
    if (!report.passes.empty()) {
        const PassReport& p = report.passes.front();
        std::printf("[ figures  ]   first list: needle %zu spindle %zu sliver %zu cap %zu\n",
                    p.found[1], p.found[2], p.found[3], p.found[4]);
    }
    for (std::size_t i = 0; i < report.remaining_reasons.size() && i < 20; ++i)
        std::printf("[ figures  ]   remaining %u: %s\n", report.remaining_elements[i].value(),
                    report.remaining_reasons[i].c_str());
    std::fflush(stdout);
}

class DegeneracyFemur : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const std::string ele = make_femur();
        ASSERT_FALSE(ele.empty()) << "tools/make-data femur failed";
        ASSERT_TRUE(std::filesystem::exists(ele)) << ele;
        unsnapped = std::make_unique<Mesh>(read_mesh(ele));
        ASSERT_EQ(unsnapped->element_count(), 212936u);
        snapped = std::make_unique<Mesh>(*unsnapped);
        snap = test::snap_femur(*snapped);
        std::printf(
            "[ figures  ] femur: h = %.6g, %zu vertices moved, %zu refused; elements below aspect "
            "ratio 0.01: %zu before snapping, %zu after\n",
            snap.mean_edge_length, snap.moved.size(), snap.refused, count_below(*unsnapped, 0.01),
            count_below(*snapped, 0.01));
    }
    static void TearDownTestSuite() {
        unsnapped.reset();
        snapped.reset();
    }
    void SetUp() override {
        if (!snapped)
            GTEST_SKIP() << "the femur could not be made";
    }

    // The "done when" except "no degenerate remains", which the two runs judge apart.
    static void expect_done(const Mesh& mesh, const Report& report) {
        EXPECT_GT(report.found, 0u);
        EXPECT_EQ(report.remaining, 0u);
        EXPECT_LE(10 * report.cut_free, report.found)
            << "cut free more than 10% of the degenerates";
        const double before = static_cast<double>(unsnapped->element_count());
        EXPECT_LE(std::abs(static_cast<double>(mesh.element_count()) - before), 0.05 * before)
            << unsnapped->element_count() << " -> " << mesh.element_count();
        EXPECT_EQ(report.elements_after, mesh.element_count());
        EXPECT_EQ(count_not_strictly_positive(mesh), 0u);
        const auto valid = mesh.validate();
        EXPECT_TRUE(valid.ok()) << valid.reason();
    }

    static std::unique_ptr<Mesh> unsnapped, snapped;
    static SnapReport snap;
};
std::unique_ptr<Mesh> DegeneracyFemur::unsnapped, DegeneracyFemur::snapped;
SnapReport DegeneracyFemur::snap;

TEST_F(DegeneracyFemur, SnapLeavesNothingFlatOrInverted) {
    EXPECT_GT(snap.moved.size(), 100u);
    EXPECT_GT(count_below(*snapped, 0.01),
              count_below(*unsnapped, 0.01));  // snapping made degenerates
    EXPECT_EQ(count_not_strictly_positive(*snapped), 0u);
    const auto valid = snapped->validate();
    EXPECT_TRUE(valid.ok()) << valid.reason();
}

TEST_F(DegeneracyFemur, WholeMeshRemovalLeavesNoDegenerate) {
    Mesh mesh = *snapped;
    const std::size_t degenerates = count_below(mesh, 0.01);
    const auto removed = remove_degeneracies(mesh);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    print("femur, whole mesh", *removed);
    EXPECT_EQ(removed->found, degenerates);
    EXPECT_EQ(count_below(mesh, 0.01), 0u);
    expect_done(mesh, *removed);
}

// The local variant: candidates = the stars of the moved vertices. TetGen's own degenerates
// away from the plane are not candidates and stay; every one the snap made goes.
TEST_F(DegeneracyFemur, RemovalAroundTheMovedVerticesLeavesOnlyDegeneratesItWasNotGiven) {
    Mesh mesh = *snapped;
    const std::vector<ElementId> candidates = elements_around(mesh, snap.moved);
    std::size_t among = 0;
    for (const ElementId t : candidates)
        among += below(mesh, t, 0.01);
    std::vector<ElementId> elsewhere;  // degenerate, not a candidate
    for (const ElementId t : elements(mesh))
        if (below(mesh, t, 0.01) && !std::binary_search(candidates.begin(), candidates.end(), t))
            elsewhere.push_back(t);
    const auto removed = remove_degeneracies(mesh, candidates);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    print("femur, around the moved vertices", *removed);
    std::printf(
        "[ figures  ]   %zu candidates, %zu degenerate among them, %zu degenerate elsewhere\n",
        candidates.size(), among, elsewhere.size());
    EXPECT_EQ(removed->found, among);
    // what is still degenerate is a degenerate that was not a candidate, untouched
    for (const ElementId t : elements(mesh)) {
        if (!below(mesh, t, 0.01))
            continue;
        EXPECT_TRUE(std::binary_search(elsewhere.begin(), elsewhere.end(), t) &&
                    mesh.simplex(t) == snapped->simplex(t))
            << "element " << t << " is degenerate after the removal";
    }
    expect_done(mesh, *removed);
}

}  // namespace
}  // namespace sxk::degeneracy
