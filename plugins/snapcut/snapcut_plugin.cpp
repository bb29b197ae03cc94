// The snapcut plug-in: `sxk cut snap IN PATH OUT` replays a recorded scalpel path through a
// SnapCutSession (snap_cut.hpp), and the plug-in's ToolFactory offers the session as the tool
// "snapcut" (options: sxk/plugins/snapcut.hpp). The degeneracy removal comes from the degeneracy
// plug-in's service, found through the host (Plugin::attach): no plug-in links another.
#include <algorithm>
#include <array>
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
#include "cut_options.hpp"
#include "cut_report.hpp"
#include "sxk/plugins/degeneracy.hpp"
#include "sxk/plugins/elasticity.hpp"
#include "snap_cut.hpp"
#include "tool_frames.hpp"
#include "sxk/io.hpp"
#include "sxk/plugin.hpp"
#include "sxk/tool_path.hpp"
#include "sxk/traversal.hpp"

extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_snapcut();

namespace sxk::snapcut {

namespace {

// The services the plug-in's sessions use, looked up when a session begins.
CutServices services_from(const sxk::Services* host) {
    CutServices services;
    if (host == nullptr) return services;
    if (auto degeneracy = host->service<degeneracy::DegeneracyService>()) services.degeneracy = *degeneracy;
    return services;
}

struct CommandOptions {
    std::string input, path, output, deform;
    RecordingOptions recording;  // --frames, --animation, --series (tool_frames.hpp)
    Options cut;
    bool json = false;
    std::string undo;  // "", a count, or "all"
    ReadOptions reading;
};

// The command's JSON object: the files and options, then the record (docs/cli.md "sxk cut snap").
void print_json(std::ostream& out, const CommandOptions& options, const CutServices& services,
                const ReplayRecord& record) {
    nlohmann::ordered_json json;
    json["file"] = options.input;
    json["path"] = options.path;
    json["output"] = options.output;
    if (!options.recording.frames.empty()) json["frames"] = options.recording.frames;
    if (!options.recording.series.empty()) json["series"] = options.recording.series;
    json["options"] = to_json(options.cut, services.degeneracy != nullptr);
    const nlohmann::ordered_json body = to_json(record);  // named: items() is a view
    for (const auto& [key, value] : body.items()) json[key] = value;
    out << json.dump(2) << '\n';
}

// The steps whose relaxation was refused or could not be shown (the mesh kept the shape before
// it): said on stderr in text and JSON mode alike, the first by its step and reason, as the
// JSON's steps[].relax says (`shown`, `refusal`).
void warn_unshown_relaxations(std::ostream& err, const ReplayRecord& record) {
    std::size_t count = 0;
    std::string first;
    for (std::size_t i = 0; i < record.steps.size(); ++i) {
        const CutStepReport& step = record.steps[i].report;
        if (!step.relaxed || (step.relax_refusal.empty() && step.relax_shown)) continue;
        if (count++ == 0)
            first = "step " + std::to_string(i + 1) + ": " +
                    (step.relax_refusal.empty() ? step.relax_not_shown : "not relaxed: " + step.relax_refusal);
    }
    if (count == 0) return;
    err << "sxk: warning: --deform: " << count << (count == 1 ? " step's" : " steps'")
        << " relaxation not shown, the mesh keeping the shape before it (" << first << ")\n";
}

class CutSnapCommand final : public PluginCommand {
public:
    // `host`: the plug-in's, set when the host attaches it
    explicit CutSnapCommand(const sxk::Services* const& host) : m_host(host) {}

