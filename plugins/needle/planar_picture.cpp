// Pictures of a planar mesh with the needle (planar_picture.hpp).
#include "planar_picture.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace sxk::needle {

std::array<double, 4> picture_view(const Mesh& mesh) {
    const double inf = std::numeric_limits<double>::infinity();
    std::array<double, 4> box{inf, inf, -inf, -inf};
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == invalid_id) continue;
        const Point& p = mesh.deformed(v);
        box = {std::min(box[0], p[0]), std::min(box[1], p[1]), std::max(box[2], p[0]), std::max(box[3], p[1])};
    }
    const double grow = 0.1 * std::max(box[2] - box[0], box[3] - box[1]);
    return {box[0] - grow, box[1] - grow, box[2] + grow, box[3] + grow};
}

pictures::Drawing planar_picture(const Mesh& mesh, const NeedleSession& session, const std::array<double, 4>& view,
                                 const std::string& title) {
    pictures::Drawing drawing;
    drawing.title = title;
    drawing.view = view;
    auto at = [&](VertexId v) { return std::array<double, 2>{mesh.deformed(v)[0], mesh.deformed(v)[1]}; };
    for (const ElementId t : elements(mesh)) {
        const auto v = mesh.simplex(t).vertices();
        // an interior edge is drawn by both its triangles, the same line twice
        for (int k = 0; k < 3; ++k) drawing.segments.push_back({at(v[k]), at(v[(k + 1) % 3]), {0.55, 0.55, 0.55}, 0.8});
    }
    if (const auto& needle = session.needle())
        drawing.segments.push_back(
            {{needle->base[0], needle->base[1]}, {needle->tip[0], needle->tip[1]}, {0.84, 0.15, 0.16}, 2.5});
    for (const NeedleNode& node : session.nodes())
        drawing.dots.push_back({at(node.vertex),
                                node.grip == Grip::stick ? pictures::Colour{0.12, 0.47, 0.71}
                                                         : pictures::Colour{1.0, 0.5, 0.05},
                                3.5});
    return drawing;
}

}  // namespace sxk::needle
