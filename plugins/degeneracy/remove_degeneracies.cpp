// The passes of degeneracy removal (thesis §3.2.3): list, handle, list again while the list
// shrinks; then flips; then cut free what remains.
#include "remove_degeneracies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "removal_steps.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/watcher.hpp"

namespace sxk::degeneracy {
namespace {

void sort_unique(std::vector<ElementId>& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

std::optional<Refusal> check(const Mesh& mesh, const Options& options) {
    if (auto checked = options.check(); !checked) return checked.refusal();
    if (mesh.topological_dimension() != 2 && mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "remove_degeneracies: not a triangle or tetrahedral mesh"};
    return std::nullopt;
}

class Remover {
public:
    Remover(Mesh& mesh, const Options& options, bool whole_mesh)
        : m_mesh(mesh), m_options(options), m_whole_mesh(whole_mesh) {}

    Report run(std::vector<ElementId> candidates) {
        // the run is one step of the mesh's journal (an application's, or one of its own), each
        // move a step inside it; an exception takes the whole run back
        JournalScope journal(m_mesh);
        EditStep run_step(journal.journal());
        detail::MoveStep move(m_mesh, journal.journal(), m_log), follow_up(m_mesh, journal.journal(), m_log);
        m_move = &move;
        m_follow_up = &follow_up;
        const ScopedWatcher watching(m_mesh, m_log);
        Report report;
        report.elements_before = m_mesh.element_count();
        report.vertices_before = m_mesh.vertices_in_elements();
        std::vector<ElementId> list;
        if (m_whole_mesh) {
            list = degenerates_among(candidates);
        } else {
            // the candidates' shapes, flattest first: what measure() walks (local runs)
            sort_unique(candidates);
            m_first_made_vertex = static_cast<VertexId>(m_mesh.vertex_count());  // add_vertex appends
            for (const ElementId t : candidates)
                for (const VertexId v : m_mesh.simplex(t).vertices()) m_region.insert(v);
            for (const ElementId t : candidates) {
                const double aspect = detail::element_aspect_ratio(m_mesh, t, m_options.positions);
                m_candidates.emplace_back(aspect, t);
                if (aspect < m_options.aspect_ratio) list.push_back(t);
            }
            std::sort(m_candidates.begin(), m_candidates.end());
        }
        report.found = list.size();

        std::size_t collapse_passes = 0;
        std::size_t previous = std::numeric_limits<std::size_t>::max();
        // each round: the stages that keep only moves that pay, then one pass keeping any move
        // that succeeds; a few rounds are worth it, more only churn (figures: performance.md)
        constexpr int rounds = 3;
        for (int round = 0;; ++round) {
            while (!list.empty()) {
                // collapse passes while the list shrinks (thesis), or (beyond the thesis) while it
                // holds elements no collapse pass has tried yet: a pass may remove some and create
                // as many new ones, which the thesis' rule would leave to be cut free untried
                while (!list.empty() && (list.size() < previous || has_untried(list)) &&
                       collapse_passes < m_options.max_passes) {
                    previous = list.size();
                    ++collapse_passes;
                    list = pass(PassReport::Kind::collapse, list, report);
                }
                if (list.empty() || !m_options.flips || m_mesh.topological_dimension() != 3) break;
                // then flips, and after any flip the collapse passes again
                const std::size_t flips_before = report.flips;
                list = pass(PassReport::Kind::flip, list, report);
                if (report.flips == flips_before || collapse_passes >= m_options.max_passes) break;
                previous = std::numeric_limits<std::size_t>::max();
            }
            // what resisted: moves whose new degenerates go by clean moves right after
            if (!list.empty() && collapse_passes < m_options.max_passes) {
                m_effort = detail::Effort::follow_up;
                previous = std::numeric_limits<std::size_t>::max();
                m_follow_up_tried.clear();
                while (!list.empty() && (list.size() < previous || has_untried_follow_up(list)) &&
                       collapse_passes < m_options.max_passes) {
                    previous = list.size();
                    ++collapse_passes;
                    list = pass(PassReport::Kind::collapse, list, report);
                }
                m_effort = detail::Effort::paying;
            }
            // what still resists: one pass keeping any move that succeeds, as the thesis keeps
            // every collapse; what it makes goes through the stages above again
            if (list.empty() || collapse_passes >= m_options.max_passes || round + 1 == rounds) break;
            const std::size_t resisting = list.size();
            m_effort = detail::Effort::any;
            ++collapse_passes;
            list = pass(PassReport::Kind::collapse, list, report);
            m_effort = detail::Effort::paying;
            if (list.size() >= resisting && !has_untried(list)) break;
            previous = std::numeric_limits<std::size_t>::max();
        }
        if (!list.empty() && m_options.peel) list = pass(PassReport::Kind::peel, list, report);
        if (!list.empty() && m_options.cut_free) list = pass(PassReport::Kind::cut_free, list, report);

        report.remaining = list.size();
        for (const ElementId t : list) {
            report.remaining_elements.push_back(t);
            Why why = reason(t);
            report.remaining_reasons.push_back(std::move(why.text));
            report.remaining_codes.push_back(why.code);
        }
        report.elements_after = m_mesh.element_count();
        report.vertices_after = m_mesh.vertices_in_elements();
        (void)run_step.commit();
        return report;
    }

private:
    // Refusals are recorded by vertex set: an undone split gives the element a new id.
    Simplex key(ElementId t) const { return Simplex(+1, m_mesh.simplex(t).vertices()); }

    bool has_untried(const std::vector<ElementId>& list) const {
        return std::any_of(list.begin(), list.end(), [&](ElementId t) {
            const auto found = m_reasons.find(key(t));
            return found == m_reasons.end() || !found->second[0];
        });
    }

    // The follow-up stage's own "untried": elements it has not had yet (it marks what it tries).
    bool has_untried_follow_up(const std::vector<ElementId>& list) {
        bool untried = false;
        for (const ElementId t : list) untried |= m_follow_up_tried.insert(key(t)).second;
        return untried;
    }

    // Why t remains: the refusals of its attempts in pass order, and the code of the first.
    struct Why {
        std::string text;
        std::optional<RefusalCode> code;
    };
    Why reason(ElementId t) const {
        const auto found = m_reasons.find(key(t));
        if (found == m_reasons.end())
            return {"not tried (the passes stopped: the list no longer shrank)", {}};
        Why why;
        const char* names[] = {"collapse: ", "flip: ", "peel: ", "cut free: "};
        for (std::size_t i = 0; i < 4; ++i) {
            const detail::Refused& refused = found->second[i];
            if (!refused) continue;
            why.text += (why.text.empty() ? "" : " | ") + std::string(names[i]) + refused->reason;
            if (!why.code) why.code = refused->code;
        }
        return why;
    }

    // Whether an element the removal made may go on the list. A whole-mesh run: any. A local run:
    // one whose corners are all the candidates' corners or vertices the run made (splits). A move
    // on a listed element edits only elements around its corners, so every edit stays among the
    // elements whose corners lie within one ring of the candidates' corners (the candidates being
    // the stars of the vertices a tool moved or split: two rings of those vertices), however many
    // passes run: a collapse joins two such corners, and what it makes has no corner from farther
    // (a move's clean follow-ups, removal_steps.hpp, remove what the move made and reach one ring
    // farther at most, without going on the list). Once,
    // any element a move made went on the list: at --aspect 0.41 on the thesis cube, where every
    // element of the Kuhn mesh is below the threshold, one step's removal collapsed 3,072
    // elements to 1 (issue 47).
    bool in_region(ElementId t) const {
        if (m_whole_mesh) return true;
        if (!m_mesh.is_element(t)) return false;
        for (const VertexId v : m_mesh.simplex(t).vertices())
            if (v < m_first_made_vertex && !m_region.count(v)) return false;
        return true;
    }

    // Whether a collapse attempt on the element with these vertices would fail as its last one
    // did. An attempt at effort clean or paying (the flip-first of slivers, then every split and
    // collapse the element's shape allows, each kept or rolled back) reads and edits the stars
    // of the element's corners, and positions never change here; so while no kept edit has
    // touched those stars, it fails again. Follow-ups reach one ring farther, and efforts above
    // paying try them: those attempts always run. Without this, the passes that go on while a
    // list of the same size has untried elements tried everything again: on the femur at aspect
    // ratio 0.2, 60 passes of 5,300 elements that kept some 135 moves each (issue 47, defect 10).
    // There it skips 288,090 attempts, and run anyway none of them keeps a move: the same mesh,
    // byte for byte, in 32 s instead of 221 (docs/performance.md "Degeneracy removal").
    bool fails_again(const Simplex& vertices) const {
        if (m_effort > detail::Effort::paying) return false;
        const auto found = m_failed.find(vertices);
        if (found == m_failed.end() || found->second.effort < m_effort) return false;
        for (const VertexId v : vertices.vertices())
            if (v < m_star_changed.size() && m_star_changed[v] > found->second.attempt) return false;
        return true;
    }

    // Marks the corners of every element the kept edits since `events_before` removed, changed or
    // made: their stars changed at this attempt (a rolled-back move left no events, move_step.hpp).
    void note_changes(const StepEvents::Mark& events_before) {
        m_log.for_changed_stars(events_before, [&](VertexId v) {
            if (v >= m_star_changed.size()) m_star_changed.resize(std::size_t{v} + 1, 0);
            m_star_changed[v] = m_attempts;
        });
    }

    bool degenerate(ElementId t) const {
        return m_mesh.is_element(t) &&
               detail::element_aspect_ratio(m_mesh, t, m_options.positions) < m_options.aspect_ratio;
    }

    std::vector<ElementId> degenerates_among(std::vector<ElementId>& ids) const {
        sort_unique(ids);
        std::vector<ElementId> list;
        for (const ElementId t : ids)
            if (degenerate(t)) list.push_back(t);
        return list;
    }

    // One pass over `list`; returns the next list: what is still degenerate of the list and of
    // the elements the pass created.
    std::vector<ElementId> pass(PassReport::Kind kind, const std::vector<ElementId>& list, Report& report) {
        PassReport p;
        p.kind = kind;
        p.elements_before = m_mesh.element_count();
        p.vertices_before = report.passes.empty() ? report.vertices_before : report.passes.back().vertices_after;
        for (const ElementId t : list) ++p.found[static_cast<std::size_t>(detail::classify_element(m_mesh, t, m_options))];
        m_log.clear();  // no move is open between passes
        detail::Tally tally;
        std::vector<ElementId> next;
        if (kind == PassReport::Kind::cut_free) {
            const auto cut = detail::cut_free(m_mesh, list);
            if (cut) {
                p.cut_free = list.size();
            } else {
                for (const ElementId t : list) m_reasons[key(t)][3] = cut.refusal();
                next = list;
            }
        } else {
            // By vertices, not ids: a move kept earlier in the pass may have removed an element
            // and given its id to a new one.
            std::vector<Simplex> keys;
            for (const ElementId t : list) keys.push_back(key(t));
            Progress progress{report.passes.size() + 1, to_string(kind), 0, keys.size()};
            for (const Simplex& vertices : keys) {
                if (m_options.progress) m_options.progress(progress);
                ++progress.done;
                // an earlier edit of this pass may have removed or repaired it
                const ElementId t = detail::element_with(m_mesh, vertices);
                if (t == invalid_id || !degenerate(t)) continue;
                if (kind == PassReport::Kind::collapse && fails_again(vertices)) continue;
                const StepEvents::Mark events_before = m_log.mark();
                detail::Refused why;
                if (kind == PassReport::Kind::peel) {
                    why = detail::peel_off_boundary(m_mesh, t, m_options);
                    if (!why) ++p.peeled;
                } else if (kind == PassReport::Kind::flip) {
                    why = detail::flip_out(m_mesh, t, m_options, tally);
                } else if (m_mesh.topological_dimension() == 2) {
                    why = detail::collapse_flat_triangle(m_mesh, t, m_options, tally, *m_move, m_effort,
                                                         m_follow_up);
                } else {
                    // A sliver's own move puts a vertex where its diagonals cross and splits
                    // every element around both: about five elements more per sliver (the
                    // thesis cube grew by 7% so). A clean flip removes it with one element more
                    // at most, so slivers try it first (beyond the thesis).
                    const bool flipped = m_options.flips &&
                                         detail::classify_element(m_mesh, t, m_options) == DegenerateClass::sliver &&
                                         !detail::flip_out(m_mesh, t, m_options, tally);
                    if (!flipped)
                        why = detail::collapse_flat_tetrahedron(m_mesh, t, m_options, tally, *m_move, m_effort,
                                                                m_follow_up);
                }
                ++m_attempts;
                note_changes(events_before);
                if (kind == PassReport::Kind::collapse && why) m_failed[vertices] = {m_attempts, m_effort};
                if (why) m_reasons[vertices][static_cast<std::size_t>(kind)] = std::move(why);
            }
            for (const Simplex& vertices : keys)
                if (const ElementId t = detail::element_with(m_mesh, vertices); t != invalid_id) next.push_back(t);
            for (const ElementId t : m_log.touched())
                if (in_region(t)) next.push_back(t);
            next = degenerates_among(next);
        }
        p.collapses = tally.collapses;
        p.splits = tally.splits;
        p.flips = tally.flips;
        report.collapses += tally.collapses;
        report.splits += tally.splits;
        report.flips += tally.flips;
        report.cut_free += p.cut_free;
        report.peeled += p.peeled;
        p.elements_after = m_mesh.element_count();
        p.vertices_after = m_mesh.vertices_in_elements();
        measure(p);
        report.passes.push_back(p);
        return next;
    }

    // Quality after the pass: of the whole mesh, or (local runs) of the candidates and every
    // element the removal made. A local run's cost must stay with the degenerates, not the
    // candidates, so it never measures all candidates again: their aspect ratios were sorted
    // once (run()), the elements edits made are measured when made, and the figures come from
    // the made ones and the flattest candidates still there and untouched. Dihedral angles are
    // computed only where they can matter: a tetrahedron of aspect ratio r has all dihedral
    // angles in [asin r, pi - asin r] (the height h of a vertex over the plane of a face through
    // edge e is at most its distance to e times sin(angle at e), and h >= r L; triangles: the
    // same for their angles), so once the flattest elements have set the range, elements
    // whose bound lies inside it cannot widen it.
    void measure(PassReport& p) {
        double min_aspect = std::numeric_limits<double>::infinity();
        double min_angle = std::numeric_limits<double>::infinity(), max_angle = 0;
        auto widen = [&](ElementId t) {
            const Simplex& tau = m_mesh.simplex(t);
            std::array<Point, 4> x{};
            for (int i = 0; i < tau.count(); ++i)
                x[static_cast<std::size_t>(i)] = position(m_mesh, tau.vertex(i), m_options.positions);
            const std::span<const Point> points(x.data(), static_cast<std::size_t>(tau.count()));
            auto take = [&](const auto& values) {
                for (const double a : values) {
                    if (std::isnan(a)) continue;
                    min_angle = std::min(min_angle, a);
                    max_angle = std::max(max_angle, a);
                }
            };
            if (tau.count() == 4)
                take(dihedral_angles(points));
            else
                take(triangle_angles(points));
        };
        auto matters = [&](double aspect) {
            const double bound = std::asin(std::min(1.0, aspect));
            return bound < min_angle || pi - bound > max_angle;
        };
        // Elements in ascending aspect ratio: the first gives the minimum, and the walk ends
        // where no later one can widen the angle range.
        auto walk = [&](const std::vector<std::pair<double, ElementId>>& sorted, auto&& usable) {
            for (const auto& [aspect, t] : sorted) {
                if (!usable(t)) continue;
                min_aspect = std::min(min_aspect, aspect);
                if (!matters(aspect)) break;
                widen(t);
            }
        };
        std::vector<std::pair<double, ElementId>> shapes;
        if (m_whole_mesh) {
            shapes.reserve(m_mesh.element_count());
            for (const ElementId t : elements(m_mesh))
                shapes.emplace_back(detail::element_aspect_ratio(m_mesh, t, m_options.positions), t);
            std::sort(shapes.begin(), shapes.end());
            walk(shapes, [](ElementId) { return true; });
        } else {
            for (const ElementId t : m_log.touched()) m_made.insert(t);
            m_touched_ever.insert(m_log.touched().begin(), m_log.touched().end());
            std::erase_if(m_made, [&](ElementId t) { return !m_mesh.is_element(t); });
            for (const ElementId t : m_made)
                shapes.emplace_back(detail::element_aspect_ratio(m_mesh, t, m_options.positions), t);
            std::sort(shapes.begin(), shapes.end());
            walk(shapes, [](ElementId) { return true; });
            // a candidate id an edit touched is a made element now (or gone)
            walk(m_candidates, [&](ElementId t) { return m_mesh.is_element(t) && !m_touched_ever.count(t); });
        }
        p.min_aspect_ratio_after = std::isinf(min_aspect) ? 0 : min_aspect;
        p.min_angle_after = std::isinf(min_angle) ? 0 : min_angle;
        p.max_angle_after = max_angle;
    }

    Mesh& m_mesh;
    const Options& m_options;
    bool m_whole_mesh;
    StepEvents m_log;  // what the run's kept edits did (rolled-back moves forget theirs)
    detail::MoveStep* m_move = nullptr;       // a removal move (run() owns it)
    detail::MoveStep* m_follow_up = nullptr;  // the follow-up moves inside it
    detail::Effort m_effort = detail::Effort::paying;
    std::unordered_set<Simplex, SimplexHash> m_follow_up_tried;
    // local runs: the candidates by aspect ratio (ascending), the elements edits made that are
    // still there, and every id an edit touched
    std::vector<std::pair<double, ElementId>> m_candidates;
    std::unordered_set<ElementId> m_made;
    std::unordered_set<ElementId> m_touched_ever;
    // local runs: the candidates' corners, and the first vertex id the run made (in_region)
    std::unordered_set<VertexId> m_region;
    VertexId m_first_made_vertex = 0;
    // fails_again's: attempts so far, per vertex the attempt whose kept edits last changed its
    // star, and per element (by vertices) its last failed collapse attempt and its effort
    struct Failed {
        std::uint64_t attempt = 0;
        detail::Effort effort = detail::Effort::clean;
    };
    std::uint64_t m_attempts = 0;
    std::vector<std::uint64_t> m_star_changed;
    std::unordered_map<Simplex, Failed, SimplexHash> m_failed;
    // why the collapse, flip and cut free attempts failed
    std::unordered_map<Simplex, std::array<detail::Refused, 4>, SimplexHash> m_reasons;  // by Kind
};

}  // namespace

Outcome<Report> remove_degeneracies(Mesh& mesh, const Options& options) {
    if (auto refused = check(mesh, options)) return *refused;
    std::vector<ElementId> all;
    all.reserve(mesh.element_count());
    for (const ElementId t : elements(mesh)) all.push_back(t);
    return Remover(mesh, options, true).run(std::move(all));
}

Outcome<Report> remove_degeneracies(Mesh& mesh, std::span<const ElementId> candidates, const Options& options) {
    if (auto refused = check(mesh, options)) return *refused;
    std::vector<ElementId> ids;
    for (const ElementId t : candidates)
        if (mesh.is_element(t)) ids.push_back(t);
    return Remover(mesh, options, false).run(std::move(ids));
}

}  // namespace sxk::degeneracy
