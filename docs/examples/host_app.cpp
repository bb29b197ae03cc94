// An application hosting simplexkit plug-ins in its own process (docs/plugins.md).
//
// It builds a mesh in code — the unit cube cut into six tetrahedra around its diagonal (the
// Freudenthal/Kuhn subdivision) — loads the plug-ins with its own PluginHost (no global
// registry: the host is an object this program owns), and runs the stats plug-in's command on
// the mesh in memory instead of on a file.
//
//        6-------7          vertex v sits at (v & 1, v >> 1 & 1, v >> 2 & 1); every tetrahedron
//       /|      /|          walks from 0 to 7 along three cube edges, one per axis, in one of
//      4-------5 |          the six axis orders, so all six share the diagonal 0-7
//      | 2-----|-3
//      |/      |/
//      0-------1
#include <algorithm>
#include <array>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "sxk/components.hpp"
#include "sxk/mesh.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/predicates.hpp"

namespace {

sxk::Mesh unit_cube() {
    sxk::Mesh mesh(3, 3);
    for (int v = 0; v < 8; ++v) mesh.add_vertex({double(v & 1), double(v >> 1 & 1), double(v >> 2 & 1)});
    std::vector<sxk::Simplex> tetrahedra;
    std::array<int, 3> axes{0, 1, 2};
    do {
        std::array<sxk::VertexId, 4> path{0, 0, 0, 0};
        for (int step = 0; step < 3; ++step) path[step + 1] = path[step] | (1u << axes[step]);
        // half of the axis orders turn the other way: keep every element positive
        const auto& p = mesh.reference_positions();
        if (sxk::orient3d(p[path[0]], p[path[1]], p[path[2]], p[path[3]]) == sxk::Sign::negative)
            std::swap(path[2], path[3]);
        tetrahedra.emplace_back(+1, std::span<const sxk::VertexId>(path));
    } while (std::next_permutation(axes.begin(), axes.end()));
    if (auto built = mesh.assign_elements(tetrahedra); !built)
        std::cerr << "host_app: cannot build the cube: " << built.reason() << '\n';
    return mesh;
}

}  // namespace

int main() {
    const sxk::Mesh cube = unit_cube();
    if (auto valid = cube.validate(); !valid) {
        std::cerr << "host_app: invalid cube: " << valid.reason() << '\n';
        return 1;
    }
    std::cout << "cube: " << cube.element_count() << " tetrahedra, " << cube.boundary_face_count()
              << " boundary triangles, " << sxk::connected_components(cube).count << " component\n";

    sxk::PluginHost host;
    host.load_default_folders();
    for (const sxk::PluginDiagnostic& diagnostic : host.diagnostics())
        std::cerr << "host_app: warning: " << diagnostic.path.string() << ": " << diagnostic.reason << '\n';
    for (const sxk::LoadedPlugin& plugin : host.plugins())
        std::cout << "plug-in " << plugin.name << ' ' << plugin.version << " from " << plugin.path.string() << '\n';

    const std::vector<std::string> command{"stats"};
    const sxk::FoundCommand stats = host.find_command(command);
    if (stats.command == nullptr || !stats.command->accepts_mesh()) {
        std::cerr << "host_app: the stats plug-in is not available\n";
        return 1;
    }
    const std::vector<std::string> options{"--bins", "6"};
    return stats.command->run_on_mesh(cube, "unit cube", options, std::cout, std::cerr);
}
