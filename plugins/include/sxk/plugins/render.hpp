// The bezier plug-in's service: pictures of meshes for other plug-ins (the snap cutter's
// `--frames`, one picture per step) and for applications that load bezier.so at run time:
//
//     auto renderer = host.service<sxk::bezier::RenderService>();
//     (*renderer)->draw_mesh(mesh, "step-0001.png", {"--colour", "plain", "--camera", "..."});
//
// The options are `sxk render`'s for a mesh (docs/cli.md): --size, --camera, --fov, --colour,
// --cut-label, --tool, --title, --explode. This header carries only the kernel's types.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::bezier {

struct RenderService {
    static constexpr std::string_view service_id = "sxk.render";
    static constexpr std::uint32_t service_version = 2;  // 2: frame_view

    // Draws the boundary of `mesh` (its deformed positions) to the PNG `output` as `sxk render
    // MESH OUTPUT OPTIONS...` would, faces on a cut in magenta (seen through the body where it
    // hides them). Refuses with the command's
    // message (without its "sxk: "): bad options or output name (bad_argument), a mesh without
    // elements or a picture that cannot be written (not_applicable).
    Outcome<Done> (*draw_mesh)(const Mesh& mesh, const std::filesystem::path& output,
                               std::span<const std::string> options);
    // The camera `sxk render` chooses for `mesh` as it is now (its default view of the deformed
    // positions of the vertices in elements, default field of view), as `--camera` takes it:
    // pass it to draw_mesh to keep one view over pictures of a changing mesh.
    std::string (*default_camera)(const Mesh& mesh);
    // The size and camera for every picture of a run that starts from `mesh` as it is now, as
    // the words {"--size", "WxH", "--camera", "..."}: the body fills the picture, whose shape
    // follows the body's (width / height within [0.4, 2.5], about `pixels` pixels, even sides),
    // with a margin of 8 % for what moves.
    std::vector<std::string> (*frame_view)(const Mesh& mesh, long long pixels);
};

}  // namespace sxk::bezier
