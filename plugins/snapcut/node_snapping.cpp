// Node snapping (node_snapping.hpp, thesis §3.2.2).
#include "node_snapping.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>

#include <Eigen/Dense>

#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::snapcut {

namespace {

using Vec = Eigen::Vector3d;

Vec vec(const Point& p) { return {p[0], p[1], p[2]}; }
Point point(const Vec& v) { return {v.x(), v.y(), v.z()}; }

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

// Where v goes in the deformed positions, or why it cannot.
std::optional<Vec> target_of(const Mesh& mesh, VertexId v, const std::vector<ElementId>& star_v,
                             const Plane& sweep, std::string& why) {
    const Vec x = vec(mesh.deformed(v));
    std::optional<Vec> best;
    double best_distance = std::numeric_limits<double>::infinity();
    bool on_boundary = false;
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
    if (!on_boundary) return x - (sweep.normal.dot(x - sweep.point) / sweep.normal.squaredNorm()) * sweep.normal;
    if (!best) why = "no boundary face around it meets the sweep's plane inside the face";
    return best;
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

SnapResult snap_nodes(Mesh& mesh, std::span<const NodeToSnap> nodes, const std::vector<Sweep>& sweeps,
                      double min_aspect_ratio) {
    SnapResult result;
    for (const NodeToSnap& node : nodes) {
        const VertexId v = node.node;
        const std::vector<ElementId> star_v = star(mesh, v);
        std::string why;
        const std::optional<Vec> y = target_of(mesh, v, star_v, plane_of(sweeps[node.sweep]), why);
        if (!y) {
            result.refused.emplace_back(v, why);
            continue;
        }
        const std::optional<Point> reference = reference_of(mesh, *y, star_v);
        if (!reference) {
            result.refused.emplace_back(v, "no element around it holds its place on the sweep");
            continue;
        }
        const Point was_deformed = mesh.deformed(v);
        Outcome<Done> moved = move_checked(mesh, v, point(*y), *reference, star_v, min_aspect_ratio);
        if (!moved) {
            // as far toward the sweep as the star allows: the incision follows the scalpel more
            // closely than a node left where it was (a node is at most half its edge from the
            // crossing that marked it)
            const Vec x = vec(was_deformed);
            bool partly = false;
            for (const double fraction : {0.875, 0.75, 0.5, 0.25}) {
                const Vec part = x + fraction * (*y - x);
                const std::optional<Point> part_reference = reference_of(mesh, part, star_v);
                if (part_reference && move_checked(mesh, v, point(part), *part_reference, star_v, min_aspect_ratio)) {
                    partly = true;
                    break;
                }
            }
            if (!partly) {
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
