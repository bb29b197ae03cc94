// The elasticity plug-in's options as `sxk deform` words (docs/cli.md "sxk deform"), for the
// commands that set up a body: `sxk deform`, and `--deform WORDS` of `sxk cut snap` and
// `sxk needle`. The words are parsed here, into the plug-in's Options (sxk/plugins/elasticity.hpp);
// the service never sees them.
//
//     --fix EXPR  --displace EXPR:DX,DY,DZ  --force EXPR:FX,FY,FZ  --share equal|area
//     --gravity GX,GY,GZ  --density RHO  --material linear|neohookean  --E  --nu  --thickness
//     --tol  --max-iterations  --stop reactions|external  --rounding
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "sxk/outcome.hpp"
#include "sxk/plugin.hpp"
#include "sxk/plugins/elasticity.hpp"

namespace sxk::cli {

// The options as words, before the vectors are read.
struct BodyWords {
    std::vector<std::string> fix, force, displace;
    std::string material = "linear", share = "equal";
    double young = 1e6, poisson = 0.25, tolerance = 1e-6, rounding = 1e-12;
    std::optional<double> thickness;
    std::string gravity;
    double density = 1000;
    std::size_t max_iterations = 100000;
    std::string stop = "reactions";
};

// Adds the options above to `app`.
void add_body_options(CLI::App& app, BodyWords& words);

// The options the words say; refuses (bad_argument) a vector that is not three finite numbers,
// with `command`'s message ("deform: --force 'z>1:0,1': expected three numbers X,Y,Z after ':',
// found 2").
Outcome<elasticity::Options> body_options(const BodyWords& words, std::string_view command = "deform");

// The options of `--deform WORDS` (the words split as a shell would not: at spaces); refuses
// what CLI11 or body_options refuses, as "deform: " + the reason.
Outcome<elasticity::Options> body_options(std::span<const std::string> words);

// The simulation `--deform WORDS` asks for (`sxk cut snap`, `sxk needle`), not yet solved: the
// elasticity plug-in's service from `host`, the words read, the body made on `mesh`. Refuses
// with what went wrong, for the command to print after "--deform: " (a missing plug-in says
// "(the elasticity plug-in)").
Outcome<std::unique_ptr<Simulation>> simulation_from_words(const Services* host, Mesh& mesh,
                                                           const std::string& words);

}  // namespace sxk::cli
