// Ray–patch intersection by triangular Bézier clipping (Roth's thesis §6.2–6.4). The ray becomes
// two orthogonal planes (eq. 6.2); the patch's signed distances to them are a 2D patch d (eq. 6.4)
// whose zero is the hit. Each iteration projects the distances to the lines L_r, L_s, L_t along
// the three parameter directions, finds r_min, s_min, t_min where the convex hulls of the
// projections reach the axis (§6.2.4: upper and lower hulls), and keeps the sub-triangle
// r >= r_min, s >= s_min, t >= t_min (eq. 6.5); a patch that clipped too little
// (r_min + s_min + t_min < 0.5) is split into four. It stops when the candidate domain is small,
// then polishes (r, s) with a few Newton steps. Collapsed edges (the teapot's knob) take the
// line L through the neighbouring control points (§6.4).
#pragma once

#include <optional>

#include "ray.hpp"

namespace sxk::bezier {

struct ClippingOptions {
    // Stop clipping when the candidate sub-triangle is smaller than this in every barycentric
    // coordinate of the patch's domain. Newton then converges quadratically from the candidate's
    // centroid (1e-4 -> 1e-8 -> 1e-16); a candidate it cannot polish is clipped on, 1000x finer.
    double parametric_tolerance = 1e-4;
    // At most this many Newton steps on (r, s) after clipping stopped (fewer once converged).
    int newton_steps = 4;
    // A reported hit b(r, s, t) lies this close to the ray (relative to the diagonal of the box
    // of the patch's control points) and inside the domain (Newton's point clamped to it, so that
    // rays through the shared edge of two patches hit one of them); a candidate Newton cannot
    // bring this close is clipped on with a finer tolerance.
    double distance_tolerance = 1e-10;
    // Bound on clipping and splitting iterations per ray: the nearest hit found until then.
    int max_iterations = 4096;
};

// The nearest hit of the ray with the patch in [ray.t_near, ray.t_far], if any. A ray that
// grazes the patch crosses it twice close together; when both crossings lie in one candidate
// cell (parametric_tolerance), Newton may give the farther (tests/plugins/bezier_clipping_test.cpp
// met one at cos 3.6e-4 between the ray and the normal: 3e-5 beyond the nearest in t).
std::optional<PatchHit> intersect(const TriangularPatch& patch, const Ray& ray,
                                  const ClippingOptions& options = {});

}  // namespace sxk::bezier
