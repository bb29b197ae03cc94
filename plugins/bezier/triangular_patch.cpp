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

// Pascal's triangle up to row `rows`: binomial(a, b) = table[a * (rows + 1) + b]. Exact in
// double up to row 56 (C(56, 28) < 2^53); read_bpt's degrees need row 40.
std::vector<double> pascal(int rows) {
    const auto size = static_cast<std::size_t>(rows + 1);
    std::vector<double> table(size * size, 0.0);
    for (std::size_t a = 0; a < size; ++a) {
        table[a * size] = 1;
        for (std::size_t b = 1; b <= a; ++b)
            table[a * size + b] = table[(a - 1) * size + b - 1] + table[(a - 1) * size + b];
    }
    return table;
}

// Q(x) = P(u(x), v(x)) over a triangle whose corners have u and v in {0, 1} (the two halves of
// the unit square). Goldman–Filip by products of Bernstein polynomials: with x the barycentric
// coordinates of the triangle,
//   P(x) = sum_b B_b^n(v(x)) Q_b(x),   Q_b(x) = sum_a B_a^m(u(x)) P_ab.
// Q_b, a curve in the affine function u(x), has the triangular Bernstein coefficients
// q_beta = (its blossom at beta_0 copies of u(A), beta_1 of u(B), beta_2 of u(C)) =
// P_(beta . u_corners) b, as the blossom of a Bézier curve at p zeros and q ones is its control
// point q; likewise B_b^n(v(x)) has the coefficient 1 at the alpha with alpha . v_corners = b
// and 0 elsewhere. The product rule B_alpha^n B_beta^m = [M(n,alpha) M(m,beta) / M(m+n,
// alpha+beta)] B_(alpha+beta)^(m+n) (M: multinomials) then gives, for gamma = alpha + beta,
//   c_gamma = sum_(alpha + beta = gamma) C(gamma_0,beta_0) C(gamma_1,beta_1) C(gamma_2,beta_2)
//             / C(m+n, m) * P_(beta . u_corners)(alpha . v_corners),
// a convex combination (Vandermonde: the weights of one gamma sum to 1). It is the blossom
// formula (c_gamma the average of the tensor blossom over the ways to give m of gamma's m + n
// corner arguments to u) with each blossom at corner arguments read off as a control point
// instead of evaluated by de Casteljau: (m+1)(m+2)/2 x (n+1)(n+2)/2 terms, 53,361 for 20 x 20,
// where one blossom per term cost O(m n (m + n)) more.
TriangularPatch triangle_of(const TensorPatch& patch,
                            const std::array<std::array<int, 2>, 3>& corners) {
    const int m = patch.degree_u, n = patch.degree_v, degree = m + n;
    const std::vector<double> binomials = pascal(degree);
    const auto binomial = [&](int a, int b) {
        return binomials[static_cast<std::size_t>(a) * static_cast<std::size_t>(degree + 1) +
                         static_cast<std::size_t>(b)];
    };
    const double total = binomial(degree, m);
    std::vector<Point> points(net_size(degree), Point{0, 0, 0});
    for (int b2 = 0; b2 <= m; ++b2)
        for (int b1 = 0; b1 <= m - b2; ++b1) {
            const std::array<int, 3> beta{m - b1 - b2, b1, b2};
            const int a_index =
                beta[0] * corners[0][0] + beta[1] * corners[1][0] + beta[2] * corners[2][0];
            for (int a2 = 0; a2 <= n; ++a2)
                for (int a1 = 0; a1 <= n - a2; ++a1) {
                    const std::array<int, 3> alpha{n - a1 - a2, a1, a2};
                    const int b_index = alpha[0] * corners[0][1] + alpha[1] * corners[1][1] +
                                        alpha[2] * corners[2][1];
                    const double weight = binomial(alpha[0] + beta[0], beta[0]) *
                                          binomial(alpha[1] + beta[1], beta[1]) *
                                          binomial(alpha[2] + beta[2], beta[2]) / total;
                    const Point& p =
                        patch.points[static_cast<std::size_t>(a_index * (n + 1) + b_index)];
                    Point& c = points[net_index(degree, a1 + b1, a2 + b2)];
                    for (std::size_t q = 0; q < 3; ++q)
                        c[q] += weight * p[q];
                }
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
