// ElasticBody and its solvers (plugins/elasticity): the element against an independent
// formulation, the properties of K, the patch test, constraints, the assembled reference, and
// the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <tbb/task_arena.h>
#include <Eigen/Dense>

#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"

namespace sxk::elasticity {
namespace {

std::uint64_t fresh_seed() {
    const std::uint64_t seed = std::random_device{}();
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    return seed;
}

// The unit cube in n^3 Kuhn cells.
Mesh unit_cube(int n) {
    auto made = make_kuhn_cube(n, 1.0 / n);
    EXPECT_TRUE(made.ok()) << made.reason();
    return std::move(*made);
}

// The textbook linear tetrahedron: K = V B^T D B with B from the shape functions' gradients and D
// the isotropic matrix in Voigt notation (xx, yy, zz, yz, xz, xy; engineering shears).
Eigen::Matrix<double, 12, 12> voigt_stiffness(const std::array<Point, 4>& x, double young,
                                              double poisson) {
    Eigen::Matrix4d m;
    for (int a = 0; a < 4; ++a)
        m.row(a) << 1, x[a][0], x[a][1], x[a][2];
    const double volume = std::abs(m.determinant()) / 6;
    const Eigen::Matrix4d c = m.inverse();  // column a: the coefficients of shape function a
    Eigen::Matrix<double, 6, 12> b = Eigen::Matrix<double, 6, 12>::Zero();
    for (int a = 0; a < 4; ++a) {
        const double gx = c(1, a), gy = c(2, a), gz = c(3, a);
        b(0, 3 * a) = gx;
        b(1, 3 * a + 1) = gy;
        b(2, 3 * a + 2) = gz;
        b(3, 3 * a + 1) = gz;
        b(3, 3 * a + 2) = gy;
        b(4, 3 * a) = gz;
        b(4, 3 * a + 2) = gx;
        b(5, 3 * a) = gy;
        b(5, 3 * a + 1) = gx;
    }
    const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson)),
                 mu = young / (2 * (1 + poisson));
    Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
    d.topLeftCorner<3, 3>().setConstant(lambda);
    d.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
    d.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
    return volume * b.transpose() * d * b;
}

TEST(ElasticityBody, ElementStiffnessIsTheTextbookOne) {
    const std::uint64_t seed = fresh_seed();
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    for (int trial = 0; trial < 20; ++trial) {
        std::array<Point, 4> x;
        for (auto& p : x)
            p = {coordinate(random), coordinate(random), coordinate(random)};
        Mesh mesh(3, 3);
        for (const Point& p : x)
            mesh.add_vertex(p);
        const Eigen::Matrix3d z{{x[1][0] - x[0][0], x[2][0] - x[0][0], x[3][0] - x[0][0]},
                                {x[1][1] - x[0][1], x[2][1] - x[0][1], x[3][1] - x[0][1]},
                                {x[1][2] - x[0][2], x[2][2] - x[0][2], x[3][2] - x[0][2]}};
        if (std::abs(z.determinant()) < 1e-3)
            continue;  // too flat for a 1e-9 comparison
        ASSERT_TRUE(mesh.assign_elements(std::vector<Simplex>{
                                             Simplex(z.determinant() > 0 ? 1 : -1, {0, 1, 2, 3})})
                        .ok());
        ASSERT_TRUE(mesh.validate().ok());
        auto body = ElasticBody::make(mesh, {.young = 2.5e3, .poisson = 0.3});
        ASSERT_TRUE(body.ok()) << body.reason();
        const Eigen::Matrix<double, 12, 12> ours = body->element_stiffness(0);
        const Eigen::Matrix<double, 12, 12> textbook = voigt_stiffness(x, 2.5e3, 0.3);
        EXPECT_LT((ours - textbook).norm(), 1e-9 * textbook.norm())
            << "trial " << trial << ", seed " << seed;
    }
}

TEST(ElasticityBody, StiffnessIsSymmetricAndRigidMotionsCostNothing) {
    const Mesh mesh = unit_cube(3);
    auto body = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.35});
    ASSERT_TRUE(body.ok()) << body.reason();
    const Eigen::SparseMatrix<double> k = assemble_stiffness(*body);
    const double scale = k.norm();
    EXPECT_LT(Eigen::SparseMatrix<double>(k - Eigen::SparseMatrix<double>(k.transpose())).norm(),
              1e-13 * scale);
    const auto n = static_cast<Eigen::Index>(body->dof_count());
    const Eigen::Vector3d omega(0.3, -0.2, 0.7), shift(1, -2, 0.5);
    Eigen::VectorXd translation(n), rotation(n), out;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Eigen::Vector3d p(mesh.reference(v)[0], mesh.reference(v)[1], mesh.reference(v)[2]);
        translation.segment<3>(3 * v) = shift;
        rotation.segment<3>(3 * v) = omega.cross(p);  // an infinitesimal rotation
    }
    body->multiply(translation, out);
    EXPECT_LT(out.norm(), 1e-12 * scale * translation.norm());
    body->multiply(rotation, out);
    EXPECT_LT(out.norm(), 1e-12 * scale * rotation.norm());
}

