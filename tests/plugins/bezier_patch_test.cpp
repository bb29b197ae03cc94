// Triangular Bézier patches (Roth §4.4): evaluation against the Bernstein sum, subdivision,
// elevation, derivatives, normals with a collapsed edge, and the tensor-to-triangle conversion,
// all checked numerically on random patches (seed printed; SXK_SEED repeats a run).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <random>
#include <string>
#include <vector>

#include "bezier_random.hpp"
#include "core/fixtures.hpp"
#include "de_casteljau.hpp"
#include "read_bpt.hpp"
#include "sxk/io.hpp"
#include "triangular_patch.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {

using test_random::random_patch;
using test_random::random_point;

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }


// The Bernstein sum of the header, term by term.
Point bernstein(const TriangularPatch& patch, const Barycentric& x) {
    const int n = patch.degree();
    Point sum{0, 0, 0};
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n - k; ++j) {
            const int i = n - j - k;
            const double w = factorial(n) / (factorial(i) * factorial(j) * factorial(k)) * std::pow(x[0], i) *
                             std::pow(x[1], j) * std::pow(x[2], k);
            for (int q = 0; q < 3; ++q) sum[q] += w * patch.control_point(j, k)[q];
        }
    return sum;
}

TEST(TriangularPatch, DeCasteljauIsTheBernsteinSum) {
    std::mt19937_64 rng(test::seed_for("TriangularPatch.DeCasteljauIsTheBernsteinSum"));
    for (int degree = 0; degree <= 7; ++degree) {
        const TriangularPatch patch = random_patch(degree, rng);
        for (int sample = 0; sample < 20; ++sample) {
            const Barycentric x = random_point(rng);
            EXPECT_LT(distance(patch.evaluate(x), bernstein(patch, x)), 1e-12) << "degree " << degree;
        }
        // corners are corner control points
        EXPECT_EQ(patch.evaluate({1, 0, 0}), patch.control_point(0, 0));
        EXPECT_EQ(patch.evaluate({0, 0, 1}), patch.control_point(0, degree));
    }
}

TEST(TriangularPatch, SubdivisionReproducesTheSurfaceOverTheSubTriangle) {
    std::mt19937_64 rng(test::seed_for("TriangularPatch.SubdivisionReproducesTheSurfaceOverTheSubTriangle"));
    for (int degree = 1; degree <= 6; ++degree) {
        const TriangularPatch patch = random_patch(degree, rng);
        const Barycentric r = random_point(rng), s = random_point(rng), t = random_point(rng);
        const TriangularPatch part = patch.subdivided(r, s, t);
        for (int sample = 0; sample < 20; ++sample) {
            const Barycentric x = random_point(rng);
            const Barycentric in_whole{x[0] * r[0] + x[1] * s[0] + x[2] * t[0], x[0] * r[1] + x[1] * s[1] + x[2] * t[1],
                                       x[0] * r[2] + x[1] * s[2] + x[2] * t[2]};
            EXPECT_LT(distance(part.evaluate(x), patch.evaluate(in_whole)), 1e-12) << "degree " << degree;
        }
    }
}

// Roth's middle quarter (flat_subdivision) by middle_quarter's line pyramids is the general
// subdivision over (BC, CA, AB).
TEST(TriangularPatch, MiddleQuarterIsTheSubdivisionOverTheMidpoints) {
    std::mt19937_64 rng(
        test::seed_for("TriangularPatch.MiddleQuarterIsTheSubdivisionOverTheMidpoints"));
    for (int degree : {0, 1, 2, 3, 6, 11, 40}) {
        const TriangularPatch patch = random_patch(degree, rng);
        const TriangularPatch expected =
            patch.subdivided({0, 0.5, 0.5}, {0.5, 0, 0.5}, {0.5, 0.5, 0});
        std::vector<Point> got;
        NetScratch scratch;
        middle_quarter(degree, patch.control_points(), got, scratch);
        ASSERT_EQ(got.size(), expected.control_points().size());
        for (std::size_t i = 0; i < got.size(); ++i)
            EXPECT_LT(distance(got[i], expected.control_points()[i]), 1e-13)
                << "degree " << degree << " point " << i;
    }
}

