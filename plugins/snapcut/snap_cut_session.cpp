// The snap cut's tool session (snap_cut.hpp): a scalpel movement, one transaction.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include "blade_track.hpp"
#include "sxk/plugins/degeneracy.hpp"
#include "sxk/simulation.hpp"
#include "loose_pieces.hpp"
#include "moved_nodes.hpp"
#include "node_snapping.hpp"
#include "snap_cut.hpp"
#include "split_far_crossings.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::snapcut {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double length(const Point& a, const Point& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The interior faces labelled `label` that contain a corner of `faces`, and `faces` themselves,
// sorted by vertices, each once.
std::vector<Simplex> labelled_faces_around(const Mesh& mesh, std::span<const Simplex> faces, int label) {
    std::vector<VertexId> corners;
    for (const Simplex& face : faces)
        for (int j = 0; j < face.count(); ++j) corners.push_back(face.vertex(j));
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    std::vector<Simplex> cut(faces.begin(), faces.end());
    std::vector<ElementId> around;
    for (const VertexId v : corners) {
        around.clear();
        collect_star(mesh, v, mesh.vertex_element(v), around);
        for (const ElementId t : around)
            for (int i = 0; i < mesh.element_vertex_count(); ++i) {
                // an interior face at v is met from both its elements, both in v's star: looked
                // up (a hash of its vertices) from the one with the lower id only
                const FaceId f = mesh.face(t, i);
                const FaceId mate = mesh.mate(f);
                if (mate == invalid_id || mesh.face_element(mate) < t) continue;
                const Simplex face = mesh.face_simplex(f);
                if (!face.contains(v) || mesh.face_label(face) != label) continue;
                cut.push_back(Simplex(+1, face.vertices()));
            }
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
    return cut;
}

// The mean length of the edges at v, deformed positions: the mesh's size where v is.
double mean_edge_at(const Mesh& mesh, VertexId v) {
    std::vector<VertexId> neighbours;
    for (const ElementId t : star(mesh, v))
        for (const VertexId w : mesh.simplex(t).vertices())
            if (w != v) neighbours.push_back(w);
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    double sum = 0;
    for (const VertexId w : neighbours) sum += length(mesh.deformed(v), mesh.deformed(w));
    return sum / double(neighbours.size());
}

}  // namespace

double SnapCutSession::distance_to_swept_surface(const Point& p, std::uint32_t sweep_index,
                                                 std::span<const Sweep> ahead) const {
    // the nearest of the movement's and the last 8 steps' sweeps first (where a corner of this
    // sweep's faces nearly always is), then any sweep nearer than that: a face that opens some
    // sweeps after the one that selected it, 8 steps at 1 kHz being 8 ms of the blade's travel
    double nearest = std::numeric_limits<double>::infinity();
    for (const Sweep& next : ahead) nearest = std::min(nearest, distance_to_sweep(next, p));
    const std::uint32_t first = sweep_index >= 15 ? sweep_index - 15 : 0;
    for (std::uint32_t i = first; i <= sweep_index; ++i)
        nearest = std::min(nearest, distance_to_sweep(m_marks.sweeps()[i], p));
    return nearest > 0 ? m_marks.distance_to_sweeps(p, nearest) : nearest;
}

void SnapCutSession::note_distances(std::vector<VertexId> corners, std::uint32_t sweep_index,
                                    std::span<const Sweep> ahead, double& farthest, double& farthest_local) const {
    // a corner is shared by several faces: each measured once (16 triangle distances and a star)
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    for (const VertexId v : corners) {
        const double away = distance_to_swept_surface(mesh().deformed(v), sweep_index, ahead);
        farthest = std::max(farthest, away);
        if (away > 0) farthest_local = std::max(farthest_local, away / mean_edge_at(mesh(), v));
    }
}

