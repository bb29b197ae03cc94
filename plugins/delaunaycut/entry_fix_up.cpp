// The entry fix-up (thesis §5.2.2, Fig. 5.6): the incision is postponed while the scalpel is near
// the boundary, the active node making a dent; once the node is eps_entry from the entry point,
// "nodes are added at the entry point, creating an incision".
//
//      before ------- E ------- after          before --- e2 e1 --- after    The dent is filled by two
//            \      dent      /                      \  /  |  \  /           triangles (a, before, e2)
//              \            /          --->           \/ | | \/            and (after, a, e1), e2 and
//                \        /                            \ | | /              e1 new nodes at the entry
//                   a                                     a                 point, each a `dilation`
//                                                                           of the way towards
// `before` and `after`: the incision's two sides e2-a and a-e1, labelled as the cut. The dent is
// empty (the node made it by moving away from the boundary), so filling it cannot overlap the mesh;
// the two triangles are checked to be counter-clockwise in both position sets, and when they are
// not (the node went along the boundary rather than into the mesh) the fix-up waits.
#include <array>

#include "cut_methods.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/predicates.hpp"

namespace sxk::delaunaycut {

Outcome<bool> DelaunayCutSession::fix_up(CutStepReport& report) {
    const VertexId a = m_state.active;
    const VertexFan fan = fan_around(mesh(), a);
    if (fan.closed) return false;
    const VertexId after = fan.ring.front(), before = fan.ring.back();
    const std::array<VertexId, 1> parent{a};
    const std::array<double, 1> weight{1.0};
    // where the new nodes go, in both position sets
    const double d = m_options.dilation;
    const std::array<Point, 2> deformed{lerp(m_state.entry, at(mesh(), before), d),
                                        lerp(m_state.entry, at(mesh(), after), d)};
    const std::array<Point, 2> reference{lerp(m_state.entry_reference, mesh().reference(before), d),
                                         lerp(m_state.entry_reference, mesh().reference(after), d)};
    for (const bool in_reference : {false, true}) {
        auto p = [&](VertexId v) { return in_reference ? mesh().reference(v) : mesh().deformed(v); };
        const std::array<Point, 2>& e = in_reference ? reference : deformed;
        if (orient2d(p(a), p(before), e[0]) != Sign::positive || orient2d(p(after), p(a), e[1]) != Sign::positive)
            return false;
    }
    EditStep filling(*EditJournal::of(mesh()));
    std::array<VertexId, 2> e{};
    for (std::size_t k = 0; k < 2; ++k) {
        // the new nodes' attributes are the active node's (it was at the entry point)
        auto made = mesh().add_interpolated_vertex(parent, weight);
        if (!made) return made.refusal().prefixed("fix-up: ");
        e[k] = *made;
        mesh().set_deformed(e[k], deformed[k]);
        mesh().set_reference(e[k], reference[k]);
    }
    const int label = mesh().label(fan.triangles.front());
    const std::array<Simplex, 2> dent{Simplex(+1, {a, before, e[0]}), Simplex(+1, {after, a, e[1]})};
    const std::array<int, 2> labels{label, label};
    // refused (a star the two triangles would pinch): `filling` takes the new nodes back when it
    // goes out of scope, and the fix-up waits for the node to move on
    if (!mesh().replace_elements({}, dent, labels)) return false;
    // the boundary's labels move from the dent's sides to the boundary they are again
    for (const auto& [side, outer] : {std::pair{Simplex(+1, {before, a}), Simplex(+1, {before, e[0]})},
                                      std::pair{Simplex(+1, {a, after}), Simplex(+1, {e[1], after})}}) {
        if (const std::optional<int> kept = mesh().face_label(side)) {
            mesh().erase_face_label(side);
            mesh().set_face_label(outer, *kept);
        }
    }
    mesh().set_face_label(Simplex(+1, {e[0], a}), m_options.cut_label);
    mesh().set_face_label(Simplex(+1, {a, e[1]}), m_options.cut_label);
    if (auto kept = filling.commit(); !kept) return kept.refusal();
    ++report.fix_ups;
    m_state.phase = Phase::cutting;
    m_state.path = {m_state.entry, at(mesh(), a)};
    return true;
}

}  // namespace sxk::delaunaycut
