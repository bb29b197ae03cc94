// The plug-in ABI: what a plug-in shared object exports and what a host (the sxk CLI, or any
// application through PluginHost) may ask of it.
//
// A plug-in is a MODULE library exporting one C function
//
//     extern "C" const sxk_plugin_info* sxk_plugin_entry(void);
//
// whose result describes the plug-in. `abi_version` is the first field and is a uint32 in every
// version of this header, so a host can read it from a plug-in built against any version and
// refuse the plug-in before touching anything else. Everything after it may change from one ABI
// version to the next: SXK_PLUGIN_ABI_VERSION is bumped whenever this struct, sxk::Plugin or
// sxk::PluginCommand change layout or meaning.
//
// Behind the C entry point the plug-in is a C++ object (sxk::Plugin), so a plug-in must be
// built with the same compiler family and standard library as the host; the ABI version guards
// simplexkit's side of the contract, not the C++ toolchain's.
//
// Writing a plug-in (see docs/plugins.md):
//
//     class Stats final : public sxk::Plugin { ... };
//     SXK_PLUGIN(stats, Stats, "0.1.0", "histograms of element quality");
//
// defines `sxk_plugin_entry_stats()` and, unless SXK_PLUGIN_STATIC is defined (static builds
// that link several plug-ins into one program), the generic `sxk_plugin_entry()`.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "sxk/outcome.hpp"

// 2: typed services (Plugin::offer with an interface id and version), run_on_mesh for a mesh
//    the command may edit.
// 3: Plugin::attach: a plug-in reaches the other plug-ins' services through its host.
// 4: Services::find_tool; ToolFactory is an object taking typed options (tool_session.hpp).
#define SXK_PLUGIN_ABI_VERSION 4u

// Entry points must be visible although the project builds with hidden visibility.
#if defined(_WIN32)
#define SXK_PLUGIN_EXPORT __declspec(dllexport)
#else
#define SXK_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

namespace sxk {

class Mesh;
class ToolFactory;  // sxk/tool_session.hpp

// A subcommand a plug-in adds to sxk ("sxk stats MESH", "sxk cut snap ...").
class PluginCommand {
public:
    virtual ~PluginCommand() = default;

    // The words after "sxk": "stats", or "cut snap" for a two-word command. Lowercase words
    // separated by single spaces, none starting with '-'.
    virtual std::string_view name() const = 0;
    // One line for `sxk plugins` and `sxk --help`.
    virtual std::string_view summary() const = 0;

    // Runs the command on the arguments after its name words (`--help` included: the command
    // prints its own usage). Returns 0 on success, 1 when the operation was refused or its
    // result is invalid, 2 on a usage or input error. Errors go to `err` as
    // "sxk: FILE:LINE: reason". Must not call exit(); may throw, the host reports it.
    virtual int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) = 0;

    // Commands that work on one mesh file may also work on a mesh the application holds in
    // memory: `args` are then the arguments without the MESH operand, `mesh_name` stands for
    // the file name in messages. The default refuses with exit code 2.
    virtual bool accepts_mesh() const { return false; }
    virtual int run_on_mesh(const Mesh& /*mesh*/, std::string_view /*mesh_name*/,
                            std::span<const std::string> /*args*/, std::ostream& /*out*/,
                            std::ostream& err) {
        err << "sxk: " << name() << ": this command needs a mesh file\n";
        return 2;
    }

    // Commands that change a mesh (IN OUT on the command line) may change one the application
    // holds instead: `args` are then the arguments without IN and OUT, and the command edits
    // `mesh` in place (as one EditJournal step when the mesh has a journal, sxk/edit_journal.hpp,
    // so the application can undo it). The default refuses with exit code 2.
    virtual bool edits_mesh() const { return false; }
    virtual int run_on_mutable_mesh(Mesh& /*mesh*/, std::string_view /*mesh_name*/,
                                    std::span<const std::string> /*args*/, std::ostream& /*out*/,
                                    std::ostream& err) {
        err << "sxk: " << name() << ": this command does not edit a mesh in memory\n";
        return 2;
    }
};

// What a plug-in offers for an interface id: the version of the interface it implements and the
// object. Applications do not see this: PluginHost::service<Interface>() checks id and version
// and returns a typed pointer (plugin_host.hpp).
struct ServiceOffer {
    std::uint32_t version = 0;  // 0: not offered
    void* object = nullptr;
};