void SnapCutSession::relax(StepReport& report) {
    if (m_services.simulation == nullptr) return;
    const auto start = Clock::now();
    m_last.relaxed = true;
    for (const auto& piece : m_loose) {
        auto held = m_services.simulation->hold_piece(piece);
        if (!held) {
            m_last.relax_refusal = held.reason();
            break;
        }
        m_last.pieces_held += *held;
    }
    if (m_last.relax_refusal.empty()) {
        auto relaxed = m_options.local_vertices > 0 ? relax_near_step()
                                                    : m_services.simulation->relax(m_options.relax_iterations);
        if (relaxed) {
            m_last.relax_iterations = relaxed->iterations;
            m_last.relax_converged = relaxed->converged;
            m_last.relax_residual = relaxed->residual;
            m_last.relax_shown = relaxed->shown;
            if (relaxed->not_shown) m_last.relax_not_shown = relaxed->not_shown->reason;
            m_last.relax_region_vertices = relaxed->region_vertices;
        } else {
            m_last.relax_refusal = relaxed.reason();
        }
    }
    if (m_last.relax_refusal.empty() && m_options.local_vertices > 0 && m_options.far_vertices > 0) {
        if (auto far = m_services.simulation->relax_far(m_options.relax_iterations, m_options.far_vertices)) {
            m_last.relax_iterations += far->iterations;
            m_last.relax_far_vertices = far->region_vertices;
        } else {
            m_last.relax_refusal = far.reason();
        }
    }
    report.actions.push_back(m_last.relax_refusal.empty()
                                 ? "relaxed " + std::to_string(m_last.relax_iterations) + " iterations"
                                 : "not relaxed: " + m_last.relax_refusal);
    m_last.seconds_relax = seconds_since(start);
}

// Around what the step changed: the corners of the elements it edited that are still there, and
// the nodes it moved (snapped).
Outcome<RelaxReport> SnapCutSession::relax_near_step() {
    std::vector<VertexId> seeds(vertices_moved_in_step().begin(), vertices_moved_in_step().end());
    for (const ElementId t : elements_edited_in_step())
        if (mesh().is_element(t))
            for (const VertexId v : mesh().simplex(t).vertices()) seeds.push_back(v);
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    return m_services.simulation->relax_near(seeds, m_options.relax_iterations, m_options.local_vertices);
}

bool same_blade(const Scalpel& a, const Scalpel& b) { return a.handle == b.handle && a.tip == b.tip; }

Scalpel between(const Scalpel& from, const Scalpel& to, double s) {
    if (s == 1) return to;
    Scalpel pose;
    for (std::size_t k = 0; k < 3; ++k) {
        pose.handle[k] = from.handle[k] + s * (to.handle[k] - from.handle[k]);
        pose.tip[k] = from.tip[k] + s * (to.tip[k] - from.tip[k]);
    }
    return pose;
}

Outcome<std::unique_ptr<SnapCutSession>> SnapCutSession::make(Mesh& mesh, const Options& options,
                                                               const CutServices& services) {
    if (mesh.topological_dimension() != 3 || mesh.ambient_dimension() != 3)
        return Refusal{RefusalCode::not_applicable, "snapcut: the snap cutter cuts tetrahedral meshes in space"};
    if (auto checked = options.check(); !checked) return checked.refusal();
    return std::make_unique<SnapCutSession>(mesh, options, services);
}

SnapCutSession::SnapCutSession(Mesh& mesh, const Options& options, const CutServices& services)
    : ToolSession(mesh),
      m_options(options),
      m_services(services),
      m_index(mesh, Positions::deformed),
      m_track(std::make_unique<BladeTrack>(mesh)),
      m_moves(std::make_unique<MovedNodes>(mesh)),
      m_element_volume(mean_element_volume(mesh, Positions::reference)),
      m_split_beyond(options.split_beyond > 0
                         ? options.split_beyond * mean_edge_length(mesh, Positions::deformed)
                         : 0) {
    // the far field's rims are measured only for a session that relaxes them
    if (services.simulation != nullptr) services.simulation->follow_far_field(options.far_vertices > 0);
    // new logs, attached nowhere else: the marks and the scalpel go back and forth with the mesh
    (void)keep_beside(m_marks);
    (void)keep_beside(m_beside);
    m_beside.on_restore([this](const Beside&) { m_track->forget(); });  // the blade is elsewhere
}

