// The Embree scene (patch_scene.hpp): patches as Embree user geometry over Roth's flat pieces
// (flat_subdivision.hpp, §6.4), whose leaves are intersected by Bézier clipping, or triangles as
// Embree's native triangles.
//
// Precision: Embree stores and traverses in float, our clipping works in double on the
// original control points. Each query therefore carries its double ray in an extension of
// Embree's RTCIntersectContext (TraceContext below, the documented way to pass per-query data to
// user callbacks; no thread_local or global state): the callbacks clip against the double ray
// and keep the nearest double hit there, and Embree's float ray only steers the BVH traversal.
// The float ray starts where the double ray enters the scene's box (computed in double), so its
// rounding is relative to the scene's size and position, not to the distance of the eye: from
// far away a float origin and direction would be off by far more than any leaf. The leaves'
// boxes are widened by a margin that covers the remaining rounding, so the float ray never
// misses a box the double ray meets. Triangle hits are recomputed in double from the triangle's
// double vertices.
#include "patch_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "embree_device.hpp"
#include "flat_subdivision.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {


// How far boxes are widened so that Embree's float rays and boxes never miss what the double
// ray meets: float carries 24 bits, and 1e-6 of the scene's size and distance from the origin
// covers their rounding many times.
double rounding_margin(const Box& box) {
    double largest_coordinate = 0;
    for (std::size_t q = 0; q < 3; ++q)
        largest_coordinate = std::max({largest_coordinate, std::abs(box.lower[q]), std::abs(box.upper[q])});
    return 1e-6 * (box.diagonal() + largest_coordinate);
}

Box widened(Box box, double margin) {
    for (std::size_t q = 0; q < 3; ++q)
        box.lower[q] -= margin, box.upper[q] += margin;
    return box;
}


// The nearest leaf hit found so far for one query, in double.
struct LeafHit {
    double t = 0;
    std::uint32_t leaf = 0;
    Barycentric at{};  // in the leaf's own coordinates
    Point normal{};    // the clipping's: the leaf keeps the patch's orientation (flat_subdivision)
};

// Embree hands this to every callback of one rtcIntersect1/rtcOccluded1 call: the extension of
// its context with our double ray. `embree` must stay the first member (Embree passes a pointer
// to it; the struct is standard-layout, so the cast back is valid).
struct TraceContext {
    RTCIntersectContext embree;
    const Ray* ray = nullptr;
    double shift = 0;  // Embree's t = ours - shift (its ray starts at ray(shift))
    bool found = false;
    LeafHit nearest;
};
static_assert(std::is_standard_layout_v<TraceContext>);

TraceContext* trace_context(RTCIntersectContext* context) {
    return reinterpret_cast<TraceContext*>(context);
}

float float_above(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity())
                                      : f;
}

float float_below(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                      : f;
}

// The ray Embree traces, back in double: only for ray packets (N > 1), which this scene never
// issues; single queries use the exact ray in their TraceContext.
Ray float_ray(RTCRayN* rays, unsigned n, unsigned i) {
    Ray ray;
    ray.origin = {RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
    ray.direction = {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i),
                     RTCRayN_dir_z(rays, n, i)};
    ray.t_near = RTCRayN_tnear(rays, n, i);
    ray.t_far = RTCRayN_tfar(rays, n, i);
    return ray;
}

// Möller–Trumbore in double: the ray's parameter and (u, v) with hit = (1-u-v) a + u b + v c;
// nothing when the ray is parallel to the triangle's plane.
std::optional<std::array<double, 3>> ray_triangle(const Ray& ray, const Point& a, const Point& b,
                                                  const Point& c) {
    const Point e1 = minus(b, a), e2 = minus(c, a);
    const Point p = cross(ray.direction, e2);
    const double determinant = dot(e1, p);
    if (determinant == 0 || !std::isfinite(determinant))
        return std::nullopt;
    const Point s = minus(ray.origin, a);
    const Point q = cross(s, e1);
    return std::array<double, 3>{dot(e2, q) / determinant, dot(s, p) / determinant,
                                 dot(ray.direction, q) / determinant};
}


}  // namespace

