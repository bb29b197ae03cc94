// The body's other element and model: triangles in plane stress (thesis §6.3) and compressible
// neo-Hookean elasticity (§4.3.3) with the nonlinear CG of §2.4.2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/fixtures.hpp"
#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"

namespace sxk::elasticity {
namespace {

using test::kuhn_cube;
using test::planar_grid;

// The textbook constant-strain triangle in plane stress, t A B^T D B, against the body's: the
// x and y rows and columns of each corner (z is held at 0).
TEST(ElasticityPlaneStress, TriangleStiffnessIsTheTextbookOne) {
    Mesh mesh(2, 2);
    const std::array<Point, 3> p{Point{0.1, 0.2, 0}, Point{2.1, 0.4, 0}, Point{0.7, 1.9, 0}};
    for (const Point& x : p)
        mesh.add_vertex(x);
    ASSERT_TRUE(mesh.assign_elements(std::vector<Simplex>{Simplex(+1, {0, 1, 2})}).ok());
    const Material material{.young = 3e4, .poisson = 0.34};
    const double thickness = 0.01;
    auto body = ElasticBody::make(mesh, material, {.thickness = thickness});
    ASSERT_TRUE(body.ok()) << body.reason();
    const double area = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                               (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
    Eigen::Matrix<double, 3, 6> b = Eigen::Matrix<double, 3, 6>::Zero();
    for (int j = 0; j < 3; ++j) {
        const Point& q = p[static_cast<std::size_t>((j + 1) % 3)];
        const Point& r = p[static_cast<std::size_t>((j + 2) % 3)];
        const double bx = (q[1] - r[1]) / (2 * area), by = (r[0] - q[0]) / (2 * area);
        b(0, 2 * j) = bx;
        b(1, 2 * j + 1) = by;
        b(2, 2 * j) = by;
        b(2, 2 * j + 1) = bx;
    }
    const double nu = material.poisson;
    Eigen::Matrix3d d;
    d << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
    d *= material.young / (1 - nu * nu);
    const Eigen::Matrix<double, 6, 6> expected = thickness * area * b.transpose() * d * b;
    const Eigen::Matrix<double, 12, 12> k = body->element_stiffness(0);
    const Simplex& s = mesh.simplex(0);
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j)
                    EXPECT_NEAR(k(3 * a + i, 3 * c + j),
                                expected(2 * static_cast<int>(s.vertex(a)) + i,
                                         2 * static_cast<int>(s.vertex(c)) + j),
                                1e-9 * expected.norm());
    // nothing in z, nothing in the unused fourth corner
    for (int a = 0; a < 12; ++a) {
        EXPECT_EQ(k(a, 2), 0.0);
        EXPECT_EQ(k(a, 11), 0.0);
    }
    EXPECT_TRUE(mesh.validate().ok());
}

// A 4 x 2 strip of triangles, 0.01 thick, pulled at x = 4 by 3 N against rollers at x = 0 (one
// corner pinned): uniform stress F / (h t), which linear triangles represent exactly, so the
// stretch and the Poisson contraction of plane stress come out to rounding.
TEST(ElasticityPlaneStress, StripStretchesAndNarrowsAsTheStaticsSay) {
    Mesh mesh(2, 2);
    const int nx = 8, ny = 4;
    const double length = 4, height = 2, thickness = 0.01, force = 3;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            mesh.add_vertex({length * i / nx, height * j / ny, 0});
    auto id = [&](int i, int j) { return VertexId(j * (nx + 1) + i); };
    std::vector<Simplex> triangles;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            triangles.emplace_back(
                +1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            triangles.emplace_back(
                +1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    const Material material{.young = 1e5, .poisson = 0.3};
    auto body = ElasticBody::make(mesh, material, {.thickness = thickness});
    ASSERT_TRUE(body.ok()) << body.reason();
    for (int j = 0; j <= ny; ++j) {
        if (j == 0)
            ASSERT_TRUE(body->fix(id(0, 0)).ok());
        else
            ASSERT_TRUE(body->constrain_to_line(id(0, j), {0, 1, 0}).ok());
        // the consistent load of a uniform traction: the end nodes carry half a share
        const double share = force / ny * (j == 0 || j == ny ? 0.5 : 1.0);
        ASSERT_TRUE(body->add_force(id(nx, j), {share, 0, 7}).ok());  // z is ignored
    }
    const auto report =
        solve_linear_cg(*body, {.tolerance = 1e-12, .stop = StopCriterion::external_force});
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_TRUE(report->converged);
    const double strain = force / (height * thickness) / material.young;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const Vector3 u = body->displacement(id(i, j));
            EXPECT_NEAR(u[0], strain * length * i / nx, 1e-9 * strain) << i << " " << j;
            EXPECT_NEAR(u[1], -material.poisson * strain * height * j / ny, 1e-9 * strain)
                << i << " " << j;
            EXPECT_EQ(u[2], 0.0);
        }
    // the assembled reference agrees
    body->displacements().setZero();
    for (int j = 0; j <= ny; ++j)
        ASSERT_TRUE(j == 0 ? body->fix(id(0, 0)).ok()
                           : body->constrain_to_line(id(0, j), {0, 1, 0}).ok());
    const auto assembled =
        solve_assembled_cg(*body, {.tolerance = 1e-12, .stop = StopCriterion::external_force});
    ASSERT_TRUE(assembled.ok()) << assembled.reason();
    EXPECT_NEAR(body->displacement(id(nx, ny))[0], strain * length, 1e-9 * strain);
    ASSERT_TRUE(body->write_deformed(mesh).ok());
    EXPECT_NEAR(mesh.deformed(id(nx, ny))[0], length + strain * length, 1e-9);
    EXPECT_TRUE(mesh.validate().ok());
}

// The neo-Hookean forces are the gradient of the neo-Hookean strain energy (central differences
// on random displacements of a fifth of an element's size), for tetrahedra and triangles.
void expect_forces_are_the_energy_gradient(const Mesh& mesh, std::uint64_t seed) {
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    auto body = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3},
                                  {.model = Model::neohookean, .thickness = 0.1});
    ASSERT_TRUE(body.ok()) << body.reason();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-0.2, 0.2);
    Eigen::VectorXd u(static_cast<Eigen::Index>(body->dof_count()));
    for (Eigen::Index i = 0; i < u.size(); ++i)
        u[i] = unit(rng);
    if (body->dimension() == 2)
        for (Eigen::Index i = 2; i < u.size(); i += 3)
            u[i] = 0;
    Eigen::VectorXd g;
    ASSERT_TRUE(body->elastic_forces(u, g));
    const double h = 1e-6;
    for (Eigen::Index i = 0; i < u.size(); i += 7) {
        if (body->dimension() == 2 && i % 3 == 2)
            continue;
        Eigen::VectorXd plus = u, minus = u;
        plus[i] += h;
        minus[i] -= h;
        const double numeric = (body->strain_energy(plus) - body->strain_energy(minus)) / (2 * h);
        EXPECT_NEAR(g[i], numeric, 1e-5 * (std::abs(numeric) + 1e-2 * g.cwiseAbs().maxCoeff()))
            << "unknown " << i;
    }
    // an inverted element: no forces, infinite energy
    Eigen::VectorXd crushed = Eigen::VectorXd::Zero(u.size());
    const Simplex& s = mesh.simplex(0);
    for (int k = 0; k < body->dimension(); ++k)
        crushed[3 * static_cast<Eigen::Index>(s.vertex(0)) + k] =
            2 * (mesh.reference(s.vertex(1))[static_cast<std::size_t>(k)] -
                 mesh.reference(s.vertex(0))[static_cast<std::size_t>(k)]) +
            2 * (mesh.reference(s.vertex(2))[static_cast<std::size_t>(k)] -
                 mesh.reference(s.vertex(0))[static_cast<std::size_t>(k)]);
    EXPECT_FALSE(body->elastic_forces(crushed, g));
    EXPECT_EQ(body->strain_energy(crushed), std::numeric_limits<double>::infinity());
}

