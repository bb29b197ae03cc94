// What degeneracy removal saves the relaxation on a real mesh (issue 14; thesis §3.3: 2439 CG
// iterations after a cut of its cube, 236 with the degenerates removed). Not a Google Benchmark:
// one solve per mesh, counted in iterations (the figure the thesis gives), timed by the report.
//
//   relax_after_degeneracies NAME=MESH.ele
//
// The mesh (the femur) is solved three times, clamped below 5% of its z extent and pushed
// sideways (x, 100 N shared equally) above 95%, E = 1e4, nu = 0.3, to ||r|| < 1e-3 ||f|| (the
// thesis' interactive tolerance): as read; snapped as the degeneracy tests snap it (every vertex
// within h/3 of the plane through the centre of the bounding box with normal (0.3, 1, 0.12)),
// stopped after twice the first solve's iterations; and after remove_degeneracies on the stars of
// the moved vertices (what a cutter would hand it). stdout: JSON lines (CONTRIBUTING.md
// "Benchmarks"), the snapped solve as the peer of the other two.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "elastic_body.hpp"
#include "remove_degeneracies.hpp"
#include "snap_to_plane.hpp"
#include "solve.hpp"
#include "sxk/io.hpp"
#include "sxk/quality.hpp"

namespace {

namespace el = sxk::elasticity;
namespace dg = sxk::degeneracy;

el::SolveReport relax(const sxk::Mesh& mesh, std::size_t max_iterations) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const sxk::ElementId t : sxk::elements(mesh))
        for (const sxk::VertexId v : mesh.simplex(t).vertices()) {
            low = std::min(low, mesh.reference(v)[2]);
            high = std::max(high, mesh.reference(v)[2]);
        }
    auto body = el::ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.3});
    if (!body)
        throw std::runtime_error(body.reason());
    std::vector<sxk::VertexId> top;
    for (sxk::VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == sxk::invalid_id)
            continue;
        const double z = mesh.reference(v)[2];
        if (z < low + 0.05 * (high - low))
            (void)body->fix(v);
        else if (z > high - 0.05 * (high - low))
            top.push_back(v);
    }
    for (const sxk::VertexId v : top)
        (void)body->add_force(v, {100.0 / static_cast<double>(top.size()), 0, 0});
    auto report = el::solve_linear_cg(*body, {.tolerance = 1e-3,
                                              .max_iterations = max_iterations,
                                              .stop = el::StopCriterion::external_force});
    if (!report)
        throw std::runtime_error(report.reason());
    return *report;
}

double least_aspect_ratio(const sxk::Mesh& mesh) {
    double least = 1;
    for (const sxk::ElementId t : sxk::elements(mesh))
        least = std::min(
            least, sxk::aspect_ratio(sxk::element_points(mesh, t, sxk::Positions::reference)));
    return least;
}

void line(const std::string& name, const el::SolveReport& ours, const el::SolveReport& peer) {
    std::printf(
        "{\"name\": \"%s\", \"unit\": \"CG iterations\", \"ours\": %zu, \"peer\": %zu, "
        "\"peer_name\": "
        "\"snapped, degenerates kept%s\", \"ratio\": %.4g, \"better\": \"lower\", \"converged\": "
        "%s, "
        "\"seconds\": %.2f}\n",
        name.c_str(), ours.iterations, peer.iterations,
        peer.converged ? "" : " (stopped, not converged)",
        static_cast<double>(ours.iterations) / static_cast<double>(peer.iterations),
        ours.converged ? "true" : "false", ours.seconds);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string argument = argc == 2 ? argv[1] : "";
    const auto equals = argument.find('=');
    if (equals == std::string::npos || equals == 0) {
        std::fputs("usage: relax_after_degeneracies NAME=MESH.ele\n", stderr);
        return 2;
    }
    const std::string name = argument.substr(0, equals);
    try {
        const sxk::Mesh mesh = sxk::read_mesh(argument.substr(equals + 1));
        const el::SolveReport unsnapped = relax(mesh, 100000);
        std::fprintf(stderr, "relax: %s as read: %zu iterations, %.1f s, least aspect ratio %.3g\n",
                     name.c_str(), unsnapped.iterations, unsnapped.seconds,
                     least_aspect_ratio(mesh));
        sxk::Mesh snapped = mesh;
        const dg::SnapReport snap =
            dg::snap_to_plane(snapped, dg::plane_through_centre(snapped, {0.3, 1, 0.12}),
                              sxk::mean_edge_length(snapped) / 3);
        const el::SolveReport before = relax(snapped, 2 * unsnapped.iterations);
        std::fprintf(stderr,
                     "relax: %s snapped (%zu vertices moved): %zu iterations%s, |r| %.3g (needed "
                     "%.3g), %.1f s, "
                     "least aspect ratio %.3g\n",
                     name.c_str(), snap.moved.size(), before.iterations,
                     before.converged ? "" : " without converging", before.residual,
                     before.threshold, before.seconds, least_aspect_ratio(snapped));
        const auto removed =
            dg::remove_degeneracies(snapped, dg::elements_around(snapped, snap.moved));
        if (!removed)
            throw std::runtime_error(removed.reason());
        const el::SolveReport after = relax(snapped, 100000);
        std::fprintf(stderr,
                     "relax: %s after removing %zu degenerates: %zu iterations, %.1f s, least "
                     "aspect ratio %.3g\n",
                     name.c_str(), removed->found, after.iterations, after.seconds,
                     least_aspect_ratio(snapped));
        line("elasticity/relax/" + name + "/unsnapped", unsnapped, before);
        line("elasticity/relax/" + name + "/after_degeneracy_removal", after, before);
        return unsnapped.converged && after.converged ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "relax_after_degeneracies: %s\n", e.what());
        return 1;
    }
}
