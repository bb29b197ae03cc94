// Pictures of a Scene (render.hpp): pinhole camera, primary rays in parallel (TBB, one task per
// block of rows), Lambert + ambient shading, sRGB encoding.
#include "render.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "vector3.hpp"

namespace sxk::bezier {
namespace {


// Unit vector along a; throws naming `what` when a is zero or not finite.
Point unit(const Point& a, const char* what) {
    const double length = norm(a);
    if (!(length > 0) || !std::isfinite(length))
        throw std::invalid_argument(std::string(what) + " has no direction");
    return scaled(1 / length, a);
}

void check_size(int width, int height) {
    if (width < 1 || height < 1)
        throw std::invalid_argument("render: image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is empty");
}

// The sRGB transfer function (IEC 61966-2-1) of a linear intensity, as an 8-bit value.
std::uint8_t srgb_byte(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(255 * encoded));
}

// The camera's orthonormal frame: right, up (as seen in the image) and forward.
struct CameraFrame {
    Point right, up, forward;
    double half_height;  // tan(fov / 2): the image plane's half height at distance 1
};

CameraFrame camera_frame(const Camera& camera) {
    if (!(camera.fov_degrees > 0 && camera.fov_degrees < 180))
        throw std::invalid_argument("camera: field of view " + std::to_string(camera.fov_degrees) +
                                    " degrees is not in (0, 180)");
    const Point forward = unit(minus(camera.target, camera.eye), "camera: target - eye");
    const Point right =
        unit(cross(forward, camera.up), "camera: the up vector is parallel to the view and");
    return {right, cross(right, forward), forward,
            std::tan(camera.fov_degrees * std::numbers::pi / 360)};
}

// A primary ray from a prepared frame (the per-pixel part of primary_ray).
Ray ray_through(const Camera& camera, const CameraFrame& frame, int width, int height, int x,
                int y) {
    // square pixels: the horizontal extent follows from the vertical one and the aspect ratio
    const double pixel = 2 * frame.half_height / height;
    const double across = (x + 0.5 - width / 2.0) * pixel, down = (y + 0.5 - height / 2.0) * pixel;
    Point direction{};
    for (std::size_t q = 0; q < 3; ++q)
        direction[q] = frame.forward[q] + across * frame.right[q] - down * frame.up[q];
    Ray ray;
    ray.origin = camera.eye;
    ray.direction = scaled(1 / norm(direction), direction);
    return ray;
}

// Runs pixel(x, y, ray) for every pixel, rows in parallel.
template <typename PerPixel>
void for_each_pixel(const Camera& camera, int width, int height, PerPixel&& pixel) {
    const CameraFrame frame = camera_frame(camera);
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
            for (int x = 0; x < width; ++x)
                pixel(x, y, ray_through(camera, frame, width, height, x, y));
    });
}

}  // namespace

Camera frame(const Box& box, const Point& from, const Point& up, double fov_degrees) {
    if (!(fov_degrees > 0 && fov_degrees < 180))
        throw std::invalid_argument("frame: field of view " + std::to_string(fov_degrees) +
                                    " degrees is not in (0, 180)");
    const Point direction = unit(from, "frame: the view direction");
    Point centre{};
    for (std::size_t q = 0; q < 3; ++q)
        centre[q] = (box.lower[q] + box.upper[q]) / 2;
    // the box's circumscribed sphere fills the vertical field of view (and a wider horizontal one)
    const double radius = std::max(box.diagonal() / 2, 1e-300);
    const double distance = radius / std::sin(fov_degrees * std::numbers::pi / 360);
    Camera camera;
    for (std::size_t q = 0; q < 3; ++q)
        camera.eye[q] = centre[q] + distance * direction[q];
    camera.target = centre;
    camera.up = up;
    camera.fov_degrees = fov_degrees;
    return camera;
}

Ray primary_ray(const Camera& camera, int width, int height, int x, int y) {
    check_size(width, height);
    return ray_through(camera, camera_frame(camera), width, height, x, y);
}

Image render(const Scene& scene, const Camera& camera, int width, int height,
             const Shading& shading) {
    check_size(width, height);
    const Point light = unit(shading.light_direction, "render: the light direction");
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    for_each_pixel(camera, width, height, [&](int x, int y, const Ray& ray) {
        Colour colour = shading.background;
        if (const std::optional<SceneHit> hit = scene.intersect(ray)) {
            const Colour surface = shading.colour ? shading.colour(*hit) : Colour{0.75, 0.75, 0.75};
            // two-sided Lambert: patches of a file are not consistently oriented; a point with no
            // normal (a patch flat to a point) is lit as if facing the light
            const double lambert = norm(hit->normal) > 0 ? std::abs(dot(hit->normal, light)) : 1.0;
            const double intensity = shading.ambient + (1 - shading.ambient) * lambert;
            for (std::size_t c = 0; c < 3; ++c)
                colour[c] = surface[c] * intensity;
        }
        const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(x)) *
                               3;
        for (std::size_t c = 0; c < 3; ++c)
            image.rgb[at + c] = srgb_byte(colour[c]);
    });
    return image;
}

std::vector<std::uint8_t> hit_mask(const Scene& scene, const Camera& camera, int width,
                                   int height) {
    check_size(width, height);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) *
                                   static_cast<std::size_t>(height));
    for_each_pixel(camera, width, height, [&](int x, int y, const Ray& ray) {
        mask[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
             static_cast<std::size_t>(x)] = scene.intersect(ray) ? 1 : 0;
    });
    return mask;
}

}  // namespace sxk::bezier
