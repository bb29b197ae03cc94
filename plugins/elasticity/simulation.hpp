// The elasticity service's function (elasticity_service.hpp), for the plug-in's entry and tests.
#pragma once

#include <memory>
#include <span>
#include <string>

#include "elasticity_service.hpp"

namespace sxk::elasticity {

Outcome<std::unique_ptr<Simulation>> simulate(Mesh& mesh, std::span<const std::string> options);

}  // namespace sxk::elasticity
