// Pictures of a Scene: a pinhole camera, primary rays traced in parallel (TBB), Lambert + ambient
// shading from one directional light, and PNG output (libpng).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
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

using Colour = std::array<double, 3>;  // linear RGB in [0, 1]

struct Shading {
    Point light_direction{-1, -2, 3};  // toward the light
    double ambient = 0.25;
    Colour background{1, 1, 1};
    // The surface colour at a hit; default: a neutral grey.
    std::function<Colour(const SceneHit&)> colour;
};

using pictures::Image;
using pictures::write_png;

// The primary ray through the centre of pixel (x, y), (0, 0) at the top-left; unit direction.
Ray primary_ray(const Camera& camera, int width, int height, int x, int y);

Image render(const Scene& scene, const Camera& camera, int width, int height,
             const Shading& shading = {});
// 1 where the primary ray hits, 0 where it misses (row-major from the top-left).
std::vector<std::uint8_t> hit_mask(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace sxk::bezier
