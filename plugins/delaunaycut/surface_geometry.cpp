// The surface near the blade (surface_geometry.hpp).
#include "surface_geometry.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "sxk/locate.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/split_element.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {

// The corners of triangle t in the order of its orientation (its normal (b - a) x (c - a) points to
// the side its neighbours' normals point to).
std::array<VertexId, 3> oriented(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    if (s.sign() > 0) return {s.vertex(0), s.vertex(1), s.vertex(2)};
    return {s.vertex(0), s.vertex(2), s.vertex(1)};
}

}  // namespace

double nearest_on_segment(const Point& a, const Point& b, const Point& p) {
    const Point d = minus(b, a);
    const double dd = dot(d, d);
    if (!(dd > 0)) return 0;
    return std::clamp(dot(minus(p, a), d) / dd, 0.0, 1.0);
}

std::optional<Point> blade_meets_triangle(const Blade& blade, const Point& p, const Point& q, const Point& r) {
    if (!segment_meets_triangle(blade.handle, blade.tip, p, q, r)) return std::nullopt;
    const Point n = cross(minus(q, p), minus(r, p));
    const double dh = dot(n, minus(blade.handle, p)), dt = dot(n, minus(blade.tip, p));
    if (dh != dt) return lerp3(blade.handle, blade.tip, std::clamp(dh / (dh - dt), 0.0, 1.0));
    // the blade in the triangle's plane: its point nearest the centroid
    const Point centroid{(p[0] + q[0] + r[0]) / 3, (p[1] + q[1] + r[1]) / 3, (p[2] + q[2] + r[2]) / 3};
    return lerp3(blade.handle, blade.tip, nearest_on_segment(blade.handle, blade.tip, centroid));
}

std::vector<std::pair<ElementId, Point>> pierce_points(const Mesh& mesh, std::span<const ElementId> triangles,
                                                       const Blade& blade, double merge) {
    std::vector<std::pair<ElementId, Point>> found;
    for (const ElementId t : triangles) {
        const Simplex& s = mesh.simplex(t);
        const std::optional<Point> point = blade_meets_triangle(blade, mesh.deformed(s.vertex(0)),
                                                                mesh.deformed(s.vertex(1)), mesh.deformed(s.vertex(2)));
        if (!point) continue;
        if (std::none_of(found.begin(), found.end(),
                         [&](const auto& known) { return distance3(known.second, *point) <= merge; }))
            found.emplace_back(t, *point);
    }
    return found;
}

NearestPoint nearest_point(const Mesh& mesh, std::span<const ElementId> triangles, const Point& p) {
    NearestPoint nearest;
    double least = std::numeric_limits<double>::infinity();
    for (const ElementId t : triangles) {
        const Simplex& s = mesh.simplex(t);
        const std::array<double, 3> w =
            nearest_on_triangle(mesh.deformed(s.vertex(0)), mesh.deformed(s.vertex(1)), mesh.deformed(s.vertex(2)), p);
        Point on{};
        for (int j = 0; j < 3; ++j)
            for (std::size_t k = 0; k < 3; ++k) on[k] += w[static_cast<std::size_t>(j)] * mesh.deformed(s.vertex(j))[k];
        if (const double d = distance3(on, p); d < least) least = d, nearest = {t, w, on};
    }
    return nearest;
}

Outcome<VertexId> node_on_triangle(Mesh& mesh, ElementId t, const Point& point, double snap) {
    const Simplex s = mesh.simplex(t);
    std::array<Point, 3> p{};
    for (int j = 0; j < 3; ++j) p[static_cast<std::size_t>(j)] = mesh.deformed(s.vertex(j));
    const std::array<ElementId, 1> one{t};
    const NearestPoint near = nearest_point(mesh, one, point);
    const std::array<double, 3>& w = near.weights;
    const Point& on = near.point;
    // a corner
    std::size_t nearest = 0;
    for (std::size_t j = 1; j < 3; ++j)
        if (distance3(on, p[j]) < distance3(on, p[nearest])) nearest = j;
    if (distance3(on, p[nearest]) <= snap) return s.vertex(static_cast<int>(nearest));
    // an edge: the one opposite the smallest weight
    const std::size_t least = static_cast<std::size_t>(std::min_element(w.begin(), w.end()) - w.begin());
    const std::size_t j = (least + 1) % 3, k = (least + 2) % 3;
    const double along = nearest_on_segment(p[j], p[k], on);
    if (distance3(on, lerp3(p[j], p[k], along)) <= snap && along > 0 && along < 1) {
        auto split = split_edge(mesh, s.vertex(static_cast<int>(j)), s.vertex(static_cast<int>(k)), along);
        if (!split) return split.refusal();
        return split->vertex;
    }
    std::array<double, 3> weights = w;
    for (double& x : weights) x = std::max(x, 1e-12);
    auto split = split_element(mesh, t, weights);
    if (!split) return split.refusal();
    return split->vertex;
}

