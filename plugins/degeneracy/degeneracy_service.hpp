// The degeneracy plug-in's service, for applications that load degeneracy.so at run time
// instead of linking sxk_plugin_degeneracy_static:
//
//     PluginHost host;
//     host.load_default_folders();
//     auto removal = host.service<sxk::degeneracy::DegeneracyService>();
//     if (removal) (*removal)->remove_among(mesh, candidates, options);
//
// The pointers call the functions of remove_degeneracies.hpp. This header carries the kernel's
// and the removal's types only (no JSON, no command line).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "remove_degeneracies.hpp"

namespace sxk::degeneracy {

struct DegeneracyService {
    static constexpr std::string_view service_id = "sxk.degeneracy";
    // 1 was the untyped "sxk.degeneracy/1"; 2 had refusals without a code and no remaining_codes;
    // 3 had no Options::progress
    static constexpr std::uint32_t service_version = 4;

    Outcome<Report> (*remove)(Mesh& mesh, const Options& options);
    Outcome<Report> (*remove_among)(Mesh& mesh, std::span<const ElementId> candidates, const Options& options);
    DegenerateClass (*classify)(const Mesh& mesh, ElementId t, const Options& options);
};

}  // namespace sxk::degeneracy
