// The needle's session: the interaction loop of thesis §6.7 as one tool step per movement
// (needle.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <unordered_set>

#include <Eigen/Geometry>

#include "friction.hpp"
#include "interception.hpp"
#include "needle.hpp"
#include "needle_frame.hpp"
#include "shaft_refinement.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::needle {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

bool finite(const Point& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

Vector3 vector3(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

Outcome<Done> check_options(const Mesh& mesh, const Options& options) {
    const bool planar = mesh.topological_dimension() == 2 && mesh.ambient_dimension() == 2;
    const bool solid = mesh.topological_dimension() == 3 && mesh.ambient_dimension() == 3;
    if (!planar && !solid)
        return Refusal{RefusalCode::wrong_dimension,
                       "needle: needs a triangle mesh in the plane or a tetrahedral mesh (this one has " +
                           std::to_string(mesh.topological_dimension()) + "-simplices in " +
                           std::to_string(mesh.ambient_dimension()) + "D)"};
    if (mesh.element_count() == 0) return Refusal{RefusalCode::bad_argument, "needle: the mesh has no element"};
    return options.check();
}

}  // namespace

ToolPose NeedleSession::pose_of(const Needle& needle) {
    const Frame frame(needle);
    ToolPose pose;
    pose.position = needle.tip;
    pose.axes[2] = point(frame.axis);
    // any two unit vectors completing the frame (the needle is round)
    const Eigen::Vector3d x = frame.axis.unitOrthogonal();
    pose.axes[0] = point(x);
    pose.axes[1] = point(frame.axis.cross(x));
    pose.length = frame.length;
    return pose;
}

Outcome<std::unique_ptr<NeedleSession>> NeedleSession::make(Mesh& mesh, const Options& options,
                                                            Simulation* simulation) {
    if (auto checked = check_options(mesh, options); !checked) return checked.refusal();
    std::unique_ptr<NeedleSession> session(new NeedleSession(mesh, options, simulation));
    if (mesh.topological_dimension() == 3) {
        auto marked = TetBisection::for_kuhn_mesh(mesh);
        if (!marked) marked = TetBisection::with_amp_marking(mesh);
        if (!marked) return marked.refusal().prefixed("needle: ");
        session->m_bisection = std::make_unique<TetBisection>(std::move(*marked));
        (void)session->keep_beside(*session->m_bisection);  // a new log, attached nowhere else
    }
    (void)session->keep_beside(session->m_beside);
    session->m_beside.on_restore([raw = session.get()](const State& replaced) { raw->follow(replaced); });
    session->m_say_geometry_only = simulation == nullptr;
    return session;
}

NeedleSession::NeedleSession(Mesh& mesh, const Options& options, Simulation* simulation)
    : ToolSession(mesh),
      m_options(options),
      m_simulation(simulation),
      m_reference_index(std::make_unique<SpatialIndex>(mesh, Positions::reference)),
      m_deformed_index(std::make_unique<SpatialIndex>(mesh, Positions::deformed)) {
    // the far field's rims are measured only for a session that relaxes them
    if (simulation != nullptr) simulation->follow_far_field(options.far_vertices > 0);
}

NeedleSession::~NeedleSession() = default;

Outcome<NeedleStepReport> NeedleSession::move(const Needle& needle) {
    if (!finite(needle.base) || !finite(needle.tip))
        return Refusal{RefusalCode::bad_argument, "needle: a coordinate of the needle is not a finite number"};
    if (needle.base == needle.tip)
        return Refusal{RefusalCode::bad_argument, "needle: the needle has zero length (base = tip)"};
    if (auto stepped = step(pose_of(needle)); !stepped) return stepped.refusal();
    return m_last;
}

Outcome<NeedleStepReport> NeedleSession::settle(std::size_t iterations) {
    if (!m_state.needle) return Refusal{RefusalCode::not_applicable, "needle: settle: the needle has not been placed"};
    if (iterations == 0) return Refusal{RefusalCode::bad_argument, "needle: settle: iterations must be >= 1"};
    m_settle = iterations;
    const auto stepped = step(pose_of(*m_state.needle));
    m_settle = 0;
    if (!stepped) return stepped.refusal();
    return m_last;
}

Outcome<Done> NeedleSession::apply(const ToolPose& pose, StepReport& report) {
    Needle needle;
    needle.tip = pose.position;
    needle.base = point(vec(pose.position) - pose.length * vec(pose.axes[2]));
    if (mesh().ambient_dimension() == 2) needle.base[2] = needle.tip[2] = 0;
    if (!finite(needle.base) || !finite(needle.tip) || !(pose.length > 0))
        return Refusal{RefusalCode::bad_argument, "needle: the pose is not a needle (length > 0, finite)"};
    // a refusal: the journal takes the mesh, the marks and the state back together (follow(),
    // when the state changed); the body, which the step may have solved even so, reads its
    // displacements from the mesh before the next step
    Outcome<Done> stepped = step_to(needle, report);
    if (!stepped) m_resync = true;
    return stepped;
}

Outcome<Done> NeedleSession::hold(const NeedleNode& node, const Needle& needle) {
    if (m_simulation == nullptr) return Done{};
    const Frame frame(needle);
    const Eigen::Vector3d target = vec(frame.place(node.along, node.perp));
    const Vector3 displacement = vector3(target - vec(mesh().reference(node.vertex)));
    if (node.grip == Grip::stick) {
        if (auto held = m_simulation->hold(node.vertex, displacement); !held) return held;
        return m_simulation->set_tool_force(node.vertex, {0, 0, 0});
    }
    if (auto held = m_simulation->hold_on_line(node.vertex, vector3(frame.axis), displacement); !held) return held;
    return m_simulation->set_tool_force(node.vertex, vector3(node.sense * node.threshold * frame.axis));
}

bool NeedleSession::relocate(VertexId v, const Point& offset) {
    Mesh& mesh = this->mesh();
    const Eigen::Vector3d shift = vec(offset);
    // thesis §6.4: "node relocation can easily lead to flattened elements": no element around v
    // may lose more than half its aspect ratio (reference positions), or CG stalls on it
    for (const ElementId t : star(mesh, v)) {
        std::vector<Point> corners = element_points(mesh, t, Positions::reference);
        const double before = aspect_ratio(corners);
        const Simplex element = mesh.simplex(t);
        corners[element.index(v)] = point(vec(mesh.reference(v)) - shift);
        if (aspect_ratio(corners) < 0.5 * before) return false;
    }
    const VertexId moved[] = {v};
    const MoveCheck check{.refuse_inverted = true, .refuse_flat = true};
    const Point was = mesh.reference(v);
    const Point reference[] = {point(vec(was) - shift)};
    if (!mesh.move_vertices(moved, reference, PositionSet::reference, check)) return false;
    const Point deformed[] = {point(vec(mesh.deformed(v)) - shift)};
    if (!mesh.move_vertices(moved, deformed, PositionSet::deformed, check)) {
        const Point back[] = {was};
        (void)mesh.move_vertices(moved, back, PositionSet::reference);
        return false;
    }
    return true;
}

void NeedleSession::follow(const State& replaced) {
    if (m_simulation != nullptr) {
        for (const NeedleNode& node : replaced.nodes) {
            const bool kept = std::any_of(m_state.nodes.begin(), m_state.nodes.end(),
                                          [&](const NeedleNode& n) { return n.vertex == node.vertex; });
            if (kept) continue;
            // a vertex the undo removed is no longer the body's: nothing to release
            (void)m_simulation->release(node.vertex);
            (void)m_simulation->set_tool_force(node.vertex, {0, 0, 0});
        }
    }
    // the mesh was just put back: the body reads its displacements from the mesh before the next
    // step, and holds the nodes as they were
    m_resync = true;
    if (m_simulation != nullptr && m_state.needle)
        for (const NeedleNode& node : m_state.nodes) (void)hold(node, *m_state.needle);
}

Outcome<Done> NeedleSession::step_to(const Needle& needle, StepReport& words) {
    const auto start = Clock::now();
    NeedleStepReport report;
    Mesh& mesh = this->mesh();
    if (m_resync && m_simulation != nullptr) {
        if (auto synced = m_simulation->displacements_from_mesh(); !synced) return synced;
        m_resync = false;
    }
    const Needle old = m_state.needle.value_or(needle);
    const Frame from(old), to(needle);
    std::vector<NeedleNode>& nodes = m_state.nodes;
    // where a node is now: the body's solution (the mesh shows it only when it inverts nothing)
    auto position = [&](VertexId v) {
        if (m_simulation == nullptr) return mesh.deformed(v);
        const Vector3 u = m_simulation->displacement(v);
        const Point& x = mesh.reference(v);
        return Point{x[0] + u[0], x[1] + u[1], x[2] + u[2]};
    };

    // 1. move the needle: sticking nodes keep their needle coordinates, slipping ones stay where
    // they are along the needle (their line turns and shifts with it)
    std::vector<double> along_before(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        NeedleNode& node = nodes[i];
        along_before[i] = node.along;
        node.perp = turned(node.perp, from, to);
        if (node.grip == Grip::slip || m_simulation == nullptr) node.along = to.along(position(node.vertex));
        if (m_simulation == nullptr) node.perp = to.perp(position(node.vertex));
    }

    // 2. refine around the tip's path
    auto phase = Clock::now();
    auto refined = refine_along(mesh, *m_reference_index, *m_deformed_index, old.tip, needle.tip, m_options.h_ref,
                                m_state.tip_element, m_bisection.get(), {m_options.radius, point(to.axis)});
    if (!refined) return refined.refusal().prefixed("needle: refinement: ");
    report.bisections = refined->bisections;
    m_state.tip_element = refined->tip_element;
    report.tip_inside = refined->tip_element != invalid_id;
    report.refine_seconds = seconds_since(phase);

    // 3. intercept the nodes of the edges (faces) the tip crossed, and with a radius those the
    // needle's cross-section passed over
    phase = Clock::now();
    if (old.tip != needle.tip) {
        std::vector<VertexId> entered = intercepted_nodes(mesh, *m_deformed_index, old.tip, needle.tip);
        if (m_options.radius > 0) {
            const std::vector<VertexId> within =
                nodes_within_radius(mesh, *m_deformed_index, old.tip, needle.tip, point(to.axis), m_options.radius);
            const std::size_t crossed = entered.size();
            entered.insert(entered.end(), within.begin(), within.end());
            std::inplace_merge(entered.begin(), entered.begin() + static_cast<std::ptrdiff_t>(crossed), entered.end());
            entered.erase(std::unique(entered.begin(), entered.end()), entered.end());
        }
        // which vertices are needle nodes already: a set, not a scan of the nodes per vertex entered
        // (with a radius across the whole body both grow to tens of thousands; the scan made
        // `--radius 0.05 --h-ref 5e-4` on the 0.1 m slab take 346 s, issue 47)
        std::unordered_set<VertexId> held_already;
        held_already.reserve(nodes.size() + entered.size());
        for (const NeedleNode& n : nodes) held_already.insert(n.vertex);
        for (const VertexId v : entered) {
            if (held_already.count(v)) continue;
            const Point x = position(v);
            NeedleNode node;
            node.vertex = v;
            node.along = node.entered = to.along(x);
            node.perp = to.perp(x);
            // a vertex the body's options hold (a fixed side) stays theirs
            if (auto held = hold(node, needle); !held) {
                if (held.refusal().code == RefusalCode::bad_argument) continue;
                return held.refusal().prefixed("needle: ");
            }
            // onto the needle: the axis, or with a radius its surface (a node inside stays)
            const Eigen::Vector3d perp = vec(node.perp);
            const double off = perp.norm();
            const Eigen::Vector3d shift =
                off > m_options.radius ? Eigen::Vector3d((1 - m_options.radius / off) * perp) : Eigen::Vector3d::Zero();
            if (m_options.relocate && shift != Eigen::Vector3d::Zero()) {
                if (relocate(v, point(shift))) {
                    node.perp = point(perp - shift);
                    ++report.relocated;
                } else {
                    ++report.not_relocated;
                }
            }
            nodes.push_back(node);
            held_already.insert(v);
            ++report.intercepted;
        }
    }
    // a node intercepted now starts where it is
    for (std::size_t i = along_before.size(); i < nodes.size(); ++i) along_before.push_back(nodes[i].along);
    share_thresholds(nodes, m_options.friction, m_options.h_ref);
    for (const NeedleNode& node : nodes)
        if (auto held = hold(node, needle); !held) return held.refusal().prefixed("needle: ");
    report.intercept_seconds = seconds_since(phase);

    // 4. solve, 5. rearrange the nodes' grips (at most `rearrangements` times)
    phase = Clock::now();
    Eigen::Vector3d needle_force = Eigen::Vector3d::Zero();
    if (m_simulation != nullptr) {
        std::vector<VertexId> vertices(nodes.size());
        for (std::size_t i = 0; i < nodes.size(); ++i) vertices[i] = nodes[i].vertex;
        // a local solve has nothing to do before a node is held: the body is as the last step left it
        const bool local = m_options.local_vertices > 0 && m_settle == 0;
        const std::size_t iterations = m_settle > 0 ? m_settle : m_options.iterations;
        for (std::size_t round = 0; round < m_options.rearrangements && !(local && nodes.empty()); ++round) {
            auto relaxed = local ? m_simulation->relax_near(vertices, iterations, m_options.local_vertices)
                                 : m_simulation->relax(iterations);
            if (!relaxed) return relaxed.refusal().prefixed("needle: ");
            ++report.solves;
            report.iterations += relaxed->iterations;
            report.solved_vertices =
                relaxed->region_vertices > 0 ? relaxed->region_vertices : mesh.vertices_in_elements();
            report.converged = report.converged && relaxed->converged;
            report.shown = relaxed->shown;
            if (nodes.empty()) break;
            auto forces = m_simulation->forces_at(vertices);
            if (!forces) return forces.refusal().prefixed("needle: ");
            needle_force.setZero();
            std::vector<std::size_t> changed;  // nodes whose grip changed: held anew
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                NeedleNode& node = nodes[i];
                const auto& f = (*forces)[i];
                // what the needle exerts on the node: the constraint's reaction, and its friction
                const Eigen::Vector3d reaction = -(vec(f.elastic) + vec(f.loaded));
                const Eigen::Vector3d friction =
                    node.grip == Grip::slip ? Eigen::Vector3d(node.sense * node.threshold * to.axis)
                                            : Eigen::Vector3d::Zero();
                needle_force += reaction + friction;
                node.axial = (reaction + friction).dot(to.axis);
                const double along_now = to.along(position(node.vertex));
                if (node.grip == Grip::stick) {
                    const double axial = reaction.dot(to.axis);
                    if (std::abs(axial) > m_options.friction.static_ratio * node.threshold) {
                        node.grip = Grip::slip;
                        node.sense = axial > 0 ? 1 : -1;
                        ++report.loosened;
                        changed.push_back(i);
                    }
                } else {
                    // kinetic friction acts while the needle slides past the node in its sense;
                    // when it no longer does (the needle stopped or turned back, or the node caught
                    // up: slid less than a thousandth of h_ref, the solver's noise), the node
                    // sticks again (docs/needle.md "Friction")
                    node.along = along_now;
                    const double slid = along_before[i] - along_now;
                    if (node.sense * slid <= 1e-3 * m_options.h_ref) {
                        node.grip = Grip::stick;
                        node.sense = 0;
                        ++report.gripped;
                        changed.push_back(i);
                    }
                }
            }
            if (changed.empty()) break;
            for (const std::size_t i : changed)
                if (auto held = hold(nodes[i], needle); !held) return held.refusal().prefixed("needle: ");
            for (std::size_t i = 0; i < nodes.size(); ++i) along_before[i] = nodes[i].along;
        }
        if (local && m_options.far_vertices > 0) {
            auto far = m_simulation->relax_far(iterations, m_options.far_vertices);
            if (!far) return far.refusal().prefixed("needle: ");
            report.iterations += far->iterations;
            report.far_vertices = far->region_vertices;
        }
    }
    report.solve_seconds = seconds_since(phase);

    // 6. release the nodes that slid off: the tip drawn back past them, or beyond the base
    std::size_t kept = 0;
    for (NeedleNode& node : nodes) {
        const bool off = node.along > std::max(node.entered, 0.0) || node.along < -to.length;
        if (off && (node.grip == Grip::slip || m_simulation == nullptr)) {
            if (m_simulation != nullptr) {
                if (auto released = m_simulation->release(node.vertex); !released)
                    return released.refusal().prefixed("needle: ");
                if (auto unloaded = m_simulation->set_tool_force(node.vertex, {0, 0, 0}); !unloaded)
                    return unloaded.refusal().prefixed("needle: ");
            }
            ++report.released;
            continue;
        }
        nodes[kept++] = node;
    }
    nodes.resize(kept);
    if (report.released > 0) share_thresholds(nodes, m_options.friction, m_options.h_ref);

    m_state.needle = needle;
    for (const NeedleNode& node : nodes) (node.grip == Grip::stick ? report.stick : report.slip) += 1;
    report.axial_force = needle_force.dot(to.axis);
    report.lateral_force = (needle_force - report.axial_force * to.axis).norm();
    report.elements = mesh.element_count();
    report.vertices = mesh.vertices_in_elements();
    report.seconds = seconds_since(start);
    if (m_say_geometry_only) {
        words.actions.push_back("geometry only: no elastic body (no simulation given to the session, or no "
                                "--deform): nothing follows the needle");
        m_say_geometry_only = false;
    }
    if (report.bisections > 0) words.actions.push_back("bisected " + std::to_string(report.bisections) + " edges");
    if (report.intercepted > 0)
        words.actions.push_back("intercepted " + std::to_string(report.intercepted) + " needle nodes");
    if (report.loosened + report.gripped > 0)
        words.actions.push_back("rearranged " + std::to_string(report.loosened) + " to slip, " +
                                std::to_string(report.gripped) + " to stick");
    if (report.released > 0) words.actions.push_back("released " + std::to_string(report.released) + " nodes");
    m_last = report;
    return Done{};
}

}  // namespace sxk::needle
