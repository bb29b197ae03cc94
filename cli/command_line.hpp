// What every plug-in command does with its arguments and its mesh, as the built-in sxk commands
// do: CLI11 parses the arguments; --help prints the usage and succeeds (exit 0); a usage error
// prints "sxk: NAME: reason" and a pointer to --help (exit 2); an unreadable mesh prints
// "sxk: FILE:LINE: reason"; --strict (add_read_options) refuses what the readers repair. Part of
// the command-line library (cli/, simplexkit::cli), which sxk_add_plugin links into every plug-in.
//
// The built-in commands use it too (tools/sxk/cli.hpp includes this header): one reading of a
// number for every command, so that `nan` or `inf` cannot slip through one command's option while
// another's refuses it; one reading and writing of a command's mesh; one "did you mean".
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <exception>
#include <new>
#include <optional>
#include <ostream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "progress_line.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/tool_session.hpp"

namespace sxk {

namespace cli {

// Exit codes of every command, built-in or a plug-in's (docs/cli.md "Exit codes and messages").
inline constexpr int exit_success = 0;
inline constexpr int exit_refused = 1;  // operation refused or result invalid
inline constexpr int exit_usage = 2;    // usage or input error

// ---- did you mean ----------------------------------------------------------------------------

// The edit distance of a and b: insertions, deletions, substitutions and swaps of two neighbours.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The candidate nearest `word`, when it is near enough to be what was meant: at most a third of
// the word's letters (at least one) changed, and no other candidate as near.
inline std::optional<std::string> nearest_word(std::string_view word, std::span<const std::string> candidates) {
    const std::size_t limit = std::max<std::size_t>(1, word.size() / 3);
    std::optional<std::string> best;
    std::size_t best_distance = limit + 1;
    bool tie = false;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = edit_distance(word, candidate);
        if (distance < best_distance) {
            best = candidate;
            best_distance = distance;
            tie = false;
        } else if (distance == best_distance && candidate != *best) {
            tie = true;
        }
    }
    if (tie) return std::nullopt;
    return best;
}

// " (did you mean --aspect?)" for the first word of `args` that looks like an option `app` does
// not have and is near one it has; "" otherwise.
inline std::string did_you_mean_option(const CLI::App& app, std::span<const std::string> args) {
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options())
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& arg : args) {
        if (arg.size() < 3 || arg.rfind("--", 0) != 0) continue;
        const std::string word = arg.substr(0, arg.find('='));
        if (std::find(names.begin(), names.end(), word) != names.end()) continue;
        if (const auto near = nearest_word(word, names)) return " (did you mean " + *near + "?)";
        return "";
    }
    return "";
}

}  // namespace cli

// ---- numbers in options ----------------------------------------------------------------------
// Every numeric option of every sxk command is checked by one of these before CLI11 converts it.
// A number is read as the mesh readers read theirs (std::from_chars: locale-independent, the
// whole text, an optional leading '+') and must be finite: "nan", "inf", and a value a double
// cannot hold (1e400, 1e-400) are refused with "expected a finite number, found 'TEXT'".
// CLI11 puts the option's name in front: "--aspect: expected a finite number, found 'nan'".

inline std::optional<double> parse_finite_number(std::string_view text) {
    if (text.size() > 1 && text[0] == '+' && text[1] != '-')
        text.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

inline std::string not_a_finite_number(std::string_view text) {
    return "expected a finite number, found '" + std::string(text) + "'";
}

// The comma-separated numbers of `text` ("X,Y,Z"), or the message for the first one that is not
// a finite number: "expected a finite number, found 'nan' in '1,nan'".
inline std::variant<std::vector<double>, std::string> parse_number_list(std::string_view text) {
    std::vector<double> numbers;
    for (std::size_t begin = 0;;) {
        const std::size_t comma = text.find(',', begin);
        const std::string_view word =
            text.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin);
        const std::optional<double> value = parse_finite_number(word);
        if (!value)
            return not_a_finite_number(word) + " in '" + std::string(text) + "'";
        numbers.push_back(*value);
        if (comma == std::string_view::npos)
            return numbers;
        begin = comma + 1;
    }
}

// Any finite number.
inline CLI::Validator finite_number() {
    return CLI::Validator(
        [](std::string& text) { return parse_finite_number(text) ? std::string() : not_a_finite_number(text); },
        "NUMBER");
}

// A finite number in the interval from `low` to `high`, each end open or closed; `interval` names
// it in the message ("'2' is not in (0, 1)") and in the help.
inline CLI::Validator number_in(double low, bool low_closed, double high, bool high_closed,
                                const std::string& interval) {
    return CLI::Validator(
        [=](std::string& text) {
            const std::optional<double> value = parse_finite_number(text);
            if (!value)
                return not_a_finite_number(text);
            if (!(low_closed ? *value >= low : *value > low) || !(high_closed ? *value <= high : *value < high))
                return "'" + text + "' is not in " + interval;
            return std::string();
        },
        interval);
}

