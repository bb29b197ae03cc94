// `--frames DIR` of the commands that replay a tool path (`sxk cut snap`, `sxk needle`): a picture
// of the mesh before the first step and after each, drawn by the bezier plug-in's renderer (found
// through the host, so no plug-in links another), one camera for all, chosen as the replay starts;
// or by the tool itself (drawn_by: a planar mesh with the needle over it).
// Header-only, for the plug-ins in this folder that put plugins/bezier on their include path.
#pragma once

#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "render_service.hpp"
#include "sxk/mesh.hpp"
#include "sxk/plugin.hpp"

namespace sxk {

class ToolFrames {
public:
    // No pictures (an empty folder): draw() does nothing. Otherwise the renderer and the folder
    // (made if missing), or the message printed ("sxk: COMMAND: --frames: ...") and nullopt.
    // `words`: the renderer's options besides the camera ("--colour", "plain", ...).
    static std::optional<ToolFrames> open(const Services* host, const Mesh& mesh, const std::string& folder,
                                          const std::string& command, std::vector<std::string> words,
                                          std::ostream& err) {
        ToolFrames frames;
        if (folder.empty()) return frames;
        auto found = host ? host->service<bezier::RenderService>()
                          : Outcome<bezier::RenderService*>(Refusal{RefusalCode::not_found, "no plug-in host"});
        if (!found) {
            err << "sxk: " << command << ": --frames: " << found.reason() << " (the bezier plug-in)\n";
            return std::nullopt;
        }
        if (!make_folder(folder, command, err)) return std::nullopt;
        frames.m_renderer = *found;
        frames.m_folder = folder;
        frames.m_command = command;
        words.push_back("--camera");
        words.push_back(frames.m_renderer->default_camera(mesh));
        frames.m_words = std::move(words);
        return frames;
    }

    // Pictures the tool draws itself (a planar mesh with its tool over it): `draw(file, index)`
    // writes picture `index` to `file`, throwing std::exception with the reason when it cannot.
    // The folder is made if missing; nullopt with the message printed when it cannot be.
    using Drawer = std::function<void(const std::filesystem::path& file, std::size_t index)>;
    static std::optional<ToolFrames> drawn_by(const std::string& folder, const std::string& command, Drawer draw,
                                              std::ostream& err) {
        ToolFrames frames;
        if (folder.empty()) return frames;
        if (!make_folder(folder, command, err)) return std::nullopt;
        frames.m_folder = folder;
        frames.m_command = command;
        frames.m_drawer = std::move(draw);
        return frames;
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
    static std::string file_name(std::size_t index) {
        char name[32];
        std::snprintf(name, sizeof name, "step-%04zu.png", index);
        return name;
    }

    // Picture `index`; false with the message printed.
    bool draw(const Mesh& mesh, std::size_t index, std::ostream& err) const {
        if (m_drawer) {
            try {
                m_drawer(std::filesystem::path(m_folder) / file_name(index), index);
            } catch (const std::exception& error) {
                err << "sxk: " << m_command << ": --frames: " << error.what() << '\n';
                return false;
            }
            return true;
        }
        if (m_renderer == nullptr) return true;
        if (auto drawn = m_renderer->draw_mesh(mesh, std::filesystem::path(m_folder) / file_name(index), m_words);
            !drawn) {
            err << "sxk: " << m_command << ": --frames: " << drawn.reason() << '\n';
            return false;
        }
        return true;
    }

private:
    const bezier::RenderService* m_renderer = nullptr;
    Drawer m_drawer;  // drawn_by's
    std::string m_folder, m_command;
    std::vector<std::string> m_words;
};

}  // namespace sxk
