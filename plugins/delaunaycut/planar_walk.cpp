// Fans and segment walks in planar triangle meshes (planar_walk.hpp).
#include "planar_walk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

std::array<VertexId, 3> corners_from(const Mesh& mesh, ElementId t, VertexId first) {
    const Simplex& s = mesh.simplex(t);
    // canonical order sorted; its sign says whether (v0, v1, v2) runs counter-clockwise
    std::array<VertexId, 3> ccw = s.sign() > 0 ? std::array<VertexId, 3>{s.vertex(0), s.vertex(1), s.vertex(2)}
                                               : std::array<VertexId, 3>{s.vertex(0), s.vertex(2), s.vertex(1)};
    while (ccw[0] != first) std::rotate(ccw.begin(), ccw.begin() + 1, ccw.end());
    return ccw;
}

bool on_boundary(const Mesh& mesh, VertexId v) {
    for (const ElementId t : star(mesh, v))
        for (int i = 0; i < 3; ++i)
            if (mesh.neighbor(t, i) == invalid_id && mesh.face_simplex(mesh.face(t, i)).contains(v)) return true;
    return false;
}

std::optional<FaceId> edge_face(const Mesh& mesh, VertexId u, VertexId v) {
    for (const ElementId t : star(mesh, u)) {
        const Simplex& s = mesh.simplex(t);
        if (!s.contains(v)) continue;
        for (int i = 0; i < 3; ++i)
            if (s.vertex(i) != u && s.vertex(i) != v) return mesh.face(t, i);
    }
    return std::nullopt;
}

Leaving leave_triangle(const Mesh& mesh, ElementId t, const Point& from, const Point& to, VertexId behind,
                       VertexId came_through) {
    const Simplex& s = mesh.simplex(t);
    const std::array<VertexId, 3> c = corners_from(mesh, t, s.vertex(0));
    Leaving leaving;
    for (std::size_t k = 0; k < 3; ++k) {
        const VertexId opposite = c[k], u = c[(k + 1) % 3], v = c[(k + 2) % 3];
        if (opposite == came_through || u == behind || v == behind) continue;
        // leaves through u-v: `to` beyond it, u on the segment's right and v on its left
        if (orient2d(at(mesh, u), at(mesh, v), to) != Sign::negative) continue;
        const Sign side_u = orient2d(from, to, at(mesh, u));
        const Sign side_v = orient2d(from, to, at(mesh, v));
        if (side_u == Sign::positive || side_v == Sign::negative) continue;
        if (side_u == Sign::zero || side_v == Sign::zero) {
            leaving.kind = Leaving::Kind::vertex;
            leaving.u = side_u == Sign::zero ? u : v;
            leaving.point = at(mesh, leaving.u);
            return leaving;
        }
        const double a_u = area2(from, to, at(mesh, u)), a_v = area2(from, to, at(mesh, v));
        leaving.kind = Leaving::Kind::edge;
        leaving.u = u;
        leaving.v = v;
        leaving.on_edge = std::clamp(a_u / (a_u - a_v), 0.0, 1.0);
        leaving.point = lerp(at(mesh, u), at(mesh, v), leaving.on_edge);
        return leaving;
    }
    return leaving;  // `to` is in t (or, by rounding of `from`, nowhere else to go): it stays
}

ElementId triangle_entered(const Mesh& mesh, VertexId v, const Point& from, const Point& to) {
    ElementId holding = invalid_id;
    for (const ElementId t : star(mesh, v)) {
        const std::array<VertexId, 3> c = corners_from(mesh, t, v);
        bool holds = true, enters = true;
        for (std::size_t k = 0; k < 3 && holds; ++k) {
            const Point& p = at(mesh, c[k]);
            const Point& q = at(mesh, c[(k + 1) % 3]);
            const Sign side = orient2d(p, q, from);
            holds = side != Sign::negative;
            // on the edge with the segment going straight out through it
            if (side == Sign::zero && orient2d(p, q, to) == Sign::negative) enters = false;
        }
        if (holds && enters) return t;
        if (holds && holding == invalid_id) holding = t;
    }
    return holding;
}

std::optional<double> crossing(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double ab_c = area2(a, b, c), ab_d = area2(a, b, d);
    const double cd_a = area2(c, d, a), cd_b = area2(c, d, b);
    if ((ab_c > 0) == (ab_d > 0) || ab_c == 0 || ab_d == 0) return std::nullopt;
    if ((cd_a > 0) == (cd_b > 0) || cd_a == cd_b) return std::nullopt;
    return cd_a / (cd_a - cd_b);
}

Outcome<Done> place_vertex(Mesh& mesh, VertexId v, const Point& p) {
    const Point target{p[0], p[1], 0};
    const std::vector<ElementId> around = star(mesh, v);
    bool same = true;
    for (const ElementId t : around)
        for (const VertexId w : mesh.simplex(t).vertices()) same = same && mesh.reference(w) == mesh.deformed(w);
    Point reference = target;
    if (!same) {
        // the triangle of the star that holds the target, or the one it is least outside of (a point
        // just across the star's rim: an incision split's node placed on the far side of the path):
        // its barycentric coordinates, extended beyond the triangle where needed, mapped to its
        // reference corners (exact for a deformation that is affine there)
        double best = -std::numeric_limits<double>::infinity();
        for (const ElementId t : around) {
            const Simplex& s = mesh.simplex(t);
            const Point& p0 = mesh.deformed(s.vertex(0));
            const Point& p1 = mesh.deformed(s.vertex(1));
            const Point& p2 = mesh.deformed(s.vertex(2));
            const double whole = area2(p0, p1, p2);
            if (whole == 0) continue;
            const std::array<double, 3> w{area2(target, p1, p2) / whole, area2(p0, target, p2) / whole,
                                          area2(p0, p1, target) / whole};
            const double least = std::min({w[0], w[1], w[2]});
            if (least <= best) continue;
            best = least;
            reference = {0, 0, 0};
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 2; ++k)
                    reference[k] += w[static_cast<std::size_t>(j)] * mesh.reference(s.vertex(j))[k];
        }
    }
    const std::array<VertexId, 1> moved{v};
    const std::array<Point, 1> deformed{target};
    const std::array<Point, 1> referenced{reference};
    MoveCheck check;
    check.refuse_inverted = true;
    check.refuse_flat = true;
    if (reference == target) return mesh.move_vertices(moved, deformed, PositionSet::both, check);
    // two moves, one per set, each checked in its set; when the second is refused the first is moved
    // back, so that a refusal changes nothing
    const Point old_deformed = mesh.deformed(v);
    if (auto done = mesh.move_vertices(moved, deformed, PositionSet::deformed, check); !done) return done;
    if (auto done = mesh.move_vertices(moved, referenced, PositionSet::reference, check); !done) {
        const std::array<Point, 1> back{old_deformed};
        (void)mesh.move_vertices(moved, back, PositionSet::deformed);
        return done;
    }
    return Done{};
}

}  // namespace sxk::delaunaycut