TEST(ElasticityBody, MatrixFreeProductIsTheAssembledOne) {
    const std::uint64_t seed = fresh_seed();
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal;
    const Mesh mesh = unit_cube(5);
    auto body = ElasticBody::make(mesh, {.young = 3e5, .poisson = 0.45});
    ASSERT_TRUE(body.ok()) << body.reason();
    Eigen::VectorXd d(static_cast<Eigen::Index>(body->dof_count())), ours;
    for (Eigen::Index i = 0; i < d.size(); ++i)
        d[i] = normal(random);
    body->multiply(d, ours);
    const Eigen::VectorXd assembled = assemble_stiffness(*body) * d;
    EXPECT_LT((ours - assembled).norm(), 1e-12 * assembled.norm()) << "seed " << seed;
}

// The same product, bit for bit, on one thread and on two: the sums per vertex have a fixed order.
TEST(ElasticityBody, ProductDoesNotDependOnTheThreadCount) {
    const Mesh mesh = unit_cube(12);
    auto body = ElasticBody::make(mesh, {.young = 1, .poisson = 0.25});
    ASSERT_TRUE(body.ok()) << body.reason();
    Eigen::VectorXd d(static_cast<Eigen::Index>(body->dof_count())), one, two;
    for (Eigen::Index i = 0; i < d.size(); ++i)
        d[i] = std::sin(0.37 * static_cast<double>(i));
    tbb::task_arena(1).execute([&] { body->multiply(d, one); });
    tbb::task_arena(2).execute([&] { body->multiply(d, two); });
    EXPECT_EQ(one, two);
}

// Linear elements represent a linear displacement field exactly: prescribe u = A x + c on the
// boundary and the interior follows it.
TEST(ElasticityBody, PassesThePatchTest) {
    const Mesh mesh = unit_cube(4);
    auto body = ElasticBody::make(mesh, {.young = 2e3, .poisson = 0.3});
    ASSERT_TRUE(body.ok()) << body.reason();
    const Eigen::Matrix3d a{{1e-3, 2e-4, -3e-4}, {-1e-4, -5e-4, 4e-4}, {3e-4, 1e-4, 2e-3}};
    const Eigen::Vector3d c(1e-3, -2e-3, 5e-4);
    auto field = [&](VertexId v) {
        const Eigen::Vector3d p(mesh.reference(v)[0], mesh.reference(v)[1], mesh.reference(v)[2]);
        return Eigen::Vector3d(a * p + c);
    };
    std::size_t interior = 0;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& p = mesh.reference(v);
        const bool boundary =
            std::min({p[0], p[1], p[2]}) < 1e-12 || std::max({p[0], p[1], p[2]}) > 1 - 1e-12;
        if (boundary) {
            const Eigen::Vector3d u = field(v);
            ASSERT_TRUE(body->fix(v, {u[0], u[1], u[2]}).ok());
        } else {
            ++interior;
        }
    }
    EXPECT_EQ(interior, 27u);
    const auto report = solve_linear_cg(*body, {.tolerance = 1e-12});
    ASSERT_TRUE(report.ok()) << report.reason();
    EXPECT_TRUE(report->converged);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Vector3 u = body->displacement(v);
        const Eigen::Vector3d expected = field(v);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(u[static_cast<std::size_t>(k)], expected[k], 1e-12) << v;
    }
}

