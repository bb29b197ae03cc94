// Triangular Bézier patches (triangular_patch.hpp; Roth §4.4).
#include "triangular_patch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "de_casteljau.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {

Point combination(double a, const Point& p, double b, const Point& q, double c, const Point& r) {
    return {a * p[0] + b * q[0] + c * r[0], a * p[1] + b * q[1] + c * r[1], a * p[2] + b * q[2] + c * r[2]};
}

double binomial(int n, int k) {
    double b = 1;
    for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
    return b;
}

}  // namespace

TriangularPatch::TriangularPatch(int degree, std::vector<Point> control_points)
    : m_degree(degree), m_points(std::move(control_points)) {
    if (degree < 0 || m_points.size() != net_size(degree))
        throw std::invalid_argument("TriangularPatch: degree " + std::to_string(degree) + " needs " +
                                    std::to_string(degree < 0 ? 0 : net_size(degree)) + " control points, not " +
                                    std::to_string(m_points.size()));
}

std::size_t TriangularPatch::index(int degree, int j, int k) { return net_index(degree, j, k); }

TriangularPatch TriangularPatch::step(const Barycentric& x) const {
    if (m_degree == 0) throw std::invalid_argument("TriangularPatch: a patch of degree 0 has no de Casteljau step");
    std::vector<Point> next(net_size(m_degree - 1));
    de_casteljau_step(m_degree, m_points.data(), x, next.data());
    return TriangularPatch(m_degree - 1, std::move(next));
}

TriangularPatch TriangularPatch::blossom(std::span<const Barycentric> arguments) const {
    TriangularPatch result = *this;
    for (const Barycentric& x : arguments) result = result.step(x);
    return result;
}

Point TriangularPatch::evaluate(const Barycentric& at) const {
    std::vector<Point> net = m_points;
    return evaluate_in_place(m_degree, net.data(), at);
}

Point TriangularPatch::derivative(const Barycentric& at, const Barycentric& direction) const {
    if (m_degree == 0) return {0, 0, 0};
    std::vector<Point> net = m_points;
    de_casteljau_step(m_degree, net.data(), direction, net.data());
    const Point d = evaluate_in_place(m_degree - 1, net.data(), at);
    return {m_degree * d[0], m_degree * d[1], m_degree * d[2]};
}

Point TriangularPatch::normal(const Barycentric& at) const {
    constexpr Barycentric du{-1, 1, 0}, dv{-1, 0, 1};
    const Barycentric centroid{1.0 / 3, 1.0 / 3, 1.0 / 3};
    // at itself first, then points from the centroid side ever closer to it
    for (double inward = 0; inward < 1; inward = inward == 0 ? 1e-9 : inward * 10) {
        const Barycentric x{(1 - inward) * at[0] + inward * centroid[0], (1 - inward) * at[1] + inward * centroid[1],
                            (1 - inward) * at[2] + inward * centroid[2]};
        const Point a = derivative(x, du), b = derivative(x, dv);
        const Point n = cross(a, b);
        const double length = norm(n);
        // parallel or vanishing derivatives: no tangent plane here
        if (length > 1e-12 * norm(a) * norm(b) && length > 0) return {n[0] / length, n[1] / length, n[2] / length};
    }
    return {0, 0, 0};
}

TriangularPatch TriangularPatch::subdivided(const Barycentric& r, const Barycentric& s, const Barycentric& t) const {
    std::vector<Point> points;
    NetScratch scratch;
    subdivide_net(m_degree, m_points, {r, s, t}, points, scratch);
    return TriangularPatch(m_degree, std::move(points));
}

TriangularPatch TriangularPatch::elevated() const {
    const int n = m_degree + 1;
    std::vector<Point> points(net_size(n), Point{0, 0, 0});
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n - k; ++j) {
            const int i = n - j - k;
            Point& c = points[index(n, j, k)];
            auto add = [&](double w, const Point& p) {
                for (std::size_t q = 0; q < 3; ++q) c[q] += w * p[q];
            };
            if (i > 0) add(static_cast<double>(i) / n, control_point(j, k));
            if (j > 0) add(static_cast<double>(j) / n, control_point(j - 1, k));
            if (k > 0) add(static_cast<double>(k) / n, control_point(j, k - 1));
        }
    return TriangularPatch(n, std::move(points));
}

