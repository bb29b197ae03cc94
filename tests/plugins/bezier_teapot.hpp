// What the Bézier tests share about the teapot and rays: Newell's teapot as triangular patches
// (tests/data/teapot.bpt), and the point a ray reaches at a parameter.
#pragma once

#include <vector>

#include "ray.hpp"
#include "read_bpt.hpp"
#include "triangular_patch.hpp"

namespace sxk::bezier::test_teapot {

inline std::vector<TriangularPatch> teapot() { return to_triangular(read_bpt(SXK_TEST_DATA_DIR "/teapot.bpt")); }

inline Point along(const Ray& ray, double t) {
    return {ray.origin[0] + t * ray.direction[0], ray.origin[1] + t * ray.direction[1],
            ray.origin[2] + t * ray.direction[2]};
}

}  // namespace sxk::bezier::test_teapot
