// The elasticity plug-in's entry: `sxk deform`, and the service "sxk.elasticity"
// (sxk/plugins/elasticity.hpp) through which other plug-ins run a simulation. Programs that link the
// plug-in in may use its library (elastic_body.hpp, solve.hpp) directly.
#include <span>

#include "deform_command.hpp"
#include "simulation.hpp"
#include "sxk/plugin.hpp"

namespace sxk::elasticity {
namespace {

class ElasticityPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == ElasticityService::service_id) return offer_of(&m_service);
        return {};
    }

private:
    ElasticityService m_service{&simulate};
    DeformCommand m_deform;
    PluginCommand* m_commands[1] = {&m_deform};
};

}  // namespace
}  // namespace sxk::elasticity

SXK_PLUGIN(elasticity, sxk::elasticity::ElasticityPlugin, "0.3.0",
           "linear and neo-Hookean elasticity: matrix-free CG on tetrahedra and plane-stress "
           "triangles; sxk deform");
