// De Casteljau on flat arrays of control points, without allocation: the kernels that
// TriangularPatch (evaluation, subdivision) and Bézier clipping (the ray-frame nets) share.
// Internal to the plug-in.
//
// A net of degree n holds (n+1)(n+2)/2 points b_ijk (i + j + k = n) in rows of constant k, j
// running along each row: net_index(n, j, k) = k(n+1) - k(k-1)/2 + j, i = n - j - k.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "sxk/mesh.hpp"  // sxk::Point

namespace sxk::bezier {

using Barycentric = std::array<double, 3>;

// In std::size_t: a tessellation's grid of 2^32 vertices is indexed like a net.
inline std::size_t net_size(int degree) {
    const auto n = static_cast<std::size_t>(degree);
    return (n + 1) * (n + 2) / 2;
}
inline std::size_t net_index(int degree, int j, int k) {
    const auto n = static_cast<std::size_t>(degree), row = static_cast<std::size_t>(k);
    return row * (n + 1) - row * (row - 1) / 2 + static_cast<std::size_t>(j);  // row 0: 0 * wrap = 0
}

// One de Casteljau step of the net a (degree m >= 1) with respect to x (a point or a direction)
// into b (degree m - 1): c_ijk = x_r b_(i+1)jk + x_s b_i(j+1)k + x_t b_ij(k+1). b may be a.
void de_casteljau_step(int m, const Point* a, const Barycentric& x, Point* b);

// The value at x of the net of degree n held in `net`, which the steps overwrite.
Point evaluate_in_place(int n, Point* net, const Barycentric& x);

// The net over the triangle whose corner `corner` (0: r, 1: s, 2: t) moved to the domain point
// x, the other two staying: one de Casteljau pyramid at x, O(n^3) (the new net's points are the
// pyramid's entries with 0 in the moved corner's slot). `level` is scratch space.
void move_corner(int n, std::span<const Point> net, int corner, const Barycentric& x, std::vector<Point>& out,
                 std::vector<Point>& level);

// Scratch space for subdivide_net and middle_quarter, kept by callers that subdivide often.
struct NetScratch {
    std::vector<Point> a, b, c;
};

// The net over the middle quarter (BC, CA, AB) of the domain, B C the midpoint of corners s and
// t and so on (the middle child of Roth's four-way split, §6.4): c_ijk = b[BC^i CA^j AB^k]. No
// three convex corner moves reach that triangle, and the general blossom costs O(n^5); but each
// argument lies on an edge, so its de Casteljau steps act along lines of the net (AB keeps the
// t index, CA the s index, BC the r index): AB's steps as a pyramid over the net, O(n^3), then
// per level CA's and BC's as univariate pyramids at 1/2 along lines, O(n^4) in all, every step
// an average.
void middle_quarter(int n, std::span<const Point> net, std::vector<Point>& out,
                    NetScratch& scratch);

// The net over the sub-triangle (R, S, T) of the domain (eq. 4.33): c_ijk = b[R^i, S^j, T^k],
// R, S, T anywhere (outside the domain too). By three corner moves of O(n^3) each where every
// move is a convex combination (r to R, then s to S and t to T, each written in the coordinates
// of the triangle so far; true of the candidates Bézier clipping keeps and of three of the four
// quarters of a split); otherwise by the blossom directly, sharing the steps with T among all
// c_ijk of one k and the steps with S among those of one (j, k).
void subdivide_net(int n, std::span<const Point> net, const std::array<Barycentric, 3>& sub,
                   std::vector<Point>& out, NetScratch& scratch);

}  // namespace sxk::bezier
