// The files a plug-in command will write, checked before it reads or changes anything: OUT and
// its side outputs (pictures: `cut delaunay --svg`, `--histogram`). A command that replaced OUT
// and then failed on a picture would exit 1 with OUT already changed, and a picture named like
// the input mesh would overwrite it. Part of the command-line library (cli/), beside
// command_line.hpp (whose write_error_line gives the "FILE:0: cannot write: why" form).
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace sxk {

// Whether `a` and `b` name one file: std::filesystem::equivalent when both exist (hard and
// symbolic links, "./x" and "x"), else the same absolute path once the folders' links are
// resolved (a file about to be created).
inline bool same_file(const std::string& a, const std::string& b) {
    std::error_code error_a, error_b;
    const bool a_exists = std::filesystem::exists(a, error_a), b_exists = std::filesystem::exists(b, error_b);
    if (a_exists && b_exists) {
        std::error_code error;
        return std::filesystem::equivalent(a, b, error) && !error;
    }
    if (a_exists != b_exists)
        return false;
    std::error_code error;
    const std::filesystem::path full_a = std::filesystem::weakly_canonical(std::filesystem::absolute(a), error);
    const std::filesystem::path full_b = std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
    return full_a == full_b;
}

// Why `file` cannot be written as write_file_atomically writes (a temporary in its folder,
// renamed over it): its folder missing, no folder, or not writable; a directory or another
// non-regular file in its place. Said as the writer says it (strerror, "is a directory", "not a
// regular file"); nullopt when the write may go ahead (a full disk can still fail it then).
inline std::optional<std::string> why_unwritable(const std::string& file) {
    struct stat info {};
    if (::stat(file.c_str(), &info) == 0) {
        if (S_ISDIR(info.st_mode))
            return std::string("is a directory");
        if (!S_ISREG(info.st_mode))
            return std::string("not a regular file");
    } else if (errno != ENOENT) {
        return std::string(std::strerror(errno));
    }
    const std::filesystem::path parent = std::filesystem::path(file).parent_path();
    const std::string folder = parent.empty() ? std::string(".") : parent.string();
    if (::stat(folder.c_str(), &info) != 0)
        return std::string(std::strerror(errno));
    if (!S_ISDIR(info.st_mode))
        return std::string(std::strerror(ENOTDIR));
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return std::string(std::strerror(errno));
    return std::nullopt;
}

// A side output of a command: its option, the file given (empty: not asked for), the extension
// it must have and what is written there, for the message ("the picture is SVG").
struct SideOutput {
    std::string option;
    std::string file;
    std::string extension;
    std::string written;
};

// Checks `output` and the side outputs asked for before the command does anything; nullopt when
// it may go ahead, else the exit code after printing why not:
// - a side output that is the same file as the input, the output or another side output
//   ("sxk: cut delaunay: --svg sq.mesh: the same file as the input mesh sq.mesh; name another
//   file"), or whose extension is not what is written ("sxk: cut delaunay: --svg x.png: the
//   picture is SVG; name it *.svg"): a usage error, exit 2;
// - a file that cannot be written (why_unwritable): "sxk: FILE:0: cannot write: why", as the
//   write itself would fail, exit 1.
inline std::optional<int> check_outputs(const std::string& command, const std::string& input,
                                        const std::string& output, std::span<const SideOutput> sides,
                                        std::ostream& err) {
    std::vector<const SideOutput*> asked;
    for (const SideOutput& side : sides)
        if (!side.file.empty())
            asked.push_back(&side);
    for (std::size_t i = 0; i < asked.size(); ++i) {
        const SideOutput& side = *asked[i];
        std::string other;
        if (same_file(side.file, input))
            other = "the input mesh " + input;
        else if (same_file(side.file, output))
            other = "the output mesh " + output;
        for (std::size_t j = 0; j < i && other.empty(); ++j)
            if (same_file(side.file, asked[j]->file))
                other = "the file of " + asked[j]->option;
        if (!other.empty()) {
            err << "sxk: " << command << ": " << side.option << ' ' << side.file << ": the same file as " << other
                << "; name another file\n";
            return cli::exit_usage;
        }
        if (std::filesystem::path(side.file).extension() != side.extension) {
            err << "sxk: " << command << ": " << side.option << ' ' << side.file << ": " << side.written
                << "; name it *" << side.extension << '\n';
            return cli::exit_usage;
        }
    }
    std::vector<std::string> files{output};
    for (const SideOutput* side : asked)
        files.push_back(side->file);
    for (const std::string& file : files)
        if (const std::optional<std::string> why = why_unwritable(file)) {
            err << "sxk: " << file << ":0: cannot write: " << *why << '\n';
            return cli::exit_refused;
        }
    return std::nullopt;
}

}  // namespace sxk
