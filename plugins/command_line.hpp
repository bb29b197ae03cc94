// What every plug-in command does with its arguments and its mesh, as the built-in sxk commands
// do: CLI11 parses the arguments; --help prints the usage and succeeds (exit 0); a usage error
// prints "sxk: NAME: reason" and a pointer to --help (exit 2); an unreadable mesh prints
// "sxk: FILE:LINE: reason"; --strict (add_read_options) refuses pinched vertices. Header-only,
// for the plug-ins in this folder (sxk_add_plugin puts the folder on their include path).
#pragma once

#include <exception>
#include <new>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

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

// The reading options of the built-in commands, for a plug-in command that reads a mesh:
// --strict refuses pinched vertices instead of splitting them (ReadOptions::split_pinched).
inline void add_read_options(CLI::App& app, ReadOptions& options) {
    app.add_flag_callback(
        "--strict", [&options] { options.split_pinched = false; },
        "Refuse a mesh with pinched vertices (elements meeting only at a vertex) instead of "
        "splitting them");
}

// Reads a command's mesh as the built-in commands do (tools/sxk/load_mesh.cpp): on failure the
// error is printed as "sxk: FILE:LINE: reason" and nothing is returned; what the reader
// repaired is said as load_mesh says it (split pinched vertices, Medit faces listed again with
// another reference).
inline std::optional<Mesh> load_mesh_for_command(const std::string& file, std::ostream& err,
                                                 const ReadOptions& options = {}) {
    try {
        ReadReport report;
        std::optional<Mesh> mesh = read_mesh(file, options, &report);
        if (report.pinched_vertices > 0) {
            const std::size_t n = report.pinched_vertices;
            err << "sxk: warning: " << file << ": split " << n << " pinched vert"
                << (n == 1 ? "ex" : "ices") << " into " << n + report.vertex_copies.size()
                << " (--strict refuses them)\n";
        }
        if (report.label_conflicts > 0) {
            err << "sxk: warning: " << report.first_label_conflict
                << "; the first reference is kept";
            if (report.label_conflicts > 1)
                err << " (" << report.label_conflicts << " faces like this)";
            err << '\n';
        }
        return mesh;
    } catch (const InputError& error) {
        err << "sxk: " << error.what() << '\n';
    } catch (const std::bad_alloc&) {
        err << "sxk: " << file << ":0: out of memory while reading\n";
    } catch (const std::exception& error) {
        err << "sxk: " << file << ":0: " << error.what() << '\n';
    }
    return std::nullopt;
}

}  // namespace sxk