struct Scene::Impl {
    embree::Device device;  // first: released last
    embree::SceneHandle scene;
    Box box;
    // the box around everything Embree may report (leaf boxes included), where rays start
    Box trace_box;
    bool of_patches = false;
    // patch scenes
    std::vector<TriangularPatch> patches;
    std::vector<SubPatch> leaves;
    ClippingOptions clipping;
    double bounds_margin = 0;
    // triangle scenes
    TriangleSoup soup;

    static void leaf_bounds(const RTCBoundsFunctionArguments* args);
    static void intersect_leaf(const RTCIntersectFunctionNArguments* args);
    static void occluded_leaf(const RTCOccludedFunctionNArguments* args);
};

// The box of a leaf's control points (it contains the leaf: convex hull property), widened by
// bounds_margin for the float ray's rounding, then rounded outward to float.
void Scene::Impl::leaf_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* impl = static_cast<const Impl*>(args->geometryUserPtr);
    const Box box = box_of(impl->leaves[args->primID].surface.control_points());
    const double margin = impl->bounds_margin;
    RTCBounds* out = args->bounds_o;
    out->lower_x = float_below(box.lower[0] - margin);
    out->lower_y = float_below(box.lower[1] - margin);
    out->lower_z = float_below(box.lower[2] - margin);
    out->upper_x = float_above(box.upper[0] + margin);
    out->upper_y = float_above(box.upper[1] + margin);
    out->upper_z = float_above(box.upper[2] + margin);
}

void Scene::Impl::intersect_leaf(const RTCIntersectFunctionNArguments* args) {
    const auto* impl = static_cast<const Impl*>(args->geometryUserPtr);
    TraceContext* context = trace_context(args->context);
    const SubPatch& leaf = impl->leaves[args->primID];
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    const bool exact = args->N == 1 && context->ray != nullptr;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0)
            continue;
        Ray ray = exact ? *context->ray : float_ray(rays, args->N, i);
        if (exact && context->found)
            ray.t_far = std::min(ray.t_far, context->nearest.t);
        const std::optional<PatchHit> hit = bezier::intersect(leaf.surface, ray, impl->clipping);
        if (!hit || hit->t < ray.t_near || hit->t > ray.t_far)
            continue;
        if (exact)
            context->found = true, context->nearest = LeafHit{hit->t, args->primID, hit->at, hit->normal};
        // Embree's float range must keep every box that could hold a nearer double hit
        RTCRayN_tfar(rays, args->N, i) = float_above(exact ? hit->t - context->shift : hit->t);
        RTCHitN_Ng_x(hits, args->N, i) = static_cast<float>(hit->normal[0]);
        RTCHitN_Ng_y(hits, args->N, i) = static_cast<float>(hit->normal[1]);
        RTCHitN_Ng_z(hits, args->N, i) = static_cast<float>(hit->normal[2]);
        RTCHitN_u(hits, args->N, i) = static_cast<float>(hit->at[1]);
        RTCHitN_v(hits, args->N, i) = static_cast<float>(hit->at[2]);
        RTCHitN_primID(hits, args->N, i) = args->primID;
        RTCHitN_geomID(hits, args->N, i) = args->geomID;
        RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
    }
}

void Scene::Impl::occluded_leaf(const RTCOccludedFunctionNArguments* args) {
    const auto* impl = static_cast<const Impl*>(args->geometryUserPtr);
    TraceContext* context = trace_context(args->context);
    const SubPatch& leaf = impl->leaves[args->primID];
    const bool exact = args->N == 1 && context->ray != nullptr;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0)
            continue;
        const Ray ray = exact ? *context->ray : float_ray(args->ray, args->N, i);
        const std::optional<PatchHit> hit = bezier::intersect(leaf.surface, ray, impl->clipping);
        if (!hit || hit->t < ray.t_near || hit->t > ray.t_far)
            continue;
        // Embree's convention for "occluded": tfar = -inf
        RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
    }
}

