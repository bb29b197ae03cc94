// Uses an installed simplexkit: builds two triangles, checks them, counts components, and runs
// the installed stats plug-in on them through a PluginHost.
//
//   3 ---- 2
//   |    / |     the unit square as two counter-clockwise triangles <0,1,2> and <0,2,3>
//   |  /   |
//   0 ---- 1
#include <array>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <sxk/components.hpp>
#include <sxk/mesh.hpp>
#include <sxk/plugin_host.hpp>

int main() {
    sxk::Mesh square(2, 2);
    for (const sxk::Point& p : std::array<sxk::Point, 4>{sxk::Point{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})
        square.add_vertex(p);
    const std::array<sxk::Simplex, 2> triangles{sxk::Simplex(+1, {0, 1, 2}), sxk::Simplex(+1, {0, 2, 3})};
    if (auto built = square.assign_elements(triangles); !built || !square.validate()) {
        std::cerr << "outside_app: cannot build the square\n";
        return 1;
    }
    std::cout << "square: " << square.element_count() << " triangles, " << sxk::connected_components(square).count
              << " component\n";

    sxk::PluginHost host;
    host.load_default_folders();
    for (const auto& diagnostic : host.diagnostics())
        std::cerr << "outside_app: warning: " << diagnostic.path.string() << ": " << diagnostic.reason << '\n';
    const std::vector<std::string> command{"stats"};
    const sxk::FoundCommand stats = host.find_command(command);
    if (stats.command == nullptr) {
        std::cerr << "outside_app: no stats plug-in in " << SIMPLEXKIT_PLUGIN_DIR << '\n';
        return 1;
    }
    const auto expected = std::filesystem::weakly_canonical(SIMPLEXKIT_PLUGIN_DIR);
    if (stats.plugin->path.parent_path() != expected) {
        std::cerr << "outside_app: stats loaded from " << stats.plugin->path << ", expected it in " << expected << '\n';
        return 1;
    }
    std::cout << "stats " << stats.plugin->version << " from " << stats.plugin->path.string() << '\n';
    const std::vector<std::string> options{"--bins", "4", "--json"};
    return stats.command->run_on_mesh(square, "square", options, std::cout, std::cerr);
}
