// Rays and ray hits shared by the Bézier clipping intersector (bezier_clipping.hpp), the Embree
// scene (patch_scene.hpp), the reference intersector and the renderer.
#pragma once

#include <limits>

#include "triangular_patch.hpp"

namespace sxk::bezier {

// r(u) = origin + u direction for u in [t_near, t_far]; direction need not be unit (t is then
// measured in multiples of it), but every intersector here is exercised with unit directions.
struct Ray {
    Point origin{};
    Point direction{0, 0, 1};
    double t_near = 0;
    double t_far = std::numeric_limits<double>::infinity();
};

// A ray meeting one patch: the ray parameter, the domain point of the patch (barycentric
// coordinates (r, s, t) of the patch it was asked about) and the patch's unit normal there
// (TriangularPatch::normal: D_u x D_v, not turned toward the ray).
struct PatchHit {
    double t = 0;
    Barycentric at{};
    Point normal{};
};

}  // namespace sxk::bezier
