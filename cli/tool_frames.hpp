// What the tool commands (`sxk cut snap`, `sxk cut delaunay`, `sxk needle`) record of a replay,
// step by step, in one place:
//
//   --frames DIR        a picture before the first step (step-0000.png) and after each
//                       (step-NNNN.png), drawn by the bezier plug-in's renderer (found through the
//                       host, so no plug-in links another) with one size and camera for the whole
//                       run, fitted to the body as the replay starts (RenderService::frame_view):
//                       pieces coloured, cut faces magenta and seen through the body, the tool at
//                       that step, the step and its time; or by the tool itself (a planar needle:
//                       `drawer`)
//   --animation FILE    with --frames: the pictures as a GIF or MP4, made by ffmpeg run as a
//                       program when it is installed (no library depends on it); without it a
//                       note says so and the command goes on
//   --series OUT.pvd    a ParaView collection (VTK XML, type "Collection"): OUT.pvd lists
//   [--series-every N]  OUT_NNNNNN.vtu (NNNNNN: the step), the mesh after every N-th step and after
//                       the last, each written by sxk::write_mesh as OUT is, at the time of the
//                       step's sample in the path (docs/formats.md "Tool paths"); file names
//                       relative to the .pvd's folder.
//
// The .pvd is rewritten atomically (sxk/atomic_write.hpp) when the replay starts (empty) and after
// every file it gains, each .vtu written before the .pvd names it: whenever the command stops,
// failed or killed, OUT.pvd is a valid collection of exactly the files this run wrote whole (a
// failed .vtu write leaves no file and stops the command with exit 1). The cost is one small file
// per written step, beside the step's .vtu itself.
// Part of the command-line library (cli/), which every plug-in links.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "sxk/plugins/render.hpp"
#include "command_line.hpp"
#include "sxk/atomic_write.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"
#include "sxk/plugin.hpp"

extern char** environ;

namespace sxk {

struct RecordingOptions {
    std::string frames;     // --frames DIR ("": none)
    std::string animation;  // --animation FILE (.gif or .mp4)
    std::string series;     // --series OUT.pvd
    std::size_t series_every = 1;
};

// The options of every tool command, worded once.
inline void add_recording_options(CLI::App& app, RecordingOptions& options) {
    app.add_option("--frames", options.frames,
                   "Write a picture of the mesh per step into folder DIR (made if missing): step-0000.png before "
                   "the first step, then one per step; one camera for the whole run, the body filling the picture, "
                   "pieces coloured, cut faces magenta (seen through the body where it hides them), the tool, the "
                   "step and its time")
        ->type_name("DIR");
    app.add_option("--animation", options.animation,
                   "With --frames: also the pictures as an animation, FILE.gif or FILE.mp4, 5 pictures a second "
                   "(made by ffmpeg when it is installed; otherwise a note and no animation)")
        ->type_name("FILE");
    app.add_option("--series", options.series,
                   "Write a ParaView time series: FILE.pvd listing FILE_NNNNNN.vtu, the mesh after each step at "
                   "its time in the path; valid after every step, so also when the command fails midway")
        ->type_name("FILE.pvd");
    app.add_option("--series-every", options.series_every,
                   "With --series: write every N-th step only (and always the last)")
        ->check(whole_number_in(1, 1000000000))
        ->type_name("N");
}

class ToolRecording {
public:
    // Pictures the tool draws itself (a planar mesh with its tool over it): `draw(file, index)`
    // writes picture `index` to `file`, throwing std::exception with the reason when it cannot.
    using Drawer = std::function<void(const std::filesystem::path& file, std::size_t index)>;

    struct Setup {
        std::string command;                     // "cut snap": messages say "sxk: cut snap: --frames: ..."
        std::size_t steps = 0;                   // the path's steps: the pictures say "step i of n"
        bezier::Colouring colour = bezier::Colouring::piece;  // the renderer's pictures: colouring,
        int cut_label = 9999;                                  // and the label of the cut faces
        Drawer drawer;                           // set: pictures drawn by the tool, not the renderer
        WriteOptions writing;                    // how the series' files are written (as OUT)
    };

