// sxk: the simplexkit command-line tool (docs/cli.md).
//
// Built-in commands (info, validate, convert, quality, components, dissect, delaunay-flip, refine, locate, generate) never load plug-ins, so a broken plug-in
// can neither slow them down nor crash them. Everything else loads the plug-ins first, prints
// what was refused as "sxk: warning: PATH: reason", and dispatches plug-in commands by their
// name words before CLI11 sees the arguments: a plug-in parses its own options and prints its
// own --help.
#include <algorithm>
#include <array>
#include <csignal>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "cli.hpp"

namespace sxk::cli {
namespace {

constexpr std::array<std::string_view, 11> builtin_commands = {
    "info", "validate", "convert", "quality", "plugins", "components", "dissect", "delaunay-flip", "refine", "locate",
    "generate"};

bool is_builtin(std::string_view word) {
    return std::find(builtin_commands.begin(), builtin_commands.end(), word) != builtin_commands.end();
}

// Loads plug-ins, prints the refusals, and keeps the commands that do not clash with built-ins.
void load_plugins(PluginHost& host, Context& context) {
    host.load_default_folders();
    for (const PluginDiagnostic& diagnostic : host.diagnostics())
        context.err << "sxk: warning: " << diagnostic.path.string() << ": " << diagnostic.reason << '\n';
    for (const FoundCommand& found : host.commands()) {
        const std::string_view name = found.command->name();
        if (is_builtin(name.substr(0, name.find(' ')))) {
            context.err << "sxk: warning: " << found.plugin->path.string() << ": command '" << name
                        << "' clashes with a built-in command; ignored\n";
            continue;
        }
        context.plugin_commands.push_back(found);
    }
    context.host = &host;
}

int run_plugin_command(const FoundCommand& found, std::span<const std::string> args, Context& context) {
    try {
        return found.command->run(args, context.out, context.err);
    } catch (const InputError& error) {
        context.err << "sxk: " << error.what() << '\n';
        return exit_usage;
    } catch (const std::exception& error) {
        context.err << "sxk: " << found.command->name() << ": " << error.what() << '\n';
        return exit_refused;
    }
}

std::string plugin_footer(const Context& context) {
    if (context.plugin_commands.empty()) return {};
    std::string footer = "Plug-in commands (sxk COMMAND --help for their options):\n";
    for (const FoundCommand& found : context.plugin_commands) {
        std::string name(found.command->name());
        name.resize(std::max<std::size_t>(name.size() + 2, 16), ' ');
        footer += "  " + name + std::string(found.command->summary()) + "  [" + found.plugin->name + "]\n";
    }
    return footer;
}

// The names a mistyped command may have meant: the built-ins, `help`, and the plug-ins' commands
// (their first words).
std::vector<std::string> command_names(const Context& context) {
    std::vector<std::string> names(builtin_commands.begin(), builtin_commands.end());
    names.emplace_back("help");
    for (const FoundCommand& found : context.plugin_commands) {
        const std::string_view name = found.command->name();
        names.emplace_back(name.substr(0, name.find(' ')));
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

int run(std::vector<std::string> args, std::ostream& out, std::ostream& err) {
    // `sxk help [COMMAND...]`: what `sxk [COMMAND...] --help` prints
    if (!args.empty() && args[0] == "help") {
        args.erase(args.begin());
        args.emplace_back("--help");
    }
    Context context{out, err};
    PluginHost host;
    const bool needs_plugins = args.empty() || (args[0] != "--version" && !(is_builtin(args[0]) && args[0] != "plugins"));
    if (needs_plugins) {
        load_plugins(host, context);
        const FoundCommand found = host.find_command(args);
        if (found.command && std::find_if(context.plugin_commands.begin(), context.plugin_commands.end(),
                                          [&](const FoundCommand& usable) {
                                              return usable.command == found.command;
                                          }) != context.plugin_commands.end())
            return run_plugin_command(found, std::span(args).subspan(found.words), context);
    }

    CLI::App app("simplexkit: simplicial meshes (triangles, tetrahedra) after Nienhuys' thesis ch. 7", "sxk");
    app.set_version_flag("--version", "sxk " SXK_VERSION);
    app.require_subcommand(1);
    app.footer("Run 'sxk help COMMAND' (or 'sxk COMMAND --help') for a command's options.\n" + plugin_footer(context));
    add_info_command(app, context);
    add_validate_command(app, context);
    add_convert_command(app, context);
    add_quality_command(app, context);
    add_plugins_command(app, context);
    add_components_command(app, context);
    add_dissect_command(app, context);
    add_delaunay_flip_command(app, context);
    add_refine_command(app, context);
    add_locate_command(app, context);
    add_generate_command(app, context);
    // One --strict for every command that reads a mesh (all but plugins): load_mesh reads it.
    // validate judges the file as it is (never splits) and has a --strict of its own: flat
    // elements are invalid.
    for (CLI::App* command : app.get_subcommands({}))
        if (command->get_name() != "plugins" && command->get_name() != "validate" && command->get_name() != "generate")
            command->add_flag("--strict", context.strict, strict_reading_help);
    // One --format for every command that reads or writes a mesh: "-" as a file name is standard
    // input or output, in this format.
    for (CLI::App* command : app.get_subcommands({}))
        if (command->get_name() != "plugins")
            command->add_option("--format", context.format,
                                "The format of a mesh read from standard input or written to standard output "
                                "('-' as its file name): medit, gmsh, off, obj, vtu, vtk, stl or ply (or their "
                                "extensions)");

    if (!args.empty() && !args[0].empty() && args[0][0] != '-' && !is_builtin(args[0])) {
        // the command may belong to a plug-in that was not found: say where sxk looked
        std::string searched;
        for (const std::filesystem::path& folder : PluginHost::search_folders())
            searched += (searched.empty() ? "" : ", ") + folder.string();
        const auto meant = nearest_word(args[0], command_names(context));
        err << "sxk: unknown command '" << args[0] << "' (" << (meant ? "did you mean " + *meant + "? " : "")
            << "see sxk --help and sxk plugins; plug-ins searched in "
            << (searched.empty() ? std::string("no folder") : searched) << ")\n";
        return exit_usage;
    }
    try {
        // CLI11 wants the arguments last-first
        std::vector<std::string> reversed(args.rbegin(), args.rend());
        app.parse(reversed);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error, out, err);  // --help, --version
        std::string command = "sxk";
        const CLI::App* parsing = &app;
        for (const CLI::App* selected : app.get_subcommands()) {
            command += " " + selected->get_name();
            parsing = selected;
        }
        err << "sxk: " << error.what() << did_you_mean_option(*parsing, args) << "\nRun '" << command
            << " --help' for more information.\n";
        return exit_usage;
    }
    return context.exit_code;
}

}  // namespace
}  // namespace sxk::cli

int main(int argc, char** argv) {
    // A file-size limit (`ulimit -f`) would otherwise kill sxk with SIGXFSZ in the middle of a
    // write: no message, the temporary file left behind. Ignored, the write fails with EFBIG,
    // which the atomic writer reports and cleans up after (sxk/atomic_write.hpp).
    std::signal(SIGXFSZ, SIG_IGN);
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        return sxk::cli::run(args, std::cout, std::cerr);
    } catch (const std::exception& error) {
        // a bug, not an input problem: say so instead of terminating with an abort
        std::cerr << "sxk: internal error: " << error.what() << '\n';
        return sxk::cli::exit_refused;
    }
}
