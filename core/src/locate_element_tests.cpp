// The element-level tests of sxk/locate.hpp: containment with barycentric coordinates, exact
// intersection of a segment or a triangle with an element or a face, nearest points and ray hits.
// Decisions are exact (CGAL's filtered kernel, core/src/cgal_kernel.hpp); the quantities
// (weights, distances, t) are computed in double precision, and weights that fail their check
// again in exact rational arithmetic.
#include <CGAL/Exact_rational.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "cgal_kernel.hpp"
#include "locate_trees.hpp"
#include "sxk/locate.hpp"
#include "sxk/predicates.hpp"
#include "sxk/point_math.hpp"

namespace sxk {
namespace {

using detail::Kernel;
using detail::to_cgal_2;
using detail::to_cgal_3;

Point along(const Point& o, const Point& d, double t) { return {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]}; }

// In a planar mesh the third coordinate of query points is ignored.
Point planar(const Point& x) { return {x[0], x[1], 0}; }

Sign orientation(const std::array<const Point*, 4>& p, int dimension) {
    return dimension == 2 ? orient2d(*p[0], *p[1], *p[2]) : orient3d(*p[0], *p[1], *p[2], *p[3]);
}

// Clamps weights to [0, 1] and makes them sum to 1 (a point inside by the exact test may get a
// weight of -1e-17 by rounding).
void normalise(std::span<double> w) {
    double total = 0;
    for (double& x : w) total += x = std::max(0.0, x);
    if (total > 0)
        for (double& x : w) x /= total;
}

// The two corners of a collinear triangle farthest apart.
std::array<const Point*, 2> farthest_pair(const Point& a, const Point& b, const Point& c) {
    const double ab = detail::distance_squared(a, b), ac = detail::distance_squared(a, c),
                 bc = detail::distance_squared(b, c);
    if (ab >= ac && ab >= bc) return {&a, &b};
    return ac >= bc ? std::array<const Point*, 2>{&a, &c} : std::array<const Point*, 2>{&b, &c};
}

bool collinear_query(const Mesh& mesh, const Point& a, const Point& b, const Point& c) {
    return mesh.ambient_dimension() == 2 ? orient2d(a, b, c) == Sign::zero : collinear(a, b, c);
}

bool is_flat(const Mesh& mesh, const detail::ElementPoints& e) {
    if (mesh.topological_dimension() < mesh.ambient_dimension()) return collinear(*e.p[0], *e.p[1], *e.p[2]);
    return orientation(e.p, mesh.topological_dimension()) == Sign::zero;
}

// The closed segment [a, b] against a simplex of 2 or 3 points (a face or a surface triangle)
// or an element, exactly, in the mesh's ambient dimension.
bool segment_meets_points(const Mesh& mesh, const detail::ElementPoints& e, const Point& a, const Point& b) {
    const auto& p = e.p;
    if (mesh.ambient_dimension() == 2) {
        const Kernel::Point_2 x = to_cgal_2(a), y = to_cgal_2(b);
        if (e.count == 3) {
            const Kernel::Triangle_2 t(to_cgal_2(*p[0]), to_cgal_2(*p[1]), to_cgal_2(*p[2]));
            return x == y ? !t.has_on_unbounded_side(x) : CGAL::do_intersect(t, Kernel::Segment_2(x, y));
        }
        const Kernel::Segment_2 s(to_cgal_2(*p[0]), to_cgal_2(*p[1]));
        return x == y ? s.has_on(x) : CGAL::do_intersect(s, Kernel::Segment_2(x, y));
    }
    const Kernel::Point_3 x = to_cgal_3(a), y = to_cgal_3(b);
    if (e.count == 4) {
        const Kernel::Tetrahedron_3 t(to_cgal_3(*p[0]), to_cgal_3(*p[1]), to_cgal_3(*p[2]), to_cgal_3(*p[3]));
        return x == y ? !t.has_on_unbounded_side(x) : CGAL::do_intersect(t, Kernel::Segment_3(x, y));
    }
    if (e.count == 3) {
        const Kernel::Triangle_3 t(to_cgal_3(*p[0]), to_cgal_3(*p[1]), to_cgal_3(*p[2]));
        return x == y ? t.has_on(x) : CGAL::do_intersect(t, Kernel::Segment_3(x, y));
    }
    const Kernel::Segment_3 s(to_cgal_3(*p[0]), to_cgal_3(*p[1]));
    return x == y ? s.has_on(x) : CGAL::do_intersect(s, Kernel::Segment_3(x, y));
}

// The closed triangle (a, b, c), not collinear, against a simplex of 2-4 points.
bool triangle_meets_points(const Mesh& mesh, const detail::ElementPoints& e, const Point& a, const Point& b,
                           const Point& c) {
    const auto& p = e.p;
    if (mesh.ambient_dimension() == 2) {
        const Kernel::Triangle_2 query(to_cgal_2(a), to_cgal_2(b), to_cgal_2(c));
        if (e.count == 3)
            return CGAL::do_intersect(query, Kernel::Triangle_2(to_cgal_2(*p[0]), to_cgal_2(*p[1]), to_cgal_2(*p[2])));
        return CGAL::do_intersect(query, Kernel::Segment_2(to_cgal_2(*p[0]), to_cgal_2(*p[1])));
    }
    if (e.count == 4) return triangle_meets_tetrahedron(a, b, c, *p[0], *p[1], *p[2], *p[3]);
    const Kernel::Triangle_3 query(to_cgal_3(a), to_cgal_3(b), to_cgal_3(c));
    if (e.count == 3) {
        if (collinear(*p[0], *p[1], *p[2])) {  // a face of a flat tetrahedron
            const auto ends = farthest_pair(*p[0], *p[1], *p[2]);
            return CGAL::do_intersect(query, Kernel::Segment_3(to_cgal_3(*ends[0]), to_cgal_3(*ends[1])));
        }
        return CGAL::do_intersect(query, Kernel::Triangle_3(to_cgal_3(*p[0]), to_cgal_3(*p[1]), to_cgal_3(*p[2])));
    }
    return CGAL::do_intersect(query, Kernel::Segment_3(to_cgal_3(*p[0]), to_cgal_3(*p[1])));
}

bool triangle_meets(const Mesh& mesh, const detail::ElementPoints& e, const Point& a, const Point& b,
                    const Point& c) {
    if (collinear_query(mesh, a, b, c)) {
        const auto ends = farthest_pair(a, b, c);
        return segment_meets_points(mesh, e, *ends[0], *ends[1]);
    }
    return triangle_meets_points(mesh, e, a, b, c);
}

// A ray that (nearly) lies in the plane of its face: the plane gives no t (or a t ruined by the
// division by almost 0). In the face's own plane (2D coordinates, dropping the axis along the
// largest normal component; a segment face in 2D is its own line), the entry into the face: 0
// when the origin is in it, else the nearest crossing of an edge. Approximate, as the contract
// says of quantities: the exact test decided that the ray meets the face.
double t_in_plane(const detail::ElementPoints& e, const Point& o, const Point& d, int drop) {
    const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
    auto flat = [&](const Point& p) {
        return std::array<double, 2>{p[static_cast<std::size_t>(u)], p[static_cast<std::size_t>(v)]};
    };
    auto cross2 = [](const std::array<double, 2>& a, const std::array<double, 2>& b) { return a[0] * b[1] - a[1] * b[0]; };
    const std::array<double, 2> origin = flat(o), direction = flat(d);
    const auto& p = e.p;
    if (e.count == 3) {
        std::array<double, 3> side{};
        for (std::size_t i = 0; i < 3; ++i) {
            const auto a = flat(*p[i]), b = flat(*p[(i + 1) % 3]);
            side[i] = cross2({b[0] - a[0], b[1] - a[1]}, {origin[0] - a[0], origin[1] - a[1]});
        }
        if ((side[0] >= 0 && side[1] >= 0 && side[2] >= 0) || (side[0] <= 0 && side[1] <= 0 && side[2] <= 0)) return 0;
    }
    double best = std::numeric_limits<double>::infinity();
    const double dd = direction[0] * direction[0] + direction[1] * direction[1];
    const int edges = e.count == 3 ? 3 : 1;
    for (int i = 0; i < edges; ++i) {
        const auto a = flat(*p[static_cast<std::size_t>(i)]), b = flat(*p[static_cast<std::size_t>((i + 1) % e.count)]);
        const std::array<double, 2> edge{b[0] - a[0], b[1] - a[1]}, w{a[0] - origin[0], a[1] - origin[1]};
        const double denominator = cross2(direction, edge);
        const double scale = std::sqrt(dd * (edge[0] * edge[0] + edge[1] * edge[1]));
        if (std::abs(denominator) > 1e-12 * scale) {
            const double t = cross2(w, edge) / denominator, s = cross2(w, direction) / denominator;
            if (t >= 0 && s >= -1e-9 && s <= 1 + 1e-9) best = std::min(best, t);
        } else if (std::abs(cross2(w, direction)) <=
                   1e-9 * std::sqrt(dd) * (std::hypot(w[0], w[1]) + std::hypot(edge[0], edge[1]))) {
            // along the edge: its nearer end ahead, 0 when the origin is on it, nothing when it is
            // behind. An edge parallel to the ray but off its line is not met along it (the
            // other edges give the crossing): taking it for one gave t = 0 for a ray 0.03 away
            // (EditJournalRandom.OctahedronSurface, SXK_SEED=358757303, step 1180)
            const double ta = (w[0] * direction[0] + w[1] * direction[1]) / dd;
            const double tb = ((b[0] - origin[0]) * direction[0] + (b[1] - origin[1]) * direction[1]) / dd;
            if (std::max(ta, tb) >= 0) best = std::min(best, std::min(ta, tb) <= 0 ? 0.0 : std::min(ta, tb));
        }
    }
    if (best == std::numeric_limits<double>::infinity()) {  // rounding: the nearest corner ahead
        for (int j = 0; j < e.count; ++j)
            if (const double t = dot(minus(*p[static_cast<std::size_t>(j)], o), d) / dot(d, d); t >= 0)
                best = std::min(best, t);
    }
    return best == std::numeric_limits<double>::infinity() ? 0 : best;
}

// Where the ray crosses the plane of the triangle e, in exact rational arithmetic: t, or nothing
// when the ray is parallel to the plane (then `drop` is the axis of the normal's largest
// component, for t_in_plane).
struct ExactCrossing {
    bool parallel = false;
    double t = 0;
    int drop = 0;
};
ExactCrossing exact_plane_crossing(const detail::ElementPoints& e, const Point& o, const Point& d) {
    using R = CGAL::Exact_rational;
    std::array<R, 3> u, v, w, n;
    for (std::size_t k = 0; k < 3; ++k) {
        u[k] = R((*e.p[1])[k]) - R((*e.p[0])[k]);
        v[k] = R((*e.p[2])[k]) - R((*e.p[0])[k]);
        w[k] = R((*e.p[0])[k]) - R(o[k]);
    }
    n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const R denominator = n[0] * R(d[0]) + n[1] * R(d[1]) + n[2] * R(d[2]);
    ExactCrossing crossing;
    if (CGAL::is_zero(denominator)) {
        crossing.parallel = true;
        for (std::size_t k = 1; k < 3; ++k)
            if (CGAL::abs(n[k]) > CGAL::abs(n[static_cast<std::size_t>(crossing.drop)])) crossing.drop = static_cast<int>(k);
        return crossing;
    }
    crossing.t = CGAL::to_double((n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / denominator);
    return crossing;
}

// Where the ray meets the segment a-b (2D) or the triangle a-b-c (3D), once the exact test said
// it does: t, the point, and the weights of the face's vertices. A ray closer to the face's
// plane than 1e-8 radians is taken as lying in it (t_in_plane). A triangle so thin that its
// normal in doubles is mostly rounding (area below a millionth of its edges' product) gets its
// crossing exactly: a needle of area 1e-19 on edges of 0.1 gave t = -0.9 in doubles, clamped to
// 0, for a ray through its corner at t = 1 (EditJournalRandom.OctahedronSurface,
// SXK_SEED=3331795627, step 1372).
RayHit ray_hit_quantities(const detail::ElementPoints& e, const Point& o, const Point& d) {
    RayHit hit;
    const auto& p = e.p;
    const double length = std::sqrt(dot(d, d));
    if (e.count == 3) {
        const Point u = minus(*p[1], *p[0]), v = minus(*p[2], *p[0]);
        const Point n = cross(u, v);
        const double denominator = dot(n, d);
        if (std::sqrt(dot(n, n)) <= 1e-6 * std::sqrt(dot(u, u) * dot(v, v))) {
            const ExactCrossing crossing = exact_plane_crossing(e, o, d);
            hit.t = crossing.parallel ? t_in_plane(e, o, d, crossing.drop) : std::max(0.0, crossing.t);
        } else if (std::abs(denominator) > 1e-8 * std::sqrt(dot(n, n)) * length) {
            hit.t = std::max(0.0, dot(n, minus(*p[0], o)) / denominator);
        } else {
            int drop = 0;
            for (int k = 1; k < 3; ++k)
                if (std::abs(n[static_cast<std::size_t>(k)]) > std::abs(n[static_cast<std::size_t>(drop)])) drop = k;
            hit.t = t_in_plane(e, o, d, drop);
        }
        hit.point = along(o, d, hit.t);
        hit.barycentric = nearest_on_triangle(*p[0], *p[1], *p[2], hit.point);
        return hit;
    }
    const Point u = minus(*p[1], *p[0]);
    const double denominator = d[0] * u[1] - d[1] * u[0];
    const Point w = minus(*p[0], o);
    hit.t = std::abs(denominator) > 1e-8 * std::sqrt(dot(u, u)) * length
                ? std::max(0.0, (w[0] * u[1] - w[1] * u[0]) / denominator)
                : t_in_plane(e, o, d, 2);
    hit.point = along(o, d, hit.t);
    const double uu = dot(u, u);
    const double s = uu > 0 ? std::clamp(dot(minus(hit.point, *p[0]), u) / uu, 0.0, 1.0) : 0.0;
    hit.barycentric = {1 - s, s, 0};
    return hit;
}

bool ray_meets_points(const Mesh& mesh, const detail::ElementPoints& e, const Point& o, const Point& d) {
    const auto& p = e.p;
    if (mesh.ambient_dimension() == 2) {
        const Kernel::Ray_2 ray(to_cgal_2(o), Kernel::Vector_2(d[0], d[1]));
        if (e.count == 3)
            return CGAL::do_intersect(ray, Kernel::Triangle_2(to_cgal_2(*p[0]), to_cgal_2(*p[1]), to_cgal_2(*p[2])));
        return CGAL::do_intersect(ray, Kernel::Segment_2(to_cgal_2(*p[0]), to_cgal_2(*p[1])));
    }
    const Kernel::Ray_3 ray(to_cgal_3(o), Kernel::Vector_3(d[0], d[1], d[2]));
    if (e.count == 3) {
        if (collinear(*p[0], *p[1], *p[2])) {
            const auto ends = farthest_pair(*p[0], *p[1], *p[2]);
            return CGAL::do_intersect(ray, Kernel::Segment_3(to_cgal_3(*ends[0]), to_cgal_3(*ends[1])));
        }
        return CGAL::do_intersect(ray, Kernel::Triangle_3(to_cgal_3(*p[0]), to_cgal_3(*p[1]), to_cgal_3(*p[2])));
    }
    // a boundary edge of a surface: the ray meets it only when coplanar with it
    const Kernel::Segment_3 s(to_cgal_3(*p[0]), to_cgal_3(*p[1]));
    return CGAL::do_intersect(ray, s);
}

RayHit ray_meets(const Mesh& mesh, const detail::ElementPoints& e, const Point& origin, const Point& direction) {
    const Point o = mesh.ambient_dimension() == 2 ? planar(origin) : origin;
    const Point d = mesh.ambient_dimension() == 2 ? planar(direction) : direction;
    if (dot(d, d) == 0 || !ray_meets_points(mesh, e, o, d)) return {};
    if (e.count == 2 && mesh.ambient_dimension() == 3) {
        // a boundary edge of a surface, which the ray crosses: the closest approach of the two
        // lines (parallel: the nearer end ahead, or the origin)
        RayHit hit;
        const Point u = minus(*e.p[1], *e.p[0]), w = minus(o, *e.p[0]);
        const double dd = dot(d, d), uu = dot(u, u), du = dot(d, u), dw = dot(d, w), uw = dot(u, w);
        const double denominator = dd * uu - du * du;
        if (denominator > 1e-16 * dd * uu) {
            hit.t = std::max(0.0, (du * uw - uu * dw) / denominator);
        } else {
            const double ta = -dw / dd, tb = dot(minus(*e.p[1], o), d) / dd;
            hit.t = std::min(ta, tb) <= 0 ? 0.0 : std::min(ta, tb);
        }
        hit.point = along(o, d, hit.t);
        const double s = uu > 0 ? std::clamp(dot(minus(hit.point, *e.p[0]), u) / uu, 0.0, 1.0) : 0.0;
        hit.barycentric = {1 - s, s, 0};
        return hit;
    }
    return ray_hit_quantities(e, o, d);
}

// The weights of x in the sub-simplex of the vertices `kept` (the others get 0), as ratios of
// exact determinants: in the affine hull of the kept vertices (x lies there: the exact test put
// it on exactly the faces opposite the others), projected onto the coordinate axes where the
// kept simplex is not flat, which keeps every ratio. Each weight comes out within a few units in
// the last place of its true value, however thin the element. Rational arithmetic costs far more
// than the double solve, so this is the fallback of weights_in below, taken when its double
// answer fails its check.
using Rational = CGAL::Exact_rational;

Rational determinant(const std::array<std::array<Rational, 3>, 3>& a, int m) {
    if (m == 1) return a[0][0];
    if (m == 2) return a[0][0] * a[1][1] - a[0][1] * a[1][0];
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The determinant of the m corners q[1..m] less q[0], on the axes `axes`.
Rational projected_volume(const std::array<const Point*, 4>& q, int m, const std::array<std::size_t, 3>& axes) {
    std::array<std::array<Rational, 3>, 3> a;
    for (int j = 0; j < m; ++j)
        for (int k = 0; k < m; ++k)
            a[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)] =
                Rational((*q[static_cast<std::size_t>(j + 1)])[axes[static_cast<std::size_t>(k)]]) -
                Rational((*q[0])[axes[static_cast<std::size_t>(k)]]);
    return determinant(a, m);
}

std::array<double, 4> exact_weights_in(const detail::ElementPoints& e, const std::array<int, 4>& kept, int count,
                                       const Point& x, int dimension) {
    std::array<double, 4> w{};
    const int m = count - 1;
    std::array<const Point*, 4> q{};
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) q[j] = e.p[static_cast<std::size_t>(kept[j])];
    // the weights in the projection onto the axes `axes` (the first m of them), or false when
    // the kept simplex is flat there
    auto solve_in = [&](const std::array<std::size_t, 3>& axes) {
        const Rational whole = projected_volume(q, m, axes);
        if (CGAL::is_zero(whole)) return false;
        for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
            std::array<const Point*, 4> part = q;
            part[j] = &x;
            w[static_cast<std::size_t>(kept[j])] = CGAL::to_double(projected_volume(part, m, axes) / whole);
        }
        return true;
    };
    // the projections onto m of the `dimension` axes, in order until one is not flat; the kept
    // simplex is a face of an element that is not flat, so one of them at least is not flat
    // either
    const auto d = static_cast<std::size_t>(dimension);
    bool solved = m == 0;
    for (std::size_t a = 0; a < d && !solved; ++a) {
        if (m == 1) solved = solve_in({a, 0, 0});
        for (std::size_t b = a + 1; b < d && !solved; ++b) {
            if (m == 2) solved = solve_in({a, b, 0});
            for (std::size_t c = b + 1; c < d && !solved; ++c)
                if (m == 3) solved = solve_in({a, b, c});
        }
    }
    if (m == 0) w[static_cast<std::size_t>(kept[0])] = 1;
    normalise(w);
    return w;
}