    // Checks the options and prepares what they ask for, the mesh as the replay starts: nullopt
    // with the message printed ("sxk: COMMAND: --frames: ..."; the command exits 2) when they
    // cannot be followed. Nothing asked: a recording that does nothing.
    static std::optional<ToolRecording> open(const Services* host, const Mesh& mesh, const RecordingOptions& options,
                                             Setup setup, std::ostream& err) {
        ToolRecording recording;
        recording.m_options = options;
        recording.m_setup = std::move(setup);
        const std::string& command = recording.m_setup.command;
        if (!options.animation.empty()) {
            const std::string extension = std::filesystem::path(options.animation).extension().string();
            if (options.frames.empty()) {
                err << "sxk: " << command << ": --animation needs --frames (it is made of the pictures)\n";
                return std::nullopt;
            }
            if (extension != ".gif" && extension != ".mp4") {
                err << "sxk: " << command << ": --animation " << options.animation << ": name it *.gif or *.mp4\n";
                return std::nullopt;
            }
        }
        if (!options.series.empty()) {
            const std::filesystem::path series(options.series);
            if (series.extension() != ".pvd" || series.stem().empty()) {
                err << "sxk: " << command << ": --series " << options.series
                    << ": the series is a ParaView collection; name it *.pvd\n";
                return std::nullopt;
            }
            const std::filesystem::path folder = series.parent_path().empty() ? "." : series.parent_path();
            std::error_code error;
            if (!std::filesystem::is_directory(folder, error)) {
                err << "sxk: " << command << ": --series " << options.series << ": no such folder "
                    << folder.string() << '\n';
                return std::nullopt;
            }
        }
        if (!options.frames.empty()) {
            if (!make_folder(options.frames, command, err)) return std::nullopt;
            if (!recording.m_setup.drawer) {
                auto found = host ? host->service<bezier::RenderService>()
                                  : Outcome<bezier::RenderService*>(Refusal{RefusalCode::not_found, "no plug-in host"});
                if (!found) {
                    err << "sxk: " << command << ": --frames: " << found.reason() << " (the bezier plug-in)\n";
                    return std::nullopt;
                }
                recording.m_renderer = *found;
                // 640 x 480 pixels' worth, shaped to the body
                recording.m_view = recording.m_renderer->frame_view(mesh, 640LL * 480);
            }
        }
        // the collection exists, empty, from the start: a run that fails before its first step
        // leaves no collection of an earlier run naming files this one may overwrite
        if (!options.series.empty() && !recording.write_collection(err)) return std::nullopt;
        return recording;
    }

    // The folder, made if missing; false with the message printed.
    static bool make_folder(const std::string& folder, const std::string& command, std::ostream& err) {
        std::error_code error;
        std::filesystem::create_directories(folder, error);
        if (error || !std::filesystem::is_directory(folder)) {
            err << "sxk: " << command << ": --frames: cannot make folder " << folder
                << (error ? ": " + error.message() : std::string()) << '\n';
            return false;
        }
        return true;
    }

    // The name of picture `index` (0: before the first step): step-NNNN.png.
    static std::string frame_name(std::size_t index) {
        char name[32];
        std::snprintf(name, sizeof name, "step-%04zu.png", index);
        return name;
    }

    // The series' file of step `index`: OUT_NNNNNN.vtu beside OUT.pvd.
    static std::string series_file_name(const std::string& series, std::size_t index) {
        char number[32];
        std::snprintf(number, sizeof number, "_%06zu.vtu", index);
        return std::filesystem::path(series).stem().string() + number;
    }

    // The mesh after step `index` (0: before the first step), at `time`, with the tool where the
    // step left it (a point, a segment or a triangle; empty: none): the picture, and the series'
    // file when it is due. False with the message printed (the command exits 1).
    bool step(const Mesh& mesh, std::size_t index, double time, std::span<const Point> tool, std::ostream& err) {
        m_last = index;
        m_last_time = time;
        if (!m_options.frames.empty() && !draw(mesh, index, time, tool, err)) return false;
        if (!m_options.series.empty() && index > 0 && index % m_options.series_every == 0)
            return add_to_series(mesh, index, time, err);
        return true;
    }

    // After the last step (before any undo): the last step's file if --series-every skipped it, and
    // the animation. False with the message printed.
    bool finish(const Mesh& mesh, std::ostream& err) {
        if (!m_options.series.empty() && m_last > 0 && (m_entries.empty() || m_entries.back().index != m_last) &&
            !add_to_series(mesh, m_last, m_last_time, err))
            return false;
        if (!m_options.animation.empty()) animate(err);
        return true;
    }

private:
    struct Entry {
        std::size_t index = 0;
        double time = 0;
        std::string file;
    };

