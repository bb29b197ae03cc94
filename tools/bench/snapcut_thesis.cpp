// The snap cutter's experiments of thesis §3.3, beside the thesis' figures (issue 15):
//
//   cube      the 729-node, 3072-tetrahedron cube (make_kuhn_cube(8)), back face (y = 0) fixed,
//             dilating forces on the opposite face, E = 1e6, nu = 1/4; a large diagonal cut (the
//             blade in the plane through (3.85, 4, 3.5) with normal (1, -0.95, 0.97), its tip 1
//             below that point, swept across the cube in 16 steps). Faces dissected,
//             degenerates the snapping made, collapses, elements cut free, final size, and the
//             CG iterations to ||r|| < 1e-3 ||f|| after the cut, without and with degeneracy
//             removal (thesis: 108, 143, 99, 13, 3034 tets / 823 nodes, 2439 vs 236).
//   steps     the same cut in 1, 4, 16 and 64 steps (Fig. 3.17: the thesis' incisions came apart
//             when made in steps): faces dissected and the pieces of the incision (faces
//             joined through edges: 1 when it is connected).
//   cylinder  three pie-like cuts (blades along the axis moving to it from three sides) in the
//             Delaunay cylinder (make_delaunay of cylinder_cloud(4, 13): 896 vertices);
//             thesis: 4020 tetrahedra / 891 vertices, 873 faces dissected, collapses about 5% of
//             them.
//
//   snapcut_thesis OUTDIR     writes OUTDIR/{cube,cube-cut,cube-cut-raw,cylinder-cut}.mesh for
//                             pictures (tools/bench/run renders them; the cut cubes pulled open
//                             by a thousand times the load)
//
// stdout: one JSON line per figure (CONTRIBUTING.md "Benchmarks"), peer = the thesis' figure.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "degeneracy_plugin.hpp"
#include "figure_line.hpp"
#include "simulation.hpp"
#include "snap_cut.hpp"
#include "sxk/components.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace {

using sxk::Mesh;
using sxk::Point;
using sxk::snapcut::Scalpel;

void line(const std::string& name, const char* unit, double ours, double thesis, const char* better) {
    print_figure(name, unit, ours, thesis, "thesis", better);
}

Point unit(Point v) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / l, v[1] / l, v[2] / l};
}

Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The diagonal cut: the blade lies in the plane, along its upward in-plane direction w, tip at
// p0 + s u - 1 w, 10 long; s from -8 to 8 in `steps` steps (u: the horizontal in-plane direction).
std::vector<Scalpel> diagonal_cut(int steps) {
    const Point p0{3.85, 4.0, 3.5};
    const Point n = unit({1, -0.95, 0.97});
    const Point u = unit(cross(n, {0, 0, 1}));
    Point w = unit(cross(n, u));
    if (w[2] < 0) w = {-w[0], -w[1], -w[2]};
    std::vector<Scalpel> path;
    for (int i = 0; i <= steps; ++i) {
        const double s = -8 + 16.0 * i / steps;
        Scalpel scalpel;
        for (std::size_t k = 0; k < 3; ++k) {
            scalpel.tip[k] = p0[k] + s * u[k] - w[k];
            scalpel.handle[k] = scalpel.tip[k] + 10 * w[k];
        }
        path.push_back(scalpel);
    }
    return path;
}

struct Totals {
    std::size_t dissected = 0, degenerate = 0, collapses = 0, cut_free = 0, snapped = 0, refused = 0, loose = 0;
    double seconds = 0;
    double farthest = 0;  // the farthest corner of a face selected or opened from the swept surface
};

Totals cut(Mesh& mesh, const std::vector<Scalpel>& path, const sxk::snapcut::Options& options,
           const sxk::snapcut::CutServices& services) {
    auto session = sxk::snapcut::SnapCutSession::make(mesh, options, services).value();
    Totals totals;
    for (const Scalpel& scalpel : path) {
        if (auto stepped = session->cut(scalpel); !stepped) throw std::runtime_error(stepped.reason());
        const auto& r = session->last_step();
        totals.dissected += r.faces_dissected;
        totals.degenerate += r.degenerates_found;
        totals.collapses += r.collapses;
        totals.cut_free += r.cut_free;
        totals.snapped += r.nodes_snapped;
        totals.refused += r.nodes_refused;
        totals.loose += r.loose_pieces.size();
        totals.seconds += r.seconds;
        totals.farthest = std::max({totals.farthest, r.placement_error, r.incision_error});
    }
    session->end();
    return totals;
}