// The weights of x in the sub-simplex of the vertices `kept` in double precision: least squares
// of sum w_j p_j = x with sum w_j = 1 by Gram-Schmidt (orthogonal, not normalised: no square
// roots, so the midpoint of an edge gets exactly 1/2 and 1/2). Cramer's rule in doubles gave
// points 0.02 away from x in thin elements; this solve gave 1.75e-3 on a near-flat face of a
// deformed tetrahedron (EditJournalRandom.JitteredKuhnCube, SXK_SEED=3763780165: a weight of
// -0.006, clamped). So the answer is checked: the weights must give back x to a few rounding
// errors of the coordinates' magnitude; otherwise exact_weights_in answers.
std::array<double, 4> weights_in(const detail::ElementPoints& e, const std::array<int, 4>& kept, int count,
                                 const Point& x, int dimension) {
    const Point& base = *e.p[static_cast<std::size_t>(kept[0])];
    const auto k = static_cast<std::size_t>(count - 1);
    std::array<Point, 3> v{};                  // a_j made orthogonal to a_0..a_{j-1}
    std::array<double, 3> vv{};                // v_j . v_j
    std::array<std::array<double, 3>, 3> r{};  // a_j = v_j + sum_{i<j} r[i][j] v_i
    for (std::size_t j = 0; j < k; ++j) {
        const Point a = minus(*e.p[static_cast<std::size_t>(kept[j + 1])], base);
        v[j] = a;
        for (std::size_t i = 0; i < j; ++i) {
            r[i][j] = vv[i] > 0 ? dot(v[i], v[j]) / vv[i] : 0;  // modified Gram-Schmidt
            for (std::size_t m = 0; m < 3; ++m) v[j][m] -= r[i][j] * v[i][m];
        }
        vv[j] = dot(v[j], v[j]);
    }
    Point b = minus(x, base);
    std::array<double, 3> y{};
    for (std::size_t j = 0; j < k; ++j) {
        y[j] = vv[j] > 0 ? dot(v[j], b) / vv[j] : 0;
        for (std::size_t m = 0; m < 3; ++m) b[m] -= y[j] * v[j][m];
    }
    for (std::size_t j = k; j-- > 0;)
        for (std::size_t i = j + 1; i < k; ++i) y[j] -= r[j][i] * y[i];
    std::array<double, 4> w{};
    double rest = 1;
    for (std::size_t j = 0; j < k; ++j) {
        w[static_cast<std::size_t>(kept[j + 1])] = y[j];
        rest -= y[j];
    }
    w[static_cast<std::size_t>(kept[0])] = rest;
    // the check: the weights, clamped to [0, 1] and summing to 1, give back x within 64 units in
    // the last place of the largest coordinate involved (a weight of -1e-17 at an edge's
    // midpoint passes; a clamped weight of -0.006 in a thin element does not)
    normalise(w);
    double magnitude = 0, miss = 0;
    for (std::size_t m = 0; m < 3; ++m) {
        double back = 0;
        magnitude = std::max(magnitude, std::abs(x[m]));
        for (std::size_t j = 0; j <= k; ++j) {
            const Point& p = *e.p[static_cast<std::size_t>(kept[j])];
            back += w[static_cast<std::size_t>(kept[j])] * p[m];
            magnitude = std::max(magnitude, std::abs(p[m]));
        }
        miss = std::max(miss, std::abs(back - x[m]));
    }
    if (miss > 64 * std::numeric_limits<double>::epsilon() * magnitude)
        return exact_weights_in(e, kept, count, x, dimension);
    return w;
}

}  // namespace

