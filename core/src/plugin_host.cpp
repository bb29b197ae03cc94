// PluginHost: dlopen-based loading of plug-in MODULE files (see sxk/plugin_host.hpp).
#include "sxk/plugin_host.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <deque>
#include <exception>
#include <set>
#include <system_error>
#include <utility>

namespace sxk {
namespace {

namespace fs = std::filesystem;

// dlclose on scope exit unless released: every refusal path unloads what it opened.
class LibraryHandle {
public:
    explicit LibraryHandle(void* handle) : m_handle(handle) {}
    ~LibraryHandle() {
        if (m_handle) dlclose(m_handle);
    }
    LibraryHandle(const LibraryHandle&) = delete;
    LibraryHandle& operator=(const LibraryHandle&) = delete;
    void* get() const { return m_handle; }
    void* release() { return std::exchange(m_handle, nullptr); }

private:
    void* m_handle;
};

fs::path normalized(const fs::path& path) {
    std::error_code error;
    fs::path canonical = fs::weakly_canonical(path, error);
    return error ? path.lexically_normal() : canonical;
}

// The file this library was loaded from (dladdr on one of its own functions).
fs::path core_library_path() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&core_library_path), &info) == 0 || info.dli_fname == nullptr)
        return {};
    return normalized(info.dli_fname);
}

bool valid_plugin_name(const char* name) {
    if (name == nullptr || *name == '\0') return false;
    for (const char* c = name; *c; ++c)
        if (!(std::islower(static_cast<unsigned char>(*c)) || std::isdigit(static_cast<unsigned char>(*c)) ||
              *c == '_'))
            return false;
    return true;
}

bool valid_command_name(std::string_view name) {
    if (name.empty() || name.front() == ' ' || name.back() == ' ' || name.front() == '-') return false;
    if (name.find("  ") != std::string_view::npos || name.find(" -") != std::string_view::npos) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
               c == '_' || c == '-' || c == ' ';
    });
}

std::vector<std::string_view> split_words(std::string_view name) {
    std::vector<std::string_view> words;
    while (!name.empty()) {
        const std::size_t space = name.find(' ');
        words.push_back(name.substr(0, space));
        if (space == std::string_view::npos) break;
        name.remove_prefix(space + 1);
    }
    return words;
}

}  // namespace

struct PluginHost::State final : Services {
    struct Entry {
        LoadedPlugin loaded;
        const sxk_plugin_info* info = nullptr;
        void* handle = nullptr;  // nullptr for add_static
    };
    struct CommandEntry {
        PluginCommand* command;
        std::size_t plugin;  // index into entries
        std::vector<std::string_view> words;
    };
    // a deque: FoundCommand::plugin points into it and must survive later loads
    std::deque<Entry> entries;
    // the same records, contiguous, for plugins()
    std::vector<LoadedPlugin> loaded;
    std::vector<CommandEntry> commands;
    std::vector<PluginDiagnostic> diagnostics;
    std::set<fs::path> seen_files;

    // PluginHost::find_service, here so that plug-ins keep a lookup that survives moving the host
    Outcome<void*> find_service(std::string_view service_id, std::uint32_t version,
                                std::string_view plugin) const override {
        bool named_found = false;
        for (const auto& entry : entries) {
            if (!plugin.empty() && entry.loaded.name != plugin) continue;
            named_found = true;
            const ServiceOffer offer = entry.loaded.plugin->offer(service_id);
            if (offer.version == 0 || offer.object == nullptr) continue;
            if (offer.version != version)
                return Refusal{RefusalCode::not_found,
                               "plug-in " + entry.loaded.name + " offers " + std::string(service_id) +
                                   " version " + std::to_string(offer.version) + ", not version " +
                                   std::to_string(version)};
            return offer.object;
        }
        if (!plugin.empty() && !named_found)
            return Refusal{RefusalCode::not_found, "no plug-in called " + std::string(plugin)};
        return Refusal{RefusalCode::not_found,
                       (plugin.empty() ? std::string("no plug-in") : "plug-in " + std::string(plugin)) +
                           " offers " + std::string(service_id)};
    }

    // PluginHost::tool, here for the same reason
    Outcome<ToolFactory*> find_tool(std::string_view name) const override {
        std::vector<std::string> offered;
        for (const auto& entry : entries) {
            const ServiceOffer offer = entry.loaded.plugin->offer(ToolFactory::service_id);
            if (offer.object == nullptr || offer.version != ToolFactory::service_version) continue;
            auto* factory = static_cast<ToolFactory*>(offer.object);
            for (const ToolFactory::Tool& tool : factory->tools()) {
                if (tool.name == name) return factory;
                offered.emplace_back(tool.name);
            }
        }
        std::sort(offered.begin(), offered.end());
        std::string known;
        for (const std::string& tool : offered) known += (known.empty() ? "" : ", ") + tool;
        return Refusal{RefusalCode::not_found,
                       "no tool called " + std::string(name) +
                           (known.empty() ? "; no loaded plug-in offers a tool" : "; the plug-ins offer: " + known)};
    }

