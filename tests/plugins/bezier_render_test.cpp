// Pictures of a Scene (render.hpp): the pinhole camera's rays, framing a box, Lambert + ambient
// shading and sRGB bytes, hit masks, the teapot at 64x64, and PNG files read back with libpng.
//
//   the square fixture: two triangles covering [-1, 1]^2 in z = 0, seen from (0, 0, 4) with a
//   vertical field of view of 2 atan(1/2): the image spans [-2, 2]^2 at z = 0, so the square
//   fills exactly the middle half of it in each direction, its edges between pixel centres.
//
//     +-----------------+   y
//     |    +-------+    |   ^
//     |    | hits  |    |   |
//     |    +-------+    |   +--> x   (camera up = +y, right = +x)
//     +-----------------+
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "bezier_teapot.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "render.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {

double degrees(double radians) {
    return radians * 180 / std::numbers::pi;
}

Scene square() {
    return Scene::from_triangles(
        TriangleSoup{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}});
}

Camera above(double height = 4) {
    return Camera{{0, 0, height}, {0, 0, 0}, {0, 1, 0}, degrees(2 * std::atan(0.5))};
}

using test_teapot::teapot;

// The sRGB byte of a linear intensity (IEC 61966-2-1), written out here independently.
int srgb(double linear) {
    const double encoded =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    return static_cast<int>(std::lround(255 * encoded));
}

std::array<int, 3> pixel(const Image& image, int x, int y) {
    const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 3;
    return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

TEST(PrimaryRay, PinholeGeometry) {
    const Camera camera;  // eye (0, -10, 0) looking along +y, up +z, 40 degrees
    const int width = 101, height = 51;
    const Ray centre = primary_ray(camera, width, height, 50, 25);
    EXPECT_EQ(centre.origin, camera.eye);
    EXPECT_NEAR(centre.direction[0], 0, 1e-15);
    EXPECT_NEAR(centre.direction[1], 1, 1e-15);
    EXPECT_NEAR(centre.direction[2], 0, 1e-15);
    // the top row's centre is 25 pixels of 2 tan(20 deg) / 51 above the axis; square pixels
    const double pixel_size = 2 * std::tan(20 * std::numbers::pi / 180) / height;
    const Ray top = primary_ray(camera, width, height, 50, 0);
    EXPECT_NEAR(top.direction[2] / top.direction[1], 25 * pixel_size, 1e-14);
    EXPECT_NEAR(top.direction[0], 0, 1e-15);
    const Ray left = primary_ray(camera, width, height, 0, 25);
    EXPECT_NEAR(left.direction[0] / left.direction[1], -50 * pixel_size, 1e-14);
    for (const Ray& ray : {centre, top, left})
        EXPECT_NEAR(std::sqrt(dot(ray.direction, ray.direction)), 1, 1e-15);
    EXPECT_THROW(primary_ray(Camera{{0, 0, 0}, {0, 0, 0}}, 4, 4, 0, 0), std::invalid_argument);
    EXPECT_THROW(primary_ray(Camera{{0, 0, 0}, {0, 0, 1}, {0, 0, 2}}, 4, 4, 0, 0),
                 std::invalid_argument);
    EXPECT_THROW(primary_ray(Camera{{0, -1, 0}, {0, 0, 0}, {0, 0, 1}, 180}, 4, 4, 0, 0),
                 std::invalid_argument);
    EXPECT_THROW(primary_ray(camera, 0, 4, 0, 0), std::invalid_argument);
}

TEST(Frame, TheBoxFitsTheFieldOfView) {
    const Box box{{-1, 2, 0}, {3, 4, 8}};
    for (const Point& from : {Point{1, -2, 1}, Point{0, 0, 5}, Point{-3, 0.1, 0}}) {
        const Camera camera = frame(box, from, {0, 0, 1}, 30);
        EXPECT_EQ(camera.target, (Point{1, 3, 4}));
        Point forward{camera.target[0] - camera.eye[0], camera.target[1] - camera.eye[1],
                      camera.target[2] - camera.eye[2]};
        const double distance = std::sqrt(dot(forward, forward));
        for (double& x : forward)
            x /= distance;
        EXPECT_NEAR(dot(forward, from) / std::sqrt(dot(from, from)), -1, 1e-12);
        for (int corner = 0; corner < 8; ++corner) {
            const Point p{corner & 1 ? box.upper[0] : box.lower[0],
                          corner & 2 ? box.upper[1] : box.lower[1],
                          corner & 4 ? box.upper[2] : box.lower[2]};
            Point to{p[0] - camera.eye[0], p[1] - camera.eye[1], p[2] - camera.eye[2]};
            // every corner within half the field of view of the axis
            EXPECT_LE(std::acos(dot(to, forward) / std::sqrt(dot(to, to))),
                      15 * std::numbers::pi / 180 + 1e-12);
        }
    }
}

TEST(Render, LambertPlusAmbientInSrgb) {
    Shading shading;
    shading.light_direction = {1, 0, 1};  // 45 degrees off the square's normal
    shading.ambient = 0.25;
    shading.background = {0, 0, 0};
    shading.colour = [](const SceneHit& hit) {
        return hit.primitive == 0 ? Colour{1, 0, 0} : Colour{0, 0, 1};
    };
    const Image image = render(square(), above(), 64, 64, shading);
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 64);
    ASSERT_EQ(image.rgb.size(), 64u * 64 * 3);
    const int lit = srgb(0.25 + 0.75 / std::sqrt(2.0));
    // triangle 0 = (-1,-1), (1,-1), (1,1): below the diagonal, the image's lower right
    EXPECT_EQ(pixel(image, 40, 40), (std::array<int, 3>{lit, 0, 0}));
    EXPECT_EQ(pixel(image, 20, 20), (std::array<int, 3>{0, 0, lit}));
    EXPECT_EQ(pixel(image, 5, 5), (std::array<int, 3>{0, 0, 0}));
    // seen from below (the image mirrored in x): two-sided, the same brightness
    const Image below = render(square(), above(-4), 64, 64, shading);
    EXPECT_EQ(pixel(below, 23, 40), (std::array<int, 3>{lit, 0, 0}));
    EXPECT_EQ(pixel(below, 43, 20), (std::array<int, 3>{0, 0, lit}));
    // the default: grey surfaces on a white background
    const Image plain = render(square(), above(), 16, 16);
    EXPECT_EQ(pixel(plain, 0, 0), (std::array<int, 3>{255, 255, 255}));
    EXPECT_LT(pixel(plain, 8, 8)[0], 255);
    EXPECT_EQ(pixel(plain, 8, 8)[0], pixel(plain, 8, 8)[2]);
    EXPECT_THROW(render(square(), above(), 0, 16), std::invalid_argument);
}

