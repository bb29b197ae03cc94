// The bezier plug-in's service "sxk.render": pictures of meshes for other plug-ins (the tool
// commands' `--frames`, one picture per step) and for applications. Installed:
//
//     auto renderer = host.service<sxk::bezier::RenderService>();
//     sxk::bezier::MeshPicture picture = (*renderer)->frame_view(mesh, 640 * 480);  // size, camera
//     picture.colour = sxk::bezier::Colouring::piece;
//     picture.title = "after the cut";
//     (*renderer)->draw_mesh(mesh, "step-0001.png", picture);
//
// `sxk render MESH OUT` draws the same pictures from its words (--size, --camera, --fov, --colour,
// --cut-label, --tool, --title, --explode; docs/cli.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"

namespace sxk::bezier {

// Where a picture is taken from: the eye looks at the target, `up` (not along the view) upwards.
struct View {
    Point eye{0, -10, 0};
    Point target{0, 0, 0};
    Point up{0, 0, 1};
};

// How a mesh's faces are coloured: by the element's aspect ratio (red bad, blue good, with a
// colour bar), by element label, by connected component, or grey. Faces on a cut are magenta
// whatever the colouring, seen through the body where it hides them.
enum class Colouring : std::uint8_t { quality, label, piece, plain };

struct MeshPicture {
    int width = 640, height = 480;  // pixels, each 1..16384, at most 2^26 in all
    // none: the body framed from direction (1, -2, 1.2), z up (a planar mesh from +z, y up)
    std::optional<View> camera;
    double fov = 40;  // vertical field of view, degrees
    Colouring colour = Colouring::quality;
    int cut_label = 9999;     // boundary faces with this label are drawn as cut faces too
    std::vector<Point> tool;  // drawn over the picture: none, a point, a segment or a triangle
    std::string title;        // a line of text at the top left
    double explode = 0;       // each piece moved away from the middle by this times its distance, 0..10

    // The ranges, bad_argument naming the field ("render: fov 180 is not in (0, 180)"). A camera
    // whose eye and target coincide, or whose up lies along the view, draw_mesh refuses.
    Outcome<Done> check() const {
        using namespace option_checks;
        constexpr std::string_view name = "render";
        if (tool.size() > 3)
            return Refusal{RefusalCode::bad_argument,
                           "render: tool has " + std::to_string(tool.size()) +
                               " points; a tool is a point, a segment or a triangle"};
        if (static_cast<long long>(width) * height > (1LL << 26) && width <= 16384 && height <= 16384 && width > 0 &&
            height > 0)
            return Refusal{RefusalCode::bad_argument, "render: " + std::to_string(width) + "x" +
                                                          std::to_string(height) +
                                                          " pixels are more than the 67108864 allowed (8192x8192)"};
        return first_refusal({
            in(name, "width", static_cast<std::size_t>(width < 0 ? 0 : width), 1, 16384),
            in(name, "height", static_cast<std::size_t>(height < 0 ? 0 : height), 1, 16384),
            in(name, "fov", fov, {0, 180, true, true}),
            in(name, "explode", explode, {0, 10}),
        });
    }
};

struct RenderService {
    static constexpr std::string_view service_id = "sxk.render";
    // 2: frame_view; 3: typed MeshPicture and View instead of `sxk render`'s words
    static constexpr std::uint32_t service_version = 3;

    // Draws the boundary of `mesh` (its deformed positions) to the PNG `output`, as `sxk render`
    // would. Refuses a picture out of range (check(), a camera that cannot see) or an output that
    // is not *.png (bad_argument), a mesh without elements or a picture that cannot be written
    // (not_applicable).
    Outcome<Done> (*draw_mesh)(const Mesh& mesh, const std::filesystem::path& output, const MeshPicture& picture);
    // The view `sxk render` chooses for `mesh` as it is now (its default direction, the deformed
    // positions of the vertices in elements framed at the default field of view): keeps one view
    // over pictures of a changing mesh.
    View (*default_camera)(const Mesh& mesh);
    // A picture's size and camera for every picture of a run that starts from `mesh` as it is
    // now: the body fills the picture, whose shape follows the body's (width / height within
    // [0.4, 2.5], about `pixels` pixels, even sides), with a margin of 8 % for what moves. The
    // other fields are MeshPicture's defaults.
    MeshPicture (*frame_view)(const Mesh& mesh, long long pixels);
};

}  // namespace sxk::bezier
