// sxk plugins [--json]: the loaded plug-ins with their versions, files and commands, the refused
// ones with the reason, and the folders searched.
#include <cstdlib>
#include <memory>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cli.hpp"

namespace sxk::cli {
namespace {

// The default folder, then SXK_PLUGIN_PATH's folders: the order PluginHost searches them.
std::vector<std::string> search_path() {
    std::vector<std::string> folders;
    for (const auto& folder : PluginHost::default_folders()) folders.push_back(folder.string());
    if (const char* environment = std::getenv("SXK_PLUGIN_PATH")) {
        std::string_view rest = environment;
        while (true) {
            const std::size_t colon = rest.find(':');
            if (!rest.substr(0, colon).empty()) folders.emplace_back(rest.substr(0, colon));
            if (colon == std::string_view::npos) break;
            rest.remove_prefix(colon + 1);
        }
    }
    return folders;
}

int run_plugins(Context& context, bool json_output) {
    const PluginHost empty;  // main() loads plug-ins for this command; stay correct without
    const PluginHost& host = context.host ? *context.host : empty;
    if (json_output) {
        nlohmann::ordered_json json;
        json["plugins"] = nlohmann::ordered_json::array();
        for (const LoadedPlugin& plugin : host.plugins()) {
            nlohmann::ordered_json entry;
            entry["name"] = plugin.name;
            entry["version"] = plugin.version;
            entry["summary"] = plugin.summary;
            entry["path"] = plugin.path.string();
            entry["commands"] = nlohmann::ordered_json::array();
            for (const FoundCommand& command : context.plugin_commands)
                if (command.plugin->name == plugin.name)
                    entry["commands"].push_back(
                        {{"name", std::string(command.command->name())},
                         {"summary", std::string(command.command->summary())}});
            json["plugins"].push_back(entry);
        }
        json["refused"] = nlohmann::ordered_json::array();
        for (const PluginDiagnostic& diagnostic : host.diagnostics())
            json["refused"].push_back({{"path", diagnostic.path.string()}, {"reason", diagnostic.reason}});
        json["search_path"] = nlohmann::ordered_json::array();
        for (const std::string& folder : search_path()) json["search_path"].push_back(folder);
        context.out << json.dump(2) << '\n';
        return exit_success;
    }

    std::ostream& out = context.out;
    if (host.plugins().empty()) out << "no plug-ins loaded\n";
    for (const LoadedPlugin& plugin : host.plugins()) {
        out << plugin.name << ' ' << plugin.version;
        if (!plugin.summary.empty()) out << "  " << plugin.summary;
        out << "\n  file: " << plugin.path.string() << '\n';
        for (const FoundCommand& command : context.plugin_commands)
            if (command.plugin->name == plugin.name)
                out << "  sxk " << command.command->name() << "  " << command.command->summary() << '\n';
    }
    if (!host.diagnostics().empty()) {
        out << "refused:\n";
        for (const PluginDiagnostic& diagnostic : host.diagnostics())
            out << "  " << diagnostic.path.string() << ": " << diagnostic.reason << '\n';
    }
    out << "search path:\n";
    for (const std::string& folder : search_path()) out << "  " << folder << '\n';
    return exit_success;
}

}  // namespace

void add_plugins_command(CLI::App& app, Context& context) {
    auto json_output = std::make_shared<bool>(false);
    CLI::App* command = app.add_subcommand("plugins", "Loaded plug-ins, versions, commands, and refused ones");
    command->add_flag("--json", *json_output, "Print one JSON object instead of text");
    command->callback([&context, json_output] { context.exit_code = run_plugins(context, *json_output); });
}

}  // namespace sxk::cli
