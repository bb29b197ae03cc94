// Exact predicates through CGAL's filtered kernel: interval arithmetic first, exact arithmetic
// only when the interval cannot decide, so the common case costs a few floating-point
// operations more than the naive determinant.
#include "sxk/predicates.hpp"

#include <array>

#include "cgal_kernel.hpp"

namespace sxk {

using detail::to_cgal_2;
using detail::to_cgal_3;
using detail::to_sign;

Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return to_sign(CGAL::orientation(to_cgal_2(a), to_cgal_2(b), to_cgal_2(c)));
}

Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    // CGAL::orientation(p,q,r,s) is POSITIVE when s lies on the positive side of (p,q,r), i.e.
    // det[q-p, r-p, s-p] > 0: the same convention as ours.
    return to_sign(CGAL::orientation(to_cgal_3(a), to_cgal_3(b), to_cgal_3(c), to_cgal_3(d)));
}

Sign incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
    // side_of_oriented_circle is POSITIVE inside for a counter-clockwise circle
    return to_sign(CGAL::side_of_oriented_circle(to_cgal_2(a), to_cgal_2(b), to_cgal_2(c), to_cgal_2(d)));
}

Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e) {
    // side_of_oriented_sphere is POSITIVE inside for a positively oriented sphere (a,b,c,d)
    return to_sign(CGAL::side_of_oriented_sphere(to_cgal_3(a), to_cgal_3(b), to_cgal_3(c),
                                                 to_cgal_3(d), to_cgal_3(e)));
}

Sign unfolded_incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
    using P = detail::ExactKernel::Point_3;
    using FT = detail::ExactKernel::FT;
    auto exact = [](const Point& p) { return P(p[0], p[1], p[2]); };
    const P pa = exact(a), pb = exact(b), pc = exact(c), pd = exact(d);
    const auto u = pa - pc, v = pb - pc, s = pa - pd, t = pb - pd;
    // the angle at c: cos ~ dot_c, sin ~ |cross_c| (same positive factor |u||v|); so at d
    const FT dot_c = u * v, dot_d = s * t;
    const FT cross_c2 = CGAL::cross_product(u, v).squared_length();
    const FT cross_d2 = CGAL::cross_product(s, t).squared_length();
    // sin(gamma_c + gamma_d) ~ X = |cross_c| dot_d + dot_c |cross_d|; the edge fails when X < 0
    const CGAL::Sign first = CGAL::sign(dot_d) * (cross_c2 == 0 ? CGAL::ZERO : CGAL::POSITIVE);
    const CGAL::Sign second = CGAL::sign(dot_c) * (cross_d2 == 0 ? CGAL::ZERO : CGAL::POSITIVE);
    CGAL::Sign x = CGAL::ZERO;
    if (first == second || second == CGAL::ZERO) {
        x = first;
    } else if (first == CGAL::ZERO) {
        x = second;
    } else {
        // opposite signs: the larger magnitude wins, compared by squares
        const CGAL::Comparison_result larger =
            CGAL::compare(cross_c2 * dot_d * dot_d, dot_c * dot_c * cross_d2);
        x = larger == CGAL::LARGER ? first : larger == CGAL::SMALLER ? second : CGAL::ZERO;
    }
    if (x != CGAL::ZERO) return to_sign(CGAL::opposite(x));
    // sin = 0: the sum is 0 or pi or 2 pi; it is pi exactly when the cosine is -1, i.e. the two
    // angles' cosines have opposite signs or both are 0 (two right angles); 2 pi cannot happen
    // for angles of at most pi each unless both are pi (flat triangles): also "more than pi" no.
    const CGAL::Sign cos_c = CGAL::sign(dot_c), cos_d = CGAL::sign(dot_d);
    if (cos_c == CGAL::ZERO && cos_d == CGAL::ZERO) return Sign::zero;
    if (cos_c != cos_d && cos_c != CGAL::ZERO && cos_d != CGAL::ZERO) return Sign::zero;
    // both angles 0 (sum 0: legal) or both pi (sum 2 pi: fails)
    return cos_c == CGAL::NEGATIVE ? Sign::positive : Sign::negative;
}

