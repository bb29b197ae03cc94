// Pictures of a Scene: a pinhole camera, primary rays traced in parallel (TBB), Lambert + ambient
// shading from one directional light, and PNG output (libpng).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "image.hpp"
#include "patch_scene.hpp"

namespace sxk::bezier {

struct Camera {
    Point eye{0, -10, 0};
    Point target{0, 0, 0};
    Point up{0, 0, 1};
    double fov_degrees = 40;  // vertical field of view
};

// A camera looking at the box's centre from direction `from` (need not be unit), far enough that
// the box fits the vertical field of view.
Camera frame(const Box& box, const Point& from, const Point& up, double fov_degrees = 40);

// A camera looking from direction `from` (need not be unit) that shows every point, the points'
// extent filling the picture (width / height = `aspect`) but for `margin` (a fraction of each
// side) on the larger of its two axes: tighter than frame(), whose sphere around the box leaves a
// long thin body a sliver of the picture. The target is the middle of the points' extent across
// the view; the eye stays outside the points. Throws as frame() does, and for aspect <= 0.
Camera fit(std::span<const Point> points, const Point& from, const Point& up, double fov_degrees, double aspect,
           double margin = 0.05);

// The width / height of the points' extent seen from `from` with `up` up (parallel projection):
// the shape of picture they fill best. 1 for fewer than two distinct points.
double extent_aspect(std::span<const Point> points, const Point& from, const Point& up);

using Colour = std::array<double, 3>;  // linear RGB in [0, 1]

struct Shading {
    Point light_direction{-1, -2, 3};  // toward the light
    double ambient = 0.25;
    Colour background{1, 1, 1};
    // The surface colour at a hit; default: a neutral grey.
    std::function<Colour(const SceneHit&)> colour;
    // Surfaces that must show even where the scene hides them (the faces of a cut inside a
    // body): where a ray meets `overlay` behind the scene's nearest hit, the overlay's colour is
    // mixed in with weight `overlay_weight`; where it is nearest, it is drawn as it is.
    const Scene* overlay = nullptr;
    std::function<Colour(const SceneHit&)> overlay_colour;
    double overlay_weight = 0.6;
};

using pictures::Image;
using pictures::write_png;

// The primary ray through the centre of pixel (x, y), (0, 0) at the top-left; unit direction.
Ray primary_ray(const Camera& camera, int width, int height, int x, int y);

// Where the camera sees `point` in a width x height picture, in pixels from the top-left corner
// (continuous: pixel (x, y) covers [x, x + 1) x [y, y + 1)); nothing when it is behind the eye.
std::optional<std::array<double, 2>> project(const Camera& camera, int width, int height, const Point& point);

Image render(const Scene& scene, const Camera& camera, int width, int height,
             const Shading& shading = {});
// 1 where the primary ray hits, 0 where it misses (row-major from the top-left).
std::vector<std::uint8_t> hit_mask(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace sxk::bezier
