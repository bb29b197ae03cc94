// State kept beside the mesh that a step must take back with it: a tool's scalpel and the phase
// of its cut, the faces it has marked, the refinement marks of a bisection. A SideLog attached to
// the mesh's EditJournal is marked when a step opens, taken back when the step is rolled back,
// and recorded when the outermost step is committed, so that undo and redo restore the mesh and
// that state together: a tool cannot forget its own restore (issue 48, "one undo").
//
//   SnapshotLog<Scalpel> scalpel;          // the state, copied when a step opens
//   journal.attach(scalpel);
//   journal.checkpoint();
//   scalpel.edit().position = p;           // ... and mesh edits
//   journal.rollback();                    // the mesh and scalpel.get() as at checkpoint()
//
// The journal calls the log after the mesh: on rollback, undo and redo the mesh is already as it
// will be when rollback_to() or replay() runs (a log may read it), and the logs run in reverse
// order of attachment. A log detaches itself when destroyed; the journal forgets its records.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "sxk/config.hpp"

namespace sxk {

class EditJournal;

// What a committed step changed in one side log, as its log records it.
struct SideRecord {
    virtual ~SideRecord() = default;
};

class SXK_API SideLog {
public:
    SideLog() = default;
    virtual ~SideLog();
    SideLog(const SideLog&) = delete;
    SideLog& operator=(const SideLog&) = delete;

    // A step opens: a mark of the state now. Steps nest, so marks are taken innermost last.
    virtual std::size_t mark() = 0;
    // The step that opened at `mark` is rolled back: the state is as at mark().
    virtual void rollback_to(std::size_t mark) = 0;
    // An inner step that opened at `mark` is committed: its changes belong to the enclosing step.
    virtual void keep(std::size_t mark) = 0;
    // The outermost step that opened at `mark` is committed: what it changed, as a record that
    // replay() can take back, or nullptr when nothing changed.
    virtual std::unique_ptr<SideRecord> commit(std::size_t mark) = 0;
    // Undo or redo of a committed step: applies `record` (one this log made) and returns the
    // record that takes it back again.
    virtual std::unique_ptr<SideRecord> replay(std::unique_ptr<SideRecord> record) = 0;

    // The journal this log is attached to, or nullptr.
    EditJournal* journal() const { return m_journal; }

private:
    friend class EditJournal;
    EditJournal* m_journal = nullptr;
};

// A side log for a small value: a copy when a step opens, the value back when it is rolled back,
// the values before and after in the record. For state of a few words (a tool's position, the
// phase of its cut); a log whose state grows with the work records its changes instead. T is
// copyable, and == tells whether a step changed it (an unchanged value records nothing).
template <class T>
class SnapshotLog final : public SideLog {
public:
    explicit SnapshotLog(T value = T{}) : m_value(std::move(value)) {}
    ~SnapshotLog() override = default;

    const T& get() const { return m_value; }
    // The value to change (inside a step, for the change to be taken back with it).
    T& edit() { return m_value; }
    // Called after a rollback, an undo or a redo has changed the value, with the value it
    // replaced: for what must follow the value outside the mesh (the needle holds the body's nodes
    // its value lists, and releases those it no longer does). A rollback that finds the value as
    // it was calls nothing (the many inner steps a removal tries and rolls back).
    void on_restore(std::function<void(const T& replaced)> follow) { m_follow = std::move(follow); }

    std::size_t mark() override {
        m_saved.push_back(m_value);
        return m_saved.size() - 1;
    }
    void rollback_to(std::size_t mark) override {
        // compared only for a follower: the planar cutters roll back a snapshot per tried flip
        const bool follow = m_follow && !(m_value == m_saved[mark]);
        T replaced = std::exchange(m_value, std::move(m_saved[mark]));
        m_saved.resize(mark);
        if (follow) m_follow(replaced);
    }
    void keep(std::size_t mark) override { m_saved.resize(mark); }
    std::unique_ptr<SideRecord> commit(std::size_t mark) override {
        auto record = std::make_unique<Record>(std::move(m_saved[mark]));
        m_saved.resize(mark);
        if (record->value == m_value) return nullptr;
        return record;
    }
    std::unique_ptr<SideRecord> replay(std::unique_ptr<SideRecord> record) override {
        // the record holds the other value: swapping makes it the record that goes back
        using std::swap;
        swap(static_cast<Record&>(*record).value, m_value);
        if (m_follow) m_follow(static_cast<const Record&>(*record).value);
        return record;
    }

private:
    struct Record final : SideRecord {
        explicit Record(T v) : value(std::move(v)) {}
        T value;
    };
    T m_value;
    std::vector<T> m_saved;  // the value when each open step began, outermost first
    std::function<void(const T&)> m_follow;
};

}  // namespace sxk
