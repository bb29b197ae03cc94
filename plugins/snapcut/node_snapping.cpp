// Node snapping (node_snapping.hpp, thesis §3.2.2).
#include "node_snapping.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>

#include <Eigen/Dense>

#include "sxk/locate.hpp"
#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::snapcut {

namespace {

using Vec = Eigen::Vector3d;

Vec vec(const Point& p) { return {p[0], p[1], p[2]}; }
Point point(const Vec& v) { return {v.x(), v.y(), v.z()}; }

// A node that cannot go all the way to the sweep goes part of it, at least this fraction, or stays.
constexpr double min_partial_snap = 0.25;

// How far outside a face or element a projected point may be, in barycentric weight, and still
// count as inside: the rounding of the projection, not a geometric allowance.
constexpr double weight_slack = 1e-9;

struct Plane {
    Vec point, normal;
};

Plane plane_of(const Sweep& sweep) {
    return {vec(sweep.a), (vec(sweep.b) - vec(sweep.a)).cross(vec(sweep.c) - vec(sweep.a))};
}

// The point nearest x on the line where the planes meet, or none when they are (nearly) parallel.
std::optional<Vec> nearest_on_meeting_line(const Vec& x, const Plane& p, const Plane& q) {
    // y = x - alpha n - beta m with n.y = n.p0 and m.y = m.q0: a 2x2 system (the Gram matrix)
    const Vec& n = p.normal;
    const Vec& m = q.normal;
    Eigen::Matrix2d gram;
    gram << n.dot(n), n.dot(m), n.dot(m), m.dot(m);
    const double det = gram.determinant();
    if (!(det > 1e-12 * gram(0, 0) * gram(1, 1))) return std::nullopt;  // angle below ~1e-6 rad
    const Eigen::Vector2d rhs(n.dot(x - p.point), m.dot(x - q.point));
    const Eigen::Vector2d ab = gram.inverse() * rhs;
    return x - ab[0] * n - ab[1] * m;
}

// Barycentric weights of y (in the triangle's plane) in triangle (p0, p1, p2).
std::array<double, 3> triangle_weights(const Vec& y, const Vec& p0, const Vec& p1, const Vec& p2) {
    const Vec normal = (p1 - p0).cross(p2 - p0);
    const double twice_area = normal.squaredNorm();
    return {(p1 - y).cross(p2 - y).dot(normal) / twice_area, (p2 - y).cross(p0 - y).dot(normal) / twice_area,
            (p0 - y).cross(p1 - y).dot(normal) / twice_area};
}

// Barycentric weights of y in the tetrahedron (canonical corner order).
std::array<double, 4> tetrahedron_weights(const Vec& y, const std::array<Vec, 4>& p) {
    Eigen::Matrix3d edges;
    edges << p[0] - p[3], p[1] - p[3], p[2] - p[3];
    const Vec w = edges.fullPivLu().solve(y - p[3]);
    return {w[0], w[1], w[2], 1 - w[0] - w[1] - w[2]};
}

// Where an interior node x goes: the point nearest x on the sweeps next to sweep `marked_by` (the
// two before it, up to four after it, none after the last), the piece of the scalpel's swept
// surface where x's edge was crossed; or, when that point is on the blade where this step left
// it (the newest sweep's edge b-c), the projection of x onto `marked_by`'s plane, as in the
// thesis. On a blade that turned, a node projected onto the plane of its own sweep lands beyond
// the triangle, off the surface (1.44 h on the deformed femur, docs/snapcut.md "The femur"); a
// node ahead of the blade belongs where the blade is going, and nodes pulled back onto the blade
// line crowd there into flat elements whose collapses kept the cube of tests/plugins/
// snapcut_session_test.cpp from coming apart.
Vec target_on_sweeps(const Vec& x, const std::vector<Sweep>& sweeps, std::uint32_t marked_by) {
    const std::size_t first = marked_by >= 2 ? marked_by - 2 : 0;
    const std::size_t last = std::min<std::size_t>(sweeps.size() - 1, std::size_t{marked_by} + 4);
    Vec best = x;
    double best_distance = std::numeric_limits<double>::infinity();
    bool on_blade = false;
    for (std::size_t i = first; i <= last; ++i) {
        const Sweep& s = sweeps[i];
        const std::array<double, 3> w = nearest_on_triangle(s.a, s.b, s.c, point(x));
        const Vec y = w[0] * vec(s.a) + w[1] * vec(s.b) + w[2] * vec(s.c);
        const double distance = (y - x).squaredNorm();
        if (distance < best_distance) {
            best_distance = distance, best = y;
            on_blade = i + 1 == sweeps.size() && w[0] == 0;
        }
    }
    if (!on_blade) return best;
    const Plane plane = plane_of(sweeps[marked_by]);
    return x - (plane.normal.dot(x - plane.point) / plane.normal.squaredNorm()) * plane.normal;
}

// Where v may go in the deformed positions, best first (node_snapping.hpp), or why it cannot go
// anywhere.
std::vector<Vec> targets_of(const Mesh& mesh, VertexId v, const std::vector<ElementId>& star_v,
                            const CutMarks& marks, std::uint32_t marked_by, std::string& why) {
    const std::vector<Sweep>& sweeps = marks.sweeps();
    const Plane sweep = plane_of(sweeps[marked_by]);
    const Vec x = vec(mesh.deformed(v));
    std::optional<Vec> best;
    double best_distance = std::numeric_limits<double>::infinity();
    bool on_boundary = false;
    std::vector<VertexId> along;  // the other ends of the edges v may slide along
    for (const ElementId t : star_v)
        for (int i = 0; i < 4; ++i) {
            const FaceId f = mesh.face(t, i);
            if (mesh.mate(f) != invalid_id) continue;
            const Simplex face = mesh.face_simplex(f);
            if (!face.contains(v)) continue;
            on_boundary = true;
            const Vec p0 = vec(mesh.deformed(face.vertex(0))), p1 = vec(mesh.deformed(face.vertex(1))),
                      p2 = vec(mesh.deformed(face.vertex(2)));
            const Plane face_plane{p0, (p1 - p0).cross(p2 - p0)};
            const std::optional<Vec> y = nearest_on_meeting_line(x, sweep, face_plane);
            if (!y) continue;
            const std::array<double, 3> w = triangle_weights(*y, p0, p1, p2);
            if (*std::min_element(w.begin(), w.end()) < -weight_slack) continue;
            const double distance = (*y - x).norm();
            if (distance < best_distance) best_distance = distance, best = *y;
        }
    std::vector<Vec> targets;
    if (on_boundary) {
        if (best) targets.push_back(*best);
    } else {
        targets.push_back(target_on_sweeps(x, sweeps, marked_by));
        const Vec on_plane = x - (sweep.normal.dot(x - sweep.point) / sweep.normal.squaredNorm()) * sweep.normal;
        if (on_plane != targets.front()) targets.push_back(on_plane);
        for (const ElementId t : star_v)
            for (const VertexId w : mesh.simplex(t).vertices())
                if (w != v) along.push_back(w);
    }
    // An interior node may also go where the sweeps cross the edges that marked it: moving along
    // an edge of the star, only the elements without that edge can invert, so these often pass
    // where the others do not. (Boundary nodes sliding along their boundary edges the same way
    // left the deformed femur of tests/real/snapcut_femur.cpp in one piece; not investigated
    // further, not done.)
    std::sort(along.begin(), along.end());
    along.erase(std::unique(along.begin(), along.end()), along.end());
    for (const VertexId w : along) {
        const std::optional<CutMarks::Mark> mark = marks.mark(v, w);
        if (!mark || mark->node != v) continue;
        const Plane crossed = plane_of(sweeps[mark->sweep]);
        const Vec y = vec(mesh.deformed(w));
        const double at_x = crossed.normal.dot(x - crossed.point), at_y = crossed.normal.dot(y - crossed.point);
        if (!(at_x != at_y) || at_x * at_y > 0) continue;  // w has moved onto v's side since
        targets.push_back(x + (at_x / (at_x - at_y)) * (y - x));
    }
    if (targets.empty()) why = "no boundary face around it meets the sweep's plane inside the face";
    return targets;
}

// The reference position of deformed point y through the element of the star holding it.
std::optional<Point> reference_of(const Mesh& mesh, const Vec& y, const std::vector<ElementId>& star_v) {
    double best_weight = -std::numeric_limits<double>::infinity();
    std::optional<Point> best;
    for (const ElementId t : star_v) {
        const Simplex s = mesh.simplex(t);
        std::array<Vec, 4> corners;
        bool rest = true;  // reference == deformed at every corner: the map is the identity
        for (int j = 0; j < 4; ++j) {
            corners[static_cast<std::size_t>(j)] = vec(mesh.deformed(s.vertex(j)));
            rest = rest && mesh.deformed(s.vertex(j)) == mesh.reference(s.vertex(j));
        }
        const std::array<double, 4> w = tetrahedron_weights(y, corners);
        const double lowest = *std::min_element(w.begin(), w.end());
        if (!(lowest > best_weight)) continue;
        best_weight = lowest;
        if (rest) {
            best = point(y);
            continue;
        }
        Vec r = Vec::Zero();
        for (int j = 0; j < 4; ++j) r += w[static_cast<std::size_t>(j)] * vec(mesh.reference(s.vertex(j)));
        best = point(r);
    }
    if (best_weight < -weight_slack) return std::nullopt;
    return best;
}

double lowest_aspect_ratio(const Mesh& mesh, const std::vector<ElementId>& star_v);

// Moves v to (deformed, reference), or refuses and leaves it where it was: an element of the star
// inverted or flat in either position set, or below `min_aspect_ratio` (0: no such check).
Outcome<Done> move_checked(Mesh& mesh, VertexId v, const Point& deformed, const Point& reference,
                           const std::vector<ElementId>& star_v, double min_aspect_ratio) {
    const MoveCheck check{.refuse_inverted = true, .refuse_flat = true};
    const Point was_reference = mesh.reference(v), was_deformed = mesh.deformed(v);
    if (deformed == was_deformed && reference == was_reference) return Done{};  // on the sweep already
    Outcome<Done> moved = Done{};
    if (reference == deformed && was_reference == was_deformed) {
        moved = mesh.move_vertices(std::span(&v, 1), std::span(&deformed, 1), PositionSet::both, check);
    } else {
        moved = mesh.move_vertices(std::span(&v, 1), std::span(&deformed, 1), PositionSet::deformed, check);
        if (moved) {
            moved = mesh.move_vertices(std::span(&v, 1), std::span(&reference, 1), PositionSet::reference, check);
            if (!moved)  // back where it was: the deformed move was checked against these positions
                (void)mesh.move_vertices(std::span(&v, 1), std::span(&was_deformed, 1), PositionSet::deformed);
        }
    }
    if (!moved) return moved;
    if (min_aspect_ratio > 0 && lowest_aspect_ratio(mesh, star_v) < min_aspect_ratio) {
        (void)mesh.move_vertices(std::span(&v, 1), std::span(&was_deformed, 1), PositionSet::deformed);
        (void)mesh.move_vertices(std::span(&v, 1), std::span(&was_reference, 1), PositionSet::reference);
        return Refusal{RefusalCode::would_flatten,
                       "an element around it would have an aspect ratio below " + std::to_string(min_aspect_ratio)};
    }
    return Done{};
}

double lowest_aspect_ratio(const Mesh& mesh, const std::vector<ElementId>& star_v) {
    double lowest = 1;
    for (const ElementId t : star_v) {
        const Simplex s = mesh.simplex(t);
        for (const auto& positions : {mesh.reference_positions(), mesh.deformed_positions()}) {
            const std::array<Point, 4> p{positions[s.vertex(0)], positions[s.vertex(1)], positions[s.vertex(2)],
                                         positions[s.vertex(3)]};
            lowest = std::min(lowest, aspect_ratio(p));
        }
    }
    return lowest;
}

}  // namespace