Scene::Scene(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

Scene Scene::from_patches(std::vector<TriangularPatch> patches, const PatchSceneOptions& options) {
    if (!(options.flatness >= 0))
        throw std::invalid_argument("Scene::from_patches: flatness " +
                                    std::to_string(options.flatness) + " is negative or NaN");
    auto impl = std::make_unique<Impl>();
    impl->of_patches = true;
    impl->clipping = options.clipping;
    impl->box = box_of(patches);
    const double diagonal = impl->box.diagonal();
    if (options.flatness < smallest_flatness(impl->box)) {
        char message[160];
        std::snprintf(message, sizeof message,
                      "Scene::from_patches: flatness %g is below the smallest the scene's rounding "
                      "resolves, %.3g",
                      options.flatness, smallest_flatness(impl->box));
        throw std::invalid_argument(message);
    }
    impl->bounds_margin = rounding_margin(impl->box);
    impl->trace_box = widened(impl->box, 2 * impl->bounds_margin);
    impl->leaves = flat_subdivision(patches, options.flatness * diagonal, options.max_depth,
                                    options.max_bytes);
    impl->patches = std::move(patches);

    impl->scene = embree::new_scene(impl->device);
    if (!impl->leaves.empty()) {
        if (impl->leaves.size() > std::numeric_limits<unsigned>::max())
            throw std::invalid_argument(
                "Scene::from_patches: " + std::to_string(impl->leaves.size()) +
                " sub-patches exceed Embree's primitive index range");
        const embree::GeometryHandle geometry =
            embree::new_geometry(impl->device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry.get(),
                                         static_cast<unsigned>(impl->leaves.size()));
        rtcSetGeometryUserData(geometry.get(), impl.get());
        rtcSetGeometryBoundsFunction(geometry.get(), &Impl::leaf_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geometry.get(), &Impl::intersect_leaf);
        rtcSetGeometryOccludedFunction(geometry.get(), &Impl::occluded_leaf);
        impl->device.check("setting up the patch geometry");
        embree::attach(impl->device, impl->scene, geometry);
    }
    embree::commit(impl->device, impl->scene);
    return Scene(std::move(impl));
}

Scene Scene::from_triangles(TriangleSoup soup) {
    const std::size_t vertex_count = soup.vertices.size();
    for (std::size_t i = 0; i < soup.triangles.size(); ++i)
        for (std::uint32_t v : soup.triangles[i])
            if (v >= vertex_count)
                throw std::invalid_argument("Scene::from_triangles: triangle " + std::to_string(i) +
                                            " names vertex " + std::to_string(v) + " of " +
                                            std::to_string(vertex_count));
    if (soup.triangles.size() > std::numeric_limits<unsigned>::max() ||
        vertex_count > std::numeric_limits<unsigned>::max())
        throw std::invalid_argument(
            "Scene::from_triangles: too many triangles or vertices for Embree");
    auto impl = std::make_unique<Impl>();
    impl->box = box_of(soup.vertices);
    impl->trace_box = widened(impl->box, rounding_margin(impl->box));
    impl->scene = embree::new_scene(impl->device);
    if (!soup.triangles.empty()) {
        const embree::GeometryHandle geometry =
            embree::new_geometry(impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), vertex_count));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), soup.triangles.size()));
        impl->device.check("allocating the triangle buffers");
        for (std::size_t i = 0; i < vertex_count; ++i)
            for (std::size_t q = 0; q < 3; ++q)
                vertices[3 * i + q] = static_cast<float>(soup.vertices[i][q]);
        for (std::size_t i = 0; i < soup.triangles.size(); ++i)
            for (std::size_t q = 0; q < 3; ++q)
                indices[3 * i + q] = soup.triangles[i][q];
        embree::attach(impl->device, impl->scene, geometry);
    }
    embree::commit(impl->device, impl->scene);
    impl->soup = std::move(soup);
    return Scene(std::move(impl));
}