// A whole number (decimal digits, an optional '-') that fits an int: "'seven' is not a whole number";
// `name` is what the help calls it.
inline CLI::Validator whole_number(const std::string& name) {
    return CLI::Validator(
        [](std::string& text) {
            int value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || error != std::errc() || end != text.data() + text.size())
                return "'" + text + "' is not a whole number";
            return std::string();
        },
        name);
}

// A whole number (decimal digits, an optional '-') in [low, high]:
// "'0' is not a whole number in 1..512".
inline CLI::Validator whole_number_in(std::int64_t low, std::int64_t high) {
    const std::string interval = std::to_string(low) + ".." + std::to_string(high);
    return CLI::Validator(
        [=](std::string& text) {
            std::int64_t value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < low ||
                value > high)
                return "'" + text + "' is not a whole number in " + interval;
            return std::string();
        },
        interval);
}

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
            return cli::exit_success;
        }
        err << "sxk: " << name << ": " << error.what() << cli::did_you_mean_option(app, args) << "\nRun 'sxk " << name
            << " --help' for more information.\n";
        return cli::exit_usage;
    }
    return std::nullopt;
}

// The help of --strict, for the built-in commands and the plug-ins alike.
inline constexpr const char* strict_reading_help =
    "Refuse a mesh with pinched vertices (elements meeting only at a vertex) or labelled faces of no element "
    "instead of splitting or dropping them";

// The reading options of the built-in commands, for a plug-in command that reads a mesh:
// --strict refuses pinched vertices instead of splitting them (ReadOptions::split_pinched) and
// labelled faces of no element instead of dropping them (ReadOptions::drop_stray_faces).
inline void add_read_options(CLI::App& app, ReadOptions& options) {
    app.add_flag_callback(
        "--strict", [&options] { options.split_pinched = options.drop_stray_faces = false; }, strict_reading_help);
}

// Reads a command's mesh: the mesh, or the error as "FILE:LINE: reason" for the caller to print
// after "sxk: " (the built-in commands print it once their progress line is gone).
inline std::variant<Mesh, std::string> try_read_mesh(const std::string& file, const ReadOptions& options,
                                                      ReadReport& report) {
    try {
        return read_mesh(file, options, &report);
    } catch (const InputError& error) {
        return std::string(error.what());
    } catch (const std::bad_alloc&) {
        return file + ":0: out of memory while reading";
    } catch (const std::exception& error) {
        // readers promise InputError; anything else (filesystem errors) still names the file
        return file + ":0: " + error.what();
    }
}

// What the reader repaired, one warning line each (docs/cli.md "Reading meshes"): split pinched
// vertices, Medit faces listed again with another reference, labelled faces of no element, STL
// triangles of zero area.
inline void print_read_warnings(std::ostream& err, const std::string& file, const ReadReport& report) {
    if (report.pinched_vertices > 0) {
        const std::size_t n = report.pinched_vertices;
        err << "sxk: warning: " << file << ": split " << n << " pinched vert" << (n == 1 ? "ex" : "ices") << " into "
            << n + report.vertex_copies.size() << " (--strict refuses them)\n";
    }
    if (report.label_conflicts > 0) {
        err << "sxk: warning: " << report.first_label_conflict << "; the first reference is kept";
        if (report.label_conflicts > 1)
            err << " (" << report.label_conflicts << " faces like this)";
        err << '\n';
    }
    if (report.stray_faces > 0) {
        err << "sxk: warning: " << report.first_stray_face << "; dropped";
        if (report.stray_faces > 1)
            err << " (" << report.stray_faces << " faces like this)";
        err << " (--strict refuses it)\n";
    }
    if (report.dropped_triangles > 0) {
        err << "sxk: warning: " << report.first_dropped_triangle << "; dropped";
        if (report.dropped_triangles > 1)
            err << " (" << report.dropped_triangles << " triangles like this)";
        err << '\n';
    }
}

// Reads a command's mesh as the built-in commands do (tools/sxk/load_mesh.cpp): on failure the
// error is printed as "sxk: FILE:LINE: reason" and nothing is returned; what the reader
// repaired is said as print_read_warnings says it.
inline std::optional<Mesh> load_mesh_for_command(const std::string& file, std::ostream& err,
                                                 const ReadOptions& options = {}, ReadReport* report = nullptr) {
    ReadReport own;
    if (report == nullptr) report = &own;
    std::variant<Mesh, std::string> read = [&] {
        ProgressLine progress("reading " + file);
        return try_read_mesh(file, options, *report);
    }();  // the progress line is gone before anything is printed
    if (std::string* error = std::get_if<std::string>(&read)) {
        err << "sxk: " << *error << '\n';
        return std::nullopt;
    }
    print_read_warnings(err, file, *report);
    return std::move(std::get<Mesh>(read));
}

// A writer's "cannot write FILE: why" (OutputError, sxk/atomic_write.hpp) as sxk prints it, with
// FILE in front: "FILE:0: cannot write: why".
inline std::string write_error_line(const std::string& file, const std::exception& error) {
    std::string why = error.what();
    const std::string named = "cannot write " + file + ": ";
    if (why.rfind(named, 0) == 0)
        why = "cannot write: " + why.substr(named.size());
    return file + ":0: " + why;
}

