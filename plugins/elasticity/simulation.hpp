// The elasticity service's function (sxk/plugins/elasticity.hpp), for the plug-in's entry and tests.
#pragma once

#include <memory>

#include "sxk/plugins/elasticity.hpp"

namespace sxk::elasticity {

Outcome<std::unique_ptr<Simulation>> simulate(Mesh& mesh, const Options& options);

}  // namespace sxk::elasticity
