// The needle plug-in: `sxk needle IN PATH OUT` replays a recorded needle path through a
// NeedleSession (needle.hpp), and the plug-in's ToolFactory offers the session as the tool
// "needle". The simulation is the elasticity plug-in's service and the pictures the bezier
// plug-in's renderer, found through the host (Plugin::attach): no plug-in links another.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "body_words.hpp"
#include "command_line.hpp"
#include "sxk/plugins/elasticity.hpp"
#include "line_plot.hpp"
#include "needle.hpp"
#include "needle_options.hpp"
#include "needle_report.hpp"
#include "planar_picture.hpp"
#include "refinement_budget.hpp"
#include "sxk/io.hpp"
#include "sxk/plugin.hpp"
#include "sxk/tool_path.hpp"
#include "tool_frames.hpp"
#include "uniform_refinement.hpp"

extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_needle();

namespace sxk::needle {

namespace {

struct CommandOptions {
    std::string input, path, output, deform, plot;
    RecordingOptions recording;  // --frames, --animation, --series (tool_frames.hpp)
    std::optional<double> h_start;
    Options needle;
    bool json = false;
    std::string undo;
    std::size_t settle = 0;
    ReadOptions reading;
};

// The force profile along the needle after the replay: the needle's force on each needle node
// along the axis, by the node's distance behind the tip, and the friction profile it works with.
void draw_profile(const std::string& file, const NeedleSession& session) {
    pictures::Plot plot;
    plot.title = "forces along the needle";
    plot.x_label = "distance behind the tip (mm)";
    plot.y_label = "force along the needle (N)";
    std::vector<NeedleNode> nodes(session.nodes().begin(), session.nodes().end());
    std::sort(nodes.begin(), nodes.end(), [](const NeedleNode& a, const NeedleNode& b) { return a.along > b.along; });
    pictures::Series on_node{"on each needle node", {}, {}};
    pictures::Series dynamic{"dynamic threshold", {}, {}};
    pictures::Series fixed{"static threshold", {}, {}};
    for (const NeedleNode& node : nodes) {
        const double mm = -node.along * 1000;
        on_node.x.push_back(mm);
        on_node.y.push_back(node.axial);
        dynamic.x.push_back(mm);
        dynamic.y.push_back(node.threshold);
        fixed.x.push_back(mm);
        fixed.y.push_back(node.threshold * session.options().friction.static_ratio);
    }
    plot.series = {on_node, dynamic, fixed};
    pictures::write_png(file, pictures::draw(plot));
}

class NeedleCommand final : public PluginCommand {
public:
    // `host`: the plug-in's, set when the host attaches it
    explicit NeedleCommand(const sxk::Services* const& host) : m_host(host) {}

