// De Casteljau kernels on flat arrays (de_casteljau.hpp).
#include "de_casteljau.hpp"

#include <cmath>

namespace sxk::bezier {

void de_casteljau_step(int m, const Point* a, const Barycentric& x, Point* b) {
    // Rows of constant k run from a[row] (j = 0); the row above starts m + 1 - k entries later.
    // Each output lies at or before every input still to be read, so b may be a.
    const double x0 = x[0], x1 = x[1], x2 = x[2];
    std::size_t row = 0, out = 0;
    for (int k = 0; k < m; ++k) {
        const std::size_t length = static_cast<std::size_t>(m - k);  // outputs in this row
        const Point* p = a + row;
        const Point* u = a + row + length + 1;
        Point* c = b + out;
        for (std::size_t j = 0; j < length; ++j) {
            const double v0 = x0 * p[j][0] + x1 * p[j + 1][0] + x2 * u[j][0];
            const double v1 = x0 * p[j][1] + x1 * p[j + 1][1] + x2 * u[j][1];
            const double v2 = x0 * p[j][2] + x1 * p[j + 1][2] + x2 * u[j][2];
            c[j] = {v0, v1, v2};
        }
        row += length + 1;
        out += length;
    }
}

Point evaluate_in_place(int n, Point* net, const Barycentric& x) {
    for (int m = n; m > 0; --m) de_casteljau_step(m, net, x, net);
    return net[0];
}

void move_corner(int n, std::span<const Point> net, int corner, const Barycentric& x, std::vector<Point>& out,
                 std::vector<Point>& level) {
    out.resize(net_size(n));
    level.assign(net.begin(), net.end());
    for (int l = 0; l <= n; ++l) {
        const int m = n - l;  // degree of the pyramid's level l; the other two exponents sum to m
        const Point* v = level.data();
        switch (corner) {
            case 0:  // c_(l, j, k) = level entry (0, j, k), j + k = m: the last of each row k
                for (int k = 0; k <= m; ++k) out[net_index(n, m - k, k)] = v[net_index(m, m - k, k)];
                break;
            case 1:  // c_(i, l, k) = level entry (i, 0, k): the first of each row k
                for (int k = 0; k <= m; ++k) out[net_index(n, l, k)] = v[net_index(m, 0, k)];
                break;
            default:  // c_(i, j, l) = level entry (i, j, 0): row 0
                for (int j = 0; j <= m; ++j) out[net_index(n, j, l)] = v[j];
                break;
        }
        if (m > 0) de_casteljau_step(m, level.data(), x, level.data());
    }
}

void middle_quarter(int n, std::span<const Point> net, std::vector<Point>& out,
                    NetScratch& scratch) {
    const auto average = [](const Point& p, const Point& q) {
        return Point{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
    };
    out.resize(net_size(n));
    std::vector<Point>& level = scratch.a;  // the net after k steps with AB, degree m = n - k
    std::vector<Point>& line = scratch.b;
    std::vector<Point>& edge = scratch.c;
    level.assign(net.begin(), net.end());
    line.resize(static_cast<std::size_t>(n) + 1);
    const auto size = static_cast<std::size_t>(n) + 1;
    edge.resize(size * size);
    for (int k = 0; k <= n; ++k) {
        const int m = n - k;
        // edge[j * size + s]: the entry (0, s, m - j - s) of the level after j steps with CA.
        // Those steps keep s: along the line of index s (entries (r, s, m - s - r), r = 0..m - s)
        // each averages neighbours, and the entry r = 0 after j of them is the pyramid's edge.
        for (int s = 0; s <= m; ++s) {
            const int length = m - s;
            for (int r = 0; r <= length; ++r)
                line[static_cast<std::size_t>(r)] = level[net_index(m, s, length - r)];
            for (int j = 0; j <= length; ++j) {
                edge[static_cast<std::size_t>(j) * size + static_cast<std::size_t>(s)] = line[0];
                for (int r = 0; r < length - j; ++r)
                    line[static_cast<std::size_t>(r)] = average(
                        line[static_cast<std::size_t>(r)], line[static_cast<std::size_t>(r + 1)]);
            }
        }
        // then i = m - j steps with BC, which keep r = 0: the curve (0, s, i - s) at 1/2
        for (int j = 0; j <= m; ++j) {
            const int i = m - j;
            for (int s = 0; s <= i; ++s)
                line[static_cast<std::size_t>(s)] =
                    edge[static_cast<std::size_t>(j) * size + static_cast<std::size_t>(s)];
            for (int step = 0; step < i; ++step)
                for (int s = 0; s < i - step; ++s)
                    line[static_cast<std::size_t>(s)] = average(
                        line[static_cast<std::size_t>(s)], line[static_cast<std::size_t>(s + 1)]);
            out[net_index(n, j, k)] = line[0];
        }
        if (m > 0)
            de_casteljau_step(m, level.data(), {0.5, 0.5, 0}, level.data());
    }
}

namespace {

bool subdivide_by_corner_moves(int n, std::span<const Point> net, const std::array<Barycentric, 3>& sub,
                               std::vector<Point>& out, NetScratch& scratch) {
    const Barycentric& R = sub[0];
    const Barycentric& S = sub[1];
    const Barycentric& T = sub[2];
    if (!(std::abs(R[0]) > 1e-12)) return false;
    // S in (R, e_s, e_t)
    const double alpha = S[0] / R[0];
    const Barycentric s_local{alpha, S[1] - alpha * R[1], S[2] - alpha * R[2]};
    // T in (R, S, e_t): T_r = p R_r + q S_r, T_s = p R_s + q S_s
    const double det = R[0] * S[1] - R[1] * S[0];
    if (!(std::abs(det) > 1e-12)) return false;
    const double p = (T[0] * S[1] - T[1] * S[0]) / det;
    const double q = (R[0] * T[1] - R[1] * T[0]) / det;
    const Barycentric t_local{p, q, T[2] - p * R[2] - q * S[2]};
    // only convex combinations: a step with weights outside [0, 1] amplifies rounding by their
    // absolute sum, and n steps of it would lose digits the blossom keeps
    for (const Barycentric* local : {&R, &s_local, &t_local})
        for (const double w : *local)
            if (w < -1e-12) return false;
    move_corner(n, net, 0, R, scratch.a, scratch.c);
    move_corner(n, scratch.a, 1, s_local, scratch.b, scratch.c);
    move_corner(n, scratch.b, 2, t_local, out, scratch.c);
    return true;
}

void subdivide_by_blossoms(int n, std::span<const Point> net, const std::array<Barycentric, 3>& sub,
                           std::vector<Point>& out, NetScratch& scratch) {
    out.resize(net_size(n));
    std::vector<Point>& by_t = scratch.a;  // the net after k steps with T
    std::vector<Point>& by_s = scratch.b;  // ... and then j steps with S
    std::vector<Point>& by_r = scratch.c;
    by_t.assign(net.begin(), net.end());
    for (int k = 0; k <= n; ++k) {
        const int after_t = n - k;
        by_s.assign(by_t.begin(), by_t.begin() + static_cast<std::ptrdiff_t>(net_size(after_t)));
        for (int j = 0; j <= after_t; ++j) {
            const int i = after_t - j;
            by_r.assign(by_s.begin(), by_s.begin() + static_cast<std::ptrdiff_t>(net_size(i)));
            out[net_index(n, j, k)] = evaluate_in_place(i, by_r.data(), sub[0]);
            if (i > 0) de_casteljau_step(i, by_s.data(), sub[1], by_s.data());
        }
        if (after_t > 0) de_casteljau_step(after_t, by_t.data(), sub[2], by_t.data());
    }
}

}  // namespace

void subdivide_net(int n, std::span<const Point> net, const std::array<Barycentric, 3>& sub,
                   std::vector<Point>& out, NetScratch& scratch) {
    if (!subdivide_by_corner_moves(n, net, sub, out, scratch)) subdivide_by_blossoms(n, net, sub, out, scratch);
}

}  // namespace sxk::bezier