TEST(ElasticityNeoHookean, ForcesAreTheEnergyGradient) {
    const std::uint64_t seed = std::random_device{}();
    std::printf("[ seed     ] ElasticityNeoHookean.ForcesAreTheEnergyGradient SXK_SEED=%llu\n",
                static_cast<unsigned long long>(seed));
    expect_forces_are_the_energy_gradient(kuhn_cube(2), seed);
    expect_forces_are_the_energy_gradient(planar_grid(3), seed);
}

// A cube on its floor, pushed sideways and down on top: small loads give the linear answer,
// large ones a different equilibrium that nonlinear CG reaches (projected residual below the
// threshold, energy below that of the linear answer in the neo-Hookean energy).
Outcome<SolveReport> push_cube(ElasticBody& body, const Mesh& mesh, double load,
                               double tolerance = 1e-9) {
    body.displacements().setZero();
    body.clear_forces();
    std::vector<VertexId> top;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.reference(v)[2] == 0 && !body.fix(v).ok())
            return Refusal{RefusalCode::bad_argument, "fix"};
        if (mesh.reference(v)[2] == 3)
            top.push_back(v);
    }
    for (const VertexId v : top)
        if (!body.add_force(v, {load / static_cast<double>(top.size()), 0,
                                -load / static_cast<double>(top.size())})
                 .ok())
            return Refusal{RefusalCode::bad_argument, "force"};
    return solve(
        body,
        {.tolerance = tolerance, .max_iterations = 5000, .stop = StopCriterion::external_force});
}

