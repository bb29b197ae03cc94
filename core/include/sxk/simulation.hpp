// A simulation of a mesh's body, as a tool sees it: what a cutter or a needle asks of the body it
// edits (thesis §3.3: the snap cutter relaxes the body after every cut step; §6.3.2: the needle
// holds the vertices on its shaft). The elasticity plug-in implements it (sxk/plugins/elasticity.hpp:
// ElasticityService::simulate); an application makes one and gives it to a tool session
// (ToolContext, sxk/tool_session.hpp), so the session keeps the body in step with its cuts.
//
//     auto simulation = (*elasticity)->simulate(mesh, body_options);
//     (*simulation)->relax(100000);          // the loaded shape: mesh.deformed() now shows it
//     auto session = host.begin_tool(mesh, snapcut_options, {.simulation = simulation->get()});
//     (*session)->step(pose);                 // the cut, then a relaxation of the body
//
// A simulation is attached to its mesh (it follows the mesh's edits, thesis §7.4) and the mesh
// must stay where it is while the simulation lives.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "sxk/ids.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

// A displacement or a force (x, y, z; a planar body ignores z).
using Vector3 = std::array<double, 3>;

// What one relax call did.
struct RelaxReport {
    std::size_t iterations = 0;  // CG steps of this call
    bool converged = false;      // the residual reached the stop criterion (eq. 6.9)
    double residual = 0, threshold = 0;
    bool shown = false;  // the deformed positions were written (not when they would invert an element)
    std::optional<Refusal> not_shown = std::nullopt;  // when not shown: why
    double seconds = 0;
    // relax_near: the vertices solved for, and the elements around them (0, 0: the whole body)
    std::size_t region_vertices = 0, region_elements = 0;
};

// A body on a mesh, attached to it (it follows the mesh's edits, thesis §7.4), with the
// constraints and loads of its options (for the elasticity plug-in's, sxk/plugins/elasticity.hpp).
class Simulation {
public:
    virtual ~Simulation() = default;
    // At most `iterations` more CG iterations (and at most the options' max_iterations) from the
    // current displacements (a warm start), then
    // the deformed positions reference + u written into the mesh (one move_vertices: watchers and
    // an open EditJournal step see it) unless they would invert or flatten an element. Refuses
    // when the body cannot be brought in step with the mesh (an element flat at rest: remove
    // degeneracies first).
    virtual Outcome<RelaxReport> relax(std::size_t iterations) = 0;
    // The same confined to the vertices around `seeds` (where a tool changed the constraints): the
    // seeds and their neighbours ring by ring up to `max_vertices` vertices, every other vertex
    // held where it is (LocalRelaxation, local_relaxation.hpp: why, and what it gives up), and
    // only the region's deformed positions written. Its cost is bounded by max_vertices whatever
    // the mesh's size; the far field settles at the next relax (or by relax_far). A neo-Hookean
    // body relaxes whole (region_vertices 0 in the report).
    virtual Outcome<RelaxReport> relax_near(std::span<const VertexId> seeds, std::size_t iterations,
                                            std::size_t max_vertices) = 0;
    // One block of the far field's relaxation, for the frames after relax_near: the rims that
    // relax_near and relax_far held are remembered with the force out of balance there, and this
    // solves, as relax_near does, the region of up to max_vertices around the rim vertex most out
    // of balance now. Called after relax_near every frame, it lets the far field follow the tool
    // at a bounded cost per frame (Southwell's relaxation, by blocks). Nothing to do (no
    // remembered vertex out of balance by more than the last relax_near's tolerance per vertex):
    // a report with region_vertices 0. A neo-Hookean body: nothing to do (relax_near relaxed it
    // whole).
    virtual Outcome<RelaxReport> relax_far(std::size_t iterations, std::size_t max_vertices) = 0;
    // Whether relax_near and relax_far remember their rims for relax_far (the default: yes).
    // Measuring how far out of balance a rim is costs about a sixth of a local solve on the femur,
    // so a tool that never calls relax_far says no; relax_far then finds nothing to do.
    virtual void follow_far_field(bool follow) = 0;
    // A piece that came loose (thesis §3.3: "all unfixed components are fixed on an arbitrary
    // face"): unless a vertex of it is held already, the corners of its lowest-id boundary face
    // are fixed where they are. True when it fixed them.
    virtual Outcome<bool> hold_piece(std::span<const ElementId> piece) = 0;
    // CG iterations over all relax calls.
    virtual std::size_t total_iterations() const = 0;

    // ---- vertices a tool holds (a needle's stick-slip friction, thesis §6.3.2 and §6.6) -------
    // Displacements are from the reference position (metres), forces in newtons; a planar body
    // ignores z. The vertices the options constrain (fix, displace) are not the tool's: hold,
    // hold_on_line and release refuse them (bad_argument, "vertex 7 is held by the body's options").
    // Refusals name the vertex; a vertex in no element is not_found.

    // u(v) = displacement (sticking).
    virtual Outcome<Done> hold(VertexId v, Vector3 displacement) = 0;
    // u(v) = displacement + s * direction for any s (slipping along a line).
    virtual Outcome<Done> hold_on_line(VertexId v, Vector3 direction, Vector3 displacement) = 0;
    // v free again (its displacement stays where it is).
    virtual Outcome<Done> release(VertexId v) = 0;
    // The tool's force on v, replacing the tool's previous force there (the options' loads stay).
    virtual Outcome<Done> set_tool_force(VertexId v, Vector3 force) = 0;
    // The forces on `vertices` at the current displacements: what the body exerts (the elastic
    // force, -dPi/du) and what is loaded (options and tool). At a solution, the force a constraint
    // exerts on a held vertex is -(elastic + loaded) (its reaction). Refuses as relax does when
    // the body cannot be brought in step with the mesh, and with would_invert when the current
    // displacements invert an element of a neo-Hookean body.
    struct VertexForces {
        Vector3 elastic{0, 0, 0};
        Vector3 loaded{0, 0, 0};
    };
    virtual Outcome<std::vector<VertexForces>> forces_at(std::span<const VertexId> vertices) = 0;
    virtual Vector3 displacement(VertexId v) const = 0;
    // Sets every displacement to the mesh's deformed minus reference position: after the mesh
    // was taken back to a state whose deformed positions this body wrote (an undo), the body
    // starts from that state again.
    virtual Outcome<Done> displacements_from_mesh() = 0;
};

}  // namespace sxk