SnapResult snap_nodes(Mesh& mesh, std::span<const NodeToSnap> nodes, const CutMarks& marks, double min_aspect_ratio) {
    const std::vector<Sweep>& sweeps = marks.sweeps();
    SnapResult result;
    for (const NodeToSnap& node : nodes) {
        const VertexId v = node.node;
        const std::vector<ElementId> star_v = star(mesh, v);
        std::string why;
        const std::vector<Vec> targets = targets_of(mesh, v, star_v, marks, node.sweep, why);
        if (targets.empty()) {
            result.refused.emplace_back(v, why);
            continue;
        }
        const Point was_deformed = mesh.deformed(v), was_reference = mesh.reference(v);
        const Vec x = vec(was_deformed);
        // v at x + fraction (y - x), or false (and v where it was before the call)
        const auto move_toward = [&](const Vec& y, double fraction) -> Outcome<Done> {
            const Vec part = fraction == 1 ? y : Vec(x + fraction * (y - x));
            const std::optional<Point> reference = reference_of(mesh, part, star_v);
            if (!reference)
                return Refusal{RefusalCode::not_applicable, "no element around it holds its place on the sweep"};
            return move_checked(mesh, v, point(part), *reference, star_v, min_aspect_ratio);
        };
        Outcome<Done> moved = Done{};
        bool snapped = false;
        for (const Vec& y : targets) {
            Outcome<Done> full = move_toward(y, 1);
            if (full) {
                snapped = true;
                break;
            }
            if (&y == &targets.front()) moved = std::move(full);  // the reason reported
        }
        if (!snapped) {
            // As far toward a target as the star allows, to 1/64 of the way by halving (each trial
            // checks the star exactly; a refused one leaves v at the last that passed): the
            // incision then follows the scalpel more closely than a node left where it was (at
            // most half its edge from the crossing that marked it); the element the move
            // flattens most is the degeneracy removal's, as after the thesis' full snaps. Of the
            // targets, the one that leaves v nearest the swept surface.
            std::optional<std::pair<Point, Point>> best;  // deformed, reference
            double best_distance = std::numeric_limits<double>::infinity();
            for (const Vec& y : targets) {
                if (!move_toward(y, min_partial_snap)) continue;
                for (double low = min_partial_snap, high = 1; high - low > 1.0 / 64;) {
                    const double fraction = (low + high) / 2;
                    (move_toward(y, fraction) ? low : high) = fraction;
                }
                const Vec at = vec(mesh.deformed(v));
                const double distance = (target_on_sweeps(at, sweeps, node.sweep) - at).norm();
                if (distance < best_distance) best_distance = distance, best = {mesh.deformed(v), mesh.reference(v)};
                (void)mesh.move_vertices(std::span(&v, 1), std::span(&was_deformed, 1), PositionSet::deformed);
                (void)mesh.move_vertices(std::span(&v, 1), std::span(&was_reference, 1), PositionSet::reference);
            }
            // the star passed this very configuration a moment ago
            if (!best || !move_checked(mesh, v, best->first, best->second, star_v, min_aspect_ratio)) {
                result.refused.emplace_back(v, moved.reason());
                continue;
            }
            ++result.partly;
        }
        result.snapped.push_back(v);
        result.snapped_from.push_back(was_deformed);
    }
    return result;
}

}  // namespace sxk::snapcut
