// Shared pieces of the sxk commands: the context every command writes to, the registration
// function of each built-in command (one command per file), and mesh loading with
// the error convention of docs/cli.md ("sxk: FILE:LINE: reason", exit code 2).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_line.hpp"  // the command-line library: exit codes, number checks, reading and writing
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"
#include "sxk/plugin_host.hpp"

namespace sxk::cli {

struct Context {
    std::ostream& out;
    std::ostream& err;
    int exit_code = exit_success;
    // Loaded only when the invocation may involve plug-ins (built-in mesh commands never run
    // foreign code); nullptr otherwise.
    const PluginHost* host = nullptr;
    // Plug-in commands sxk accepts (those not clashing with a built-in name).
    std::vector<FoundCommand> plugin_commands = {};
    // --strict, which main.cpp gives every command that reads a mesh: load_mesh refuses pinched
    // vertices instead of splitting them (ReadOptions::split_pinched).
    bool strict = false;
    // --format, which main.cpp gives every command that reads or writes a mesh: the format of a
    // mesh read from standard input or written to standard output (the file name "-").
    std::string format = {};
    // A mesh went to standard output: what the command reports goes to `err` instead (report()).
    bool out_taken = false;

    // Where the command's report goes: `out`, unless standard output carries the mesh.
    std::ostream& report() { return out_taken ? err : out; }
};

// The message for a mesh file name that names no format: "-" without --format, or an unknown
// extension ("FILE:0: unknown output format (known: ...)"); nullopt when the format is known.
std::optional<std::string> unknown_format(const Context& context, const std::string& file, bool output);

void add_info_command(CLI::App& app, Context& context);
void add_validate_command(CLI::App& app, Context& context);
void add_convert_command(CLI::App& app, Context& context);
void add_quality_command(CLI::App& app, Context& context);
void add_plugins_command(CLI::App& app, Context& context);
void add_components_command(CLI::App& app, Context& context);
void add_dissect_command(CLI::App& app, Context& context);
void add_delaunay_flip_command(CLI::App& app, Context& context);
void add_refine_command(CLI::App& app, Context& context);
void add_locate_command(CLI::App& app, Context& context);
void add_generate_command(CLI::App& app, Context& context);

// Reads a mesh under a progress indicator ("-": standard input, in context.format). On failure
// prints "sxk: FILE:LINE: reason" to
// context.err, sets context.exit_code to 2 and returns nullopt. What the reader repaired is said
// on context.err ("sxk: warning: FILE: split 2 pinched vertices into 4 (--strict refuses
// them)", Medit faces listed again with another reference); context.strict refuses pinched
// vertices instead.
std::optional<Mesh> load_mesh(Context& context, const std::string& file, const ReadOptions& options = {},
                              ReadReport* report = nullptr);

// Writes a mesh under a progress indicator ("-": standard output, in context.format, and the
// command's report goes to standard error), atomically, and only when it has elements and
// validates with the orientation check (WriteOptions::refuse_invalid). On failure prints
// "sxk: FILE:0: reason" to context.err and returns false (the caller exits with exit_refused:
// the mesh was read, the writer refused it; an existing FILE is left as it was).
bool save_mesh(Context& context, const Mesh& mesh, const std::string& file, const WriteOptions& options = {});

// Reads a side input of a command (dissect --faces, locate --points) as mesh files are read
// (read_text_file: a directory, a device or a read error is an input error, a byte order mark is
// dropped) and hands the whitespace-separated words of each line to `take`, with '#' comments
// removed and blank lines skipped; `take` returns an empty string, or why the line is bad. On an
// unreadable file or a bad line prints "sxk: FILE:LINE: reason" and returns false.
bool read_word_lines(Context& context, const std::string& file,
                     const std::function<std::string(std::size_t line, const std::vector<std::string>& words)>& take);

// The format of a mesh file name: by extension, or --format for "-"; nullopt when it names none.
std::optional<Format> format_of(const Context& context, const std::string& file);

// What a file of `format` holds of `mesh`: the vertices and elements, or for a tetrahedral mesh in
// a format of triangles (.off .obj .stl .ply) its boundary surface's vertices and triangles.
struct Written {
    std::size_t vertices = 0, elements = 0;
    bool surface = false;  // the boundary of the tetrahedra
};
Written written_of(const Mesh& mesh, Format format);
// "27 vertices, 48 tetrahedra", or "26 vertices, 48 triangles (the boundary of 48 tetrahedra)".
std::string written_text(const Mesh& mesh, const Written& written);

// "tetrahedron" / "triangle"; element_count_text: "1 tetrahedron", "2 tetrahedra".
const char* element_kind(const Mesh& mesh);
std::string element_count_text(const Mesh& mesh, std::size_t count);
std::string element_count_text(const Mesh& mesh);

}  // namespace sxk::cli
