// Steps, rollback and the undo/redo history over the mesh's record (edit_journal.hpp,
// undo_log.hpp).
#include "sxk/edit_journal.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "undo_log.hpp"

namespace sxk {

// A record of the mesh's stores and, in the history, what each side log recorded of the step (in
// the order of attachment).
struct EditJournal::Log : detail::UndoLog {
    std::vector<std::pair<SideLog*, std::unique_ptr<SideRecord>>> sides;
    bool holds_nothing() const { return empty() && sides.empty(); }
};

SideLog::~SideLog() {
    if (m_journal != nullptr) m_journal->detach(*this);
}

EditJournal::EditJournal(Mesh& mesh) : m_mesh(mesh), m_open(std::make_unique<Log>()) {
    if (mesh.m_journal != nullptr) throw std::logic_error("EditJournal: the mesh already has a journal");
    mesh.m_journal = this;
    m_history_revision = mesh.revision();
}

EditJournal::~EditJournal() {
    // steps that were not committed did not happen
    if (!m_marks.empty()) {
        m_mesh.m_undo = nullptr;
        m_open->undo(m_mesh, 0, nullptr);
        for (auto side = m_sides.rbegin(); side != m_sides.rend(); ++side) side->log->rollback_to(side->marks.front());
    }
    for (Side& side : m_sides) side.log->m_journal = nullptr;
    m_mesh.m_journal = nullptr;
}

Outcome<Done> EditJournal::attach(SideLog& log) {
    if (log.m_journal == this) return Done{};
    if (log.m_journal != nullptr)
        return Refusal{RefusalCode::not_applicable, "attach: the side log is attached to another journal"};
    Side side{&log, {}};
    for (std::size_t level = 0; level < m_marks.size(); ++level) side.marks.push_back(log.mark());
    m_sides.push_back(std::move(side));
    log.m_journal = this;
    return Done{};
}

void EditJournal::detach(SideLog& log) {
    if (log.m_journal != this) return;
    std::erase_if(m_sides, [&](const Side& side) { return side.log == &log; });
    for (auto* history : {&m_undo, &m_redo}) {
        for (std::unique_ptr<Log>& step : *history)
            std::erase_if(step->sides, [&](const auto& record) { return record.first == &log; });
        std::erase_if(*history, [](const std::unique_ptr<Log>& step) { return step->holds_nothing(); });
    }
    log.m_journal = nullptr;
}

void EditJournal::checkpoint() {
    if (m_marks.empty()) {
        m_open->clear();
        m_open->sides.clear();  // a history that keeps no step dropped the last ones here
        m_revision_at_open = m_mesh.revision();
        m_mesh.m_undo = m_open.get();
    }
    m_marks.push_back(m_open->size());
    for (Side& side : m_sides) side.marks.push_back(side.log->mark());
    m_mesh.new_record_stretch();
}

std::size_t EditJournal::recorded() const { return m_marks.empty() ? 0 : m_open->size(); }

Outcome<Done> EditJournal::commit() {
    if (m_marks.empty()) return Refusal{RefusalCode::not_applicable, "commit: no step is open"};
    m_marks.pop_back();
    if (!m_marks.empty()) {
        for (Side& side : m_sides) {
            side.log->keep(side.marks.back());
            side.marks.pop_back();
        }
        return Done{};
    }
    m_mesh.m_undo = nullptr;
    for (Side& side : m_sides) {
        if (std::unique_ptr<SideRecord> record = side.log->commit(side.marks.back()))
            m_open->sides.emplace_back(side.log, std::move(record));
        side.marks.pop_back();
    }
    if (m_open->holds_nothing()) {
        // Nothing happened to the mesh or a side log, or all that happened was rolled back by
        // inner steps: no step to undo.
        // The rollbacks moved the revision on, but the mesh is as when the step opened, so the
        // history still holds when it held then.
        if (m_revision_at_open == m_history_revision) m_history_revision = m_mesh.revision();
        return Done{};
    }
    ++m_steps_recorded;
    // the history holds only if nothing changed between its last step and this one
    if (m_revision_at_open != m_history_revision) clear_history();
    m_redo.clear();
    if (m_history_limit > 0) {
        // room for a step like this one: a tool's steps are alike, and a record grown from empty
        // by doubling copied itself about ten times a step (the femur needle's 300 moved vertices).
        // At most a frame's worth: after one large edit the history keeps the next record's room.
        constexpr std::size_t frame_entries = std::size_t{1} << 16;
        const std::size_t entries = std::min(m_open->size(), frame_entries);
        m_undo.push_back(std::move(m_open));
        m_open = std::make_unique<Log>();
        m_open->reserve(entries);
        while (m_undo.size() > m_history_limit) m_undo.pop_front();
    }
    m_history_revision = m_mesh.revision();
    return Done{};
}

Outcome<Done> EditJournal::rollback() {
    if (m_marks.empty()) return Refusal{RefusalCode::not_applicable, "rollback: no step is open"};
    const std::size_t mark = m_marks.back();
    m_marks.pop_back();
    // replaying must not record itself
    m_mesh.m_undo = nullptr;
    m_open->undo(m_mesh, mark, nullptr);
    for (auto side = m_sides.rbegin(); side != m_sides.rend(); ++side) {
        side->log->rollback_to(side->marks.back());
        side->marks.pop_back();
    }
    if (!m_marks.empty()) {
        m_mesh.m_undo = m_open.get();
        m_mesh.new_record_stretch();
    } else if (m_revision_at_open == m_history_revision) {
        // the mesh is exactly as after the history's last step again
        m_history_revision = m_mesh.revision();
    }
    return Done{};
}

void EditJournal::set_history_limit(std::size_t steps) {
    m_history_limit = steps;
    while (m_undo.size() > steps) m_undo.pop_front();
    while (m_redo.size() > steps) m_redo.pop_front();
}

void EditJournal::clear_history() {
    m_undo.clear();
    m_redo.clear();
}

Outcome<Done> EditJournal::replay_history(std::deque<std::unique_ptr<Log>>& from,
                                          std::deque<std::unique_ptr<Log>>& to, const char* what) {
    if (!m_marks.empty())
        return Refusal{RefusalCode::not_applicable, std::string(what) + ": a step is open"};
    if (from.empty())
        return Refusal{RefusalCode::not_applicable, std::string(what) + ": nothing to " + what};
    if (m_mesh.revision() != m_history_revision)
        return Refusal{RefusalCode::stale,
                       std::string(what) +
                           ": the mesh changed outside the journal since its last step"};
    std::unique_ptr<Log> step = std::move(from.back());
    from.pop_back();
    auto inverse = std::make_unique<Log>();
    step->undo(m_mesh, 0, inverse.get());
    for (auto record = step->sides.rbegin(); record != step->sides.rend(); ++record)
        inverse->sides.emplace_back(record->first, record->first->replay(std::move(record->second)));
    std::reverse(inverse->sides.begin(), inverse->sides.end());  // in the order of attachment again
    to.push_back(std::move(inverse));
    m_history_revision = m_mesh.revision();
    return Done{};
}

EditStep::~EditStep() {
    if (m_closed) return;
    while (m_journal.depth() > m_depth) (void)m_journal.rollback();
}

Outcome<Done> EditStep::commit() {
    if (m_closed || m_journal.depth() <= m_depth)
        return Refusal{RefusalCode::not_applicable, "commit: the step is closed"};
    while (m_journal.depth() > m_depth) (void)m_journal.commit();
    m_closed = true;
    return Done{};
}

JournalScope::JournalScope(Mesh& mesh) : m_journal(EditJournal::of(mesh)) {
    if (m_journal == nullptr) {
        m_own = std::make_unique<EditJournal>(mesh);
        m_journal = m_own.get();
    }
}

Outcome<Done> EditJournal::undo() { return replay_history(m_undo, m_redo, "undo"); }
Outcome<Done> EditJournal::redo() { return replay_history(m_redo, m_undo, "redo"); }

}  // namespace sxk
