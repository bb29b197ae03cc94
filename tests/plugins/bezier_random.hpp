// Random inputs the Bézier tests share: domain points and control nets, from a seeded generator
// (test::seed_for prints the seed).
#pragma once

#include <random>
#include <vector>

#include "triangular_patch.hpp"

namespace sxk::bezier::test_random {

// A point of the domain triangle, uniformly distributed.
inline Barycentric random_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    double r = unit(rng), s = unit(rng);
    if (r + s > 1) r = 1 - r, s = 1 - s;
    return {r, s, 1 - r - s};
}

// A patch of the given degree whose control points are uniform in [-1, 1]^3.
inline TriangularPatch random_patch(int degree, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> coordinate(-1, 1);
    std::vector<Point> points(static_cast<std::size_t>((degree + 1) * (degree + 2) / 2));
    for (Point& p : points) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
    return TriangularPatch(degree, points);
}

}  // namespace sxk::bezier::test_random
