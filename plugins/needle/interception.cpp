// The nodes the tip intercepts (interception.hpp).
#include "interception.hpp"

#include <algorithm>
#include <array>
#include <set>

#include <Eigen/Geometry>

#include "needle_frame.hpp"
#include "sxk/predicates.hpp"

namespace sxk::needle {

namespace {

int sign(Sign s) { return static_cast<int>(s); }

// The vertex of {a, b} (ids) nearer the point at parameter t on a -> b; ties to the smaller id.
VertexId nearer(VertexId a, VertexId b, double t) {
    if (t < 0.5) return a;
    if (t > 0.5) return b;
    return std::min(a, b);
}

// Edge ab of a planar mesh against the path pq: the intercepted vertices (none, one, or the
// edge's vertices on the path when it runs along the edge).
void edge_crossing(const Mesh& mesh, VertexId a, VertexId b, const Point& p, const Point& q,
                   std::vector<VertexId>& out) {
    const Point& pa = mesh.deformed(a);
    const Point& pb = mesh.deformed(b);
    const int oa = sign(orient2d(p, q, pa)), ob = sign(orient2d(p, q, pb));
    if (oa == 0 && ob == 0) {
        // collinear: the edge's vertices that lie on the path (exact comparisons along the
        // coordinate the path moves most in)
        const int k = std::abs(q[0] - p[0]) >= std::abs(q[1] - p[1]) ? 0 : 1;
        const double low = std::min(p[k], q[k]), high = std::max(p[k], q[k]);
        for (const VertexId v : {a, b})
            if (mesh.deformed(v)[k] >= low && mesh.deformed(v)[k] <= high) out.push_back(v);
        return;
    }
    if (oa * ob > 0) return;
    const int op = sign(orient2d(pa, pb, p)), oq = sign(orient2d(pa, pb, q));
    if (op * oq > 0) return;
    if (oa == 0) return out.push_back(a);
    if (ob == 0) return out.push_back(b);
    // the crossing's parameter along ab, from the areas on either side of the path
    const Eigen::Vector2d d(q[0] - p[0], q[1] - p[1]);
    auto side = [&](const Point& x) { return d.x() * (x[1] - p[1]) - d.y() * (x[0] - p[0]); };
    const double sa = side(pa), sb = side(pb);
    out.push_back(nearer(a, b, sa / (sa - sb)));
}

// The point of the segment from `from` along `path` nearest x (`from` for a segment of no length).
Eigen::Vector3d nearest_on_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& path, const Eigen::Vector3d& x) {
    const double length2 = path.squaredNorm();
    return from + (length2 > 0 ? std::clamp((x - from).dot(path) / length2, 0.0, 1.0) : 0.0) * path;
}

// Face abc of a tetrahedral mesh against the path pq.
void face_crossing(const Mesh& mesh, const std::array<VertexId, 3>& face, const Point& p, const Point& q,
                   std::vector<VertexId>& out) {
    const Point& pa = mesh.deformed(face[0]);
    const Point& pb = mesh.deformed(face[1]);
    const Point& pc = mesh.deformed(face[2]);
    if (!segment_meets_triangle(p, q, pa, pb, pc)) return;
    const Eigen::Vector3d a = vec(pa), b = vec(pb), c = vec(pc), from = vec(p), path = vec(q) - vec(p);
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    Eigen::Vector3d crossing;
    const double across = normal.dot(path);
    if (sign(orient3d(pa, pb, pc, p)) != 0 || sign(orient3d(pa, pb, pc, q)) != 0) {
        crossing = from + std::clamp(normal.dot(a - from) / across, 0.0, 1.0) * path;
    } else {
        // the path lies in the face's plane: its point nearest the face's centre
        crossing = nearest_on_segment(from, path, (a + b + c) / 3);
    }
    VertexId best = invalid_id;
    double best_distance = 0;
    for (const VertexId v : face) {
        const double distance = (vec(mesh.deformed(v)) - crossing).squaredNorm();
        if (best == invalid_id || distance < best_distance || (distance == best_distance && v < best)) {
            best = v;
            best_distance = distance;
        }
    }
    out.push_back(best);
}

}  // namespace

std::vector<VertexId> intercepted_nodes(const Mesh& mesh, const SpatialIndex& deformed, const Point& from,
                                        const Point& to) {
    std::vector<VertexId> out;
    std::set<std::array<VertexId, 3>> seen;  // faces (edges: third id invalid) already tested
    for (const ElementId t : deformed.elements_crossed(from, to)) {
        const Simplex element = mesh.simplex(t);
        const auto vertices = element.vertices();
        const int corners = static_cast<int>(vertices.size());
        for (int skip = 0; skip < corners; ++skip) {
            std::array<VertexId, 3> face{invalid_id, invalid_id, invalid_id};
            int n = 0;
            for (int j = 0; j < corners; ++j)
                if (j != skip) face[n++] = vertices[j];
            std::sort(face.begin(), face.end());  // an edge's unused slot, invalid_id, stays last
            if (!seen.insert(face).second) continue;
            if (n == 2) edge_crossing(mesh, face[0], face[1], from, to, out);
            else face_crossing(mesh, face, from, to, out);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<VertexId> nodes_within_radius(const Mesh& mesh, const SpatialIndex& deformed, const Point& from,
                                          const Point& to, const Point& axis, double radius) {
    std::vector<VertexId> out;
    Point low = from, high = from;
    for (std::size_t k = 0; k < 3; ++k) {
        low[k] = std::min(from[k], to[k]) - radius;
        high[k] = std::max(from[k], to[k]) + radius;
    }
    const Eigen::Vector3d a = vec(from), path = vec(to) - a, tip = vec(to), direction = vec(axis);
    for (const ElementId t : deformed.elements_with_vertex_in_box(low, high))
        for (const VertexId v : mesh.simplex(t).vertices()) {
            const Eigen::Vector3d x = vec(mesh.deformed(v));
            if ((x - tip).dot(direction) > 0) continue;  // ahead of the tip
            if ((x - nearest_on_segment(a, path, x)).norm() <= radius) out.push_back(v);
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace sxk::needle
