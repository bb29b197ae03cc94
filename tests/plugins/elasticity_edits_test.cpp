// ElasticBody following the edits of its mesh (elastic_body.hpp; issue 14 item 2): new vertices
// get interpolated displacements, a warm re-solve after a split reaches the fresh solution, and
// after random edits the body's state is the one a fresh body builds on the edited mesh: its
// elements and its product K d bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "../../fuzz/ops_driver.hpp"
#include "../ops/random_steps.hpp"
#include "core/fixtures.hpp"
#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::elasticity {
namespace {

// Bottom (z = min) fixed, top (z = max) lifted by 0.01: displacements only, so every part that
// touches neither stays where it is in both bodies compared.
void hold(ElasticBody& body, const Mesh& mesh) {
    double low = INFINITY, high = -INFINITY;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.vertex_element(v) != invalid_id) {
            low = std::min(low, mesh.reference(v)[2]);
            high = std::max(high, mesh.reference(v)[2]);
        }
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == invalid_id)
            continue;
        const double z = mesh.reference(v)[2];
        if (z <= low + 1e-9) {
            ASSERT_TRUE(body.fix(v).ok());
        } else if (z >= high - 1e-9) {
            ASSERT_TRUE(body.fix(v, {0, 0, 0.01}).ok());
        } else {
            ASSERT_TRUE(body.free(v).ok());
        }
    }
}

// A loaded unit cube of 3^3 Kuhn cells, solved.
struct Solved {
    Mesh mesh = *make_kuhn_cube(3, 1.0 / 3);
    std::optional<ElasticBody> body;
    Solved() {
        auto made = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3});
        EXPECT_TRUE(made.ok()) << made.reason();
        body.emplace(std::move(*made));
        hold(*body, mesh);
        EXPECT_TRUE(solve_linear_cg(*body, {.tolerance = 1e-10})->converged);
    }
};

Eigen::VectorXd u_of(const ElasticBody& body, VertexId v) {
    return body.displacements().segment<3>(3 * v);
}

TEST(ElasticityEdits, SplitMidpointStartsAtTheMeanOfItsEnds) {
    Solved s;
    ScopedWatcher following(s.mesh, *s.body);
    const Simplex& t = s.mesh.simplex(40);
    const VertexId a = t.vertex(0), b = t.vertex(2);
    const auto split = split_edge(s.mesh, a, b, 0.5);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(s.mesh.validate().ok());
    const VertexId m = static_cast<VertexId>(s.mesh.vertex_count() - 1);
    EXPECT_TRUE(s.body->needs_refresh());
    EXPECT_LT((u_of(*s.body, m) - 0.5 * (u_of(*s.body, a) + u_of(*s.body, b))).norm(), 1e-15);
    EXPECT_EQ(s.body->freedom(m), Freedom::free);
    // warm: the rest of the body is already at its solution
    const auto warm = solve_linear_cg(*s.body, {.tolerance = 1e-10});
    ASSERT_TRUE(warm.ok()) << warm.reason();
    auto fresh = ElasticBody::make(s.mesh, {.young = 1e3, .poisson = 0.3});
    ASSERT_TRUE(fresh.ok());
    hold(*fresh, s.mesh);
    const auto cold = solve_linear_cg(*fresh, {.tolerance = 1e-10});
    std::printf("after a split: %zu iterations warm, %zu from rest\n", warm->iterations,
                cold->iterations);
    EXPECT_LT(warm->iterations, cold->iterations);
    EXPECT_LT((s.body->displacements() - fresh->displacements()).norm(),
              1e-7 * fresh->displacements().norm());
}

TEST(ElasticityEdits, DissectionCopiesStartWhereTheirOriginalsAre) {
    Solved s;
    ScopedWatcher following(s.mesh, *s.body);
    // every face in the plane x = 1/3: the cut splits the cube in two
    std::vector<Simplex> cut;
    for (const ElementId t : elements(s.mesh))
        for (int i = 0; i < 4; ++i) {
            const Simplex f = s.mesh.face_simplex(s.mesh.face(t, i));
            bool on = true;
            for (int j = 0; j < 3; ++j)
                on = on && s.mesh.reference(f.vertex(j))[0] == 1.0 / 3;
            if (on && s.mesh.neighbor(t, i) != invalid_id && s.mesh.neighbor(t, i) > t)
                cut.push_back(f);
        }
    ASSERT_EQ(cut.size(), 18u);
    const auto dissected = dissect(s.mesh, cut);
    ASSERT_TRUE(dissected.ok()) << dissected.reason();
    ASSERT_TRUE(s.mesh.validate().ok());
    ASSERT_FALSE(dissected->new_vertices.empty());
    for (const auto& [original, copy] : dissected->new_vertices)
        EXPECT_EQ(u_of(*s.body, copy), u_of(*s.body, original)) << original << " -> " << copy;
    ASSERT_TRUE(s.body->refresh().ok());
    auto fresh = ElasticBody::make(s.mesh, {.young = 1e3, .poisson = 0.3});
    ASSERT_TRUE(fresh.ok());
    Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(static_cast<Eigen::Index>(fresh->dof_count()),
                                                   -1, 1),
                    ours, theirs;
    s.body->multiply(d, ours);
    fresh->multiply(d, theirs);
    EXPECT_EQ(ours, theirs);
}