TEST(TriangularPatch, ElevationKeepsTheSurface) {
    std::mt19937_64 rng(test::seed_for("TriangularPatch.ElevationKeepsTheSurface"));
    for (int degree = 0; degree <= 6; ++degree) {
        const TriangularPatch patch = random_patch(degree, rng);
        const TriangularPatch higher = patch.elevated().elevated();
        EXPECT_EQ(higher.degree(), degree + 2);
        for (int sample = 0; sample < 20; ++sample) {
            const Barycentric x = random_point(rng);
            EXPECT_LT(distance(higher.evaluate(x), patch.evaluate(x)), 1e-12);
        }
    }
}

TEST(TriangularPatch, DerivativeMatchesCentralDifferences) {
    std::mt19937_64 rng(test::seed_for("TriangularPatch.DerivativeMatchesCentralDifferences"));
    const TriangularPatch patch = random_patch(5, rng);
    const Barycentric x{0.3, 0.3, 0.4}, d{-1, 1, 0};
    const double h = 1e-5;
    const Point plus = patch.evaluate({x[0] - h, x[1] + h, x[2]}), minus = patch.evaluate({x[0] + h, x[1] - h, x[2]});
    const Point derivative = patch.derivative(x, d);
    for (int q = 0; q < 3; ++q) EXPECT_NEAR(derivative[q], (plus[q] - minus[q]) / (2 * h), 1e-7);
}

// A flat quadratic patch (z = 0) whose control points b_200, b_110 and b_101 coincide: both
// edges leave that corner with zero speed, the derivatives vanish there and the normal is the
// limit from inside, the z axis (as at the teapot's lid knob, where an edge collapses).
TEST(TriangularPatch, NormalAtACollapsedCornerIsTheLimitFromInside) {
    const TriangularPatch patch(2, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const Point corner = patch.normal({1, 0, 0});
    EXPECT_NEAR(std::abs(corner[2]), 1.0, 1e-9);
    const Point inside = patch.normal({0.2, 0.3, 0.5});
    EXPECT_NEAR(corner[2], inside[2], 1e-9);  // the same side
}

TEST(TriangularPatch, RefusesAWrongNumberOfControlPoints) {
    try {
        TriangularPatch(2, std::vector<Point>(5));
        FAIL() << "no throw";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "TriangularPatch: degree 2 needs 6 control points, not 5");
    }
}

// The conversion as it was before issue 12 (one tensor blossom per term, by de Casteljau; 2.5 s
// for a 20 x 20 patch), kept as the oracle of the fast one: Q(x) = P(A x_r + B x_s + C x_t) has
// total degree m + n, and its control point c_ijk over the triangle A B C is the average of the
// tensor blossom over the ways to give m of its m + n arguments (i copies of A, j of B, k of C)
// to u and the rest to v.
Point tensor_blossom(const TensorPatch& patch, const std::vector<double>& us,
                     const std::vector<double>& vs) {
    const int m = patch.degree_u, n = patch.degree_v;
    std::vector<Point> column(n + 1), row(m + 1);
    for (int b = 0; b <= n; ++b) {
        for (int a = 0; a <= m; ++a)
            row[a] = patch.points[a * (n + 1) + b];
        for (int level = m; level > 0; --level)
            for (int a = 0; a < level; ++a)
                for (int q = 0; q < 3; ++q)
                    row[a][q] = (1 - us[m - level]) * row[a][q] + us[m - level] * row[a + 1][q];
        column[b] = row[0];
    }
    for (int level = n; level > 0; --level)
        for (int b = 0; b < level; ++b)
            for (int q = 0; q < 3; ++q)
                column[b][q] =
                    (1 - vs[n - level]) * column[b][q] + vs[n - level] * column[b + 1][q];
    return column[0];
}

double binomial(int n, int k) {
    return factorial(n) / (factorial(k) * factorial(n - k));
}

TriangularPatch half_by_blossoms(const TensorPatch& patch,
                                 const std::array<std::array<double, 2>, 3>& corners) {
    const int m = patch.degree_u, n = patch.degree_v, degree = m + n;
    std::vector<Point> points((degree + 1) * (degree + 2) / 2);
    for (int k = 0; k <= degree; ++k)
        for (int j = 0; j <= degree - k; ++j) {
            const int i = degree - j - k;
            const std::array<int, 3> copies{i, j, k};
            Point sum{0, 0, 0};
            for (int a = 0; a <= std::min(i, m); ++a)
                for (int b = 0; b <= std::min(j, m - a); ++b) {
                    const int c = m - a - b;
                    if (c > k)
                        continue;
                    const std::array<int, 3> to_u{a, b, c};
                    std::vector<double> us, vs;
                    for (int corner = 0; corner < 3; ++corner) {
                        us.insert(us.end(), to_u[corner], corners[corner][0]);
                        vs.insert(vs.end(), copies[corner] - to_u[corner], corners[corner][1]);
                    }
                    const double weight =
                        binomial(i, a) * binomial(j, b) * binomial(k, c) / binomial(degree, m);
                    const Point f = tensor_blossom(patch, us, vs);
                    for (int q = 0; q < 3; ++q)
                        sum[q] += weight * f[q];
                }
            points[TriangularPatch::index(degree, j, k)] = sum;
        }
    return TriangularPatch(degree, points);
}

