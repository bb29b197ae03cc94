// The elasticity plug-in's service, for the tools that run a simulation while they edit (the snap
// cutter re-solves after every cut step, thesis §3.3) and for applications that load
// elasticity.so at run time:
//
//     auto elasticity = host.service<sxk::elasticity::ElasticityService>();
//     auto simulation = (*elasticity)->simulate(mesh, {"--fix", "z<0.001", "--force", "z>7.99:0,0,-100"});
//     (*simulation)->relax(100000);     // the loaded shape: mesh.deformed() now shows it
//     ... edit the mesh (the body follows every edit) ...
//     (*simulation)->relax(200);        // per frame: a bounded number of CG iterations, warm start
//
// The options are `sxk deform`'s (docs/cli.md): --fix, --displace, --force, --share, --gravity,
// --density, --material, --E, --nu, --thickness, --tol, --max-iterations, --stop. This header carries
// only the kernel's types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::elasticity {

// What one relax call did.
struct RelaxReport {
    std::size_t iterations = 0;  // CG steps of this call
    bool converged = false;      // the residual reached the stop criterion (eq. 6.9)
    double residual = 0, threshold = 0;
    bool shown = false;  // the deformed positions were written (not when they would invert an element)
    double seconds = 0;
};

// A body on a mesh, attached to it (it follows the mesh's edits, thesis §7.4), with the
// constraints and loads of its options.
class Simulation {
public:
    virtual ~Simulation() = default;
    // At most `iterations` more CG iterations (and at most the options' --max-iterations) from the
    // current displacements (a warm start), then
    // the deformed positions reference + u written into the mesh (one move_vertices: watchers and
    // an open EditJournal step see it) unless they would invert or flatten an element. Refuses
    // when the body cannot be brought in step with the mesh (an element flat at rest: remove
    // degeneracies first).
    virtual Outcome<RelaxReport> relax(std::size_t iterations) = 0;
    // A piece that came loose (thesis §3.3: "all unfixed components are fixed on an arbitrary
    // face"): unless a vertex of it is held already, the corners of its lowest-id boundary face
    // are fixed where they are. True when it fixed them.
    virtual Outcome<bool> hold_piece(std::span<const ElementId> piece) = 0;
    // CG iterations over all relax calls.
    virtual std::size_t total_iterations() const = 0;
};

struct ElasticityService {
    static constexpr std::string_view service_id = "sxk.elasticity";
    static constexpr std::uint32_t service_version = 1;

    // A simulation of `mesh` (which must stay where it is while the simulation lives) set up from
    // `sxk deform`'s options; refuses bad options and empty selections with `sxk deform`'s
    // messages ("deform: --fix 'x<9' selects no vertex of the mesh").
    Outcome<std::unique_ptr<Simulation>> (*simulate)(Mesh& mesh, std::span<const std::string> options);
};

}  // namespace sxk::elasticity
