// Loading plug-ins into a process (docs/plugins.md).
//
// A PluginHost is an object the application owns (no global registry): it dlopens
// plug-in MODULE files, checks them, creates one sxk::Plugin per file and destroys and unloads
// them again in its destructor, in reverse order of loading.
//
// Refusals never stop the host: a file that dlopen cannot load, that has no sxk_plugin_entry,
// whose ABI version differs from SXK_PLUGIN_ABI_VERSION, whose info is malformed, or whose name
// is already taken is unloaded again and recorded in diagnostics() as (path, reason); the host
// goes on with the next file. The sxk CLI prints them as "sxk: warning: PATH: reason".
//
// Search path of load_default_folders(), in this order (the first plug-in of a name wins):
//   1. the build's plug-in folder (SXK_PLUGIN_BUILD_DIR) while this library runs from where the
//      build put it; otherwise the install folder <libdir>/simplexkit/plugins beside this
//      library (found with dladdr, so a relocated install tree works). An installed copy never
//      picks up build products, not even when installed inside the build folder;
//   2. each folder of the environment variable SXK_PLUGIN_PATH (colon-separated).
// Applications add folders of their own with load_folder(), before or after the defaults.
// A folder's *.so files are loaded in name order; the same file reached twice is loaded once.
//
// Plug-ins stay loaded until the host is destroyed: PluginCommand pointers, services and any
// watcher a plug-in registered must not outlive it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugin.hpp"
#include "sxk/tool_session.hpp"

namespace sxk {

struct LoadedPlugin {
    std::string name;
    std::string version;
    std::string summary;
    std::filesystem::path path;  // the .so file, or the origin given to add_static()
    Plugin* plugin = nullptr;    // owned by the host
};

struct PluginDiagnostic {
    std::filesystem::path path;
    std::string reason;
};

// A command and the plug-in that provides it.
struct FoundCommand {
    PluginCommand* command = nullptr;
    const LoadedPlugin* plugin = nullptr;
    std::size_t words = 0;  // how many leading arguments name the command
};

class SXK_API PluginHost {
public:
    PluginHost();
    ~PluginHost();
    PluginHost(const PluginHost&) = delete;
    PluginHost& operator=(const PluginHost&) = delete;
    PluginHost(PluginHost&&) noexcept;
    PluginHost& operator=(PluginHost&&) noexcept;

    // The folder load_default_folders() searches before SXK_PLUGIN_PATH (see above; it may not
    // exist). Empty when this library cannot find its own file.
    static std::vector<std::filesystem::path> default_folders();

    // default_folders() followed by the folders of SXK_PLUGIN_PATH: what load_default_folders()
    // searches, in its order (for messages such as sxk's "unknown command").
    static std::vector<std::filesystem::path> search_folders();

    // Loads every plug-in of the default folders; missing default folders are skipped quietly,
    // a missing SXK_PLUGIN_PATH entry is reported.
    void load_default_folders();
    // Loads every *.so in `folder` (a plug-in file is accepted too). A missing folder is
    // reported. Returns the number of plug-ins loaded.
    std::size_t load_folder(const std::filesystem::path& folder);
    // Loads one plug-in file; false (and a diagnostic) when refused.
    bool load_file(const std::filesystem::path& file);
    // Registers a plug-in linked into the program (built with SXK_PLUGIN_STATIC; pass
    // sxk_plugin_entry_NAME()). Checked like a loaded one; `origin` names it in messages.
    bool add_static(const sxk_plugin_info* info, std::string origin);

    std::span<const LoadedPlugin> plugins() const;
    std::span<const PluginDiagnostic> diagnostics() const;
    // The plug-in called `name`, or nullptr.
    Plugin* find(std::string_view name) const;
    // The command whose name words are the longest prefix of `args` ("cut snap" before "cut"),
    // or {nullptr, nullptr, 0}.
    FoundCommand find_command(std::span<const std::string> args) const;
    // All commands, in loading order.
    std::vector<FoundCommand> commands() const;

    // The first loaded plug-in (or the one called `plugin`, when given) offering Interface
    // (Interface::service_id, Interface::service_version; plugin.hpp). Refuses when no plug-in
    // offers the id ("no plug-in offers sxk.cutter"), or the one found offers another version
    // ("plug-in snapcut offers sxk.cutter version 1, not version 2"): the host never hands out an
    // interface the plug-in was not built against.
    template <class Interface>
    Outcome<Interface*> service(std::string_view plugin = {}) const {
        auto found = find_service(Interface::service_id, Interface::service_version, plugin);
        if (!found) return found.refusal();
        return static_cast<Interface*>(*found);
    }
    // The untyped lookup behind service<Interface>().
    Outcome<void*> find_service(std::string_view service_id, std::uint32_t version,
                                std::string_view plugin = {}) const;

    // The factory of the tool called `name` (ToolFactory::tools), whichever loaded plug-in offers
    // it: the first in loading order. Refuses when none does, naming the tools there are ("no
    // tool called scalpel; the plug-ins offer: degeneracies, delaunaycut, needle, snapcut").
    Outcome<ToolFactory*> tool(std::string_view name) const;
    // A session of the tool whose options `options` are (a struct of a plug-in's installed
    // header, sxk/plugins/NAME.hpp, naming its tool), on `mesh`, with what the application gives
    // it (a simulation):
    //
    //     sxk::snapcut::Options cut;  cut.largest_crumb = 8;
    //     auto session = host.begin_tool(mesh, cut, {.simulation = simulation.get()});
    template <class Options>
    Outcome<std::unique_ptr<ToolSession>> begin_tool(Mesh& mesh, const Options& options,
                                                     const ToolContext& context = {}) const {
        auto factory = tool(Options::tool_name);
        if (!factory) return factory.refusal();
        return sxk::begin_tool(**factory, mesh, options, context);
    }

private:
    struct State;
    std::unique_ptr<State> m_state;
};

}  // namespace sxk
