// Uses an installed simplexkit to cut a deforming body, as `sxk cut snap --deform` does, through
// typed options only: the elasticity plug-in's simulation of a Kuhn cube (held at y = 0, pulled
// at y = 6), the snapcut plug-in's tool given that simulation, ten movements of a scalpel through
// the middle of the cube, every step undone and redone, and the cube back as it was byte for byte.
//
//   outside_cut      prints "cut: 11 steps, N cut faces, undone byte for byte, redone byte for byte"
#include <algorithm>
#include <array>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sxk/generators.hpp>
#include <sxk/mesh.hpp>
#include <sxk/plugin_host.hpp>
#include <sxk/plugins/elasticity.hpp>
#include <sxk/plugins/snapcut.hpp>
#include <sxk/simulation.hpp>

namespace {

// Everything a cut and its undo may change, exactly (hexadecimal floating point): both positions
// of every vertex, every element's corners and label, every boundary face's label (the faces
// sorted: the order in which the mesh visits them may differ after an undo).
std::string state_of(const sxk::Mesh& mesh) {
    std::ostringstream text;
    text << std::hexfloat;
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == sxk::invalid_id) continue;
        for (const double x : mesh.reference(v)) text << x << ' ';
        for (const double x : mesh.deformed(v)) text << x << ' ';
        text << '\n';
    }
    for (const sxk::ElementId t : sxk::elements(mesh)) {
        for (const sxk::VertexId v : mesh.simplex(t).vertices()) text << v << ' ';
        text << mesh.label(t) << '\n';
    }
    std::vector<std::string> faces;
    mesh.for_each_boundary_face([&](sxk::FaceId f) {
        const sxk::Simplex face = mesh.face_simplex(f);
        std::string line;
        for (const sxk::VertexId v : face.vertices()) line += std::to_string(v) + ' ';
        faces.push_back(line + std::to_string(mesh.face_label(face).value_or(-1)));
    });
    std::sort(faces.begin(), faces.end());
    for (const std::string& face : faces) text << face << '\n';
    return text.str();
}

int fail(const std::string& why) {
    std::cerr << "outside_cut: " << why << '\n';
    return 1;
}

}  // namespace

int main() {
    auto made = sxk::make_kuhn_cube(6);
    if (!made) return fail(made.reason());
    sxk::Mesh cube = std::move(*made);

    sxk::PluginHost host;
    host.load_default_folders();
    auto elasticity = host.service<sxk::elasticity::ElasticityService>();
    if (!elasticity) return fail(elasticity.reason());

    // the body: held at y = 0, pulled along y at y = 6, as `--deform "--fix y<0.001 --force
    // y>5.99:0,2000,0 --E 1e5"` says it
    sxk::elasticity::Options body;
    body.fix = {"y<0.001"};
    body.force = {{"y>5.99", {0, 2000, 0}}};
    body.young = 1e5;
    auto simulation = (*elasticity)->simulate(cube, body);
    if (!simulation) return fail(simulation.reason());
    if (auto rest = (*simulation)->relax(100000); !rest || !rest->converged) return fail("the body does not settle");
    const std::string loaded = state_of(cube);

    sxk::snapcut::Options cut;  // the thesis' snap cut: snapping, degeneracy removal, crumbs
    cut.relax_iterations = 50;
    auto session = host.begin_tool(cube, cut, {.simulation = simulation->get()});
    if (!session) return fail(session.reason());
    // the blade upright at x = 3.3, from below the cube to above it, moved across it along y
    std::vector<sxk::snapcut::Scalpel> path;
    for (int i = 0; i <= 10; ++i) {
        const double y = -1 + 0.8 * i;
        path.push_back({{3.3, y, 7}, {3.3, y, -1}});
    }
    for (const sxk::snapcut::Scalpel& scalpel : path)
        if (auto step = (*session)->step(sxk::snapcut::to_pose(scalpel)); !step) return fail(step.reason());
    if (auto valid = cube.validate(); !valid) return fail("the cut mesh is not valid: " + valid.reason());
    std::size_t cut_faces = 0;
    cube.for_each_boundary_face([&](sxk::FaceId f) { cut_faces += cube.face_label(cube.face_simplex(f)) == cut.cut_label; });
    if (cut_faces == 0) return fail("nothing was cut");
    const std::string after = state_of(cube);
    const std::size_t steps = (*session)->steps();

    // every step back: the cube as loaded, exactly; then every step again: the cut, exactly (the
    // mesh and the cutter's state beside it go back and forth together)
    if (auto back = (*session)->cancel(); !back) return fail(back.reason());
    if (state_of(cube) != loaded) return fail("undoing every step did not give the loaded cube back");
    for (std::size_t i = 0; i < steps; ++i)
        if (auto again = (*session)->redo_step(); !again) return fail(again.reason());
    if (state_of(cube) != after) return fail("redoing every step did not give the cut back");
    if (auto back = (*session)->cancel(); !back || state_of(cube) != loaded) return fail("the second undo differs");

    std::cout << "cut: " << steps << " steps, " << cut_faces << " cut faces, undone byte for byte, redone byte for byte\n";
    return 0;
}