// Two materials by the element attribute: a column 1 x 1 x 2, E = 1e3 below z = 1 and 4e3 above,
// nu = 0, the bottom held and the top pulled up by 0.01. The stress is the same in both halves,
// so the lower one stretches 4 times as much: the interface rises by 0.008 (linear elements
// represent this exactly). A split of an upper element keeps its material in both children.
TEST(ElasticityEdits, MaterialsPerElementFollowSplits) {
    Mesh mesh = *make_kuhn_box({2, 2, 4}, {0.5, 0.5, 0.5});
    const std::array<double, 2> soft{1e3, 0}, stiff{4e3, 0};
    const auto materials = mesh.add_element_attribute(material_attribute, 2, soft);
    ASSERT_TRUE(materials.ok()) << materials.reason();
    for (const ElementId t : elements(mesh)) {
        double z = 0;
        for (int j = 0; j < 4; ++j)
            z += mesh.reference(mesh.simplex(t).vertex(j))[2] / 4;
        if (z > 1) {
            ASSERT_TRUE(mesh.set_element_attribute(*materials, t, stiff).ok());
        }
    }
    auto body = ElasticBody::make(
        mesh, {.young = 7, .poisson = 0.2});  // the attribute overrides it everywhere
    ASSERT_TRUE(body.ok()) << body.reason();
    EXPECT_EQ(body->largest_young(), 4e3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const double z = mesh.reference(v)[2];
        if (z == 0) {
            ASSERT_TRUE(body->fix(v).ok());
        } else if (z == 2) {
            ASSERT_TRUE(body->fix(v, {0, 0, 0.01}).ok());
        }
    }
    ASSERT_TRUE(solve_linear_cg(*body, {.tolerance = 1e-12})->converged);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const double z = mesh.reference(v)[2];
        const double expected = z <= 1 ? 0.008 * z : 0.008 + 0.002 * (z - 1);
        const Vector3 u = body->displacement(v);
        EXPECT_NEAR(u[2], expected, 1e-12) << v;
        EXPECT_NEAR(u[0], 0, 1e-12) << v;
        EXPECT_NEAR(u[1], 0, 1e-12) << v;
    }
    // a split in the stiff half: both children stiff, the state a fresh body's
    ScopedWatcher following(mesh, *body);
    ElementId upper = invalid_id;
    for (const ElementId t : elements(mesh))
        if (mesh.element_attribute(*materials, t)[0] == stiff[0])
            upper = t;
    ASSERT_TRUE(
        split_edge(mesh, mesh.simplex(upper).vertex(0), mesh.simplex(upper).vertex(1), 0.5).ok());
    ASSERT_TRUE(body->refresh().ok());
    auto fresh = ElasticBody::make(mesh, {.young = 7, .poisson = 0.2});
    ASSERT_TRUE(fresh.ok());
    Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(static_cast<Eigen::Index>(fresh->dof_count()),
                                                   -1, 1),
                    ours, theirs;
    body->multiply(d, ours);
    fresh->multiply(d, theirs);
    EXPECT_EQ(ours, theirs);
    // and a material out of range is refused by name
    ASSERT_TRUE(
        mesh.set_element_attribute(*materials, upper, std::array<double, 2>{4e3, 0.5}).ok());
    body->materials_changed();
    EXPECT_EQ(body->refresh().reason(),
              "elasticity: element " + std::to_string(upper) +
                  " (elasticity.material): Poisson's ratio 0.5 is not in (-1, 0.5)");
}