    std::string_view name() const override { return "cut snap"; }
    std::string_view summary() const override {
        return "cut a tetrahedral mesh along a recorded scalpel path: select, snap, dissect, remove "
               "degeneracies (thesis 3.2)";
    }

    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override {
        CommandOptions options;
        CLI::App app("Cut a tetrahedral mesh along a recorded scalpel path (thesis chapter 3): each "
                     "movement of the scalpel selects the faces its sweep crosses, snaps their "
                     "corners onto the sweep, dissects them and removes the flat elements left, as "
                     "one undoable step.",
                     "sxk cut snap");
        app.add_option("IN", options.input, "Tetrahedral mesh")->required();
        app.add_option("PATH", options.path,
                       "Scalpel path: one sample per line, 'time hx hy hz tx ty tz' (handle, tip), or "
                       "an .obj of the triangles it sweeps, in order, one step each (docs/formats.md)")
            ->required();
        app.add_option("OUT", options.output,
                       "Output mesh, format by extension (" + std::string(known_mesh_extensions()) + ")")
            ->required();
        add_cut_options(app, options.cut);
        add_undo_option(app, options.undo);
        app.add_option("--deform", options.deform,
                       "Cut a deforming body: `sxk deform`'s options in one word, e.g. \"--fix z<0.001 "
                       "--force z>7.99:0,0,-50 --E 1e4\" (the elasticity plug-in; the body is solved "
                       "first and relaxed after every step)");
        add_recording_options(app, options.recording);
        app.add_flag("--json", options.json, "Print one JSON object (with a 'steps' array) instead of the table");
        add_read_options(app, options.reading);
        if (const auto done = parse_command_line(app, args, "cut snap", out, err)) return *done;
        // the relaxation's options say how a deforming body relaxes after each step: without
        // --deform (or --far without --local) they were once ignored in silence (issue 47)
        auto usage = [&err](const std::string& what) {
            err << "sxk: cut snap: " << what << "\nRun 'sxk cut snap --help' for more information.\n";
            return cli::exit_usage;
        };
        if (options.deform.empty())
            for (const char* relaxing : {"--relax-iterations", "--local", "--far"})
                if (app.count(relaxing) > 0)
                    return usage(std::string(relaxing) +
                                 ": only with --deform (it says how the deforming body relaxes after each step)");
        if (app.count("--far") > 0 && options.cut.local_vertices == 0)
            return usage("--far: only with --local N > 0 (it relaxes the far field that a local relaxation leaves)");

        if (const auto unknown = unknown_output_format(options.output)) {
            err << "sxk: " << *unknown << '\n';
            return cli::exit_usage;
        }
        // the path's steps: scalpel samples, or swept triangles (an .obj)
        struct Move {
            double time = 0;  // a sample's time; a triangle's number (1, 2, ...)
            std::size_t line = 0;
            Scalpel scalpel;               // samples
            std::optional<Sweep> triangle;  // .obj
        };
        std::vector<Move> path;
        try {
            if (std::filesystem::path(options.path).extension() == ".obj") {
                for (const SweptTriangle& t : read_swept_triangles(options.path))
                    path.push_back({double(path.size() + 1), t.line, {t.corners[0], t.corners[2]},
                                    Sweep{t.corners[0], t.corners[1], t.corners[2]}});
            } else {
                const std::array<int, 1> columns{6};
                for (const ToolSample& sample : read_tool_path(options.path, columns).samples)
                    path.push_back({sample.time, sample.line,
                                    {{sample.values[0], sample.values[1], sample.values[2]},
                                     {sample.values[3], sample.values[4], sample.values[5]}},
                                    std::nullopt});
            }
        } catch (const InputError& error) {
            err << "sxk: " << error.what() << '\n';
            return cli::exit_usage;
        }
        std::optional<Mesh> mesh = load_mesh_for_command(options.input, err, options.reading);
        if (!mesh) return cli::exit_usage;
        if (mesh->topological_dimension() != 3 || mesh->ambient_dimension() != 3) {
            err << "sxk: " << options.input << ":0: the snap cutter cuts tetrahedral meshes in space\n";
            return cli::exit_usage;
        }
        CutServices services = services_from(m_host);
        if (options.cut.remove_degeneracies && services.degeneracy == nullptr)
            err << "sxk: warning: the degeneracy plug-in is not loaded: flat elements stay\n";
        ReplayRecord record;
        std::unique_ptr<Simulation> simulation;
        std::vector<Point> unloaded;  // with --deform: IN's deformed positions, before the first solve
        if (!options.deform.empty()) {
            auto made = cli::simulation_from_words(m_host, *mesh, options.deform);
            if (!made) {
                err << "sxk: cut snap: --deform: " << made.reason() << '\n';
                return cli::exit_usage;
            }
            simulation = std::move(*made);
            record.deformed = true;
            unloaded.assign(mesh->deformed_positions().begin(), mesh->deformed_positions().end());
            // the loaded shape before the first cut; a cut of any other shape is not what was
            // asked for, so a solve that is refused (loads whose norm overflows, a residual that
            // is not finite) or whose shape cannot be shown (it would invert an element: issue
            // 47 saw the undeformed body cut in silence) ends the command as `sxk deform` ends:
            // exit 1, nothing written, the JSON object with initial_relax's refusal
            auto settled = simulation->relax(std::numeric_limits<std::size_t>::max());
            if (settled) {
                record.initial_relax = *settled;
                record.initial_solved = true;
                if (!settled->shown && settled->not_shown)
                    record.initial_refusal = *settled->not_shown;
            } else {
                record.initial_refusal = settled.refusal();
            }
            if (record.initial_refusal) {
                err << "sxk: cut snap: --deform: " << record.initial_refusal->reason << "; nothing cut or written\n";
                if (options.json) print_json(out, options, services, record);
                return cli::exit_refused;
            }
            if (!settled->converged)
                err << "sxk: warning: --deform: CG did not converge before the cut (|r| = " << settled->residual
                    << ", needed " << settled->threshold << ")\n";
            services.simulation = simulation.get();
        }
        auto session = SnapCutSession::make(*mesh, options.cut, services);
        if (!session) {
            err << "sxk: " << options.input << ":0: " << session.reason() << '\n';
            return cli::exit_usage;
        }
        // --frames, --series: pictures by piece with the blade, and the series' files written as OUT is
        WriteOptions writing;
        writing.drop_unused_vertices = true;  // collapses leave vertices in no element
        auto recording = ToolRecording::open(
            m_host, *mesh, options.recording,
            {"cut snap", path.size(), bezier::Colouring::piece, options.cut.cut_label, {}, writing},
            err);
        if (!recording) return cli::exit_usage;
        // the blade at a step: the scalpel from handle to tip, or the swept triangle
        const auto blade = [](const Move& move) {
            return move.triangle ? std::vector<Point>{move.triangle->a, move.triangle->b, move.triangle->c}
                                 : std::vector<Point>{move.scalpel.handle, move.scalpel.tip};
        };
        if (!recording->step(*mesh, 0, path.front().time, blade(path.front()), err)) return cli::exit_refused;

        record.elements_before = mesh->element_count();
        record.vertices_before = mesh->vertices_in_elements();
        for (const Move& move : path) {
            const auto stepped = move.triangle
                                     ? (*session)->sweep(move.triangle->a, move.triangle->b, move.triangle->c)
                                     : (*session)->cut(move.scalpel);
            if (!stepped) {
                err << "sxk: " << options.path << ':' << move.line << ": the step was refused (the mesh is as "
                    << "before it): " << stepped.reason() << '\n';
                return cli::exit_refused;
            }
            record.steps.push_back({move.time, move.line, (*session)->last_step()});
            if (!recording->step(*mesh, record.steps.size(), move.time, blade(move), err)) return cli::exit_refused;
        }
        if (std::none_of(record.steps.begin(), record.steps.end(),
                         [](const ReplayStep& step) { return step.report.edges_hit > 0; })) {
            err << "sxk: " << options.path << ':' << path.front().line
                << ": the scalpel never meets the mesh (no sweep crosses an edge)\n";
            return cli::exit_usage;
        }
        if (!recording->finish(*mesh, err)) return cli::exit_refused;
        const auto undone = undo_steps(**session, options.undo, "cut snap", err);
        if (const int* code = std::get_if<int>(&undone)) return *code;
        record.undone = std::get<std::size_t>(undone);
        (*session)->end();
        if (simulation && record.undone > 0 && record.undone == record.steps.size()) {
            // every step undone: the loaded shape goes too, which the solve before the first
            // step wrote outside any step (issue 47: `--undo all` with --deform was not IN)
            std::vector<VertexId> all(unloaded.size());
            for (VertexId v = 0; v < all.size(); ++v) all[v] = v;
            if (auto back = mesh->move_vertices(all, unloaded, PositionSet::deformed); !back) {
                err << "sxk: cut snap: --undo: " << back.reason() << '\n';
                return cli::exit_refused;
            }
        }
        record.elements_after = mesh->element_count();
        record.vertices_after = mesh->vertices_in_elements();

        if (!save_mesh_for_command(*mesh, options.output, err, writing)) return cli::exit_refused;
        warn_unshown_relaxations(err, record);
        if (options.json) {
            print_json(out, options, services, record);
        } else {
            print_replay(out, record);
            out << options.input << " -> " << options.output << '\n';
        }
        return cli::exit_success;
    }

private:
    const sxk::Services* const& m_host;
};

class SnapcutPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == ToolFactory::service_id) return offer_of<ToolFactory>(&m_tools);
        return {};
    }
    void attach(const sxk::Services& services) override { m_host = &services; }

private:
    const sxk::Services* m_host = nullptr;  // the host's services, which outlive the plug-in
    CutSnapCommand m_cut{m_host};
    PluginCommand* m_commands[1] = {&m_cut};
    // the tool "snapcut": the degeneracy removal from the host, the simulation from the application
    ToolFactoryOf<Options> m_tools{
        [this](Mesh& mesh, const Options& options, const ToolContext& context) -> Outcome<std::unique_ptr<ToolSession>> {
            CutServices services = services_from(m_host);
            services.simulation = context.simulation;
            auto session = SnapCutSession::make(mesh, options, services);
            if (!session) return session.refusal();
            return std::unique_ptr<ToolSession>(std::move(*session));
        }};
};

}  // namespace
}  // namespace sxk::snapcut

SXK_PLUGIN(snapcut, sxk::snapcut::SnapcutPlugin, "0.1.0",
           "snap cutting: a scalpel cuts tetrahedral meshes along faces, snapped and cleaned (thesis 3.2)");