SnapCutSession::~SnapCutSession() = default;

Outcome<StepReport> SnapCutSession::cut(const Scalpel& scalpel) {
    m_exact = scalpel;
    auto result = step(to_pose(scalpel));
    m_exact.reset();
    return result;
}

Outcome<StepReport> SnapCutSession::sweep(const Point& a, const Point& b, const Point& c) {
    m_swept = Sweep{a, b, c};
    m_exact = Scalpel{a, c};
    auto result = step(to_pose(*m_exact));
    m_exact.reset();
    m_swept.reset();
    return result;
}

Outcome<Done> SnapCutSession::apply(const ToolPose& pose, StepReport& report) {
    const auto start = Clock::now();
    const Scalpel next = m_exact ? *m_exact : scalpel_of(pose);
    for (const Point& p : {next.handle, next.tip, m_swept ? m_swept->b : next.tip})
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            return Refusal{RefusalCode::bad_argument, "snapcut: the scalpel's coordinates must be finite"};
    m_last = {};
    m_loose.clear();
    // a refusal below: the journal takes the mesh, the marks and the scalpel back together, and
    // the step's count, changed here, makes the blade track start over (m_beside.on_restore)
    ++m_beside.edit().steps;
    if (m_scalpel || m_swept) {
        // the movement's sweep: (h, t, t') then (h, t', h'), or sweep()'s triangle alone; a
        // sweep with collinear corners (the scalpel stood still, or slid along itself) sweeps no
        // area and is skipped
        std::vector<Sweep> sweeps;
        std::vector<BladeMove> blades;
        if (m_swept) {
            sweeps.push_back(*m_swept);
            m_track->forget();  // a triangle from anywhere: nothing to follow
        } else {
            const Scalpel& was = *m_scalpel;
            const Scalpel turned{was.handle, next.tip};
            sweeps = {Sweep{was.handle, was.tip, next.tip}, Sweep{was.handle, next.tip, next.handle}};
            blades = {BladeMove{was, turned}, BladeMove{turned, next}};
        }
        for (std::size_t i = 0; i < sweeps.size(); ++i) {
            const Sweep& sweep = sweeps[i];
            const BladeMove* blade = blades.empty() ? nullptr : &blades[i];
            if (collinear(sweep.a, sweep.b, sweep.c)) {
                // no area swept; but a blade that slid along itself may lie in other elements
                if (blade != nullptr && !same_blade(blade->from, blade->to)) m_track->forget();
                continue;
            }
            if (Outcome<Done> done = cut_sweep(sweep, std::span<const Sweep>(sweeps).subspan(i + 1), blade, report);
                !done) {
                m_seeds.clear();
                m_cut_pairs.clear();
                m_last.seconds = seconds_since(start);
                return done.refusal();
            }
        }
        if (Outcome<Done> settled = settle_loose_pieces(); !settled) {
            m_last.seconds = seconds_since(start);
            return settled.refusal();
        }
    } else {
        report.actions.push_back("placed the scalpel");
    }
    relax(report);
    m_scalpel = next;
    m_last.elements = mesh().element_count();
    m_last.vertices = mesh().vertex_count();
    m_last.incomplete = m_marks.incomplete().size();
    m_last.seconds = seconds_since(start);
    return Done{};
}

