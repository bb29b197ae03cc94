// Tool sessions: a cutter, a needle or a brush driven once per frame by an application, each
// frame one transaction that can be undone.
//
//     auto session = host.begin_tool(mesh, snapcut_options);      // a plug-in's tool (plugin_host.hpp)
//     for each frame:
//         auto report = (*session)->step(pose);   // completes, or the mesh is as before
//         if (report) solver.update(report->elements, report->vertices);
//     (*session)->undo_step();                    // the last frame back
//     (*session)->end();                          // or cancel(): every frame of the session back
//
// A tool derives from ToolSession and implements apply(): whatever Mesh calls and operations
// the pose asks for. step() makes them one EditJournal step (sxk/edit_journal.hpp): if apply()
// refuses, everything it did is rolled back exactly and the refusal is returned. The session
// uses the mesh's journal when the application attached one (its steps then are entries of the
// application's undo history, or parts of the application's open step) and one of its own
// otherwise. Watchers hear each step's changes as they happen, and the net change back on a
// rollback or undo.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

// Where a tool is for one step, in the positions the tool works in (a cutter acts on the
// deformed positions, thesis §3.2.2): its reference point (a scalpel's tip, a needle's tip) and
// its axes (unit vectors in mesh coordinates: the tool's x, y and z; a needle points along z).
// A tool with extent (a scalpel's blade, a needle's shaft) reaches back from `position` along
// -axes[2] by `length`: the blade runs from its handle end position - length * axes[2] to its tip.
struct ToolPose {
    Point position{0, 0, 0};
    std::array<Point, 3> axes{Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}};
    double length = 0;
};

// What one step did, for the application (solver, renderer) and for logs.
struct StepReport {
    std::vector<ElementId> elements;   // created or changed by the step and still there, sorted
    std::size_t elements_removed = 0;  // elements of before the step that it removed
    std::vector<VertexId> vertices;    // moved or added by the step, sorted
    std::vector<std::string> actions;  // what the tool did, in order, in words ("snapped 3 vertices")
};

class SXK_API ToolSession {
public:
    explicit ToolSession(Mesh& mesh);
    virtual ~ToolSession();
    ToolSession(const ToolSession&) = delete;
    ToolSession& operator=(const ToolSession&) = delete;

    Mesh& mesh() { return m_mesh; }
    const Mesh& mesh() const { return m_mesh; }

    // One transaction: apply(pose) as one step. Refuses (the mesh as before, watchers told the
    // net change back) when apply refuses, and after end().
    Outcome<StepReport> step(const ToolPose& pose);
    // Takes back the newest step of this session still kept. Refuses when there is none, when
    // that step was part of an application's open step (the application undoes it), or when
    // the mesh changed since (another tool or the application edited it).
    Outcome<Done> undo_step();
    // Takes again the newest step undo_step took back, as it was: the mesh and the tool's side
    // logs (the journal's redo). Refuses when there is none, when a step was taken since, or when
    // the mesh changed since.
    Outcome<Done> redo_step();
    // Takes back every kept step of this session, newest first; stops at the first that cannot
    // be (the reason says how many were).
    Outcome<Done> cancel();
    // Ends the session: its steps stay; step() refuses from now on.
    void end() { m_ended = true; }
    bool ended() const { return m_ended; }
    // Steps kept (taken and not undone).
    std::size_t steps() const { return m_kept.size(); }

protected:
    // What the tool does at `pose`: any Mesh calls and operations, adding what it did to
    // `report.actions` (step() fills in elements and vertices). A refusal takes it all back.
    virtual Outcome<Done> apply(const ToolPose& pose, StepReport& report) = 0;
    // State the tool keeps between steps, attached to the session's journal (side_log.hpp): every
    // step marks it, a refused step takes it back, and undo_step and redo_step (or an
    // application's undo and redo) take it back and forth with the mesh, so the tool needs no
    // stack of its own. Call it from the tool's constructor; the log, a member of the tool,
    // detaches itself when destroyed. Refuses a log attached to another journal.
    Outcome<Done> keep_beside(SideLog& log);
    // Inside apply(): the elements the step's edits have changed or added so far, in the order of
    // their events (an id may repeat, and may have been removed since). It only grows during a
    // step, so a tool that follows what its own edits made (a cutter carrying its marks over to
    // new edges) keeps how far it has read. Empty outside apply().
    std::span<const ElementId> elements_edited_in_step() const;
    // Inside apply(): the vertices the step's edits have moved so far (Mesh::move_vertices, in
    // either position set), in the order of their events (a vertex may repeat). With
    // elements_edited_in_step(), where the step changed the body: a simulation relaxes around
    // them (Simulation::relax_near). Empty outside apply().
    std::span<const VertexId> vertices_moved_in_step() const;

private:
    Mesh& m_mesh;
    JournalScope m_journal;
    // per kept step: an entry of the journal's history (undo_step takes it back), part of an
    // application's open step (the application undoes it), or a step that changed nothing, in
    // the mesh or a side log (the journal keeps no entry for it; undoing it is taking back nothing)
    enum class Kept : std::uint8_t { history_entry, application_step, nothing };
    std::vector<Kept> m_kept;
    std::vector<Kept> m_undone;  // taken back by undo_step, newest last: what redo_step takes again
    std::uint64_t m_revision = 0;  // the mesh's revision after this session's last change
    const std::vector<ElementId>* m_step_elements = nullptr;  // the step watcher's, during apply()
    const std::vector<VertexId>* m_step_vertices = nullptr;   // the same
    bool m_ended = false;
};