// An interface a plug-in can offer names itself and its version:
//
//     struct CutterService {
//         static constexpr std::string_view service_id = "sxk.cutter";
//         static constexpr std::uint32_t service_version = 1;  // bumped on any change
//         ...function pointers or virtual functions...
//     };
//
// and the plug-in answers offer("sxk.cutter") with offer_of(&its_object).
template <class Interface>
ServiceOffer offer_of(Interface* object) {
    return ServiceOffer{Interface::service_version, object};
}

// The services of the plug-ins a host has loaded, as a plug-in sees them (Plugin::attach): the
// same lookup as PluginHost::service, through an object that stays where it is when the host is
// moved.
class Services {
public:
    // The first loaded plug-in (or the one called `plugin`) offering Interface; refuses as
    // PluginHost::service does ("no plug-in offers sxk.degeneracy").
    template <class Interface>
    Outcome<Interface*> service(std::string_view plugin = {}) const {
        auto found = find_service(Interface::service_id, Interface::service_version, plugin);
        if (!found) return found.refusal();
        return static_cast<Interface*>(*found);
    }
    virtual Outcome<void*> find_service(std::string_view service_id, std::uint32_t version,
                                        std::string_view plugin = {}) const = 0;
    // The factory of the tool called `name`, whichever loaded plug-in offers it (PluginHost::tool).
    virtual Outcome<ToolFactory*> find_tool(std::string_view name) const = 0;

protected:
    ~Services() = default;
};

// A loaded plug-in. It owns its commands; they stay valid as long as the plug-in object.
class Plugin {
public:
    virtual ~Plugin() = default;

    virtual std::span<PluginCommand* const> commands() = 0;

    // Other services (a tool-session factory, the degeneracy removal, ...) by interface id;
    // {} when not offered. Implement with offer_of; look up with PluginHost::service.
    virtual ServiceOffer offer(std::string_view /*service_id*/) { return {}; }

    // Called once by the host that created the plug-in, before anything else is asked of it,
    // with the host's services. A plug-in that uses other plug-ins' services (the snap cutter:
    // the degeneracy removal, the elasticity) keeps the reference and looks them up when it
    // needs them, so plug-ins loaded after it count too. `services` outlives the plug-in (the
    // host destroys its plug-ins first).
    virtual void attach(const Services& /*services*/) {}
};

}  // namespace sxk

extern "C" {

// What sxk_plugin_entry returns. Static storage owned by the plug-in.
struct sxk_plugin_info {
    std::uint32_t abi_version;  // SXK_PLUGIN_ABI_VERSION the plug-in was built with; first field
    const char* name;           // unique among loaded plug-ins: [a-z0-9_]+
    const char* version;        // the plug-in's own version, e.g. "0.1.0"
    const char* summary;        // one line
    sxk::Plugin* (*create)();   // nullptr on failure (never throws)
    void (*destroy)(sxk::Plugin* plugin);
};

using sxk_plugin_entry_fn = const sxk_plugin_info* (*)();

}  // extern "C"

namespace sxk {
inline constexpr const char* plugin_entry_symbol = "sxk_plugin_entry";
}  // namespace sxk

#if defined(SXK_PLUGIN_STATIC)
#define SXK_PLUGIN_DEFAULT_ENTRY_(NAME)
#else
#define SXK_PLUGIN_DEFAULT_ENTRY_(NAME)                                                         \
    extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry() {                    \
        return sxk_plugin_entry_##NAME();                                                       \
    }
#endif

// Defines the entry point(s) of plug-in NAME (an identifier) whose sxk::Plugin subclass is
// PLUGIN_CLASS (default-constructible). Use once, at namespace scope, outside any namespace.
#define SXK_PLUGIN(NAME, PLUGIN_CLASS, VERSION, SUMMARY)                                        \
    extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_##NAME() {             \
        static const sxk_plugin_info info = {                                                   \
            SXK_PLUGIN_ABI_VERSION, #NAME, VERSION, SUMMARY,                                    \
            []() noexcept -> ::sxk::Plugin* {                                                   \
                try {                                                                           \
                    return new PLUGIN_CLASS();                                                  \
                } catch (...) {                                                                 \
                    return nullptr;                                                             \
                }                                                                               \
            },                                                                                  \
            [](::sxk::Plugin* plugin) noexcept { delete plugin; }};                             \
        return &info;                                                                           \
    }                                                                                           \
    SXK_PLUGIN_DEFAULT_ENTRY_(NAME)                                                             \
    static_assert(SXK_PLUGIN_ABI_VERSION > 0, "lets the use end with a semicolon")
