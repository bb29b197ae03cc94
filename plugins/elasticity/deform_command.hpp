// `sxk deform IN OUT` (deform_command.cpp; docs/cli.md "sxk deform").
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "sxk/plugin.hpp"

namespace sxk::elasticity {

class DeformCommand final : public PluginCommand {
public:
    std::string_view name() const override { return "deform"; }
    std::string_view summary() const override;
    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override;
};

}  // namespace sxk::elasticity