// Writes a command's result atomically, and only when it has elements and passes
// Mesh::validate with the orientation check (WriteOptions::refuse_invalid): a command's output
// is a file every command accepts, or no file (an existing one stays as it was). nullopt when
// written, else the error as "FILE:0: cannot write: why" for the caller to print after "sxk: ".
inline std::optional<std::string> try_write_mesh(const Mesh& mesh, const std::string& file, WriteOptions options) {
    options.refuse_invalid = true;
    try {
        write_mesh(mesh, file, options);
        return std::nullopt;
    } catch (const std::exception& error) {
        return write_error_line(file, error);
    }
}

// The message for an output file whose extension names no mesh format, "FILE:0: unknown output
// format (known: .mesh .msh ...)" for the caller to print after "sxk: " (exit 2), checked before
// the input is read; nullopt when the format is known.
inline std::optional<std::string> unknown_output_format(const std::string& file) {
    if (format_from_extension(file))
        return std::nullopt;
    return file + ":0: unknown output format (known: " + std::string(known_mesh_extensions()) + ")";
}

// try_write_mesh for a plug-in command: prints "sxk: FILE:0: cannot write: why" and returns
// false when the result was not written (the command then exits 1).
inline bool save_mesh_for_command(const Mesh& mesh, const std::string& file, std::ostream& err,
                                  const WriteOptions& options = {}) {
    const std::optional<std::string> error = [&] {
        ProgressLine progress("writing " + file);
        return try_write_mesh(mesh, file, options);
    }();  // the progress line is gone before anything is printed
    if (error) {
        err << "sxk: " << *error << '\n';
        return false;
    }
    return true;
}

// ---- tool commands ----------------------------------------------------------------------------
// `--undo N|all` of the commands that replay a recorded path through a tool session (`cut snap`,
// `cut delaunay`, `needle`): after the replay, the last N steps are undone through the session, so
// that with `all` OUT is IN as the writer writes it.

// What `--undo` asks for: every step, or a count.
struct UndoRequest {
    bool all = false;
    std::size_t count = 0;
};

// `all`, or N written as decimal digits only; nullopt for anything else. One reading for the
// option's check and for undo_steps: the check once took any whole-valued number ("20e-1",
// "1e3") and undo_steps then read the leading digits with std::stoull, undoing 20 steps for
// "20e-1" and 1 for "1e3" (issue 47).
inline std::optional<UndoRequest> parse_undo(std::string_view text) {
    if (text == "all") return UndoRequest{true, 0};
    if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
    std::size_t count = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;  // beyond size_t
    return UndoRequest{false, count};
}

inline std::string not_an_undo_count(std::string_view text) {
    return "'" + std::string(text) + "' is neither a whole number >= 0 nor 'all'";
}

inline void add_undo_option(CLI::App& app, std::string& undo) {
    app.add_option("--undo", undo,
                   "After the replay, undo the last N steps (N in decimal digits, or 'all': OUT is then IN as the "
                   "writer writes it)")
        ->check(CLI::Validator(
            [](std::string& text) { return parse_undo(text) ? std::string() : not_an_undo_count(text); }, "N|all"));
}

// Whitespace-separated words: an option that carries another command's options in one word
// (`--deform "--fix z<0.001 --E 1e4"`).
inline std::vector<std::string> words_of(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream in(text);
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

// Another command's option words carried in one option (`--deform WORDS`, split by words_of),
// parsed into `app` as that command's line would be; a refusal (bad_argument, "COMMAND: --fix:
// ...") when they do not parse.
inline std::optional<Refusal> parse_words(CLI::App& app, std::span<const std::string> words,
                                          std::string_view command) {
    std::vector<std::string> arguments(words.rbegin(), words.rend());  // CLI11 parses from the back
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& error) {
        return Refusal{RefusalCode::bad_argument, std::string(command) + ": " + error.what()};
    }
    return std::nullopt;
}

// Undoes what `undo` (the option's text; empty: nothing) asks of `session`: the steps undone, or the
// command's exit code after printing why not ("sxk: NAME: --undo 9: only 4 steps were taken", exit 2;
// a refused undo, exit 1).
inline std::variant<std::size_t, int> undo_steps(ToolSession& session, const std::string& undo,
                                                 const std::string& name, std::ostream& err) {
    if (undo.empty()) return std::size_t{0};
    const std::optional<UndoRequest> request = parse_undo(undo);
    if (!request) {  // add_undo_option's check refuses it first; a caller without it gets the same words
        err << "sxk: " << name << ": --undo: " << not_an_undo_count(undo) << '\n';
        return cli::exit_usage;
    }
    const std::size_t kept = session.steps();
    const std::size_t count = request->all ? kept : request->count;
    if (count > kept) {
        err << "sxk: " << name << ": --undo " << undo << ": only " << kept << " steps were taken\n";
        return cli::exit_usage;
    }
    for (std::size_t i = 0; i < count; ++i)
        if (auto undone = session.undo_step(); !undone) {
            err << "sxk: " << name << ": " << undone.reason() << '\n';
            return cli::exit_refused;
        }
    return count;
}

}  // namespace sxk