// Fixed vertices, vertices on lines and loads: the matrix-free CG and Eigen's assembled CG find
// the same displacements, and each constraint holds exactly.
TEST(ElasticityBody, ConstrainedSolveMatchesTheAssembledReference) {
    const std::uint64_t seed = fresh_seed();
    const Mesh mesh = unit_cube(5);
    auto setup = [&](ElasticBody& body) {
        std::mt19937_64 again(seed);
        std::normal_distribution<double> n01;
        for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
            const Point& p = mesh.reference(v);
            if (p[2] == 0) {
                ASSERT_TRUE(body.fix(v).ok());
            } else if (p[2] > 1 - 1e-12 && v % 3 == 0) {
                ASSERT_TRUE(
                    body.constrain_to_line(v, {n01(again), n01(again), n01(again)}, {0, 0, 1e-3})
                        .ok());
            } else if (v % 7 == 0) {
                ASSERT_TRUE(body.add_force(v, {n01(again), n01(again), n01(again)}).ok());
            }
        }
    };
    auto matrix_free = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3});
    auto assembled = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3});
    ASSERT_TRUE(matrix_free.ok() && assembled.ok());
    setup(*matrix_free);
    setup(*assembled);
    const SolveOptions options{.tolerance = 1e-11};
    const auto ours = solve_linear_cg(*matrix_free, options);
    const auto reference = solve_assembled_cg(*assembled, options);
    ASSERT_TRUE(ours.ok() && reference.ok());
    EXPECT_TRUE(ours->converged);
    EXPECT_TRUE(reference->converged);
    std::printf("iterations: matrix-free %zu, Eigen (Jacobi) %zu\n", ours->iterations,
                reference->iterations);
    const Eigen::VectorXd& u = matrix_free->displacements();
    EXPECT_LT((u - assembled->displacements()).norm(), 1e-8 * u.norm()) << "seed " << seed;
    EXPECT_NEAR(ours->energy, reference->energy, 1e-9 * std::abs(reference->energy));
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Vector3 d = matrix_free->displacement(v);
        if (matrix_free->freedom(v) == Freedom::fixed) {
            EXPECT_EQ(d, (Vector3{0, 0, 0})) << v;
        } else if (matrix_free->freedom(v) == Freedom::line) {
            const Eigen::Vector3d along(d[0], d[1], d[2] - 1e-3);
            const Vector3 l = matrix_free->line_direction(v);
            EXPECT_LT(along.cross(Eigen::Vector3d(l[0], l[1], l[2])).norm(), 1e-15) << v;
        }
    }
}

// A solved body solves again in no iteration; a small change in the load from there takes fewer
// iterations than from rest.
TEST(ElasticityBody, WarmStartSavesIterations) {
    const Mesh mesh = unit_cube(6);
    auto body = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.25});
    ASSERT_TRUE(body.ok()) << body.reason();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& p = mesh.reference(v);
        if (p[0] == 0) {
            ASSERT_TRUE(body->fix(v).ok());
        }
        if (p[0] > 1 - 1e-12) {
            ASSERT_TRUE(body->add_force(v, {0, 0, -1}).ok());
        }
    }
    const SolveOptions options{.tolerance = 1e-6, .stop = StopCriterion::external_force};
    const auto cold = solve_linear_cg(*body, options);
    ASSERT_TRUE(cold.ok() && cold->converged);
    const auto again = solve_linear_cg(*body, options);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->iterations, 0u);
    ASSERT_TRUE(body->add_force(static_cast<VertexId>(mesh.vertex_count() - 1), {0, 0.5, 0}).ok());
    const auto warm = solve_linear_cg(*body, options);
    ASSERT_TRUE(warm.ok() && warm->converged);
    body->displacements().setZero();
    const auto from_rest = solve_linear_cg(*body, options);
    ASSERT_TRUE(from_rest.ok() && from_rest->converged);
    std::printf("iterations: cold %zu, warm %zu, from rest %zu\n", cold->iterations,
                warm->iterations, from_rest->iterations);
    EXPECT_LT(warm->iterations, from_rest->iterations);
}

// The relaxation a few iterations per frame (LinearRelaxation) is the solve, bit for bit.
TEST(ElasticityBody, RelaxationInStepsIsTheSolve) {
    const Mesh mesh = unit_cube(4);
    auto setup = [&](ElasticBody& body) {
        for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
            const Point& p = mesh.reference(v);
            if (p[1] == 0) {
                ASSERT_TRUE(body.fix(v).ok());
            } else if (p[1] == 1) {
                ASSERT_TRUE(body.add_force(v, {0.1, 1, -0.2}).ok());
            }
        }
    };
    auto whole = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3});
    auto framed = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3});
    ASSERT_TRUE(whole.ok() && framed.ok());
    setup(*whole);
    setup(*framed);
    const SolveOptions options{.tolerance = 1e-9};
    const auto solved = solve_linear_cg(*whole, options);
    ASSERT_TRUE(solved.ok() && solved->converged);
    auto relaxation = LinearRelaxation::start(*framed, options);
    ASSERT_TRUE(relaxation.ok()) << relaxation.reason();
    int frames = 0;
    while (!relaxation->done()) {
        relaxation->run(7);
        ++frames;
        ASSERT_LT(frames, 10000);
    }
    const SolveReport report = relaxation->report();
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.iterations, solved->iterations);
    EXPECT_EQ(frames, static_cast<int>((solved->iterations + 6) / 7));
    EXPECT_EQ(report.history, solved->history);
    EXPECT_EQ(framed->displacements(), whole->displacements());
    EXPECT_EQ(report.energy, solved->energy);
    EXPECT_TRUE(relaxation->run(5));  // converged already: nothing more happens
    EXPECT_EQ(relaxation->report().iterations, solved->iterations);
}