Outcome<Done> place_on_surface(Mesh& mesh, VertexId v, const Point& point) {
    const std::vector<ElementId> around = star(mesh, v);
    bool same = true;
    for (const ElementId t : around)
        for (const VertexId w : mesh.simplex(t).vertices()) same = same && mesh.reference(w) == mesh.deformed(w);
    Point reference = point;
    if (!same) {
        const NearestPoint near = nearest_point(mesh, around, point);
        const Simplex& s = mesh.simplex(near.triangle);
        reference = {0, 0, 0};
        for (int j = 0; j < 3; ++j)
            for (std::size_t k = 0; k < 3; ++k)
                reference[k] += near.weights[static_cast<std::size_t>(j)] * mesh.reference(s.vertex(j))[k];
    }
    // the star after the move: no triangle collinear, none turned against a neighbour it faced along with
    for (const bool in_reference : {false, true}) {
        if (in_reference && same) break;
        auto at = [&](VertexId w, bool after) -> const Point& {
            if (after && w == v) return in_reference ? reference : point;
            return in_reference ? mesh.reference(w) : mesh.deformed(w);
        };
        for (const ElementId t : around) {
            const std::array<VertexId, 3> c = oriented(mesh, t);
            if (collinear(at(c[0], true), at(c[1], true), at(c[2], true)))
                return Refusal{RefusalCode::would_invert,
                               "triangle " + std::to_string(t) + " would be flat", t};
            for (int i = 0; i < 3; ++i) {
                const ElementId n = mesh.neighbor(t, i);
                if (n == invalid_id) continue;
                const std::array<VertexId, 3> e = oriented(mesh, n);
                const Sign before = normal_alignment(at(c[0], false), at(c[1], false), at(c[2], false),
                                                     at(e[0], false), at(e[1], false), at(e[2], false));
                const Sign after = normal_alignment(at(c[0], true), at(c[1], true), at(c[2], true),
                                                    at(e[0], true), at(e[1], true), at(e[2], true));
                if (before == Sign::positive && after != Sign::positive)
                    return Refusal{RefusalCode::would_invert,
                                   "triangles " + std::to_string(t) + " and " + std::to_string(n) +
                                       " would fold over each other", t};
            }
        }
    }
    const std::array<VertexId, 1> moved{v};
    const std::array<Point, 1> deformed{point};
    const std::array<Point, 1> referenced{reference};
    if (same) return mesh.move_vertices(moved, deformed, PositionSet::both);
    if (auto done = mesh.move_vertices(moved, deformed, PositionSet::deformed); !done) return done;
    return mesh.move_vertices(moved, referenced, PositionSet::reference);
}

std::size_t folds_at(const Mesh& mesh, std::span<const ElementId> triangles) {
    std::size_t folds = 0;
    for (const ElementId t : triangles) {
        const std::array<VertexId, 3> c = oriented(mesh, t);
        for (int i = 0; i < 3; ++i) {
            const ElementId n = mesh.neighbor(t, i);
            if (n == invalid_id) continue;
            if (n < t && std::find(triangles.begin(), triangles.end(), n) != triangles.end()) continue;
            const std::array<VertexId, 3> e = oriented(mesh, n);
            if (normal_alignment(mesh.deformed(c[0]), mesh.deformed(c[1]), mesh.deformed(c[2]), mesh.deformed(e[0]),
                                 mesh.deformed(e[1]), mesh.deformed(e[2])) == Sign::negative)
                ++folds;
        }
    }
    return folds;
}

std::optional<Beyond> pierced_beyond(const Mesh& mesh, VertexId v, const Blade& blade) {
    const VertexFan fan = fan_around(mesh, v);
    for (std::size_t k = 0; k < fan.triangles.size(); ++k) {
        const ElementId t = fan.triangles[k];
        const ElementId beyond = mesh.neighbor(t, mesh.simplex(t).index(v));
        if (beyond == invalid_id) continue;
        const std::array<ElementId, 1> one{beyond};
        const auto found = pierce_points(mesh, one, blade, 0);
        if (found.empty()) continue;
        const Point& px = mesh.deformed(fan.ring[k]);
        const Point& py = mesh.deformed(fan.next(k));
        return Beyond{t, lerp3(px, py, nearest_on_segment(px, py, found.front().second))};
    }
    return std::nullopt;
}

std::vector<std::array<Point, 2>> far_edges(const Mesh& mesh, VertexId v) {
    const VertexFan fan = fan_around(mesh, v);
    std::vector<std::array<Point, 2>> edges;
    for (std::size_t i = 0; i < fan.triangles.size(); ++i)
        edges.push_back({mesh.deformed(fan.ring[i]), mesh.deformed(fan.next(i))});
    return edges;
}

}  // namespace sxk::delaunaycut