class Simulation;  // sxk/simulation.hpp

// What an application gives a session beside the tool's options.
struct ToolContext {
    // A simulation of the session's mesh (the elasticity plug-in's, or the application's own),
    // owned by the application, outliving the session. A tool that works on a deforming body
    // (the snap cutter relaxes it after every step, the needle holds the nodes on its shaft)
    // uses it; nullptr: the tool works on the shape as it is (the snap cutter relaxes nothing,
    // the needle is geometry only and its first step says so).
    Simulation* simulation = nullptr;
};

// The service a plug-in offers for its tools (PluginHost::tool finds a tool by name across the
// loaded plug-ins; plugin.hpp). A tool's options are a struct of the plug-in's installed header
// (sxk/plugins/NAME.hpp) that names the tool and the layout it has:
//
//     struct Options {
//         static constexpr std::string_view tool_name = "snapcut";
//         static constexpr std::uint32_t options_version = 1;  // bumped on any change of layout
//         ...fields with defaults...
//         Outcome<Done> check() const;                          // the ranges, with a code
//     };
//
// and begin_tool passes them with that name and version, so a factory never reads options of
// another layout than it was built with. A factory is an object of its plug-in: it holds the
// host's services (Plugin::attach) that its sessions use.
class ToolFactory {
public:
    static constexpr std::string_view service_id = "sxk.tools";
    // 1: a struct of function pointers taking command-line words
    static constexpr std::uint32_t service_version = 2;

    struct Tool {
        std::string_view name;
        std::uint32_t options_version = 0;
    };
    // The tools offered, e.g. {{"snapcut", 1}}.
    virtual std::span<const Tool> tools() const = 0;
    // A session of `tool` on `mesh`; `options` points to the tool's options struct of layout
    // `options_version`. Refuses a tool it does not offer (not_found), another layout
    // (bad_argument), options out of range (their check()) and a mesh the tool cannot work on.
    // Use begin_tool, which passes the name and version of the struct.
    virtual Outcome<std::unique_ptr<ToolSession>> begin(std::string_view tool, std::uint32_t options_version,
                                                        const void* options, Mesh& mesh,
                                                        const ToolContext& context) = 0;

    // For implementations of begin: the options as `Options` when `tool` and `options_version`
    // are Options', else the refusal.
    template <class Options>
    static Outcome<const Options*> options_of(std::string_view tool, std::uint32_t options_version,
                                              const void* options) {
        if (tool != Options::tool_name)
            return Refusal{RefusalCode::not_found, "no tool called " + std::string(tool) + " here (this factory has " +
                                                       std::string(Options::tool_name) + ")"};
        if (options_version != Options::options_version)
            return Refusal{RefusalCode::bad_argument,
                           std::string(tool) + ": options of version " + std::to_string(options_version) +
                               ", the plug-in reads version " + std::to_string(Options::options_version) +
                               " (rebuild against its installed header)"};
        if (options == nullptr) return Refusal{RefusalCode::bad_argument, std::string(tool) + ": no options"};
        return static_cast<const Options*>(options);
    }

protected:
    ~ToolFactory() = default;
};

// The factory of a plug-in that offers one tool, whose options are `Options`: begin checks the
// name, the layout and the options (Options::check), and hands them to `make`, which a plug-in
// gives as a lambda holding what its sessions need (the host's services).
template <class Options>
class ToolFactoryOf final : public ToolFactory {
public:
    using Make = std::function<Outcome<std::unique_ptr<ToolSession>>(Mesh&, const Options&, const ToolContext&)>;
    explicit ToolFactoryOf(Make make) : m_make(std::move(make)) {}

    std::span<const Tool> tools() const override { return {&m_tool, 1}; }
    Outcome<std::unique_ptr<ToolSession>> begin(std::string_view tool, std::uint32_t options_version,
                                                const void* options, Mesh& mesh,
                                                const ToolContext& context) override {
        const Outcome<const Options*> typed = options_of<Options>(tool, options_version, options);
        if (!typed) return typed.refusal();
        if (Outcome<Done> checked = (*typed)->check(); !checked) return checked.refusal();
        return m_make(mesh, **typed, context);
    }

private:
    Tool m_tool{Options::tool_name, Options::options_version};
    Make m_make;
};

// A session of the tool whose options `options` are, from `factory`.
template <class Options>
Outcome<std::unique_ptr<ToolSession>> begin_tool(ToolFactory& factory, Mesh& mesh, const Options& options,
                                                 const ToolContext& context = {}) {
    return factory.begin(Options::tool_name, Options::options_version, &options, mesh, context);
}

}  // namespace sxk
