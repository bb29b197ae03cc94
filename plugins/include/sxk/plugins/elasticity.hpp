// The elasticity plug-in's service "sxk.elasticity" (thesis §2-4, §6.3): a simulation of a mesh's
// body, for applications and for the tools that cut or pierce a deforming body. Installed:
//
//     auto elasticity = host.service<sxk::elasticity::ElasticityService>();
//     sxk::elasticity::Options body;
//     body.fix = {"z<0.001"};                         // a vertex selection (below)
//     body.force = {{"z>7.99", {0, 0, -100}}};        // a total force on the selected vertices
//     body.young = 1e4;
//     auto simulation = (*elasticity)->simulate(mesh, body);
//     (*simulation)->relax(100000);      // the loaded shape: mesh.deformed() now shows it
//     ... edit the mesh (the body follows every edit), or give the simulation to a tool session
//     (ToolContext::simulation, sxk/tool_session.hpp) ...
//     (*simulation)->relax(200);         // per frame: a bounded number of CG iterations, warm start
//
// Vertex selections are terms joined by '&', a vertex selected when every term holds for it:
// `x<0.001`, `y>=0.2`, `z=1` (a reference coordinate against a number; < <= > >= =, '=' exact),
// `label=N` (a corner of an element labelled N), `boundary` (a corner of a boundary face). Only
// vertices in elements are selected. `sxk deform` reads the same options from its words (--fix,
// --force, --E, ...; docs/cli.md), and its refusals name the options by those words.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"
#include "sxk/simulation.hpp"

namespace sxk::elasticity {

// The material model.
enum class Model : std::uint8_t {
    linear,      // linear elasticity, small strains (§3.1; eq. 6.3 for triangles)
    neohookean,  // compressible neo-Hookean, large strains, nonlinear CG (eq. 4.6, §4.5; eq. 6.4's 2D analogue)
};
// How a force is shared among the vertices it selects: the same part each, or by the boundary
// area around each vertex (a uniform traction on the selected boundary).
enum class Share : std::uint8_t { equal, area };
// What the tolerance is relative to (thesis eq. 6.9): the loads and the reactions that hold the
// fixed vertices, or the loads only (eq. 6.8, the thesis' chapters 3 and 4).
enum class Stop : std::uint8_t { reactions, external };

// A vector on the vertices a selection selects: a prescribed displacement (m), or a total force
// (N) shared among them.
struct Load {
    std::string where;
    Vector3 value{0, 0, 0};
};

struct Options {
    std::vector<std::string> fix;  // vertices held in place
    std::vector<Load> displace;    // vertices moved by a prescribed displacement
    std::vector<Load> force;       // total forces, shared as `share` says
    Share share = Share::equal;
    std::optional<Vector3> gravity;  // an acceleration on every element's mass (m/s^2)
    double density = 1000;           // mass per volume for gravity (kg/m^3)
    Model model = Model::linear;
    double young = 1e6;                // Young's modulus E
    double poisson = 0.25;             // Poisson's ratio nu
    std::optional<double> thickness;   // a triangle mesh's slab (plane stress; 1 when not given)
    double tolerance = 1e-6;           // relative residual (eq. 6.9)
    double rounding = 1e-12;           // epsilon_round of eq. 6.9, relative to E times the area
    std::size_t max_iterations = 100000;  // CG iterations before giving up
    Stop stop = Stop::reactions;

    // The ranges; bad_argument naming the field ("elasticity: poisson 0.5 is not in (-1, 0.5)").
    // The selections are read by simulate, which refuses one that does not parse or selects no
    // vertex, and a body nothing holds.
    Outcome<Done> check() const {
        using namespace option_checks;
        constexpr std::string_view tool = "elasticity";
        return first_refusal({
            in(tool, "density", density, {0, 1e300, true, false}),
            in(tool, "young", young, {0, 1e300, true, false}),
            in(tool, "poisson", poisson, {-1, 0.5, true, true}),
            thickness ? in(tool, "thickness", *thickness, {0, 1e300, true, false}) : std::nullopt,
            in(tool, "tolerance", tolerance, {0, 1, true, true}),
            in(tool, "rounding", rounding, {0, 1, false, true}),
            in(tool, "max_iterations", max_iterations, 1, 100000000),
        });
    }
};

struct ElasticityService {
    static constexpr std::string_view service_id = "sxk.elasticity";
    // 2: vertices a tool holds; 3: relax_near, relax_far; 4: follow_far_field;
    // 5: RelaxReport::not_shown; 6: typed Options, Simulation in sxk/simulation.hpp
    static constexpr std::uint32_t service_version = 6;

    // A simulation of `mesh` (which must stay where it is while the simulation lives) with the
    // constraints and loads of `options`, not yet solved. Refuses options out of range
    // (bad_argument), a selection that does not parse or selects no vertex ("--fix 'x<9' selects
    // no vertex of the mesh", bad_argument), a body nothing holds, and a mesh with an element
    // flat at rest.
    Outcome<std::unique_ptr<Simulation>> (*simulate)(Mesh& mesh, const Options& options);
};

}  // namespace sxk::elasticity