TensorPatch random_tensor_patch(int m, int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> coordinate(-1, 1);
    TensorPatch patch{m, n, std::vector<Point>((m + 1) * (n + 1))};
    for (Point& p : patch.points)
        p = {coordinate(rng), coordinate(rng), coordinate(rng)};
    return patch;
}

// The fast conversion (products of Bernstein polynomials) gives the control points the blossoms
// gave, on random patches of every degree pair up to 8 x 8 and a few larger ones (the blossoms
// take 0.3 s for 10 x 10; 20 x 20 is checked against the tensor patch below).
TEST(TensorPatch, ConversionMatchesTheBlossomConversion) {
    std::mt19937_64 rng(test::seed_for("TensorPatch.ConversionMatchesTheBlossomConversion"));
    std::vector<std::pair<int, int>> degrees{{10, 10}, {12, 3}, {0, 14}, {14, 0}};
    for (int m = 0; m <= 8; ++m)
        for (int n = 0; n <= 8; ++n)
            degrees.emplace_back(m, n);
    double worst = 0;
    for (const auto& [m, n] : degrees) {
        const TensorPatch patch = random_tensor_patch(m, n, rng);
        const auto halves = to_triangular(patch);
        const std::array<TriangularPatch, 2> expected{
            half_by_blossoms(patch, {{{0, 0}, {1, 0}, {1, 1}}}),
            half_by_blossoms(patch, {{{0, 0}, {1, 1}, {0, 1}}})};
        for (std::size_t h = 0; h < 2; ++h) {
            ASSERT_EQ(halves[h].degree(), m + n);
            for (std::size_t i = 0; i < expected[h].control_points().size(); ++i) {
                const double error =
                    distance(halves[h].control_points()[i], expected[h].control_points()[i]);
                worst = std::max(worst, error);
                EXPECT_LT(error, 1e-12) << m << "x" << n << " half " << h << " point " << i;
            }
        }
    }
    std::cout << "worst difference from the blossom conversion: " << worst << '\n';
}

// Goldman–Filip: the two triangular halves of degree m + n reproduce the tensor patch.
TEST(TensorPatch, TwoTriangularHalvesReproduceIt) {
    std::mt19937_64 rng(test::seed_for("TensorPatch.TwoTriangularHalvesReproduceIt"));
    std::uniform_real_distribution<double> unit(0, 1);
    for (const auto& [m, n] : std::vector<std::pair<int, int>>{
             {3, 3}, {1, 2}, {2, 4}, {0, 3}, {20, 20}, {20, 7}, {0, 20}}) {
        const TensorPatch patch = random_tensor_patch(m, n, rng);
        const auto halves = to_triangular(patch);
        EXPECT_EQ(halves[0].degree(), m + n);
        for (int sample = 0; sample < 200; ++sample) {
            const double u = unit(rng), v = unit(rng);
            const Point expected = patch.evaluate(u, v);
            // (u, v) = r (0,0) + s (1,0) + t (1,1) for u >= v, r (0,0) + s (1,1) + t (0,1) else
            const Point got = u >= v ? halves[0].evaluate({1 - u, u - v, v}) : halves[1].evaluate({1 - v, u, v - u});
            EXPECT_LT(distance(got, expected), 1e-12) << m << "x" << n << " at " << u << ", " << v;
        }
    }
}