namespace {

// The tensor patch's blossom f(u_1..u_m; v_1..v_n): de Casteljau steps with u_1..u_m along u,
// then v_1..v_n along v (multi-affine in each set, symmetric within it).
Point tensor_blossom(const TensorPatch& patch, std::span<const double> us, std::span<const double> vs) {
    const int m = patch.degree_u, n = patch.degree_v;
    std::vector<Point> column(static_cast<std::size_t>(n + 1));
    std::vector<Point> row(static_cast<std::size_t>(m + 1));
    for (int b = 0; b <= n; ++b) {
        for (int a = 0; a <= m; ++a) row[static_cast<std::size_t>(a)] = patch.points[static_cast<std::size_t>(a * (n + 1) + b)];
        for (int level = m; level > 0; --level) {
            const double u = us[static_cast<std::size_t>(m - level)];
            for (int a = 0; a < level; ++a)
                row[static_cast<std::size_t>(a)] = combination(1 - u, row[static_cast<std::size_t>(a)], u,
                                                               row[static_cast<std::size_t>(a + 1)], 0, row[0]);
        }
        column[static_cast<std::size_t>(b)] = row[0];
    }
    for (int level = n; level > 0; --level) {
        const double v = vs[static_cast<std::size_t>(n - level)];
        for (int b = 0; b < level; ++b)
            column[static_cast<std::size_t>(b)] = combination(1 - v, column[static_cast<std::size_t>(b)], v,
                                                              column[static_cast<std::size_t>(b + 1)], 0, column[0]);
    }
    return column[0];
}

// Q(x) = P(A x_r + B x_s + C x_t) has total degree m + n; its blossom at i copies of A, j of
// B and k of C (the control point c_ijk over the triangle A B C) is the average of the tensor
// blossom over the ways to give m of those m + n arguments to u and the rest to v.
TriangularPatch triangle_of(const TensorPatch& patch, const std::array<std::array<double, 2>, 3>& corners) {
    const int m = patch.degree_u, n = patch.degree_v, degree = m + n;
    std::vector<Point> points(net_size(degree));
    std::vector<double> us, vs;
    for (int k = 0; k <= degree; ++k)
        for (int j = 0; j <= degree - k; ++j) {
            const int i = degree - j - k;
            const std::array<int, 3> copies{i, j, k};
            Point sum{0, 0, 0};
            for (int a = 0; a <= std::min(i, m); ++a)
                for (int b = 0; b <= std::min(j, m - a); ++b) {
                    const int c = m - a - b;
                    if (c > k) continue;
                    const std::array<int, 3> to_u{a, b, c};
                    const double weight = binomial(i, a) * binomial(j, b) * binomial(k, c) / binomial(degree, m);
                    us.clear();
                    vs.clear();
                    for (std::size_t corner = 0; corner < 3; ++corner) {
                        us.insert(us.end(), static_cast<std::size_t>(to_u[corner]), corners[corner][0]);
                        vs.insert(vs.end(), static_cast<std::size_t>(copies[corner] - to_u[corner]), corners[corner][1]);
                    }
                    const Point f = tensor_blossom(patch, us, vs);
                    for (std::size_t q = 0; q < 3; ++q) sum[q] += weight * f[q];
                }
            points[TriangularPatch::index(degree, j, k)] = sum;
        }
    return TriangularPatch(degree, std::move(points));
}

}  // namespace

Point TensorPatch::evaluate(double u, double v) const {
    const std::vector<double> us(static_cast<std::size_t>(degree_u), u), vs(static_cast<std::size_t>(degree_v), v);
    return tensor_blossom(*this, us, vs);
}

std::vector<TriangularPatch> to_triangular(const std::vector<TensorPatch>& patches) {
    std::vector<TriangularPatch> halves;
    halves.reserve(2 * patches.size());
    for (const TensorPatch& patch : patches)
        for (TriangularPatch& half : to_triangular(patch)) halves.push_back(std::move(half));
    return halves;
}

std::array<TriangularPatch, 2> to_triangular(const TensorPatch& patch) {
    if (patch.degree_u < 0 || patch.degree_v < 0 ||
        patch.points.size() != static_cast<std::size_t>((patch.degree_u + 1) * (patch.degree_v + 1)))
        throw std::invalid_argument("TensorPatch: degrees " + std::to_string(patch.degree_u) + " x " +
                                    std::to_string(patch.degree_v) + " need " +
                                    std::to_string((patch.degree_u + 1) * (patch.degree_v + 1)) +
                                    " control points, not " + std::to_string(patch.points.size()));
    return {triangle_of(patch, {{{0, 0}, {1, 0}, {1, 1}}}), triangle_of(patch, {{{0, 0}, {1, 1}, {0, 1}}})};
}

}  // namespace sxk::bezier