std::array<double, 3> nearest_on_triangle(const Point& a, const Point& b, const Point& c, const Point& p) {
    const Point ab = minus(b, a), ac = minus(c, a);
    const Point n = cross(ab, ac);
    if (dot(n, n) == 0) {
        // degenerate: the nearest of the three edges' nearest points
        std::array<double, 3> best{1, 0, 0};
        double best_distance = std::numeric_limits<double>::infinity();
        const std::array<const Point*, 3> corners{&a, &b, &c};
        for (std::size_t i = 0; i < 3; ++i) {
            const std::size_t j = (i + 1) % 3;
            const Point u = minus(*corners[j], *corners[i]);
            const double uu = dot(u, u);
            const double s = uu > 0 ? std::clamp(dot(minus(p, *corners[i]), u) / uu, 0.0, 1.0) : 0.0;
            const Point q = along(*corners[i], u, s);
            if (const double distance = detail::distance_squared(p, q); distance < best_distance) {
                best_distance = distance;
                best = {0, 0, 0};
                best[i] = 1 - s;
                best[j] = s;
            }
        }
        return best;
    }
    // the Voronoi regions of the corners, edges and face, in turn (the classic closest-point
    // test; every division below is by a positive quantity in its region)
    const Point ap = minus(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
    const Point bp = minus(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const Point cp = minus(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const double total = va + vb + vc;
    std::array<double, 3> w{va / total, vb / total, vc / total};
    normalise(w);
    return w;
}

Location locate_in_element(const Mesh& mesh, ElementId t, const Point& x, Positions positions,
                           double surface_tolerance) {
    Location location;
    if (!mesh.is_element(t)) return location;
    for (int k = 0; k < mesh.ambient_dimension(); ++k)
        if (!std::isfinite(x[static_cast<std::size_t>(k)])) return location;
    const detail::ElementPoints e = detail::element_points(mesh, t, positions);
    const int d = mesh.topological_dimension();
    if (d < mesh.ambient_dimension()) {  // a triangle in space: nearest within the tolerance
        if (collinear(*e.p[0], *e.p[1], *e.p[2])) return location;
        const std::array<double, 3> w = nearest_on_triangle(*e.p[0], *e.p[1], *e.p[2], x);
        Point q{};
        for (std::size_t k = 0; k < 3; ++k) q[k] = w[0] * (*e.p[0])[k] + w[1] * (*e.p[1])[k] + w[2] * (*e.p[2])[k];
        if (!(std::sqrt(detail::distance_squared(q, x)) <= surface_tolerance)) return location;
        location.element = t;
        std::copy(w.begin(), w.end(), location.barycentric.begin());
        return location;
    }
    const Sign whole = orientation(e.p, d);
    if (whole == Sign::zero) return location;
    // the exact test, and which faces x lies on (their opposite weight is exactly 0)
    std::array<int, 4> kept{};
    int count = 0;
    for (int i = 0; i <= d; ++i) {
        std::array<const Point*, 4> q = e.p;
        q[static_cast<std::size_t>(i)] = &x;
        const Sign part = orientation(q, d);
        if (static_cast<int>(part) * static_cast<int>(whole) < 0) return location;
        if (part != Sign::zero) kept[static_cast<std::size_t>(count++)] = i;
    }
    location.element = t;
    location.barycentric = weights_in(e, kept, count, d == 2 ? planar(x) : x, d);
    return location;
}

bool segment_meets_element(const Mesh& mesh, ElementId t, const Point& a, const Point& b, Positions positions) {
    if (!mesh.is_element(t)) return false;
    const detail::ElementPoints e = detail::element_points(mesh, t, positions);
    if (is_flat(mesh, e)) return false;
    return segment_meets_points(mesh, e, a, b);
}

bool triangle_meets_element(const Mesh& mesh, ElementId t, const Point& a, const Point& b, const Point& c,
                            Positions positions) {
    if (!mesh.is_element(t)) return false;
    const detail::ElementPoints e = detail::element_points(mesh, t, positions);
    if (is_flat(mesh, e)) return false;
    return triangle_meets(mesh, e, a, b, c);
}

bool triangle_meets_face(const Mesh& mesh, FaceId f, const Point& a, const Point& b, const Point& c,
                         Positions positions) {
    if (!mesh.is_face(f)) return false;
    return triangle_meets(mesh, detail::face_points(mesh, f, positions), a, b, c);
}

BoundaryPoint nearest_point_on_face(const Mesh& mesh, FaceId f, const Point& query, Positions positions) {
    BoundaryPoint nearest;
    if (!mesh.is_face(f)) return nearest;
    const Point x = mesh.ambient_dimension() == 2 ? planar(query) : query;
    const detail::ElementPoints e = detail::face_points(mesh, f, positions);
    const auto& p = e.p;
    if (e.count == 3) {
        nearest.barycentric = nearest_on_triangle(*p[0], *p[1], *p[2], x);
    } else {
        const Point u = minus(*p[1], *p[0]);
        const double uu = dot(u, u);
        const double s = uu > 0 ? std::clamp(dot(minus(x, *p[0]), u) / uu, 0.0, 1.0) : 0.0;
        nearest.barycentric = {1 - s, s, 0};
    }
    for (std::size_t k = 0; k < 3; ++k) {
        nearest.point[k] = 0;
        for (int j = 0; j < e.count; ++j)
            nearest.point[k] += nearest.barycentric[static_cast<std::size_t>(j)] * (*p[static_cast<std::size_t>(j)])[k];
    }
    nearest.face = f;
    nearest.element = mesh.face_element(f);
    nearest.distance = std::sqrt(detail::distance_squared(nearest.point, x));
    return nearest;
}

RayHit ray_meets_face(const Mesh& mesh, FaceId f, const Point& origin, const Point& direction, Positions positions) {
    if (!mesh.is_face(f)) return {};
    RayHit hit = ray_meets(mesh, detail::face_points(mesh, f, positions), origin, direction);
    if (hit.t != std::numeric_limits<double>::infinity()) {
        hit.face = f;
        hit.element = mesh.face_element(f);
    }
    return hit;
}

RayHit ray_meets_triangle_element(const Mesh& mesh, ElementId t, const Point& origin, const Point& direction,
                                  Positions positions) {
    if (!mesh.is_element(t) || mesh.topological_dimension() != 2) return {};
    RayHit hit = ray_meets(mesh, detail::element_points(mesh, t, positions), origin, direction);
    if (hit.t != std::numeric_limits<double>::infinity()) hit.element = t;
    return hit;
}

}  // namespace sxk