    std::string_view name() const override { return "needle"; }
    std::string_view summary() const override {
        return "insert a needle along a recorded path: refine around it, stick-slip friction, solve "
               "(thesis chapter 6)";
    }

    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override {
        CommandOptions o;
        CLI::App app("Insert a rigid needle into an elastic body along a recorded path (thesis chapter 6): "
                     "each movement refines the mesh by bisection around the tip's path, makes the nodes "
                     "of the edges the tip enters needle nodes, solves the body with the needle nodes "
                     "sticking or slipping (static and dynamic friction), as one undoable step.",
                     "sxk needle");
        app.add_option("IN", o.input, "Triangle mesh in the plane, or tetrahedral mesh")->required();
        app.add_option("PATH", o.path,
                       "Needle path: one sample per line, 'time bx by tx ty' (2D) or 'time bx by bz tx ty "
                       "tz' (3D): base and tip (docs/formats.md)")
            ->required();
        app.add_option("OUT", o.output, "Output mesh, format by extension (" + std::string(known_mesh_extensions()) + ")")
            ->required();
        app.add_option("--h-start", o.h_start,
                       "Refine the whole mesh to elements of this size first (thesis h_start; not a step)")
            ->check(number_in(0, false, 1e300, true, "(0, 1e300]"));
        add_needle_options(app, o.needle, o.deform);
        add_recording_options(app, o.recording);  // a planar mesh's pictures show the needle's nodes too
        app.add_option("--plot", o.plot,
                       "Draw the forces along the needle after the replay (PNG): per needle node, and "
                       "the friction thresholds");
        app.add_option("--settle", o.settle,
                       "After the path, one more step at the needle's last pose that solves the whole body with at "
                       "most this many CG iterations: with --local, the far field catches up (0: none)")
            ->check(CLI::Range(std::size_t{0}, std::size_t{100000000}));
        add_undo_option(app, o.undo);
        app.add_flag("--json", o.json, "Print one JSON object (with a 'steps' array) instead of the table");
        add_read_options(app, o.reading);
        if (const auto done = parse_command_line(app, args, "needle", out, err)) return *done;

        if (const auto unknown = unknown_output_format(o.output)) {
            err << "sxk: " << *unknown << '\n';
            return cli::exit_usage;
        }
        if (!o.plot.empty() && std::filesystem::path(o.plot).extension() != ".png") {
            err << "sxk: needle: --plot " << o.plot << ": the plot is a PNG picture; name it *.png\n";
            return cli::exit_usage;
        }
        ToolPath path;
        try {
            const std::array<int, 2> columns{4, 6};
            path = read_tool_path(o.path, columns);
        } catch (const InputError& error) {
            err << "sxk: " << error.what() << '\n';
            return cli::exit_usage;
        }
        std::optional<Mesh> mesh = load_mesh_for_command(o.input, err, o.reading);
        if (!mesh) return cli::exit_usage;
        const bool planar = mesh->topological_dimension() == 2 && mesh->ambient_dimension() == 2;
        const bool solid = mesh->topological_dimension() == 3 && mesh->ambient_dimension() == 3;
        if (!planar && !solid) {
            err << "sxk: " << o.input << ":0: the needle goes into triangle meshes in the plane or tetrahedral "
                << "meshes\n";
            return cli::exit_usage;
        }
        if ((path.columns == 4) != planar) {
            err << "sxk: " << o.path << ':' << path.samples.front().line << ": a "
                << (path.columns == 4 ? "2D needle path (time bx by tx ty)" : "3D needle path (time bx by bz tx ty tz)")
                << " does not fit " << o.input << ", a " << (planar ? "planar triangle" : "tetrahedral") << " mesh\n";
            return cli::exit_usage;
        }
        for (const ToolSample& sample : path.samples) {
            const int half = path.columns / 2;
            if (std::equal(sample.values.begin(), sample.values.begin() + half, sample.values.begin() + half)) {
                err << "sxk: " << o.path << ':' << sample.line << ": the needle has zero length (base = tip)\n";
                return cli::exit_usage;
            }
        }
        // the refinement the options imply, estimated before any of it is done (refinement_budget.hpp)
        {
            const double elements = static_cast<double>(mesh->element_count());
            const double start = o.h_start ? uniform_refinement_elements(*mesh, *o.h_start) - elements : 0;
            char line[320];
            if (start > refinement_element_limit) {
                std::snprintf(line, sizeof line,
                              "sxk: needle: --h-start %g: refining %s to this size would add about %.2g elements, "
                              "more than the limit of %.0f; take a larger --h-start\n",
                              *o.h_start, o.input.c_str(), start, refinement_element_limit);
                err << line;
                return cli::exit_usage;
            }
            std::vector<Point> tips;
            for (const ToolSample& sample : path.samples) {
                const auto& v = sample.values;
                tips.push_back(planar ? Point{v[2], v[3], 0} : Point{v[3], v[4], v[5]});
            }
            // after --h-start the elements along the path are already of size h_start
            const double along = !o.h_start || o.needle.h_ref < *o.h_start
                                     ? path_refinement_elements(*mesh, tips, o.needle.h_ref, o.needle.radius)
                                     : 0;
            if (start + along > refinement_element_limit) {
                char radius[64] = "";
                if (o.needle.radius > 0) std::snprintf(radius, sizeof radius, " --radius %g", o.needle.radius);
                std::snprintf(line, sizeof line,
                              "sxk: needle: --h-ref %g%s: refining along the path would add about %.2g elements, "
                              "more than the limit of %.0f; take a larger --h-ref%s\n",
                              o.needle.h_ref, radius, start + along, refinement_element_limit,
                              o.needle.radius > 0 ? " or a smaller --radius" : "");
                err << line;
                return cli::exit_usage;
            }
        }
        Replay record;
        if (o.h_start) {
            auto refined = refine_uniformly(*mesh, *o.h_start);
            if (!refined) {
                err << "sxk: " << o.input << ":0: --h-start: " << refined.reason() << '\n';
                return cli::exit_usage;
            }
            record.start_bisections = *refined;
        }
        std::unique_ptr<Simulation> simulation;
        if (!o.deform.empty()) {
            auto made = cli::simulation_from_words(m_host, *mesh, o.deform);
            if (!made) {
                err << "sxk: needle: --deform: " << made.reason() << '\n';
                return cli::exit_usage;
            }
            simulation = std::move(*made);
            auto settled = simulation->relax(std::numeric_limits<std::size_t>::max());
            if (!settled) {
                err << "sxk: needle: --deform: " << settled.reason() << '\n';
                return cli::exit_usage;
            }
        } else {
            err << "sxk: note: no --deform: geometry only (the mesh is refined and needle nodes are tracked; "
                   "nothing moves)\n";
        }
        auto session = NeedleSession::make(*mesh, o.needle, simulation.get());
        if (!session) {
            err << "sxk: " << o.input << ":0: " << session.reason() << '\n';
            return cli::exit_usage;
        }
        // --frames: a planar mesh drawn with its needle (planar_picture.hpp), a tetrahedral one by the
        // renderer; one view for every picture, framing the body before the first step
        const std::size_t steps = path.samples.size() + (o.settle > 0 ? 1 : 0);
        ToolRecording::Drawer planar_drawer;
        if (planar) {
            const std::array<double, 4> view = picture_view(*mesh);
            planar_drawer = [&mesh, &session, view, steps](const std::filesystem::path& file, std::size_t index) {
                const std::string title = index == 0 ? std::string("before the first step")
                                                     : "step " + std::to_string(index) + " of " + std::to_string(steps);
                pictures::write_png(file, pictures::draw(planar_picture(*mesh, **session, view, title)));
            };
        }
        auto recording = ToolRecording::open(m_host, *mesh, o.recording,
                                             {"needle", steps, bezier::Colouring::piece, 9999, planar_drawer, {}},
                                             err);
        if (!recording) return cli::exit_usage;
        // the needle at a sample: base to tip
        const auto shaft = [planar](const ToolSample& sample) {
            const auto& v = sample.values;
            return planar ? std::vector<Point>{{v[0], v[1], 0}, {v[2], v[3], 0}}
                          : std::vector<Point>{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
        };
        if (!recording->step(*mesh, 0, path.samples.front().time, {}, err)) return cli::exit_refused;

        record.elements_before = mesh->element_count();
        record.vertices_before = mesh->vertices_in_elements();
        record.geometry_only = simulation == nullptr;
        for (const ToolSample& sample : path.samples) {
            const auto& v = sample.values;
            const Needle needle = planar ? Needle{{v[0], v[1], 0}, {v[2], v[3], 0}}
                                         : Needle{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
            const auto stepped = (*session)->move(needle);
            if (!stepped) {
                err << "sxk: " << o.path << ':' << sample.line << ": the step was refused (the mesh is as before it): "
                    << stepped.reason() << '\n';
                return cli::exit_refused;
            }
            record.steps.push_back({sample.time, sample.line, *stepped});
            if (!recording->step(*mesh, record.steps.size(), sample.time, shaft(sample), err)) return cli::exit_refused;
        }
        if (o.settle > 0 && (*session)->needle()) {
            const auto settled = (*session)->settle(o.settle);
            if (!settled) {
                err << "sxk: needle: --settle: the step was refused (the mesh is as before it): " << settled.reason()
                    << '\n';
                return cli::exit_refused;
            }
            record.steps.push_back({path.samples.back().time, path.samples.back().line, *settled});
            if (!recording->step(*mesh, record.steps.size(), path.samples.back().time, shaft(path.samples.back()), err))
                return cli::exit_refused;
        }
        if (std::none_of(record.steps.begin(), record.steps.end(),
                         [](const ReplayStep& step) {
                             return step.report.tip_inside || step.report.intercepted > 0;
                         })) {
            err << "sxk: " << o.path << ':' << path.samples.front().line
                << ": the needle never meets the mesh (its tip is never inside)\n";
            return cli::exit_usage;
        }
        if (!o.plot.empty()) {
            try {
                draw_profile(o.plot, **session);
            } catch (const std::exception& error) {
                err << "sxk: needle: --plot " << o.plot << ": " << error.what() << '\n';
                return cli::exit_refused;
            }
        }
        if (!recording->finish(*mesh, err)) return cli::exit_refused;
        const auto undone = undo_steps(**session, o.undo, "needle", err);
        if (const int* code = std::get_if<int>(&undone)) return *code;
        record.undone = std::get<std::size_t>(undone);
        (*session)->end();
        record.elements_after = mesh->element_count();
        record.vertices_after = mesh->vertices_in_elements();
        if (!save_mesh_for_command(*mesh, o.output, err)) return cli::exit_refused;
        if (o.json) {
            nlohmann::ordered_json json;
            json["file"] = o.input;
            json["path"] = o.path;
            json["output"] = o.output;
            json["options"] = to_json(o.needle);
            if (o.h_start) json["options"]["h_start"] = *o.h_start;
            json["options"]["settle"] = o.settle;
            const nlohmann::ordered_json body = to_json(record);
            for (const auto& [key, value] : body.items()) json[key] = value;
            out << json.dump(2) << '\n';
        } else {
            print_replay(out, record);
            out << o.input << " -> " << o.output << '\n';
        }
        return cli::exit_success;
    }

private:
    const sxk::Services* const& m_host;
};

class NeedlePlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == ToolFactory::service_id) return offer_of<ToolFactory>(&m_tools);
        return {};
    }
    void attach(const sxk::Services& services) override { m_host = &services; }

private:
    const sxk::Services* m_host = nullptr;  // the host's services, which outlive the plug-in
    NeedleCommand m_command{m_host};
    PluginCommand* m_commands[1] = {&m_command};
    // the tool "needle": the body is the application's simulation (none: geometry only)
    ToolFactoryOf<Options> m_tools{
        [](Mesh& mesh, const Options& options, const ToolContext& context) -> Outcome<std::unique_ptr<ToolSession>> {
            auto session = NeedleSession::make(mesh, options, context.simulation);
            if (!session) return session.refusal();
            return std::unique_ptr<ToolSession>(std::move(*session));
        }};
};

}  // namespace
}  // namespace sxk::needle

SXK_PLUGIN(needle, sxk::needle::NeedlePlugin, "0.1.0",
           "needle insertion: bisection around the needle, stick-slip friction, projected CG (thesis 6)");
