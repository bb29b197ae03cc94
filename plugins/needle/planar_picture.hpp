// `sxk needle --frames` for planar meshes: the mesh's edges in the deformed positions, the needle
// over them (red) and its nodes (blue sticking, orange slipping), drawn with the shared pictures
// (Cairo) - what the thesis' Figs. 6.9 and 6.12 show. Tetrahedral meshes go to the bezier plug-in's
// renderer instead (tool_frames.hpp).
#pragma once

#include <array>
#include <string>

#include "needle.hpp"
#include "planar_drawing.hpp"

namespace sxk::needle {

// The box a replay's pictures show: the mesh's deformed positions as they are, grown by a tenth.
std::array<double, 4> picture_view(const Mesh& mesh);

pictures::Drawing planar_picture(const Mesh& mesh, const NeedleSession& session, const std::array<double, 4>& view,
                                 const std::string& title);

}  // namespace sxk::needle
