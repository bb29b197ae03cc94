// A body from `sxk deform`'s options (docs/cli.md "sxk deform"): what the command and the
// elasticity service (elasticity_service.hpp: the snap cutter's --deform) both set up, with the
// same words and the same messages.
//
//     BodyOptions words:  --fix EXPR  --displace EXPR:DX,DY,DZ  --force EXPR:FX,FY,FZ
//                         --share equal|area  --gravity GX,GY,GZ  --density RHO
//                         --material linear|neohookean  --E  --nu  --thickness  --tol
//                         --max-iterations  --stop reactions|external  --rounding
//
// Two stages, as the command checks them: the words alone (parse_body_setup: selectors, vectors,
// something holds the body), then on the mesh (build_body: the body, its constraints and loads;
// a selection that selects nothing is refused). Messages go to `err` as the command prints them
// ("sxk: deform: --fix 'x<9' selects no vertex of IN").
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "elastic_body.hpp"
#include "vertex_selector.hpp"

namespace sxk::elasticity {

struct BodySetup {
    std::vector<std::string> fix, force, displace;
    std::string material = "linear", share = "equal";
    double young = 1e6, poisson = 0.25, tolerance = 1e-6, rounding = 1e-12;
    std::optional<double> thickness;
    std::string gravity;
    double density = 1000;
    std::size_t max_iterations = 100000;
    std::string stop = "reactions";  // or "external" (StopCriterion)
};

// Adds the options above to `app`.
void add_body_options(CLI::App& app, BodySetup& setup);

// A selector with a vector: "EXPR:X,Y,Z".
struct Selected {
    VertexSelector selector;
    Vector3 vector{0, 0, 0};
};

struct ParsedBody {
    std::vector<Selected> fixes, displaces, forces;
    Vector3 gravity{0, 0, 0};
};

// The words alone; nullopt with the message printed.
std::optional<ParsedBody> parse_body_setup(const BodySetup& setup, std::ostream& err);

struct BuiltBody {
    std::unique_ptr<ElasticBody> body;  // on the heap: a body attached as a watcher must not move
    std::size_t loaded = 0;             // vertices with a load
    bool planar = false;
    Model model = Model::linear;
};

// The body of `mesh`; nullopt with the message printed. `file` names the mesh's file in messages
// ("FILE:0: ..."); a caller without one (the service's simulate) passes "" and the messages
// say "the mesh", with no location that is not a file's.
std::optional<BuiltBody> build_body(const Mesh& mesh, const std::string& file, const BodySetup& setup,
                                    const ParsedBody& parsed, std::ostream& err);

}  // namespace sxk::elasticity
