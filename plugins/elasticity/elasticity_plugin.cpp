// The elasticity plug-in's entry. Its library (elastic_body.hpp, solve.hpp) is what
// applications and the other plug-ins use today; the `sxk deform` command is to come.
#include <span>

#include "sxk/plugin.hpp"

namespace sxk::elasticity {
namespace {

class ElasticityPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return {}; }
};

}  // namespace
}  // namespace sxk::elasticity

SXK_PLUGIN(elasticity, sxk::elasticity::ElasticityPlugin, "0.1.0", "linear elasticity: matrix-free CG on tetrahedral meshes");
