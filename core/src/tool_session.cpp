// ToolSession (tool_session.hpp): each step one EditJournal step, and the session's undo.
#include "sxk/tool_session.hpp"

#include <algorithm>
#include <limits>

#include "sxk/step_events.hpp"

namespace sxk {

namespace {

template <class T>
void sort_unique(std::vector<T>& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

}  // namespace

ToolSession::ToolSession(Mesh& mesh) : m_mesh(mesh), m_journal(mesh), m_revision(mesh.revision()) {
    // a journal of its own keeps every step, so that cancel() can take them all back
    if (m_journal.owned()) m_journal->set_history_limit(std::numeric_limits<std::size_t>::max());
    // Room for the mesh to grow by half before a step copies its pools: a pool that grows past
    // its capacity is copied whole, and a mesh just read has none to spare (the first cutting
    // step on the 213k femur spent 16 ms dissecting, most of it copying the element and face
    // pools). Copied here, before the first step, once; address space until elements use it.
    mesh.reserve(mesh.vertex_count() + mesh.vertex_count() / 2, mesh.element_capacity() + mesh.element_capacity() / 2);
}

ToolSession::~ToolSession() = default;

std::span<const ElementId> ToolSession::elements_edited_in_step() const {
    if (m_step_elements == nullptr) return {};
    return *m_step_elements;
}

std::span<const VertexId> ToolSession::vertices_moved_in_step() const {
    if (m_step_vertices == nullptr) return {};
    return *m_step_vertices;
}

Outcome<StepReport> ToolSession::step(const ToolPose& pose) {
    if (m_ended) return Refusal{RefusalCode::not_applicable, "step: the session has ended"};
    EditJournal& journal = m_journal.journal();
    const bool outermost = journal.depth() == 0;
    // an outermost step that recorded nothing (in the mesh or a side log) leaves no history entry
    const std::uint64_t recorded_before = journal.steps_recorded();
    const std::size_t vertices_before = m_mesh.vertex_count();
    const std::size_t elements_before = m_mesh.element_count();
    const bool in_step = m_mesh.revision() == m_revision;  // nothing changed since our last step
    StepReport report;
    // what the step's edits did, rolled-back inner steps included (a tool may have read their
    // elements, which are dead or remade since)
    StepEvents watcher;
    Outcome<Done> applied = Done{};
    {
        EditStep step(journal);
        const ScopedWatcher watching(m_mesh, watcher);
        m_step_elements = &watcher.touched();
        m_step_vertices = &watcher.moved();
        struct Forget {  // also when apply throws: the watcher's lists go out of scope with it
            const std::vector<ElementId>*& elements;
            const std::vector<VertexId>*& vertices;
            ~Forget() {
                elements = nullptr;
                vertices = nullptr;
            }
        } forget{m_step_elements, m_step_vertices};
        applied = apply(pose, report);
        if (applied) (void)step.commit();
    }  // a refusal is rolled back here
    const bool recorded = journal.steps_recorded() != recorded_before;
    if (!applied) {
        if (in_step) m_revision = m_mesh.revision();  // the mesh is as after our last step again
        return applied.refusal();
    }
    m_kept.push_back(!outermost ? Kept::application_step : recorded ? Kept::history_entry : Kept::nothing);
    m_undone.clear();  // a new step: what was undone is no longer ahead
    m_revision = m_mesh.revision();
    report.elements = watcher.created_since(m_mesh, StepEvents::Mark{});
    // after = before - removed + made, counting only the made elements still there
    std::vector<ElementId> added = watcher.added();
    sort_unique(added);
    const auto made = static_cast<std::size_t>(
        std::count_if(added.begin(), added.end(), [&](ElementId t) { return m_mesh.is_element(t); }));
    report.elements_removed = elements_before + made - m_mesh.element_count();
    report.vertices = watcher.moved();
    for (std::size_t v = vertices_before; v < m_mesh.vertex_count(); ++v)
        report.vertices.push_back(static_cast<VertexId>(v));
    sort_unique(report.vertices);
    std::erase_if(report.vertices, [&](VertexId v) { return v >= m_mesh.vertex_count(); });
    return report;
}

Outcome<Done> ToolSession::keep_beside(SideLog& log) { return m_journal->attach(log); }

Outcome<Done> ToolSession::undo_step() {
    if (m_kept.empty())
        return Refusal{RefusalCode::not_applicable, "undo_step: the session has no step to undo"};
    if (m_kept.back() == Kept::application_step)
        return Refusal{RefusalCode::not_applicable,
                       "undo_step: the step is part of the application's open step"};
    if (m_kept.back() == Kept::nothing) {
        m_undone.push_back(Kept::nothing);
        m_kept.pop_back();
        return Done{};
    }
    if (m_mesh.revision() != m_revision)
        return Refusal{RefusalCode::stale,
                       "undo_step: the mesh changed since the session's last step"};
    if (Outcome<Done> undone = m_journal.journal().undo(); !undone)
        return undone.refusal().prefixed("undo_step: ");
    m_undone.push_back(Kept::history_entry);
    m_kept.pop_back();
    m_revision = m_mesh.revision();
    return Done{};
}

Outcome<Done> ToolSession::redo_step() {
    if (m_undone.empty())
        return Refusal{RefusalCode::not_applicable, "redo_step: the session has no undone step to redo"};
    if (m_undone.back() == Kept::nothing) {
        m_kept.push_back(Kept::nothing);
        m_undone.pop_back();
        return Done{};
    }
    if (m_mesh.revision() != m_revision)
        return Refusal{RefusalCode::stale, "redo_step: the mesh changed since the session's last undo"};
    if (Outcome<Done> redone = m_journal.journal().redo(); !redone)
        return redone.refusal().prefixed("redo_step: ");
    m_kept.push_back(Kept::history_entry);
    m_undone.pop_back();
    m_revision = m_mesh.revision();
    return Done{};
}

Outcome<Done> ToolSession::cancel() {
    std::size_t undone = 0;
    while (!m_kept.empty()) {
        if (Outcome<Done> one = undo_step(); !one)
            return one.refusal().prefixed("cancel: " + std::to_string(undone) +
                                          " steps taken back, then ");
        ++undone;
    }
    m_ended = true;
    return Done{};
}

}  // namespace sxk
