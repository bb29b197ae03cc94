// libFuzzer target for the .bpt reader of the bezier plug-in, and through it for the patch
// conversion and Bézier clipping on whatever control points a file can hold. The oracle: the
// reader throws InputError or returns patches with finite coordinates; every tensor patch (any
// degree the reader takes, up to 20 x 20: the conversion is 0.8 ms there) becomes two triangular
// patches that agree with it at their corners and at the square's centre; and
// rays through the middle of each triangular patch's box either miss or hit a point of the
// patch within 1e-9 of its size (clipping must also stop: its iterations are bounded). Anything
// else aborts, as the reader oracles do (oracle.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "bezier_clipping.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "sxk/io.hpp"
#include "vector3.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz oracle: %s\n", what.c_str());
    std::abort();
}

void check_clipping(const sxk::bezier::TriangularPatch& patch) {
    using namespace sxk::bezier;
    using sxk::minus, sxk::scaled;
    using sxk::Point;
    const auto [lower, upper] = box_of(patch.control_points());
    const double size = distance(lower, upper);
    const double scale = std::max({size, std::abs(lower[0]), std::abs(lower[1]), std::abs(lower[2]),
                                   std::abs(upper[0]), std::abs(upper[1]), std::abs(upper[2])});
    if (!std::isfinite(scale) || scale > 1e100) return;  // beyond what distances can hold in a double
    const Point centre = scaled(0.5, {lower[0] + upper[0], lower[1] + upper[1], lower[2] + upper[2]});
    for (const Point& direction : {Point{0, 0, -1}, Point{1, 0, 0}, Point{0.48, -0.6, 0.64}}) {
        const double back = size + 1;
        const Ray ray{minus(centre, scaled(back, direction)), direction};
        const auto hit = intersect(patch, ray);
        if (!hit) continue;
        const Point on_ray = {ray.origin[0] + hit->t * direction[0], ray.origin[1] + hit->t * direction[1],
                              ray.origin[2] + hit->t * direction[2]};
        // the hit's own tolerance is 1e-10 of the net's size; rounding of the ray frame adds some
        // of the coordinates' magnitude
        if (distance(on_ray, patch.evaluate(hit->at)) > 1e-9 * scale)
            finding("clipping hit off the patch by " + std::to_string(distance(on_ray, patch.evaluate(hit->at))));
        for (double c : hit->at)
            if (!(c >= 0 && c <= 1)) finding("clipping hit outside the domain");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sxk::bezier;
    using sxk::Point;
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    std::vector<TensorPatch> patches;
    try {
        patches = read_bpt(in, "fuzz.bpt");
    } catch (const sxk::InputError& error) {
        if (error.reason().empty()) finding("InputError without a reason");
        return 0;
    }
    if (patches.empty()) finding("no patches and no error");
    for (const TensorPatch& patch : patches) {
        for (const Point& p : patch.points)
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                finding("non-finite point read");
        const auto halves = to_triangular(patch);
        // the corners: (0,0), (1,0), (1,1) and (0,0), (1,1), (0,1) of the rectangle; inside, both
        // sides round like convex combinations of the control points, so relative to their size
        double net_scale = 1;
        for (const Point& p : patch.points)
            net_scale = std::max({net_scale, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
        const auto agrees = [&](const TriangularPatch& half, const Barycentric& at, double u, double v) {
            const Point a = half.evaluate(at), b = patch.evaluate(u, v);
            const double scale = net_scale;
            return distance(a, b) <= 1e-9 * scale || !std::isfinite(distance(a, b));
        };
        if (!agrees(halves[0], {1, 0, 0}, 0, 0) || !agrees(halves[0], {0, 1, 0}, 1, 0) ||
            !agrees(halves[0], {0, 0, 1}, 1, 1) || !agrees(halves[1], {0, 0, 1}, 0, 1))
            finding("a triangular half does not meet the tensor patch at a corner");
        // (1/2, 1/2) lies on the diagonal both halves share: (r, s, t) = (1/2, 0, 1/2) in the first,
        // (1/2, 1/2, 0) in the second
        if (!agrees(halves[0], {0.5, 0, 0.5}, 0.5, 0.5) ||
            !agrees(halves[1], {0.5, 0.5, 0}, 0.5, 0.5))
            finding("a triangular half does not meet the tensor patch at the centre");
        for (const TriangularPatch& half : halves) check_clipping(half);
    }
    return 0;
}