namespace {

// The ray Embree traces: from `shift` on, in Embree's float range.
Ray starting_at(const Ray& ray, double shift) {
    Ray shifted = ray;
    for (std::size_t q = 0; q < 3; ++q)
        shifted.origin[q] += shift * ray.direction[q];
    shifted.t_near = 0;
    shifted.t_far = ray.t_far - shift;
    return shifted;
}

}  // namespace

std::optional<SceneHit> Scene::intersect(const Ray& ray) const {
    const std::optional<double> shift = entry(ray, m_impl->trace_box);
    if (!shift)
        return std::nullopt;
    TraceContext context;
    rtcInitIntersectContext(&context.embree);
    context.ray = &ray;
    context.shift = *shift;
    RTCRayHit query = embree::ray_hit(starting_at(ray, *shift));
    rtcIntersect1(m_impl->scene.get(), &context.embree, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return std::nullopt;

    if (m_impl->of_patches) {
        if (!context.found)
            return std::nullopt;
        const SubPatch& leaf = m_impl->leaves[context.nearest.leaf];
        const Barycentric& local = context.nearest.at;
        SceneHit hit;
        hit.t = context.nearest.t;
        hit.primitive = leaf.patch;
        for (std::size_t q = 0; q < 3; ++q)
            hit.at[q] = local[0] * leaf.corners[0][q] + local[1] * leaf.corners[1][q] +
                        local[2] * leaf.corners[2][q];
        // the leaf's normal is the patch's; where the leaf has none (flat to a point), the
        // patch's limit from inside
        hit.normal = context.nearest.normal;
        if (hit.normal == Point{0, 0, 0}) hit.normal = m_impl->patches[leaf.patch].normal(hit.at);
        return hit;
    }

    const auto& corners = m_impl->soup.triangles[query.hit.primID];
    const Point& a = m_impl->soup.vertices[corners[0]];
    const Point& b = m_impl->soup.vertices[corners[1]];
    const Point& c = m_impl->soup.vertices[corners[2]];
    SceneHit hit;
    hit.primitive = query.hit.primID;
    hit.normal = unit_or_zero(cross(minus(b, a), minus(c, a)));  // right-handed a -> b -> c
    // Embree found the triangle in float; its t and (u, v) again in double
    if (const auto exact = ray_triangle(ray, a, b, c)) {
        const auto [t, u, v] = *exact;
        if (t < ray.t_near || t > ray.t_far)
            return std::nullopt;
        hit.t = t;
        hit.at = {1 - u - v, u, v};
    } else {
        hit.t = query.ray.tfar + *shift;
        hit.at = {1.0 - query.hit.u - query.hit.v, query.hit.u, query.hit.v};
    }
    return hit;
}

bool Scene::occluded(const Ray& ray) const {
    const std::optional<double> shift = entry(ray, m_impl->trace_box);
    if (!shift)
        return false;
    TraceContext context;
    rtcInitIntersectContext(&context.embree);
    context.ray = &ray;
    context.shift = *shift;
    RTCRayHit query = embree::ray_hit(starting_at(ray, *shift));
    rtcOccluded1(m_impl->scene.get(), &context.embree, &query.ray);
    return query.ray.tfar == -std::numeric_limits<float>::infinity();
}

Box Scene::bounds() const {
    return m_impl->box;
}

std::size_t Scene::primitive_count() const {
    return m_impl->of_patches ? m_impl->patches.size() : m_impl->soup.triangles.size();
}

std::size_t Scene::leaf_count() const {
    return m_impl->of_patches ? m_impl->leaves.size() : m_impl->soup.triangles.size();
}

}  // namespace sxk::bezier