TEST(ElasticityBody, RefusesWhatItCannotSolve) {
    Mesh surface(2, 3);
    surface.add_vertex({0, 0, 0});
    surface.add_vertex({1, 0, 0});
    surface.add_vertex({0, 1, 1});
    ASSERT_TRUE(surface.assign_elements(std::vector<Simplex>{Simplex(1, {0, 1, 2})}).ok());
    auto curved = ElasticBody::make(surface, {});
    EXPECT_EQ(curved.code(), RefusalCode::wrong_dimension);
    EXPECT_EQ(curved.reason(),
              "elasticity: the mesh has 2-dimensional elements in 3-dimensional space; the body "
              "needs tetrahedra in "
              "space or triangles in the plane");
    Mesh triangles(2, 2);
    triangles.add_vertex({0, 0, 0});
    triangles.add_vertex({1, 0, 0});
    triangles.add_vertex({0, 1, 0});
    ASSERT_TRUE(triangles.assign_elements(std::vector<Simplex>{Simplex(1, {0, 1, 2})}).ok());
    EXPECT_EQ(ElasticBody::make(triangles, {}, {.thickness = 0}).reason(),
              "elasticity: the thickness 0 is not positive and finite");
    auto planar = ElasticBody::make(triangles, {});
    ASSERT_TRUE(planar.ok()) << planar.reason();
    EXPECT_EQ(planar->constrain_to_line(0, {0, 1, 1}).reason(),
              "elasticity: constrain_to_line: a planar body's line must lie in the plane "
              "(direction z = 0)");

    const Mesh mesh = unit_cube(2);
    EXPECT_EQ(ElasticBody::make(mesh, {.young = 0}).reason(),
              "elasticity: Young's modulus 0 is not positive and finite");
    EXPECT_EQ(ElasticBody::make(mesh, {.young = 0}).code(), RefusalCode::bad_argument);
    EXPECT_EQ(ElasticBody::make(mesh, {.poisson = 0.5}).reason(),
              "elasticity: Poisson's ratio 0.5 is not in (-1, 0.5)");

    Mesh flat(3, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}, Point{1, 1, 0}})
        flat.add_vertex(p);
    ASSERT_TRUE(flat.assign_elements(std::vector<Simplex>{Simplex(1, {0, 1, 2, 3})})
                    .ok());  // the kernel allows flat elements
    EXPECT_EQ(ElasticBody::make(flat, {}).reason(),
              "elasticity: element 0 is flat at rest (its stiffness is undefined)");
    EXPECT_EQ(ElasticBody::make(flat, {}).code(), RefusalCode::would_flatten);

    auto body = ElasticBody::make(mesh, {});
    ASSERT_TRUE(body.ok()) << body.reason();
    EXPECT_EQ(body->fix(27).reason(), "elasticity: fix: 27 is not a vertex of an element");
    EXPECT_EQ(body->fix(27).code(), RefusalCode::not_found);
    EXPECT_EQ(body->add_force(0, {0, NAN, 0}).reason(),
              "elasticity: add_force: the force is not finite");
    EXPECT_EQ(body->constrain_to_line(0, {0, 0, 0}).code(), RefusalCode::bad_argument);
    const auto unconstrained = solve_linear_cg(*body);
    EXPECT_EQ(unconstrained.code(), RefusalCode::bad_argument);
    EXPECT_EQ(unconstrained.reason(),
              "elasticity: no vertex is constrained, so the body can move freely and its stiffness "
              "matrix is singular; "
              "fix at least three non-collinear vertices of every connected part");
    EXPECT_EQ(solve_assembled_cg(*body).reason(), unconstrained.reason());
    EXPECT_EQ(LinearRelaxation::start(*body).reason(), unconstrained.reason());
}

}  // namespace
}  // namespace sxk::elasticity
