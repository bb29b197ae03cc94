// MoveStep (move_step.hpp): a removal move as one EditJournal step.
#include "move_step.hpp"

namespace sxk::degeneracy::detail {

void MoveStep::begin() {
    m_journal.checkpoint();
    m_start = m_events.mark();
}

std::vector<ElementId> MoveStep::created() const { return m_events.created_since(m_mesh, m_start); }

std::vector<Simplex> MoveStep::removed() const { return m_events.removed_since(m_start); }

void MoveStep::keep() { (void)m_journal.commit(); }  // begin() opened the step
void MoveStep::undo() {
    (void)m_journal.rollback();  // begin() opened the step
    m_events.truncate(m_start);
}

}  // namespace sxk::degeneracy::detail