bool collinear(const Point& a, const Point& b, const Point& c) {
    return CGAL::collinear(to_cgal_3(a), to_cgal_3(b), to_cgal_3(c));
}

Sign normal_alignment(const Point& a, const Point& b, const Point& c, const Point& d,
                      const Point& e, const Point& f) {
    using P = detail::ExactKernel::Point_3;
    auto exact = [](const Point& p) { return P(p[0], p[1], p[2]); };
    const auto n0 = CGAL::cross_product(exact(b) - exact(a), exact(c) - exact(a));
    const auto n1 = CGAL::cross_product(exact(e) - exact(d), exact(f) - exact(d));
    return to_sign(CGAL::sign(n0 * n1));
}

bool segment_meets_triangle(const Point& a, const Point& b, const Point& p, const Point& q,
                            const Point& r) {
    using K = detail::Kernel;
    const K::Point_3 x = to_cgal_3(a), y = to_cgal_3(b);
    const K::Point_3 t0 = to_cgal_3(p), t1 = to_cgal_3(q), t2 = to_cgal_3(r);
    if (CGAL::collinear(t0, t1, t2)) {
        // CGAL's triangle tests need a proper triangle: use its longest side (squared lengths
        // compared in doubles only pick which side; the side covers the others when collinear)
        K::Point_3 e0 = t0, e1 = t1;
        const auto d01 = CGAL::squared_distance(t0, t1), d02 = CGAL::squared_distance(t0, t2),
                   d12 = CGAL::squared_distance(t1, t2);
        if (d02 >= d01 && d02 >= d12) e1 = t2;
        else if (d12 >= d01 && d12 >= d02) e0 = t1, e1 = t2;
        if (e0 == e1) return x == y ? x == e0 : K::Segment_3(x, y).has_on(e0);
        const K::Segment_3 side(e0, e1);
        return x == y ? side.has_on(x) : CGAL::do_intersect(side, K::Segment_3(x, y));
    }
    const K::Triangle_3 triangle(t0, t1, t2);
    return x == y ? triangle.has_on(x) : CGAL::do_intersect(triangle, K::Segment_3(x, y));
}

Sign compare_distances_to_plane(const Point& a, const Point& b, const Point& p, const Point& q,
                                const Point& r) {
    // The distances are |det[q-p, r-p, x-p]| over the same |(q-p) x (r-p)|: compare the
    // determinants' magnitudes. The lazy exact kernel decides in interval arithmetic when the
    // magnitudes are apart and in exact arithmetic only when they are (nearly) equal.
    using P = detail::ExactKernel::Point_3;
    auto exact = [](const Point& x) { return P(x[0], x[1], x[2]); };
    const P ep = exact(p);
    const auto normal = CGAL::cross_product(exact(q) - ep, exact(r) - ep);
    const auto da = CGAL::abs(normal * (exact(a) - ep));
    const auto db = CGAL::abs(normal * (exact(b) - ep));
    return to_sign(CGAL::compare(da, db));
}

Sign simplex_orientation(const Simplex& s, int ambient_dimension, std::span<const Point* const> points) {
    Sign raw;
    if (s.count() == 4) {
        raw = orient3d(*points[0], *points[1], *points[2], *points[3]);
    } else if (ambient_dimension == 2) {
        raw = orient2d(*points[0], *points[1], *points[2]);
    } else {
        // a triangle in space has no orientation of its own: only flatness (collinearity) is
        // decidable; collinear exactly when all three coordinate projections are collinear
        return collinear(*points[0], *points[1], *points[2]) ? Sign::zero : Sign::positive;
    }
    if (raw == Sign::zero) return raw;
    return (static_cast<int>(raw) * s.sign() > 0) ? Sign::positive : Sign::negative;
}

Sign element_orientation(const Mesh& mesh, ElementId t, Positions positions) {
    const Simplex& s = mesh.simplex(t);
    std::array<const Point*, 4> points{};
    for (int j = 0; j < s.count(); ++j)
        points[static_cast<std::size_t>(j)] =
            positions == Positions::reference ? &mesh.reference(s.vertex(j)) : &mesh.deformed(s.vertex(j));
    return simplex_orientation(s, mesh.ambient_dimension(), {points.data(), static_cast<std::size_t>(s.count())});
}

}  // namespace sxk