Outcome<Done> SnapCutSession::cut_sweep(const Sweep& sweep, std::span<const Sweep> ahead, const BladeMove* blade,
                                        StepReport& report) {
    ++m_last.sweeps;
    const std::uint32_t sweep_index = m_marks.add_sweep(sweep);
    // The degeneracy removal's collapses replace edges, and with them the marks of the sweeps
    // that crossed them: the tetrahedra at the rim of the incision lose what would connect it to
    // the next sweep (thesis §3.3, Fig. 3.17: disconnected incisions). The new edges take the
    // marks of the sweeps that cross them (CutMarks::mark_from_earlier_sweeps, and the copies of
    // a dissection those of their originals), and as the thesis proposes the sweep is then
    // processed again: what the new marks and the new edges it crosses complete is cut. When only
    // marks were carried over (a dissection's copies, no removal edit), the next round selects
    // among the elements they may have completed alone: the rest of the sweep did not change.
    // Twice more at most (what is left waits for the next sweep); a round that selects nothing,
    // edits nothing and carries no mark over ends it.
    bool whole_sweep = true;
    for (int round = 0; round < 3; ++round) {
        bool edited = false;
        if (Outcome<Done> done = cut_round(sweep_index, ahead, blade, whole_sweep, report, edited); !done)
            return done;
        if (edited) {
            whole_sweep = true;
            ++m_last.repeats;
        } else if (m_marks.pending().empty()) {
            break;
        } else {
            whole_sweep = false;
        }
    }
    return Done{};
}

SweptElements SnapCutSession::elements_met(std::uint32_t sweep_index, const BladeMove* blade) {
    const Mesh& mesh = this->mesh();
    const Sweep sweep = m_marks.sweeps()[sweep_index];
    // The selection sees snapped nodes where they were before the cut moved them, the index and
    // the track where they are: an element may meet the sweep only as the selection sees it, and
    // then it has a snapped corner within reach of the sweep (CutMarks::elements_near: those the
    // sweep meets; the selection looks at the others when they change, CutMarks::look_again).
    if (!m_options.follow_blade) blade = nullptr;
    // what the sweep meets, less the elements the blade it starts from lies in: roots below
    const bool from_followed = blade != nullptr && m_track->follows(blade->from);
    std::vector<ElementId> met =
        m_marks.elements_near(mesh, sweep, from_followed ? std::span<const ElementId>(m_track->inside())
                                                         : std::span<const ElementId>());
    if (blade != nullptr && (from_followed || m_track->follows(blade->to))) {
        // the first round of a followed sweep, or a later round (the sweep again, and the
        // elements the last one's edits made)
        std::vector<ElementId> roots = from_followed
                                           ? m_track->roots(m_index, m_marks, blade->from, blade->to, sweep)
                                           : m_track->roots_again(mesh, m_marks, sweep);
        roots.insert(roots.end(), met.begin(), met.end());
        SweptElements closed = close_over_crossed_edges(mesh, m_marks, sweep, roots);  // sorted, each once
        m_track->set_met(closed.elements);
        return closed;
    }
    if (blade != nullptr) m_track->start(blade->to);
    const std::vector<ElementId> hits =
        m_index.elements_hit_by_triangle(sweep.a, sweep.b, sweep.c, TriangleHitsOf::elements).elements;
    met.insert(met.end(), hits.begin(), hits.end());
    std::sort(met.begin(), met.end());
    met.erase(std::unique(met.begin(), met.end()), met.end());
    if (blade != nullptr) m_track->set_met(met);
    return {std::move(met), {}};
}