TEST(ElasticityNeoHookean, SmallLoadsGiveTheLinearAnswer) {
    const Mesh mesh = kuhn_cube(3);
    auto linear = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3});
    auto rubber =
        ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3}, {.model = Model::neohookean});
    ASSERT_TRUE(linear.ok() && rubber.ok());
    // strains of about 1e-6; the neo-Hookean forces mu (F - F^-T) cancel to about 1e-10 of
    // themselves there, so the residual can fall to 1e-6 of the load but not to 1e-9
    const double load = 1e-2;
    auto a = push_cube(*linear, mesh, load, 1e-6);
    auto b = push_cube(*rubber, mesh, load, 1e-6);
    ASSERT_TRUE(a.ok() && b.ok()) << a.reason() << b.reason();
    EXPECT_TRUE(a->converged && b->converged);
    const double scale = linear->displacements().cwiseAbs().maxCoeff();
    EXPECT_LT((linear->displacements() - rubber->displacements()).cwiseAbs().maxCoeff(),
              1e-4 * scale);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ElasticityNeoHookean, LargeLoadsReachANonlinearEquilibrium) {
    Mesh mesh = kuhn_cube(3);
    auto linear = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3});
    auto rubber =
        ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3}, {.model = Model::neohookean});
    ASSERT_TRUE(linear.ok() && rubber.ok());
    const double load = 8e3;  // shear strains of about a third
    auto a = push_cube(*linear, mesh, load);
    auto b = push_cube(*rubber, mesh, load);
    ASSERT_TRUE(a.ok() && b.ok()) << a.reason() << b.reason();
    ASSERT_TRUE(b->converged) << b->residual << " > " << b->threshold;
    std::printf(
        "[ measured ] neo-Hookean cube: %zu iterations, %zu force evaluations; top corner moves "
        "%.4g (linear %.4g)\n",
        b->iterations, b->evaluations, rubber->displacement(mesh.vertex_count() - 1)[0],
        linear->displacement(mesh.vertex_count() - 1)[0]);
    // the answers differ by more than the tolerance, and each is its own model's minimum
    const double scale = linear->displacements().cwiseAbs().maxCoeff();
    EXPECT_GT((linear->displacements() - rubber->displacements()).cwiseAbs().maxCoeff(),
              1e-2 * scale);
    const double at_linear = rubber->strain_energy(linear->displacements()) -
                             rubber->forces().dot(linear->displacements());
    EXPECT_LT(rubber->energy(), at_linear);
    // a relaxation in frames of 3 iterations is the same solve
    Eigen::VectorXd solved = rubber->displacements();
    rubber->displacements().setZero();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.reference(v)[2] == 0) {
            ASSERT_TRUE(rubber->fix(v).ok());
        }
    auto relaxation = NonlinearRelaxation::start(
        *rubber, {.tolerance = 1e-9, .stop = StopCriterion::external_force});
    ASSERT_TRUE(relaxation.ok()) << relaxation.reason();
    while (!relaxation->done())
        relaxation->run(3);
    EXPECT_EQ(relaxation->report().iterations, b->iterations);
    EXPECT_EQ(rubber->displacements(), solved);
    ASSERT_TRUE(rubber->write_deformed(mesh).ok());
    EXPECT_TRUE(mesh.validate().ok());
}