    void refuse(const fs::path& path, std::string reason) {
        diagnostics.push_back({path, std::move(reason)});
    }

    bool add(const sxk_plugin_info* info, void* handle, const fs::path& path) {
        if (info == nullptr) {
            refuse(path, "sxk_plugin_entry returned no plug-in information");
            return false;
        }
        // Only the first field is read before the version is known to match.
        if (info->abi_version != SXK_PLUGIN_ABI_VERSION) {
            refuse(path, "plug-in ABI version " + std::to_string(info->abi_version) + ", this host needs " +
                             std::to_string(SXK_PLUGIN_ABI_VERSION));
            return false;
        }
        if (!valid_plugin_name(info->name)) {
            refuse(path, "malformed plug-in information: the name must match [a-z0-9_]+");
            return false;
        }
        if (info->version == nullptr || info->create == nullptr || info->destroy == nullptr) {
            refuse(path, std::string("malformed plug-in information for '") + info->name +
                             "': version, create and destroy are required");
            return false;
        }
        for (const Entry& entry : entries)
            if (entry.loaded.name == info->name) {
                refuse(path, std::string("plug-in '") + info->name + "' is already loaded from " +
                                 entry.loaded.path.string() + "; this one is ignored");
                return false;
            }
        Plugin* plugin = nullptr;
        try {
            plugin = info->create();
        } catch (...) {
            // create() must not throw (SXK_PLUGIN guarantees it); a hand-written one might
        }
        if (plugin == nullptr) {
            refuse(path, std::string("plug-in '") + info->name + "' failed to initialise");
            return false;
        }
        plugin->attach(*this);
        Entry entry;
        entry.loaded = {info->name, info->version, info->summary ? info->summary : "", path, plugin};
        entry.info = info;
        entry.handle = handle;
        entries.push_back(std::move(entry));
        loaded.push_back(entries.back().loaded);
        register_commands(entries.size() - 1);
        return true;
    }

    void register_commands(std::size_t index) {
        const Entry& entry = entries[index];
        std::span<PluginCommand* const> provided;
        try {
            provided = entry.loaded.plugin->commands();
        } catch (const std::exception& error) {
            refuse(entry.loaded.path, "plug-in '" + entry.loaded.name + "' failed to list its commands: " + error.what());
            return;
        }
        for (PluginCommand* command : provided) {
            if (command == nullptr) continue;
            const std::string_view name = command->name();
            if (!valid_command_name(name)) {
                refuse(entry.loaded.path, "command '" + std::string(name) + "' of plug-in '" + entry.loaded.name +
                                              "' has a malformed name; ignored");
                continue;
            }
            auto same = std::find_if(commands.begin(), commands.end(),
                                     [&](const CommandEntry& other) { return other.command->name() == name; });
            if (same != commands.end()) {
                refuse(entry.loaded.path, "command '" + std::string(name) + "' of plug-in '" + entry.loaded.name +
                                              "' is already provided by plug-in '" +
                                              entries[same->plugin].loaded.name + "'; ignored");
                continue;
            }
            commands.push_back({command, index, split_words(name)});
        }
    }
};

PluginHost::PluginHost() : m_state(std::make_unique<State>()) {}

PluginHost::~PluginHost() {
    if (!m_state) return;  // moved from
    // Commands point into the plug-ins; plug-ins' code lives in the libraries: drop in that order.
    m_state->commands.clear();
    for (auto entry = m_state->entries.rbegin(); entry != m_state->entries.rend(); ++entry) {
        entry->info->destroy(entry->loaded.plugin);
        if (entry->handle) dlclose(entry->handle);
    }
}

PluginHost::PluginHost(PluginHost&&) noexcept = default;
PluginHost& PluginHost::operator=(PluginHost&& other) noexcept {
    if (this != &other) {
        PluginHost old(std::move(*this));  // unloads what this host held
        m_state = std::move(other.m_state);
    }
    return *this;
}

std::vector<fs::path> PluginHost::default_folders() {
    const fs::path library = core_library_path();
    // The library running from where the build put it uses the build's plug-ins; any other copy
    // (an install tree, even one inside the build folder) uses the folder beside it and never
    // picks up build products.
    if (!library.empty() && library.parent_path() == normalized(SXK_CORE_BUILD_DIR))
        return {fs::path(SXK_PLUGIN_BUILD_DIR)};
    const fs::path suffix = SXK_PLUGIN_INSTALL_SUFFIX;
    if (suffix.is_absolute()) return {suffix};
    // <prefix>/<libdir>/libsimplexkit.so -> <prefix>/<libdir>/simplexkit/plugins
    if (!library.empty()) return {library.parent_path() / "simplexkit" / "plugins"};
    return {};
}