// The teapot (tests/data/teapot.bpt): 32 bicubic patches become 64 sextic triangular ones
// (Roth §6.4) that reproduce them.
TEST(TensorPatch, TeapotBecomes64SexticTriangularPatches) {
    const std::vector<TensorPatch> teapot = read_bpt(SXK_TEST_DATA_DIR "/teapot.bpt");
    ASSERT_EQ(teapot.size(), 32u);
    std::size_t triangular = 0;
    double worst = 0;
    for (const TensorPatch& patch : teapot) {
        ASSERT_EQ(patch.degree_u, 3);
        ASSERT_EQ(patch.degree_v, 3);
        const auto halves = to_triangular(patch);
        for (const TriangularPatch& half : halves) {
            EXPECT_EQ(half.degree(), 6);
            ++triangular;
            // a unit normal everywhere, the collapsed lid and bottom corners included
            for (const Barycentric& corner : {Barycentric{1, 0, 0}, Barycentric{0, 1, 0}, Barycentric{0, 0, 1}}) {
                const Point normal = half.normal(corner);
                EXPECT_NEAR(std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]), 1.0, 1e-12);
            }
        }
        for (int a = 0; a <= 10; ++a)
            for (int b = 0; b <= 10; ++b) {
                const double u = a / 10.0, v = b / 10.0;
                const Point got = u >= v ? halves[0].evaluate({1 - u, u - v, v}) : halves[1].evaluate({1 - v, u, v - u});
                worst = std::max(worst, distance(got, patch.evaluate(u, v)));
            }
    }
    EXPECT_EQ(triangular, 64u);
    EXPECT_LT(worst, 1e-12);
    // the list form: patch p's halves are 2p and 2p + 1
    const std::vector<TriangularPatch> all = to_triangular(teapot);
    ASSERT_EQ(all.size(), 64u);
    for (std::size_t p = 0; p < teapot.size(); ++p) {
        const auto halves = to_triangular(teapot[p]);
        for (std::size_t h = 0; h < 2; ++h)
            EXPECT_TRUE(std::equal(halves[h].control_points().begin(), halves[h].control_points().end(),
                                   all[2 * p + h].control_points().begin()));
    }
}

TEST(ReadBpt, RefusesMalformedFilesNamingTheLine) {
    const auto dir = std::filesystem::temp_directory_path() / ("sxk-bpt-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    auto expect_error = [&](const std::string& text, const std::string& message) {
        const auto file = dir / "bad.bpt";
        std::ofstream(file) << text;
        try {
            (void)read_bpt(file);
            ADD_FAILURE() << "no error for: " << text;
        } catch (const InputError& error) {
            EXPECT_EQ(std::string(error.what()), file.string() + ":" + message);
        }
    };
    expect_error("", "0: unexpected end of file, expected the patch count");
    expect_error("0\n", "1: patch count 0 is not in 1..1000000");
    expect_error("1\n1 1\n0 0 0\n1 0 0\n0 1 0\n", "5: unexpected end of file, expected a point x y z");
    expect_error("1\n1 x\n", "2: expected two degrees");
    expect_error("1\n0 0\n0 0 nan\n", "3: expected a point x y z");
    expect_error("1\n0 0\n0 0 0 4\n", "3: unexpected '4' after a point x y z");
    expect_error("1\n0 0\n0 0 0\n7\n", "4: trailing data after 1 patches");
    expect_error("1\n21 0\n", "2: degrees 21 0 are not in 0..20");
    expect_error(std::string("1\n0 0\n0 0\0 0\n", 12), "3: binary data (byte 0x00)");
    std::filesystem::remove_all(dir);
}

// A .bpt file is read as mesh files are (sxk::read_text_file): a byte order mark is dropped, and
// what is not a file is refused instead of being read as an empty one.
TEST(ReadBpt, ReadsLikeAMeshFile) {
    const auto dir = std::filesystem::temp_directory_path() / ("sxk-bpt-bom-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir / "folder.bpt");
    std::ofstream(dir / "bom.bpt") << "\xEF\xBB\xBF" "1\n0 0\n1 2 3\n";
    const std::vector<TensorPatch> patches = read_bpt(dir / "bom.bpt");
    ASSERT_EQ(patches.size(), 1u);
    EXPECT_EQ(patches[0].points, (std::vector<Point>{{1, 2, 3}}));
    std::istringstream stream("\xEF\xBB\xBF" "1\n0 0\n4 5 6\n");
    EXPECT_EQ(read_bpt(stream, "s.bpt")[0].points, (std::vector<Point>{{4, 5, 6}}));
    for (const auto& [file, reason] : std::vector<std::pair<std::string, std::string>>{
             {(dir / "folder.bpt").string(), "is a directory"},
             {"/dev/zero", "is a character device, not a file"},
             {(dir / "none.bpt").string(), "no such file"}}) {
        try {
            (void)read_bpt(file);
            ADD_FAILURE() << file << " was read";
        } catch (const InputError& error) {
            EXPECT_EQ(std::string(error.what()), file + ":0: " + reason);
        }
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sxk::bezier
