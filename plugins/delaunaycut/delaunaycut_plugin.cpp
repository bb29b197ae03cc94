// The delaunaycut plug-in: `sxk cut delaunay IN PATH OUT` replays a recorded scalpel path through a
// PlanarCutSession (planar_cut.hpp), and the plug-in's ToolFactory offers the session as the tool
// "delaunaycut".
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "cut_options.hpp"
#include "incision_distance.hpp"
#include "output_checks.hpp"
#include "planar_cut.hpp"
#include "surface_cut.hpp"
#include "svg_picture.hpp"
#include "tool_frames.hpp"
#include "sxk/atomic_write.hpp"
#include "sxk/io.hpp"
#include "sxk/plugin.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_path.hpp"

extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_delaunaycut();

namespace sxk::delaunaycut {

namespace {

struct CommandOptions {
    std::string input, path, output, svg, histogram, undo;
    RecordingOptions recording;  // --frames, --animation, --series (tool_frames.hpp)
    Options cut;
    bool json = false;
    ReadOptions reading;
};

struct ReplayedStep {
    double time = 0;
    std::size_t line = 0;
    CutStepReport report;
};

double smallest(const std::vector<double>& values) {
    return values.empty() ? 0 : *std::min_element(values.begin(), values.end());
}
double largest(const std::vector<double>& values) {
    return values.empty() ? 0 : *std::max_element(values.begin(), values.end());
}

nlohmann::ordered_json step_json(const ReplayedStep& step) {
    const CutStepReport& r = step.report;
    nlohmann::ordered_json json;
    json["time"] = step.time;
    json["line"] = step.line;
    json["phase"] = std::string(phase_name(r.phase));
    json["entries"] = r.entries;
    json["fix_ups"] = r.fix_ups;
    json["exits"] = r.exits;
    json["retractions"] = r.retractions;
    json["moves"] = r.moves;
    json["flips"] = r.flips;
    json["nodes_removed"] = r.nodes_removed;
    json["incision_splits"] = r.incision_splits;
    json["edges_split"] = r.edges_split;
    json["faces_dissected"] = r.faces_dissected;
    json["collapses"] = r.collapses;
    json["branches"] = r.branches;
    json["annihilations"] = r.annihilations;
    json["incisions"] = r.incisions;
    json["lag"] = r.lag;
    if (!r.lag_reason.empty()) json["lag_reason"] = r.lag_reason;
    json["elements"] = r.elements;
    json["vertices"] = r.vertices;
    json["seconds"] = r.seconds;
    return json;
}

class CutDelaunayCommand final : public PluginCommand {
public:
    // `host`: the plug-in's, set when the host attaches it
    explicit CutDelaunayCommand(const sxk::Services* const& host) : m_host(host) {}

