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

namespace {

// The view's axes for `from` and `up`: right, up in the picture, and forward (toward the scene).
CameraFrame view_axes(const Point& from, const Point& up) {
    const Point forward = scaled(-1, unit(from, "fit: the view direction"));
    const Point right = unit(cross(forward, up), "fit: the up vector is parallel to the view and");
    return {right, cross(right, forward), forward, 0};
}

}  // namespace

double extent_aspect(std::span<const Point> points, const Point& from, const Point& up) {
    const CameraFrame axes = view_axes(from, up);
    double low[2] = {0, 0}, high[2] = {0, 0};
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double x = dot(points[i], axes.right), y = dot(points[i], axes.up);
        low[0] = i == 0 ? x : std::min(low[0], x), high[0] = i == 0 ? x : std::max(high[0], x);
        low[1] = i == 0 ? y : std::min(low[1], y), high[1] = i == 0 ? y : std::max(high[1], y);
    }
    const double width = high[0] - low[0], height = high[1] - low[1];
    return width > 0 && height > 0 ? width / height : 1.0;
}

Camera fit(std::span<const Point> points, const Point& from, const Point& up, double fov_degrees, double aspect,
           double margin) {
    if (!(fov_degrees > 0 && fov_degrees < 180))
        throw std::invalid_argument("fit: field of view " + std::to_string(fov_degrees) +
                                    " degrees is not in (0, 180)");
    if (!(aspect > 0)) throw std::invalid_argument("fit: the picture's aspect ratio is not positive");
    const CameraFrame axes = view_axes(from, up);
    if (points.empty()) return frame(Box{}, from, up, fov_degrees);
    // the points' extent across the view (parallel projection) decides the target
    double low[3], high[3];
    for (std::size_t q = 0; q < 3; ++q) low[q] = high[q] = 0;
    const Point* axis[3] = {&axes.right, &axes.up, &axes.forward};
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t q = 0; q < 3; ++q) {
            const double c = dot(points[i], *axis[q]);
            low[q] = i == 0 ? c : std::min(low[q], c);
            high[q] = i == 0 ? c : std::max(high[q], c);
        }
    Point target{};
    for (std::size_t q = 0; q < 3; ++q)
        for (std::size_t k = 0; k < 3; ++k) target[k] += (low[q] + high[q]) / 2 * (*axis[q])[k];
    // a point at (x, y) across the view and z along it, seen from distance d before the target,
    // lies at y / (d + z) of the picture's half height in units of tan(fov / 2): the smallest d
    // that keeps every point inside (1 - margin) of both half sides
    const double half = std::tan(fov_degrees * std::numbers::pi / 360) * (1 - std::clamp(margin, 0.0, 0.9));
    const double depth = std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2], 1e-300});
    double distance = (high[2] - low[2]) / 2 + 1e-3 * depth;  // the eye outside the points
    for (const Point& p : points) {
        const Point d = minus(p, target);
        const double x = std::abs(dot(d, axes.right)), y = std::abs(dot(d, axes.up)), z = dot(d, axes.forward);
        distance = std::max({distance, y / half - z, x / (half * aspect) - z});
    }
    Camera camera;
    for (std::size_t k = 0; k < 3; ++k) camera.eye[k] = target[k] - distance * axes.forward[k];
    camera.target = target;
    camera.up = up;
    camera.fov_degrees = fov_degrees;
    return camera;
}

std::optional<std::array<double, 2>> project(const Camera& camera, int width, int height, const Point& point) {
    check_size(width, height);
    const CameraFrame axes = camera_frame(camera);
    const Point d = minus(point, camera.eye);
    const double depth = dot(d, axes.forward);
    if (!(depth > 0)) return std::nullopt;
    // ray_through's inverse: pixel centres x + 0.5 at across = (x + 0.5 - width / 2) * pixel
    const double pixel = 2 * axes.half_height / height;
    return std::array<double, 2>{width / 2.0 + dot(d, axes.right) / depth / pixel,
                                 height / 2.0 - dot(d, axes.up) / depth / pixel};
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
        // two-sided Lambert: patches of a file are not consistently oriented; a point with no
        // normal (a patch flat to a point) is lit as if facing the light
        const auto intensity = [&](const SceneHit& hit) {
            const double lambert = norm(hit.normal) > 0 ? std::abs(dot(hit.normal, light)) : 1.0;
            return shading.ambient + (1 - shading.ambient) * lambert;
        };
        const std::optional<SceneHit> hit = scene.intersect(ray);
        if (hit) {
            const Colour surface = shading.colour ? shading.colour(*hit) : Colour{0.75, 0.75, 0.75};
            const double lit = intensity(*hit);
            for (std::size_t c = 0; c < 3; ++c)
                colour[c] = surface[c] * lit;
        }
        if (shading.overlay != nullptr && shading.overlay_colour) {
            if (const std::optional<SceneHit> seen = shading.overlay->intersect(ray)) {
                const Colour surface = shading.overlay_colour(*seen);
                // hidden: lit as if facing the light, so that it reads the same at any angle
                const bool nearest = !hit || seen->t <= hit->t * (1 + 1e-9);
                const double lit = nearest ? intensity(*seen) : 0.8;
                const double weight = nearest ? 1.0 : shading.overlay_weight;
                for (std::size_t c = 0; c < 3; ++c)
                    colour[c] = weight * surface[c] * lit + (1 - weight) * colour[c];
            }
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
