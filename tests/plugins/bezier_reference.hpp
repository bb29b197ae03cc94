// The reference intersector of issue 5's "no missed hits" test: a ray against triangular Bézier
// patches by dense subdivision to flatness `tolerance` (world units; the test takes 1e-7 x the
// box diagonal) and exact ray/triangle tests. Test-side only: it is the oracle the plug-in's
// Bézier clipping + Embree scene is checked against, so it shares none of their subdivision
// or intersection code (only the patch type and sxk::orient3d).
//
// Every patch is bisected uniformly to `depth` levels (newest-vertex bisection: the edge opposite
// the newest corner is halved), and the segment of the ray is tested against the triangle of the
// corners of each leaf with exact orientation tests (sxk::orient3d, CGAL's exact predicates).
//
//        P0                       a node (P0, P1, P2), P0 its newest corner, is halved at the
//       /  \                      midpoint m of P1 P2 into (m, P0, P1) and (m, P2, P0); after
//      / A  \ B                   2k levels every edge of the patch is cut into 2^k equal
//     P1 --- m --- P2             parametric pieces, so the leaves of neighbouring nodes, and of
//                                 neighbouring patches that share a boundary curve, share their
//                                 corners: the leaf triangles form a surface without cracks.
//
// (Stopping each node as soon as it is flat would leave T-junctions between leaves of different
// depths: cracks up to 2 x tolerance wide, through which a ray on the surface could pass.)
//
// Lazy per ray: only the nodes whose control-point box the segment meets are subdivided (the
// convex hull property makes this pruning exact; boxes are widened by 1e-12 x the diagonal so
// that rounding never prunes a node the segment touches). The result is the one a dense
// subdivision of every patch to `depth` would give, only evaluated where the ray goes.
//
// Contract: the leaves' triangles lie within `tolerance` of the patches when every leaf's control
// net lies within `tolerance` of the linear patch of its corners (then |b(x) - L(x)| <= tolerance
// for every x of the leaf, and Roth's height, §6.4, is at most 2 x tolerance: this bound is the
// stronger one, it also limits how far a leaf's boundary curves bow away from its triangle's
// edges). ReferenceStats::coarse_leaves counts the leaves reached that miss this bound: `depth`
// too small for them; a test asserts it is 0.
//
// Degenerate leaves (the teapot's lid knob and bottom centre, where an edge of a patch collapses
// to a point): a leaf touching the collapsed point has two equal corners, its triangle is a
// segment and no ray crosses it. That is right within the tolerance: such a leaf lies within
// `tolerance` of its segment, and the leaves around it, which share the segment's ends, close the
// surface there. Rays in the plane of a leaf triangle (a null set) are misses for the same reason.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "ray.hpp"
#include "triangular_patch.hpp"

namespace sxk::bezier::oracle {

struct ReferenceOptions {
    // World units: a leaf's control net must lie within this distance of its corners' triangle.
    double tolerance = 0;
    // Bisection levels, the same for every node (even: then every edge is cut into 2^(depth/2)).
    int depth = 24;
};

// Work done and the flatness reached, added up over calls (not thread-safe: one per thread).
struct ReferenceStats {
    std::uint64_t rays = 0;
    std::uint64_t bisections = 0;
    std::uint64_t leaves = 0;         // leaf triangles tested exactly
    std::uint64_t coarse_leaves = 0;  // leaves whose net is farther than the tolerance from flat
    double worst_deviation = 0;       // the largest leaf deviation from flat seen (world units)
    void add(const ReferenceStats& other);
};

struct ReferenceHit {
    double t = 0;               // ray parameter of the hit on the leaf triangle (rounded)
    std::uint32_t patch = 0;    // index in ReferencePatches::patches()
};

// The patches with what every ray needs of them: their control-point boxes (widened by 1e-12 x
// the diagonal), the box of all, its diagonal.
class ReferencePatches {
public:
    struct Box {
        Point lower{}, upper{};
    };
    explicit ReferencePatches(std::vector<TriangularPatch> patches);
    const std::vector<TriangularPatch>& patches() const { return m_patches; }
    const std::vector<Box>& boxes() const { return m_boxes; }
    const Box& box() const { return m_box; }
    double diagonal() const { return m_diagonal; }  // of the box of all control points
    double widening() const { return 1e-12 * m_diagonal; }
    int max_degree() const { return m_max_degree; }

private:
    std::vector<TriangularPatch> m_patches;
    std::vector<Box> m_boxes;
    Box m_box{};
    double m_diagonal = 0;
    int m_max_degree = 0;
};

// The nearest leaf triangle the segment [ray.t_near, ray.t_far] of the ray crosses (closed
// triangles; an infinite t_far is cut where the ray leaves the box of all control points).
// Hit or miss is exact for the leaf triangles; t is rounded. Thread-safe. Throws
// std::invalid_argument for a tolerance <= 0, a depth that is odd or outside [0, 60], or a zero
// direction.
std::optional<ReferenceHit> reference_intersect(const ReferencePatches& patches, const Ray& ray,
                                                const ReferenceOptions& options, ReferenceStats* stats = nullptr);

}  // namespace sxk::bezier::oracle