std::vector<fs::path> PluginHost::search_folders() {
    std::vector<fs::path> folders = default_folders();
    const char* environment = std::getenv("SXK_PLUGIN_PATH");
    if (environment == nullptr) return folders;
    std::string_view rest = environment;
    while (true) {
        const std::size_t colon = rest.find(':');
        const std::string_view folder = rest.substr(0, colon);
        if (!folder.empty()) folders.emplace_back(folder);
        if (colon == std::string_view::npos) break;
        rest.remove_prefix(colon + 1);
    }
    return folders;
}

void PluginHost::load_default_folders() {
    const std::size_t defaults = default_folders().size();
    const std::vector<fs::path> folders = search_folders();
    for (std::size_t i = 0; i < folders.size(); ++i) {
        std::error_code error;
        // a missing default folder is normal (no plug-ins built); a missing SXK_PLUGIN_PATH
        // entry is reported by load_folder
        if (i >= defaults || fs::is_directory(folders[i], error)) load_folder(folders[i]);
    }
}

std::size_t PluginHost::load_folder(const fs::path& folder) {
    std::error_code error;
    if (fs::is_regular_file(folder, error)) return load_file(folder) ? 1 : 0;
    if (!fs::is_directory(folder, error)) {
        m_state->refuse(folder, "no such plug-in folder");
        return 0;
    }
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
        if (it->path().extension() == ".so" && it->is_regular_file(error)) files.push_back(it->path());
    if (error) {
        m_state->refuse(folder, "cannot list the plug-in folder: " + error.message());
        return 0;
    }
    std::sort(files.begin(), files.end());
    std::size_t count = 0;
    for (const fs::path& file : files) count += load_file(file) ? 1 : 0;
    return count;
}

bool PluginHost::load_file(const fs::path& file) {
    const fs::path path = normalized(file);
    // the build folder and SXK_PLUGIN_PATH may name the same folder: one load per file
    if (!m_state->seen_files.insert(path).second) return false;

    // RTLD_LOCAL: plug-ins do not see each other's symbols; RTLD_NOW: unresolved symbols
    // refuse the file here rather than abort the process on first call.
    dlerror();
    LibraryHandle handle(dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL));
    if (handle.get() == nullptr) {
        const char* reason = dlerror();
        m_state->refuse(path, std::string("cannot load: ") + (reason ? reason : "unknown dlopen error"));
        return false;
    }
    dlerror();
    void* symbol = dlsym(handle.get(), plugin_entry_symbol);
    if (symbol == nullptr) {
        m_state->refuse(path, std::string("not a simplexkit plug-in: no entry point ") + plugin_entry_symbol);
        return false;
    }
    const auto entry = reinterpret_cast<sxk_plugin_entry_fn>(symbol);
    const sxk_plugin_info* info = nullptr;
    try {
        info = entry();
    } catch (...) {
        m_state->refuse(path, std::string(plugin_entry_symbol) + " threw an exception");
        return false;
    }
    if (!m_state->add(info, handle.get(), path)) return false;
    handle.release();
    return true;
}

bool PluginHost::add_static(const sxk_plugin_info* info, std::string origin) {
    return m_state->add(info, nullptr, fs::path(std::move(origin)));
}

std::span<const LoadedPlugin> PluginHost::plugins() const { return m_state->loaded; }

std::span<const PluginDiagnostic> PluginHost::diagnostics() const { return m_state->diagnostics; }

Plugin* PluginHost::find(std::string_view name) const {
    for (const auto& entry : m_state->entries)
        if (entry.loaded.name == name) return entry.loaded.plugin;
    return nullptr;
}

Outcome<void*> PluginHost::find_service(std::string_view service_id, std::uint32_t version,
                                        std::string_view plugin) const {
    return m_state->find_service(service_id, version, plugin);
}

Outcome<ToolFactory*> PluginHost::tool(std::string_view name) const { return m_state->find_tool(name); }

FoundCommand PluginHost::find_command(std::span<const std::string> args) const {
    FoundCommand best;
    for (const auto& command : m_state->commands) {
        if (command.words.size() > args.size() || command.words.size() <= best.words) continue;
        if (std::equal(command.words.begin(), command.words.end(), args.begin()))
            best = {command.command, &m_state->entries[command.plugin].loaded, command.words.size()};
    }
    return best;
}

std::vector<FoundCommand> PluginHost::commands() const {
    std::vector<FoundCommand> result;
    for (const auto& command : m_state->commands)
        result.push_back({command.command, &m_state->entries[command.plugin].loaded, command.words.size()});
    return result;
}

}  // namespace sxk