// Random flips, splits, collapses, dissections, bisections and vertex moves (the operation
// driver of the fuzzers) on jittered Kuhn cubes, the body attached; every few steps its elements
// and its product K d must equal a fresh body's bit for bit: the same K, whatever edits came
// between. (Solving both and comparing was tried: random moves make slivers and dissections
// hinges, so the problem can be too ill-conditioned for a residual test to pin the energy; the
// solves after an edit are compared on well-shaped meshes above.)
// kind: the ops driver's start mesh (0 jittered planar grid, 3 jittered Kuhn cube).
void random_edits_keep_the_state_of_a_fresh_body(const char* name, std::uint32_t kind,
                                                 BodyOptions options) {
    const std::uint64_t seed = test::seed_for(name);
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 rng(seed);
    test::StartChoices start(rng, kind);
    int compared = 0, edits = 0, flat = 0;
    // A flat element usually stays until the round ends (nothing edits it away), so a round
    // that makes one early compares little: more rounds until 30 states are compared (the
    // seed 1712318564 had 17 of its 40 checks flat in 4 rounds).
    for (int round = 0; round < 4 || (compared < 30 && round < 12); ++round) {
        start.restart();
        Mesh mesh = ops_driver::start_mesh(start.choices(), 3, 2);
        ASSERT_EQ(mesh.topological_dimension(), kind == 3 ? 3 : 2);
        auto made = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3}, options);
        ASSERT_TRUE(made.ok()) << made.reason();
        ElasticBody body = std::move(*made);
        ScopedWatcher following(mesh, body);
        for (int step = 0; step < 150; ++step) {
            if (rng() % 6 == 0) {
                test::random_move(mesh, rng);
            } else {
                const ops_driver::Step done = ops_driver::run_step(mesh, start.choices(), 400);
                ASSERT_TRUE(done.finding.empty()) << done.finding;
                edits += done.done;
            }
            if (step % 15 != 14)
                continue;
            ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
            // a sliver whose volume rounds to zero has no stiffness: both refuse it alike
            const auto refreshed = body.refresh();
            auto fresh = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3}, options);
            ASSERT_EQ(refreshed.ok(), fresh.ok())
                << (refreshed.ok() ? fresh.reason() : refreshed.reason());
            if (!fresh.ok()) {
                EXPECT_EQ(refreshed.reason(), fresh.reason());
                EXPECT_EQ(fresh.code(), RefusalCode::would_flatten);
                ++flat;
                continue;
            }
            ASSERT_EQ(body.dof_count(), fresh->dof_count());
            ASSERT_TRUE(std::equal(body.elements().begin(), body.elements().end(),
                                   fresh->elements().begin(), fresh->elements().end()));
            Eigen::VectorXd d(static_cast<Eigen::Index>(body.dof_count())), ours, theirs;
            for (Eigen::Index i = 0; i < d.size(); ++i)
                d[i] = 1e-3 * std::sin(0.7 * static_cast<double>(i) + step);
            body.multiply(d, ours);
            fresh->multiply(d, theirs);
            ASSERT_EQ(ours, theirs) << "round " << round << ", step " << step;
            // the model's forces too (neo-Hookean: nonlinear in d; d small enough to invert
            // nothing)
            const bool ok = body.elastic_forces(d, ours);
            ASSERT_EQ(ok, fresh->elastic_forces(d, theirs));
            if (ok) {
                ASSERT_EQ(ours, theirs) << "round " << round << ", step " << step;
            }
            ++compared;
        }
    }
    std::printf(
        "%d states compared (%d times both refused an element flat in doubles) after %d successful "
        "edits\n",
        compared, flat, edits);
    EXPECT_GE(compared, 30);
    EXPECT_GT(edits, 60);
}

TEST(ElasticityEdits, RandomEditsKeepTheStateOfAFreshBody) {
    random_edits_keep_the_state_of_a_fresh_body(
        "ElasticityEdits.RandomEditsKeepTheStateOfAFreshBody", 3, {});
}

TEST(ElasticityEdits, RandomEditsKeepTheStateOfAFreshPlaneStressBody) {
    random_edits_keep_the_state_of_a_fresh_body(
        "ElasticityEdits.RandomEditsKeepTheStateOfAFreshPlaneStressBody", 0, {.thickness = 0.05});
}

TEST(ElasticityEdits, RandomEditsKeepTheStateOfAFreshNeoHookeanBody) {
    random_edits_keep_the_state_of_a_fresh_body(
        "ElasticityEdits.RandomEditsKeepTheStateOfAFreshNeoHookeanBody", 3,
        {.model = Model::neohookean});
}

}  // namespace
}  // namespace sxk::elasticity
