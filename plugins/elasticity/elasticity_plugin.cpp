// The elasticity plug-in's entry: `sxk deform`. Applications and the other plug-ins use its
// library (elastic_body.hpp, solve.hpp) directly.
#include <span>

#include "deform_command.hpp"
#include "sxk/plugin.hpp"

namespace sxk::elasticity {
namespace {

class ElasticityPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }

private:
    DeformCommand m_deform;
    PluginCommand* m_commands[1] = {&m_deform};
};

}  // namespace
}  // namespace sxk::elasticity

SXK_PLUGIN(elasticity, sxk::elasticity::ElasticityPlugin, "0.2.0",
           "linear and neo-Hookean elasticity: matrix-free CG on tetrahedra and plane-stress "
           "triangles; sxk deform");