// On a linear body the nonlinear CG finds the linear CG's answer.
TEST(ElasticityNeoHookean, NonlinearCGSolvesALinearBodyToo) {
    const Mesh mesh = kuhn_cube(3);
    auto body = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3});
    ASSERT_TRUE(body.ok());
    ASSERT_TRUE(push_cube(*body, mesh, 10).ok());
    const Eigen::VectorXd expected = body->displacements();
    body->displacements().setZero();
    const auto report =
        solve_nonlinear_cg(*body, {.tolerance = 1e-9, .stop = StopCriterion::external_force});
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_TRUE(report->converged);
    EXPECT_LT((body->displacements() - expected).cwiseAbs().maxCoeff(),
              1e-6 * expected.cwiseAbs().maxCoeff());
}

// A prescribed displacement larger than the elements next to it: at the start (free vertices at
// rest) the top layer is turned inside out, where the neo-Hookean energy is infinite; the solve
// starts from the linear answer instead and reaches the neo-Hookean equilibrium. Squashing the
// cube past its floor inverts elements even in the linear answer: refused.
TEST(ElasticityNeoHookean, LargePrescribedDisplacementsStartFromTheLinearAnswer) {
    Mesh mesh = kuhn_cube(3);
    auto body =
        ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3}, {.model = Model::neohookean});
    ASSERT_TRUE(body.ok()) << body.reason();
    auto press = [&](double down) {
        body->displacements().setZero();
        for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
            if (mesh.reference(v)[2] == 0) {
                EXPECT_TRUE(body->fix(v).ok());
            } else if (mesh.reference(v)[2] == 3) {
                EXPECT_TRUE(body->fix(v, {0, 0, -down}).ok());
            } else {
                EXPECT_TRUE(body->free(v).ok());
            }
        }
        return solve_nonlinear_cg(*body,
                                  {.tolerance = 1e-8, .stop = StopCriterion::with_reactions});
    };
    Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(body->dof_count()));
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.reference(v)[2] == 3)
            at_rest[3 * static_cast<Eigen::Index>(v) + 2] = -1.2;
    Eigen::VectorXd forces;
    EXPECT_FALSE(body->elastic_forces(at_rest, forces));  // the start the solver was given inverts
    const auto squeezed = press(1.2);                     // 40% of the height, more than a layer
    ASSERT_TRUE(squeezed.ok()) << squeezed.reason();
    EXPECT_TRUE(squeezed->converged);
    ASSERT_TRUE(body->write_deformed(mesh).ok());
    const auto flattened = press(3.5);
    EXPECT_EQ(flattened.code(), RefusalCode::would_invert);
    EXPECT_EQ(
        flattened.reason(),
        "elasticity: the prescribed displacements invert an element even in the linear answer, "
        "where the neo-Hookean energy is infinite; prescribe them in smaller steps");
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk::elasticity
