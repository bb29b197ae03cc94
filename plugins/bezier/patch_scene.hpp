// A ray-tracing scene over Embree 3: triangular Bézier patches registered as Embree user
// geometry (Embree's BVH over flatness-subdivided sub-patches replaces Roth's bounding sphere
// hierarchy, §6.4; each leaf is intersected by Bézier clipping), or plain triangles (Embree's
// native triangles: meshes, and the tessellated patches `--tessellate` and the benchmark
// compare with). No Embree type appears here: embree_device.hpp is the only header that
// includes Embree, and only .cpp files include it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "bezier_clipping.hpp"
#include "ray.hpp"
#include "triangular_patch.hpp"

namespace sxk::bezier {

struct Box {
    Point lower{}, upper{};
    double diagonal() const;
};

// The box of the points (the zero box at the origin when there are none), and the box of all
// the patches' control points, which holds the patches (convex hull property).
Box box_of(std::span<const Point> points);
Box box_of(const std::vector<TriangularPatch>& patches);
// Where the ray enters the box within [t_near, t_far] (t_near when it starts inside), or
// nothing when it misses the box there.
std::optional<double> entry(const Ray& ray, const Box& box);

// A hit in a scene: primitive is the index of the patch (patch scenes) or of the triangle
// (triangle scenes) in the order given; `at` is barycentric in that primitive; the normal is
// unit and not turned toward the ray.
struct SceneHit {
    double t = 0;
    std::uint32_t primitive = 0;
    Barycentric at{};
    Point normal{};
};

struct PatchSceneOptions {
    // Roth's height criterion (§6.4): a patch is split into four until the extent of its control
    // points along the normal of its corner plane is below flatness x the scene's box diagonal.
    double flatness = 1e-3;
    // Bound on the split depth (4^depth sub-patches per patch at most).
    int max_depth = 8;
    // Bound on the sub-patches' memory (leaf_bytes each, flat_subdivision.hpp): 1 GiB, about
    // 1.1 million sextic or 51,000 degree-40 sub-patches; the teapot takes 8.4 MB at 1e-3.
    std::size_t max_bytes = std::size_t{1} << 30;
    ClippingOptions clipping{};
};

// The smallest flatness whose height double rounding can still tell apart in a scene with this
// box: 1e-12 x (diagonal + largest |coordinate|) / diagonal (0 for a box of one point). A
// sub-patch's control points carry the rounding of the de Casteljau steps that cut it, about
// 3n steps of 2^-53 x the largest coordinate per level at degree n, 1.1e-13 at n = 40 (read_bpt's
// highest) after the 8 levels of max_depth, and its height the rounding of the products
// measuring it: heights below 1e-12 of that scale are rounding, and splitting toward them only
// ends at max_depth.
double smallest_flatness(const Box& box);

struct TriangleSoup {
    std::vector<Point> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

class Scene {
public:
    // Throws std::invalid_argument for a flatness below smallest_flatness(box_of(patches)) and
    // SubdivisionTooLarge (flat_subdivision.hpp) when the sub-patches exceed options.max_bytes.
    static Scene from_patches(std::vector<TriangularPatch> patches,
                              const PatchSceneOptions& options = {});
    static Scene from_triangles(TriangleSoup soup);
    ~Scene();
    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;

    // The nearest hit in [ray.t_near, ray.t_far]; thread-safe (renders call it from TBB).
    std::optional<SceneHit> intersect(const Ray& ray) const;
    // Whether anything lies on the ray in [t_near, t_far] (shadow rays).
    bool occluded(const Ray& ray) const;

    Box bounds() const;
    std::size_t primitive_count() const;  // patches or triangles
    std::size_t leaf_count() const;       // Embree primitives: sub-patches or triangles

private:
    struct Impl;
    explicit Scene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

// Uniform tessellation: each patch's domain cut into segments^2 triangles, vertices evaluated on
// the patch (triangle i belongs to patch i / segments^2).
TriangleSoup tessellate(const std::vector<TriangularPatch>& patches, int segments);
// The smallest segment count whose tessellation deviates at most max_error from the patches
// (measured by sampling each small triangle's interior against the flat triangle), searching no
// count above max_segments: that bound is returned when none up to it is fine enough. Throws
// std::invalid_argument when the count needed exceeds what tessellate can index (2^32 vertices).
int segments_for_error(const std::vector<TriangularPatch>& patches, double max_error,
                       int max_segments = std::numeric_limits<int>::max());

}  // namespace sxk::bezier