// Elements whose aspect ratio is below the thesis' threshold 0.01, in the reference positions.
std::size_t degenerates(const Mesh& mesh) {
    std::size_t count = 0;
    for (const sxk::ElementId t : sxk::elements(mesh)) {
        const sxk::Simplex s = mesh.simplex(t);
        const std::array<Point, 4> p{mesh.reference(s.vertex(0)), mesh.reference(s.vertex(1)),
                                     mesh.reference(s.vertex(2)), mesh.reference(s.vertex(3))};
        count += sxk::aspect_ratio(p) < 0.01;
    }
    return count;
}

// The pieces of the incision: the boundary faces with the cut label, joined when they share an
// edge (its two sides meet at its rim, so a connected incision is one piece).
std::size_t incision_pieces(const Mesh& mesh, int label) {
    std::vector<sxk::Simplex> faces;
    mesh.for_each_boundary_face([&](sxk::FaceId f) {
        const sxk::Simplex s = mesh.face_simplex(f);
        if (mesh.face_label(s) == label) faces.push_back(s);
    });
    std::vector<std::size_t> parent(faces.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto root = [&](std::size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    std::map<std::pair<sxk::VertexId, sxk::VertexId>, std::size_t> edge_owner;
    for (std::size_t i = 0; i < faces.size(); ++i)
        for (int a = 0; a < 3; ++a)
            for (int b = a + 1; b < 3; ++b) {
                const auto key = std::make_pair(faces[i].vertex(a), faces[i].vertex(b));
                const auto [it, fresh] = edge_owner.emplace(key, i);
                if (!fresh) parent[root(i)] = root(it->second);
            }
    std::set<std::size_t> roots;
    for (std::size_t i = 0; i < faces.size(); ++i) roots.insert(root(i));
    return roots.size();
}

// Every component not held yet is held on a face (hold_piece leaves held ones alone): a free
// piece makes the problem singular.
void hold_every_piece(const Mesh& mesh, sxk::Simulation& simulation) {
    const sxk::Components components = sxk::connected_components(mesh);
    std::vector<std::vector<sxk::ElementId>> pieces(components.count);
    for (const sxk::ElementId t : sxk::elements(mesh)) pieces[components.element_component[t]].push_back(t);
    for (const auto& piece : pieces) (void)simulation.hold_piece(piece).value();
}

const std::vector<std::string> cube_loads{"--fix", "y<0.001", "--force", "y>7.999:0,2000,0", "--E", "1e6",
                                          "--nu",  "0.25",    "--tol",   "1e-3", "--stop", "external"};

// The CG iterations to bring the body back to rest after the cut: the simulation settled before
// the cut, the cut made without relaxing, the pieces it cut loose held on a face (as the thesis
// fixes "all unfixed components"; a free piece makes the problem singular), then one relaxation
// from the pre-cut displacements (the thesis' "iterations needed to compute the deformation caused
// by the cut").
std::size_t iterations_after_cut(bool remove_degeneracies, Mesh* keep) {
    Mesh mesh = sxk::make_kuhn_cube(8).value();
    auto simulation = sxk::elasticity::simulate(mesh, sxk::cli::body_options(cube_loads).value()).value();
    (void)simulation->relax(100000).value();
    sxk::snapcut::Options options;
    options.remove_degeneracies = remove_degeneracies;
    (void)cut(mesh, diagonal_cut(16), options, {sxk::degeneracy::linked_in_service(), nullptr});
    hold_every_piece(mesh, *simulation);
    const auto relaxed = simulation->relax(20000).value();
    if (keep) *keep = mesh;
    return relaxed.converged ? relaxed.iterations : 20000;
}

// The cut mesh pulled open for the pictures: the same loads a thousand times larger (a 3% stretch,
// linear elasticity still), relaxed, written with its deformed positions.
void write_opened(const Mesh& cut_mesh, const std::filesystem::path& file) {
    Mesh mesh = cut_mesh;
    std::vector<std::string> loads = cube_loads;
    loads[3] = "y>7.999:0,2000000,0";
    auto simulation = sxk::elasticity::simulate(mesh, sxk::cli::body_options(loads).value()).value();
    hold_every_piece(mesh, *simulation);
    (void)simulation->relax(20000).value();
    sxk::write_mesh(mesh, file, {.drop_unused_vertices = true});
}

void cube_experiment(const std::filesystem::path& out) {
    Mesh cube = sxk::make_kuhn_cube(8).value();
    sxk::write_mesh(cube, out / "cube.mesh");
    Mesh raw = cube;
    sxk::snapcut::Options no_removal;
    no_removal.remove_degeneracies = false;
    const Totals snapped = cut(raw, diagonal_cut(16), no_removal, {sxk::degeneracy::linked_in_service(), nullptr});
    write_opened(raw, out / "cube-cut-raw.mesh");
    Mesh mesh = cube;
    const Totals t = cut(mesh, diagonal_cut(16), {}, {sxk::degeneracy::linked_in_service(), nullptr});
    write_opened(mesh, out / "cube-cut.mesh");
    line("cube: faces dissected", "faces", double(t.dissected), 108, "none");
    line("cube: degenerates made by snapping (aspect < 0.01)", "elements", double(degenerates(raw)), 143, "lower");
    line("cube: degenerates found by the removal", "elements", double(t.degenerate), 143, "lower");
    line("cube: collapses", "collapses", double(t.collapses), 99, "lower");
    line("cube: elements cut free (cracks)", "elements", double(t.cut_free), 13, "lower");
    line("cube: final tetrahedra", "elements", double(mesh.element_count()), 3034, "none");
    line("cube: final nodes", "vertices", double(mesh.vertices_in_elements()), 823, "none");
    line("cube: nodes snapped", "vertices", double(t.snapped), 0, "none");
    line("cube: snaps refused (would invert or flatten)", "vertices", double(t.refused), 0, "lower");
    line("cube: cut time, all 16 steps", "ms", t.seconds * 1e3, 0, "lower");
    line("cube: farthest corner of the cut from the sweeps", "h", t.farthest / sxk::mean_edge_length(cube), 0, "lower");
    (void)snapped;
    const std::size_t without = iterations_after_cut(false, nullptr);
    const std::size_t with = iterations_after_cut(true, nullptr);
    line("cube: CG iterations after the cut, degeneracies left", "iterations", double(without), 2439, "lower");
    line("cube: CG iterations after the cut, degeneracies removed", "iterations", double(with), 236, "lower");
}

void steps_experiment() {
    for (const int steps : {1, 4, 16, 64}) {
        Mesh mesh = sxk::make_kuhn_cube(8).value();
        const Totals t = cut(mesh, diagonal_cut(steps), {}, {sxk::degeneracy::linked_in_service(), nullptr});
        const std::string name = "cube in " + std::to_string(steps) + " steps: ";
        line(name + "faces dissected", "faces", double(t.dissected), 108, "none");
        line(name + "pieces of the incision", "pieces", double(incision_pieces(mesh, sxk::snapcut::Options{}.cut_label)),
             1, "lower");
    }
}

// A blade along the cylinder's axis (z from -1 to 14), at angle `angle`, moving from radius 5.5
// to the axis in 8 steps.
std::vector<Scalpel> pie_cut(double angle) {
    std::vector<Scalpel> path;
    for (int i = 0; i <= 8; ++i) {
        const double r = 5.5 * (1 - i / 8.0);
        const double x = r * std::cos(angle), y = r * std::sin(angle);
        path.push_back({{x, y, 14}, {x, y, -1}});
    }
    return path;
}

void cylinder_experiment(const std::filesystem::path& out) {
    Mesh mesh = sxk::make_delaunay(sxk::cylinder_cloud(4, 13)).value();
    line("cylinder: tetrahedra", "elements", double(mesh.element_count()), 4020, "none");
    line("cylinder: vertices", "vertices", double(mesh.vertex_count()), 891, "none");
    Totals all;
    for (const double angle : {0.3, 0.3 + 2 * std::numbers::pi / 3, 0.3 + 4 * std::numbers::pi / 3}) {
        const Totals t = cut(mesh, pie_cut(angle), {}, {sxk::degeneracy::linked_in_service(), nullptr});
        all.dissected += t.dissected;
        all.collapses += t.collapses;
        all.cut_free += t.cut_free;
        all.degenerate += t.degenerate;
    }
    sxk::write_mesh(mesh, out / "cylinder-cut.mesh", {.drop_unused_vertices = true});
    line("cylinder: faces dissected (3 pie cuts)", "faces", double(all.dissected), 873, "none");
    line("cylinder: collapses per face dissected", "%", 100.0 * double(all.collapses) / double(all.dissected), 5,
         "lower");
    line("cylinder: elements cut free", "elements", double(all.cut_free), 0, "lower");
    line("cylinder: degenerates found", "elements", double(all.degenerate), 0, "lower");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: snapcut_thesis OUTDIR\n");
        return 2;
    }
    const std::filesystem::path out = argv[1];
    std::filesystem::create_directories(out);
    try {
        cube_experiment(out);
        steps_experiment();
        cylinder_experiment(out);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "snapcut_thesis: %s\n", error.what());
        return 1;
    }
    return 0;
}