Outcome<Done> SnapCutSession::cut_round(std::uint32_t sweep_index, std::span<const Sweep> ahead,
                                        const BladeMove* blade, bool whole_sweep, StepReport& report, bool& edited) {
    Mesh& mesh = this->mesh();

    // 1. select (§3.2.1) among the elements the sweep meets (face_selection.hpp: they include
    // every incomplete tetrahedron this sweep can complete)
    auto phase = Clock::now();
    m_moves->cover(mesh, m_marks);
    const std::size_t edited_at_start = elements_edited_in_step().size();
    std::vector<ElementId> candidates;
    MissedEdges missed;                 // edges the following found the sweep does not cross
    std::vector<ElementId> incomplete;  // the sweep's, kept by a partial round
    if (whole_sweep) {
        SweptElements met = elements_met(sweep_index, blade);
        candidates = std::move(met.elements);
        missed = std::move(met.missed);
    } else {
        incomplete = m_marks.incomplete();
    }
    // and the elements whose edges took marks over from the last round's edits, whose corners
    // were snapped or that edits made (they may be complete now, wherever the sweep is)
    const std::vector<ElementId> pending = m_marks.take_pending();
    candidates.insert(candidates.end(), pending.begin(), pending.end());
    const std::vector<ElementId> look_again = m_marks.take_look_again();
    candidates.insert(candidates.end(), look_again.begin(), look_again.end());
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    // crossed edges whose nearer end is far from where the blade has swept get a node of their
    // own where crossed (split_far_crossings.hpp)
    const SweptSurface swept{m_marks, ahead, m_split_beyond};
    const bool far_rules = m_split_beyond > 0 && m_options.snap;
    if (far_rules) {
        const FarCrossings far = split_far_crossings(mesh, m_marks, sweep_index, swept, candidates);
        m_last.edges_split += far.split;
        m_last.edges_hit += far.split;  // crossed, and marked by the split rather than the selection
        m_last.splits_refused += far.refused;
        if (far.split > 0) report.actions.push_back("split " + std::to_string(far.split) + " far crossings");
    }
    const Selection selection =
        select_faces(mesh, m_marks, sweep_index, candidates, far_rules ? &swept : nullptr, std::move(missed));
    // what the blade now lies in, for the next sweep, of what the sweep met (the elements the
    // far crossings' splits made come to the track as fresh ones)
    if (whole_sweep) m_track->settle(mesh, m_marks);
    if (!whole_sweep) {
        std::vector<ElementId> merged;
        std::set_union(incomplete.begin(), incomplete.end(), m_marks.incomplete().begin(), m_marks.incomplete().end(),
                       std::back_inserter(merged));
        std::erase_if(merged, [&](ElementId t) { return !mesh.is_element(t); });
        m_marks.set_incomplete(std::move(merged));
    }
    m_last.elements_searched += selection.elements_searched;
    m_last.edges_hit += selection.edges_hit;
    m_last.faces_selected += selection.faces.size();
    m_last.seconds_select += seconds_since(phase);
    if (selection.faces.empty()) return Done{};

    // 2. snap (§3.2.2) the corners not snapped before, each to the plane of the first sweep that
    // marked it
    phase = Clock::now();
    std::vector<NodeToSnap> nodes;
    std::vector<Simplex> faces;
    for (const SelectedFace& face : selection.faces) {
        faces.push_back(face.face);
        for (int j = 0; j < 3; ++j)
            if (!m_marks.snapped(face.face.vertex(j)))
                nodes.push_back({face.face.vertex(j), face.sweep[static_cast<std::size_t>(j)]});
    }
    std::sort(nodes.begin(), nodes.end(), [](const NodeToSnap& x, const NodeToSnap& y) {
        return x.node != y.node ? x.node < y.node : x.sweep < y.sweep;
    });
    nodes.erase(std::unique(nodes.begin(), nodes.end(),
                            [](const NodeToSnap& x, const NodeToSnap& y) { return x.node == y.node; }),
                nodes.end());
    std::vector<VertexId> touched;  // whose stars the degeneracy removal looks at
    if (m_options.snap) {
        m_track->watch_moves(false);  // the selection, and the track, see snapped nodes where they were
        SnapResult snapped = snap_nodes(mesh, nodes, m_marks.sweeps(), m_options.min_snap_aspect_ratio);
        m_track->watch_moves(true);
        for (std::size_t i = 0; i < snapped.snapped.size(); ++i)
            m_marks.add_snapped(mesh, snapped.snapped[i], snapped.snapped_from[i]);
        m_last.nodes_snapped += snapped.snapped.size();
        m_last.nodes_partly_snapped += snapped.partly;
        m_last.nodes_refused += snapped.refused.size();
        touched = snapped.snapped;
        for (auto& refusal : snapped.refused) m_last.refusals.push_back(std::move(refusal));
        report.actions.push_back("snapped " + std::to_string(snapped.snapped.size()) + " nodes, refused " +
                                 std::to_string(snapped.refused.size()));
    }
    std::vector<VertexId> corners;
    for (const Simplex& face : faces) corners.insert(corners.end(), face.vertices().begin(), face.vertices().end());
    note_distances(std::move(corners), sweep_index, ahead, m_last.placement_error, m_last.placement_error_local);
    m_last.seconds_snap += seconds_since(phase);

    // 3. dissect (§7.3). A selected face opens only once the faces around its corners separate
    // their stars (at the rim of the incision they do not yet: the selection lags, Fig. 3.4), so
    // the selected faces carry the cut label from now on, and each sweep dissects every labelled
    // interior face around the corners of its own: those it selected, and those earlier sweeps
    // selected that could not open then.
    phase = Clock::now();
    for (const Simplex& face : faces)
        if (!mesh.face_label(face)) mesh.set_face_label(face, m_options.cut_label);
    std::vector<Simplex> cut = labelled_faces_around(mesh, faces, m_options.cut_label);
    cut = keep_crumbs_attached(mesh, std::move(cut), m_options.largest_crumb, &m_marks);
    auto dissected = dissect(mesh, cut, DissectOptions{m_options.cut_label});
    if (!dissected) return dissected.refusal().prefixed("snapcut: ");
    const std::size_t opened = dissected->opened.size() / 2;
    m_last.faces_dissected += opened;
    m_marks.carry_to_copies(mesh, dissected->new_vertices);
    m_cut_pairs.insert(m_cut_pairs.end(), dissected->new_vertices.begin(), dissected->new_vertices.end());
    for (const auto& [original, copy] : dissected->new_vertices) {
        touched.push_back(original);
        touched.push_back(copy);
        if (m_marks.snapped(original)) m_marks.add_snapped(mesh, copy, m_marks.selection_position(mesh, original));
    }
    corners.clear();
    for (const FaceId f : dissected->opened) {
        const Simplex face = mesh.face_simplex(f);  // by value: a range over a temporary's span dangles
        corners.insert(corners.end(), face.vertices().begin(), face.vertices().end());
    }
    note_distances(std::move(corners), sweep_index, ahead, m_last.incision_error, m_last.incision_error_local);
    report.actions.push_back("dissected " + std::to_string(opened) + " faces, " +
                             std::to_string(dissected->new_vertices.size()) + " new nodes");
    m_last.seconds_dissect += seconds_since(phase);

    // 4. degeneracy removal (§3.2.3) among the elements around what moved or split
    phase = Clock::now();
    if (m_options.remove_degeneracies && m_services.degeneracy != nullptr && !touched.empty()) {
        degeneracy::Options removal;
        removal.aspect_ratio = m_options.aspect_ratio;
        removal.large_angle = m_options.large_angle;
        const std::vector<ElementId> around = stars_of(mesh, touched);
        const std::size_t edited_before = elements_edited_in_step().size();
        auto removed = m_services.degeneracy->remove_among(mesh, around, removal);
        if (!removed) return removed.refusal().prefixed("snapcut: degeneracy removal: ");
        const std::span<const ElementId> remade = elements_edited_in_step().subspan(edited_before);
        m_marks.mark_from_earlier_sweeps(mesh, remade, far_rules ? &swept : nullptr);
        // a collapse moves a node of the cut faces around it: measured again where the removal
        // left them (a corner the session had measured at 0.447 h ended at 0.785 h: docs/snapcut.md
        // "What is not done yet")
        corners.clear();
        for (const ElementId t : remade) {
            if (!mesh.is_element(t)) continue;
            for (int i = 0; i < mesh.element_vertex_count(); ++i) {
                const FaceId f = mesh.face(t, i);
                if (mesh.mate(f) != invalid_id) continue;
                const Simplex face = mesh.face_simplex(f);
                if (mesh.face_label(face) != m_options.cut_label) continue;
                corners.insert(corners.end(), face.vertices().begin(), face.vertices().end());
            }
        }
        note_distances(std::move(corners), sweep_index, ahead, m_last.incision_error, m_last.incision_error_local);
        m_last.degeneracy_removal_ran = true;
        m_last.degenerates_found += removed->found;
        m_last.collapses += removed->collapses;
        m_last.splits += removed->splits;
        m_last.flips += removed->flips;
        m_last.peeled += removed->peeled;
        m_last.cut_free += removed->cut_free;
        m_last.degenerates_remaining = removed->remaining;
        edited = removed->collapses + removed->splits + removed->flips + removed->peeled + removed->cut_free > 0;
        report.actions.push_back(std::to_string(removed->found) + " degenerate, " +
                                 std::to_string(removed->collapses) + " collapses, " +
                                 std::to_string(removed->cut_free) + " cut free");
    }
    m_last.seconds_degeneracy += seconds_since(phase);

    // 5. both sides of the new cut faces: where the step's loose pieces are looked for
    phase = Clock::now();
    const std::vector<ElementId> seeds = stars_of(mesh, touched);
    m_seeds.insert(m_seeds.end(), seeds.begin(), seeds.end());
    // which the next selection looks at again, with what this round's edits made
    m_marks.look_again(seeds);
    m_marks.look_again(elements_edited_in_step().subspan(edited_at_start));
    // the round's edits (the removal's collapses above all) may make a snapped node's star reach
    // farther
    m_marks.cover_elements(mesh, elements_edited_in_step().subspan(edited_at_start));
    for (const FaceId f : dissected->opened)
        if (mesh.is_face(f)) m_seeds.push_back(mesh.face_element(f));
    m_last.seconds_pieces += seconds_since(phase);
    return Done{};
}

