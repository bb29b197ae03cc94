// MoveStep (move_step.hpp): a removal move as one EditJournal step.
#include "move_step.hpp"

#include <algorithm>

namespace sxk::degeneracy::detail {

void MoveStep::begin() {
    m_journal.checkpoint();
    m_touched_start = m_log.touched.size();
    m_events_start = m_log.events.size();
}

std::vector<ElementId> MoveStep::created() const {
    std::vector<ElementId> ids(m_log.touched.begin() + static_cast<std::ptrdiff_t>(m_touched_start),
                               m_log.touched.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::erase_if(ids, [&](ElementId t) { return !m_mesh.is_element(t); });
    return ids;
}

std::vector<Simplex> MoveStep::removed() const {
    // an element the move made and then removed again was not there before: the simplexes made
    // so far are matched off first
    std::vector<Simplex> made, gone;
    auto made_before = [&](const Simplex& s) {
        const auto it = std::find(made.begin(), made.end(), s);
        if (it == made.end()) return false;
        made.erase(it);
        return true;
    };
    for (std::size_t i = m_events_start; i < m_log.events.size(); ++i) {
        const MoveLog::Event& e = m_log.events[i];
        if (e.kind != MoveLog::Event::Kind::added && !made_before(e.was)) gone.push_back(e.was);
        if (e.kind != MoveLog::Event::Kind::removed) made.push_back(e.now);
    }
    return gone;
}

void MoveStep::keep() { (void)m_journal.commit(); }    // begin() opened the step
void MoveStep::undo() {
    (void)m_journal.rollback();  // begin() opened the step
    m_log.truncate(m_touched_start, m_events_start);
}

}  // namespace sxk::degeneracy::detail