TEST(HitMask, SquareFillsTheMiddleHalf) {
    const std::vector<std::uint8_t> mask = hit_mask(square(), above(), 64, 64);
    ASSERT_EQ(mask.size(), 64u * 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const bool inside = x >= 16 && x < 48 && y >= 16 && y < 48;
            ASSERT_EQ(mask[static_cast<std::size_t>(y * 64 + x)], inside ? 1 : 0)
                << "pixel " << x << ", " << y;
        }
}

// The teapot at 64x64 (Roth Fig. 6.12): its patches hit a plausible share of the framed image,
// every hit pixel is shaded and every other one is background, and its uniform tessellation
// (within 1e-3 of the box) covers nearly the same pixels.
TEST(Render, TeapotAt64) {
    const std::vector<TriangularPatch> patches = teapot();
    const Scene scene = Scene::from_patches(patches);
    EXPECT_GT(scene.leaf_count(), 64u);
    const Camera camera = frame(scene.bounds(), {1, -2, 1.2}, {0, 0, 1}, 35);
    const Image image = render(scene, camera, 64, 64);
    const std::vector<std::uint8_t> mask = hit_mask(scene, camera, 64, 64);
    std::size_t hits = 0, shaded = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        hits += mask[i];
        const bool background =
            image.rgb[3 * i] == 255 && image.rgb[3 * i + 1] == 255 && image.rgb[3 * i + 2] == 255;
        shaded += background ? 0 : 1;
        EXPECT_EQ(mask[i] == 1, !background) << "pixel " << i;
    }
    EXPECT_EQ(hits, shaded);
    // the bounding sphere fills the height: the teapot covers a fair part, never all of it
    EXPECT_GT(hits, 64u * 64 / 10);
    EXPECT_LT(hits, 64u * 64 * 7 / 10);

    const int segments = segments_for_error(patches, 1e-3 * scene.bounds().diagonal());
    const std::vector<std::uint8_t> triangles =
        hit_mask(Scene::from_triangles(tessellate(patches, segments)), camera, 64, 64);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < mask.size(); ++i)
        differ += mask[i] != triangles[i] ? 1 : 0;
    EXPECT_LE(differ, hits / 50) << segments << " segments";
}

// A temporary folder removed at the end of the test.
struct TemporaryFolder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("sxk-png-" + std::to_string(::getpid()));
    TemporaryFolder() { std::filesystem::create_directories(path); }
    ~TemporaryFolder() { std::filesystem::remove_all(path); }
};

TEST(WritePng, RoundTripThroughLibpng) {
    Image image;
    image.width = 7;
    image.height = 5;
    for (int i = 0; i < 7 * 5 * 3; ++i)
        image.rgb.push_back(static_cast<std::uint8_t>(i * 37 % 256));
    const TemporaryFolder folder;
    const std::filesystem::path file = folder.path / "round trip.png";
    write_png(file, image);

    png_image read{};
    read.version = PNG_IMAGE_VERSION;
    ASSERT_NE(png_image_begin_read_from_file(&read, file.c_str()), 0) << read.message;
    EXPECT_EQ(read.width, 7u);
    EXPECT_EQ(read.height, 5u);
    read.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(read));
    ASSERT_NE(png_image_finish_read(&read, nullptr, pixels.data(), 0, nullptr), 0) << read.message;
    EXPECT_EQ(pixels, image.rgb);
}

TEST(WritePng, NamesTheFileAndTheReasonWhenItCannotWrite) {
    Image image{1, 1, {0, 0, 0}};
    try {
        write_png("/nonexistent-dir/x.png", image);
        FAIL() << "no exception";
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("/nonexistent-dir/x.png"), std::string::npos) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
    image.rgb.pop_back();
    EXPECT_THROW(write_png("/tmp/never-written.png", image), std::invalid_argument);
}

}  // namespace
}  // namespace sxk::bezier