bool SnapCutSession::crumb(std::span<const ElementId> piece) const {
    if (piece.size() * 100 >= mesh().element_count()) return false;
    const double most = double(m_options.largest_crumb) * m_element_volume;
    double material = 0;
    for (const ElementId t : piece)
        if ((material += element_volume(mesh(), t, Positions::reference)) > most) return false;
    return true;
}

Outcome<Done> SnapCutSession::settle_loose_pieces() {
    // Looked for once per step, after every round of every sweep: a later round that cuts near a
    // piece an earlier one separated would otherwise find it again (the thesis' cube cut in one
    // step reported its loose half twice), and the removal's later edits change the pieces'
    // elements. The seeds of earlier rounds the removal replaced are dead (skipped) or reused
    // elsewhere along the cut (a seed too many costs a search at most); the elements the removal
    // made are seeds too, since they replaced some.
    const auto start = Clock::now();
    Mesh& mesh = this->mesh();
    std::vector<ElementId> seeds = std::exchange(m_seeds, {});
    if (!seeds.empty()) {
        const std::span<const ElementId> edited = elements_edited_in_step();
        seeds.insert(seeds.end(), edited.begin(), edited.end());
    }
    const std::vector<std::pair<VertexId, VertexId>> cut_pairs = std::exchange(m_cut_pairs, {});
    LoosePieces pieces = find_loose_pieces(mesh, seeds, cut_pairs);
    for (auto& piece : pieces.pieces) {
        // a crumb the dissection could not keep attached, or a layer of flat elements along the
        // cut (its corners on the cut, and faces selected from both sides) is cut free, as the
        // thesis' degeneracy removal cuts free flat elements (§3.3)
        const bool crumb = this->crumb(piece);
        if (crumb) m_last.cut_free += piece.size();
        else m_last.loose_pieces.push_back(piece.size());
        if (crumb || m_options.remove_loose_pieces) {
            if (Outcome<Done> removed = remove_elements(mesh, piece); !removed)
                return removed.refusal().prefixed("snapcut: removing a loose piece: ");
        } else {
            m_loose.push_back(std::move(piece));
        }
    }
    std::sort(m_last.loose_pieces.begin(), m_last.loose_pieces.end());
    m_last.seconds_pieces += seconds_since(start);
    return Done{};
}

}  // namespace sxk::snapcut
