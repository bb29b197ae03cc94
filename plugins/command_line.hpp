// What every plug-in command does with its arguments, as the built-in sxk commands do: CLI11
// parses them; --help prints the usage and succeeds (exit 0); a usage error prints
// "sxk: NAME: reason" and a pointer to --help (exit 2). Header-only, for the plug-ins in this
// folder (sxk_add_plugin puts the folder on their include path).
#pragma once

#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace sxk {

// nullopt when the arguments parsed and the command should run; otherwise the exit code the
// command ends with (the usage or the error already printed).
inline std::optional<int> parse_command_line(CLI::App& app, std::span<const std::string> args, const std::string& name,
                                             std::ostream& out, std::ostream& err) {
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last-first
        app.parse(reversed);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) {  // --help
            out << app.help();
            return 0;
        }
        err << "sxk: " << name << ": " << error.what() << "\nRun 'sxk " << name << " --help' for more information.\n";
        return 2;
    }
    return std::nullopt;
}

}  // namespace sxk