    std::string_view name() const override { return "cut delaunay"; }
    std::string_view summary() const override {
        return "cut a planar triangle mesh along a recorded point-scalpel path, or a triangle surface in space "
               "with a line scalpel: drag, flip, remove, split (thesis 5.2, 5.3), or subdivide (the baseline)";
    }

    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override {
        CommandOptions options;
        CLI::App app("Cut a planar triangle mesh along a recorded scalpel path (thesis chapter 5): the scalpel "
                     "drags an active node through the mesh, edges around it flip by the empty-circle test, nodes "
                     "it comes close to are removed and the incision behind it is split where needed; or, with "
                     "--method subdivision, every edge the path crosses is split there. A triangle surface in "
                     "space is cut by a line scalpel the same way (thesis 5.3), with as many incisions as the "
                     "blade makes: they branch and meet. Each movement is one undoable step.",
                     "sxk cut delaunay");
        app.add_option("IN", options.input,
                       "Planar triangle mesh (Dimension 2), or a triangle surface in space (Dimension 3)")
            ->required();
        app.add_option("PATH", options.path,
                       "Scalpel path: one sample per line, 'time x y' (planar), or 'time hx hy hz tx ty tz' (a "
                       "blade from its handle end to its tip, surfaces) (docs/formats.md \"Tool paths\")")
            ->required();
        app.add_option("OUT", options.output, "Output mesh, format by extension (" + std::string(known_mesh_extensions()) + ")")
            ->required();
        add_cut_options(app, options.cut);
        app.add_option("--svg", options.svg, "Planar cuts: draw the cut mesh with the path over it into FILE (SVG)")
            ->type_name("FILE");
        app.add_option("--histogram", options.histogram,
                       "Draw the triangles' smallest and largest angles before and after the cut into FILE (SVG)")
            ->type_name("FILE");
        add_undo_option(app, options.undo);
        add_recording_options(app, options.recording);
        app.add_flag("--json", options.json, "Print one JSON object (with a 'steps' array) instead of the table");
        add_read_options(app, options.reading);
        if (const auto done = parse_command_line(app, args, "cut delaunay", out, err)) return *done;

        if (const auto unknown = unknown_output_format(options.output)) {
            err << "sxk: " << *unknown << '\n';
            return cli::exit_usage;
        }
        ToolPath path;
        try {
            const std::array<int, 2> columns{2, 6};
            path = read_tool_path(options.path, columns);
        } catch (const InputError& error) {
            err << "sxk: " << error.what() << '\n';
            return cli::exit_usage;
        }
        std::optional<Mesh> mesh = load_mesh_for_command(options.input, err, options.reading);
        if (!mesh) return cli::exit_usage;
        const bool surface = mesh->topological_dimension() == 2 && mesh->ambient_dimension() == 3;
        const std::size_t first_line = path.samples.front().line;
        if (path.columns == 6 && !surface) {
            err << "sxk: " << options.path << ':' << first_line
                << ": a line scalpel ('time hx hy hz tx ty tz') cuts triangle surfaces in space (thesis 5.3); "
                << options.input << " is not one (planar cuts take 'time x y')\n";
            return cli::exit_usage;
        }
        if (path.columns == 2 && surface) {
            err << "sxk: " << options.path << ':' << first_line << ": a point scalpel ('time x y') cuts planar meshes; "
                << options.input << " is a surface in space, cut by a line scalpel ('time hx hy hz tx ty tz')\n";
            return cli::exit_usage;
        }
        if (surface && !options.svg.empty()) {
            err << "sxk: --svg draws planar cuts; draw a surface's cut with 'sxk render " << options.output
                << " PICTURE.png'\n";
            return cli::exit_usage;
        }
        // every file this command writes, checked before the cut: OUT is not replaced when a
        // picture cannot be written after it, and no picture overwrites the input or OUT
        const std::array<SideOutput, 2> pictures{
            SideOutput{"--svg", options.svg, ".svg", "the picture is SVG"},
            SideOutput{"--histogram", options.histogram, ".svg", "the histogram is SVG"}};
        if (const std::optional<int> refused =
                check_outputs("cut delaunay", options.input, options.output, pictures, err))
            return *refused;
        const Mesh before = *mesh;
        // the session, and how a sample moves its scalpel
        std::unique_ptr<ToolSession> session;
        std::function<Outcome<StepReport>(const ToolSample&)> step;
        std::function<const CutStepReport&()> last;
        std::function<std::optional<std::string>(const ToolSample&)> too_far;  // why the scalpel may not be there
        std::vector<Point> scalpel;
        std::vector<Blade> blades;
        double h = 0;
        if (surface) {
            auto made = SurfaceCutSession::make(*mesh, options.cut);
            if (!made) {
                err << "sxk: " << options.input << ":0: " << made.reason() << '\n';
                return cli::exit_usage;
            }
            SurfaceCutSession* cutter = made->get();
            h = cutter->mean_edge();
            const auto blade_of = [](const ToolSample& sample) {
                const auto& v = sample.values;
                return Blade{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
            };
            too_far = [cutter, blade_of](const ToolSample& sample) { return cutter->too_far(blade_of(sample)); };
            step = [&, cutter, blade_of](const ToolSample& sample) {
                const Blade blade = blade_of(sample);
                blades.push_back(blade);
                return cutter->cut(blade.handle, blade.tip);
            };
            last = [cutter]() -> const CutStepReport& { return cutter->last_step(); };
            session = std::move(*made);
        } else {
            auto made = PlanarCutSession::make(*mesh, options.cut);
            if (!made) {
                err << "sxk: " << options.input << ":0: " << made.reason() << '\n';
                return cli::exit_usage;
            }
            PlanarCutSession* cutter = made->get();
            h = cutter->mean_edge();
            too_far = [cutter](const ToolSample& sample) {
                return cutter->too_far({sample.values[0], sample.values[1], 0});
            };
            step = [&, cutter](const ToolSample& sample) {
                const Point p{sample.values[0], sample.values[1], 0};
                scalpel.push_back(p);
                return cutter->cut(p);
            };
            last = [cutter]() -> const CutStepReport& { return cutter->last_step(); };
            session = std::move(*made);
        }
        // a sample the session would refuse is a bad path: said with its line, before any step
        for (const ToolSample& sample : path.samples)
            if (const auto far = too_far(sample)) {
                err << "sxk: " << options.path << ':' << sample.line << ": " << *far << '\n';
                return cli::exit_usage;
            }
        // --frames, --series: pictures by piece with the scalpel, and the series' files written as OUT is
        WriteOptions writing;
        writing.drop_unused_vertices = true;  // removals and contractions leave vertices in no element
        auto recording = ToolRecording::open(
            m_host, *mesh, options.recording,
            {"cut delaunay", path.samples.size(),
             bezier::Colouring::piece, options.cut.cut_label, {}, writing},
            err);
        if (!recording) return cli::exit_usage;
        // the scalpel at a sample: a blade from handle to tip (surfaces), a point (planar cuts)
        const auto scalpel_at = [surface](const ToolSample& sample) {
            const auto& v = sample.values;
            return surface ? std::vector<Point>{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}
                           : std::vector<Point>{{v[0], v[1], 0}};
        };
        if (!recording->step(*mesh, 0, path.samples.front().time, scalpel_at(path.samples.front()), err)) return cli::exit_refused;
        std::vector<ReplayedStep> steps;
        std::size_t entries = 0;
        double seconds = 0;  // the cut's, without the pictures and files recorded
        for (const ToolSample& sample : path.samples) {
            const auto started = std::chrono::steady_clock::now();
            if (auto stepped = step(sample); !stepped) {
                err << "sxk: " << options.path << ':' << sample.line
                    << ": the step was refused (the mesh is as before it): " << stepped.reason() << '\n';
                return cli::exit_refused;
            }
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            steps.push_back({sample.time, sample.line, last()});
            entries += steps.back().report.entries;
            if (!recording->step(*mesh, steps.size(), sample.time, scalpel_at(sample), err)) return cli::exit_refused;
        }
        if (entries == 0) {
            err << "sxk: " << options.path << ':' << first_line
                << (surface ? ": the blade never enters the surface (no movement meets an edge or takes the tip "
                              "through a triangle)\n"
                            : ": the scalpel never enters the mesh (no movement crosses its boundary inwards)\n");
            return cli::exit_usage;
        }
        if (!recording->finish(*mesh, err)) return cli::exit_refused;
        const auto undoing = undo_steps(*session, options.undo, "cut delaunay", err);
        if (const int* code = std::get_if<int>(&undoing)) return *code;
        const std::size_t undone = std::get<std::size_t>(undoing);
        session->end();

        if (!save_mesh_for_command(*mesh, options.output, err, writing)) return cli::exit_refused;
        const AngleCounts angles_before = triangle_angle_degrees(before), angles_after = triangle_angle_degrees(*mesh);
        const IncisionDistance incision = surface ? incision_distance(*mesh, blades, options.cut.cut_label)
                                                  : incision_distance(*mesh, scalpel, options.cut.cut_label);
        // a picture that fails now (a full disk: check_outputs ruled out the rest) says which
        // file, as a failed OUT does
        std::string writing_now;
        try {
            if (!options.svg.empty()) {
                writing_now = options.svg;
                write_file_atomically(options.svg,
                                      mesh_svg(*mesh, scalpel, options.cut.cut_label,
                                               std::string(method_name(options.cut.method)) + " cut: " +
                                                   std::to_string(before.element_count()) + " -> " +
                                                   std::to_string(mesh->element_count()) + " triangles"));
            }
            if (!options.histogram.empty()) {
                writing_now = options.histogram;
                const std::array<AngleSeries, 4> series{
                    AngleSeries{"smallest angle, before", angles_before.smallest},
                    AngleSeries{"smallest angle, after", angles_after.smallest},
                    AngleSeries{"largest angle, before", angles_before.largest},
                    AngleSeries{"largest angle, after", angles_after.largest}};
                write_file_atomically(options.histogram,
                                      angle_histogram_svg(std::string(method_name(options.cut.method)) +
                                                              " cut: triangle angles", series));
            }
        } catch (const std::exception& error) {
            err << "sxk: " << write_error_line(writing_now, error) << '\n';
            return cli::exit_refused;
        }
        const auto growth =
            static_cast<long long>(mesh->element_count()) - static_cast<long long>(before.element_count());
        CutStepReport total;
        double slowest = 0;
        for (const ReplayedStep& step : steps) {
            const CutStepReport& r = step.report;
            total.entries += r.entries, total.fix_ups += r.fix_ups, total.exits += r.exits;
            total.flips += r.flips, total.nodes_removed += r.nodes_removed, total.incision_splits += r.incision_splits;
            total.edges_split += r.edges_split, total.faces_dissected += r.faces_dissected;
            total.collapses += r.collapses, total.branches += r.branches, total.annihilations += r.annihilations;
            slowest = std::max(slowest, r.seconds);
        }
        if (options.json) {
            nlohmann::ordered_json json;
            json["file"] = options.input;
            json["path"] = options.path;
            json["output"] = options.output;
            json["method"] = std::string(method_name(options.cut.method));
            json["options"] = {{"eps_edge", options.cut.eps_edge}, {"short_angle", options.cut.short_angle},
                               {"eps_entry", options.cut.eps_entry},
                               {"eps_exit", options.cut.eps_exit}, {"dilation", options.cut.dilation},
                               {"cut_label", options.cut.cut_label}};
            json["mean_edge"] = h;
            json["steps"] = nlohmann::ordered_json::array();
            for (const ReplayedStep& step : steps) json["steps"].push_back(step_json(step));
            json["undone"] = undone;
            json["triangles_before"] = before.element_count();
            json["triangles_after"] = mesh->element_count();
            json["growth"] = growth;
            json["smallest_angle_before"] = smallest(angles_before.smallest);
            json["smallest_angle_after"] = smallest(angles_after.smallest);
            json["largest_angle_after"] = largest(angles_after.largest);
            if (surface) {
                json["branches"] = total.branches;
                json["annihilations"] = total.annihilations;
                json["folded_neighbours_before"] = folded_neighbours(before);
                json["folded_neighbours_after"] = folded_neighbours(*mesh);
            }
            json["incision_nodes"] = incision.nodes;
            json["incision_farthest"] = incision.farthest / h;
            json["incision_mean"] = incision.mean / h;
            json["seconds"] = seconds;
            out << json.dump(2) << '\n';
            return cli::exit_success;
        }
        char line[160];
        out << method_name(options.cut.method) << " cut of " << options.input << " along " << options.path << " ("
            << steps.size() << " samples)\n";
        std::snprintf(line, sizeof line, "  entries %zu, incisions begun %zu, exits %zu\n", total.entries,
                      total.fix_ups, total.exits);
        out << line;
        if (surface) {
            std::snprintf(line, sizeof line, "  branches %zu, annihilations %zu; folded neighbours %zu -> %zu\n",
                          total.branches, total.annihilations, folded_neighbours(before), folded_neighbours(*mesh));
            out << line;
        }
        std::snprintf(line, sizeof line,
                      "  flips %zu, nodes removed %zu, incision splits %zu, edges split %zu, edges dissected %zu, "
                      "contracted %zu\n",
                      total.flips, total.nodes_removed, total.incision_splits, total.edges_split,
                      total.faces_dissected, total.collapses);
        out << line;
        const std::string undone_text = undone > 0 ? ", " + std::to_string(undone) + " steps undone" : "";
        std::snprintf(line, sizeof line, "  triangles %zu -> %zu (%+lld)%s\n", before.element_count(),
                      mesh->element_count(), growth, undone_text.c_str());
        out << line;
        std::snprintf(line, sizeof line, "  smallest angle %.1f -> %.1f degrees, largest %.1f -> %.1f degrees\n",
                      smallest(angles_before.smallest), smallest(angles_after.smallest), largest(angles_before.largest),
                      largest(angles_after.largest));
        out << line;
        std::snprintf(line, sizeof line, "  incision from the %s: farthest %.3f h, mean %.3f h (%zu nodes, h = %g)\n",
                      surface ? "sweep" : "path", incision.farthest / h, incision.mean / h, incision.nodes, h);
        out << line;
        std::snprintf(line, sizeof line, "  %.1f ms in all, slowest step %.3f ms\n", seconds * 1e3, slowest * 1e3);
        out << line << options.input << " -> " << options.output << '\n';
        return cli::exit_success;
    }

private:
    const sxk::Services* const& m_host;
};

// The tool "delaunaycut": the planar cutter on a planar mesh, the surface cutter on a surface in
// space.
Outcome<std::unique_ptr<ToolSession>> begin_delaunaycut(Mesh& mesh, const Options& options, const ToolContext&) {
    if (mesh.ambient_dimension() == 3) {
        auto surface = SurfaceCutSession::make(mesh, options);
        if (!surface) return surface.refusal();
        return std::unique_ptr<ToolSession>(std::move(*surface));
    }
    auto session = PlanarCutSession::make(mesh, options);
    if (!session) return session.refusal();
    return std::unique_ptr<ToolSession>(std::move(*session));
}

class DelaunaycutPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == ToolFactory::service_id) return offer_of<ToolFactory>(&m_tools);
        return {};
    }
    void attach(const sxk::Services& services) override { m_host = &services; }

private:
    const sxk::Services* m_host = nullptr;  // the host's services, which outlive the plug-in
    CutDelaunayCommand m_cut{m_host};
    PluginCommand* m_commands[1] = {&m_cut};
    ToolFactoryOf<Options> m_tools{&begin_delaunaycut};
};

}  // namespace
}  // namespace sxk::delaunaycut

SXK_PLUGIN(delaunaycut, sxk::delaunaycut::DelaunaycutPlugin, "0.1.0",
           "Delaunay cutting: a point scalpel cuts planar triangle meshes, keeping them small and round (thesis 5.2)");