    bool draw(const Mesh& mesh, std::size_t index, double time, std::span<const Point> tool, std::ostream& err) const {
        const std::filesystem::path file = std::filesystem::path(m_options.frames) / frame_name(index);
        if (m_setup.drawer) {
            try {
                m_setup.drawer(file, index);
            } catch (const std::exception& error) {
                err << "sxk: " << m_setup.command << ": --frames: " << error.what() << '\n';
                return false;
            }
            return true;
        }
        bezier::MeshPicture picture = m_view;
        picture.colour = m_setup.colour;
        picture.cut_label = m_setup.cut_label;
        picture.title = title(index, time);
        picture.tool.assign(tool.begin(), tool.end());
        if (auto drawn = m_renderer->draw_mesh(mesh, file, picture); !drawn) {
            err << "sxk: " << m_setup.command << ": --frames: " << drawn.reason() << '\n';
            return false;
        }
        return true;
    }

    std::string title(std::size_t index, double time) const {
        if (index == 0) return m_setup.command + ": before the first step";
        char text[160];
        std::snprintf(text, sizeof text, "%s: step %zu of %zu, t = %g", m_setup.command.c_str(), index, m_setup.steps,
                      time);
        return text;
    }

    bool add_to_series(const Mesh& mesh, std::size_t index, double time, std::ostream& err) {
        const std::string name = series_file_name(m_options.series, index);
        const std::filesystem::path file = std::filesystem::path(m_options.series).parent_path() / name;
        if (const std::optional<std::string> error = try_write_mesh(mesh, file.string(), m_setup.writing)) {
            err << "sxk: " << *error << '\n';
            return false;
        }
        m_entries.push_back({index, time, name});
        return write_collection(err);
    }

    static std::string xml_attribute(const std::string& text) {
        std::string escaped;
        for (const char c : text) {
            switch (c) {
                case '&': escaped += "&amp;"; break;
                case '<': escaped += "&lt;"; break;
                case '>': escaped += "&gt;"; break;
                case '"': escaped += "&quot;"; break;
                default: escaped += c;
            }
        }
        return escaped;
    }

    bool write_collection(std::ostream& err) const {
        std::string text =
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n";
        char time[40];
        for (const Entry& entry : m_entries) {
            // the shortest text that reads back to the sample's time: 0.1, not 0.10000000000000001
            const auto written = std::to_chars(time, time + sizeof time, entry.time);
            text += "    <DataSet timestep=\"" + std::string(time, written.ptr) + "\" group=\"\" part=\"0\" file=\"" +
                    xml_attribute(entry.file) + "\"/>\n";
        }
        text += "  </Collection>\n</VTKFile>\n";
        try {
            write_file_atomically(m_options.series, text);
        } catch (const std::exception& error) {
            err << "sxk: " << write_error_line(m_options.series, error) << '\n';
            return false;
        }
        return true;
    }

    // ffmpeg, found on PATH and run as a program (posix_spawnp, no shell): the frames at 5 a second;
    // a GIF through a palette made from them (the default 256-colour palette bands the shading),
    // an MP4 in H.264 with the yuv420p pixels every player reads. A missing ffmpeg or a failed run
    // is a note, not an error: the pictures are written already.
    void animate(std::ostream& err) const {
        const std::string pattern = (std::filesystem::path(m_options.frames) / "step-%04d.png").string();
        std::vector<std::string> args{"ffmpeg", "-y", "-loglevel", "error", "-framerate", "5", "-i", pattern};
        if (std::filesystem::path(m_options.animation).extension() == ".gif")
            args.insert(args.end(), {"-filter_complex", "[0:v]split[a][b];[a]palettegen[p];[b][p]paletteuse"});
        else
            args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p"});
        args.push_back(m_options.animation);
        std::vector<char*> argv;
        for (std::string& arg : args) argv.push_back(arg.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
        pid_t pid = 0;
        const int spawned = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        if (spawned != 0) {
            err << "sxk: note: --animation: ffmpeg " << (spawned == ENOENT ? "is not installed" : std::strerror(spawned))
                << " (apt-get install ffmpeg): no animation, the pictures are in " << m_options.frames << '\n';
            return;
        }
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
            err << "sxk: note: --animation: ffmpeg failed making " << m_options.animation
                << ": no animation, the pictures are in " << m_options.frames << '\n';
    }

    RecordingOptions m_options;
    Setup m_setup;
    const bezier::RenderService* m_renderer = nullptr;
    bezier::MeshPicture m_view;  // the size and camera of every picture
    std::vector<Entry> m_entries;     // the series' files written
    std::size_t m_last = 0;
    double m_last_time = 0;
};

}  // namespace sxk
