// The elements of the body: their rest shapes, and the forces of the linear element (thesis §3.1,
// eq. 3.4; triangles in plane stress, §6.3) and of the compressible neo-Hookean element (§4.3.3,
// eq. 4.6) for given corner displacements. D is the dimension: tetrahedra (3) or triangles (2).
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "elastic_body.hpp"

namespace sxk::elasticity::detail {

// Z of simplex s in reference positions: the edges from its last corner D to corners 0..D-1 as
// columns (§3.1).
template <int D>
Eigen::Matrix<double, D, D> edge_matrix(const Mesh& mesh, const Simplex& s) {
    Eigen::Matrix<double, D, D> z;
    const Point& origin = mesh.reference(s.vertex(D));
    for (int j = 0; j < D; ++j)
        for (int k = 0; k < D; ++k)
            z(k, j) = mesh.reference(s.vertex(j))[static_cast<std::size_t>(k)] -
                      origin[static_cast<std::size_t>(k)];
    return z;
}

// The rest shape (without its material) of the element whose edge matrix is z; a triangle's
// volume is its area times `thickness`.
template <int D>
RestShape rest_shape(const Eigen::Matrix<double, D, D>& z, double thickness) {
    const Eigen::Matrix<double, D, D> inverse = z.inverse();
    RestShape rest;
    for (int j = 0; j < D; ++j)
        for (int k = 0; k < D; ++k)
            rest.gradient[static_cast<std::size_t>(3 * j + k)] = inverse(j, k);
    rest.volume =
        D == 3 ? std::abs(z.determinant()) / 6 : std::abs(z.determinant()) / 2 * thickness;
    return rest;
}

// G = U Z^-1 = sum_j (d_j - d_D) b_j^T, the displacement gradient of corner displacements d
// (3 per corner, x y z; a triangle's z ignored).
template <int D>
Eigen::Matrix<double, D, D> displacement_gradient(const RestShape& rest, const double* d) {
    Eigen::Matrix<double, D, D> g = Eigen::Matrix<double, D, D>::Zero();
    for (int j = 0; j < D; ++j)
        for (int i = 0; i < D; ++i) {
            const double w = d[3 * j + i] - d[3 * D + i];
            for (int k = 0; k < D; ++k)
                g(i, k) += w * rest.gradient[static_cast<std::size_t>(3 * j + k)];
        }
    return g;
}

// out_j = T b_j for corners j < D and out_D = -(out_0 + ... + out_{D-1}), T a D x D stress
// already multiplied by the volume: the nodal forces T Z^-T of §3.1 (3 per corner; z = 0 for a
// triangle).
template <int D>
void corner_forces(const RestShape& rest, const Eigen::Matrix<double, D, D>& t, double* out) {
    const double* b = rest.gradient.data();
    double last[3] = {0, 0, 0};
    for (int j = 0; j < D; ++j) {
        for (int i = 0; i < D; ++i) {
            double f = 0;
            for (int k = 0; k < D; ++k)
                f += t(i, k) * b[3 * j + k];
            out[3 * j + i] = f;
            last[i] -= f;
        }
        if constexpr (D == 2)
            out[3 * j + 2] = 0;
    }
    for (int i = 0; i < 3; ++i)
        out[3 * D + i] = last[i];
}

// K_t d for one linear element (of material rest.lame): the force on each corner that the
// displacements d call for, i.e. the elastic force of eq. 3.4 with its sign reversed:
//
//     E = (G + G^T) / 2, T = 2 mu E + lambda trace(E) I, out_j = volume T b_j.
//
// (The thesis numbers the corners from 1 and measures from the last; here from 0.)
//
// The tetrahedron's is written out on scalars with the symmetry of T, in a function of its own:
// the same product on Eigen's dynamic 3 x 3 matrices took twice as long per CG iteration, and
// so did a template over D with this body inside (femur, 213k tets, two threads: 7.5 against
// 4.9-5.0 ms per product, one thread 11.7 against 9.8; docs/elasticity.md "Speed").
inline void linear_tetrahedron_forces(const RestShape& rest, const double* d, double* out) {
    const Lame& lame = rest.lame;
    const double* b = rest.gradient.data();
    double g[3][3] = {};
    for (int j = 0; j < 3; ++j) {
        const double w[3] = {d[3 * j] - d[9], d[3 * j + 1] - d[10], d[3 * j + 2] - d[11]};
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                g[i][k] += w[i] * b[3 * j + k];
    }
    const double v = rest.volume, trace = g[0][0] + g[1][1] + g[2][2];
    const double two_mu = 2 * lame.mu * v, lambda = lame.lambda * trace * v, mu = lame.mu * v;
    const double t[3][3] = {
        {two_mu * g[0][0] + lambda, mu * (g[0][1] + g[1][0]), mu * (g[0][2] + g[2][0])},
        {mu * (g[0][1] + g[1][0]), two_mu * g[1][1] + lambda, mu * (g[1][2] + g[2][1])},
        {mu * (g[0][2] + g[2][0]), mu * (g[1][2] + g[2][1]), two_mu * g[2][2] + lambda}};
    double last[3] = {0, 0, 0};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const double f = t[i][0] * b[3 * j] + t[i][1] * b[3 * j + 1] + t[i][2] * b[3 * j + 2];
            out[3 * j + i] = f;
            last[i] -= f;
        }
    for (int i = 0; i < 3; ++i)
        out[9 + i] = last[i];
}

// The triangle's, in plane stress: its lambda is the plane-stress one (eq. 6.3), set in its rest
// shape.
inline void linear_triangle_forces(const RestShape& rest, const double* d, double* out) {
    const Eigen::Matrix2d g = displacement_gradient<2>(rest, d);
    Eigen::Matrix2d t = (rest.lame.mu * rest.volume) * (g + g.transpose());
    t.diagonal().array() += rest.lame.lambda * rest.volume * g.trace();
    corner_forces<2>(rest, t, out);
}

template <int D>
void linear_element_forces(const RestShape& rest, const double* d, double* out) {
    if constexpr (D == 3)
        linear_tetrahedron_forces(rest, d, out);
    else
        linear_triangle_forces(rest, d, out);
}

// Row j of a linear element's stiffness as 3 x 3 blocks (row-major): block l is the force on
// corner j per unit displacement of corner l. With G = sum_l d_l b_l^T (b_D = -(b_0 + ... +
// b_{D-1})), out_j = volume T b_j above is linear in each d_l:
//
//     K_jl = volume (mu (b_j . b_l) I + mu b_l b_j^T + lambda b_j b_l^T)
//
// (a triangle's I is the plane's: its z row and column are zero, as its forces' z are). For a
// region's assembled product (LocalRelaxation); the element-by-element product above stays the
// whole body's (no matrix to rebuild when the mesh changes).
template <int D>
void linear_element_row(const RestShape& rest, int j, std::array<std::array<double, 9>, 4>& blocks) {
    std::array<std::array<double, 3>, D + 1> b{};  // the corners' gradients
    for (int k = 0; k < D; ++k)
        for (std::size_t i = 0; i < 3; ++i) {
            const double g = rest.gradient[3 * static_cast<std::size_t>(k) + i];
            b[static_cast<std::size_t>(k)][i] = g;
            b[D][i] -= g;
        }
    const double v = rest.volume, mu = rest.lame.mu * v, lambda = rest.lame.lambda * v;
    const std::array<double, 3>& bj = b[static_cast<std::size_t>(j)];
    for (std::size_t l = 0; l <= D; ++l) {
        const std::array<double, 3>& bl = b[l];
        double dot = 0;
        for (std::size_t a = 0; a < D; ++a) dot += bj[a] * bl[a];
        std::array<double, 9>& block = blocks[l];
        block.fill(0);  // a triangle's z row and column stay zero
        for (std::size_t a = 0; a < D; ++a) {
            for (std::size_t c = 0; c < D; ++c) block[3 * a + c] = mu * bl[a] * bj[c] + lambda * bj[a] * bl[c];
            block[4 * a] += mu * dot;
        }
    }
}

// The neo-Hookean element of eq. 4.6, W = 1/2 (mu (trace C - D) - mu ln det C + lambda (J - 1)^2)
// with C = F^T F, F = I + G, J = det F: out_j = volume P b_j, P = dW/dF = mu (F - F^-T) +
// lambda (J - 1) J F^-T the first Piola-Kirchhoff stress (the gradient of the element's strain
// energy), and the element's strain energy volume W. For small G this is the linear element.
// Triangles use the 2D analogue (§6.3, eq. 6.4) with the plane-stress lambda: exact for nu = 0,
// and the plane-stress linear element for small strains. Returns false (out and energy
// untouched) when the element is inverted or flat at d (J <= 0: W is infinite there).
template <int D>
bool neo_hookean_forces(const RestShape& rest, const double* d, double* out, double& energy) {
    const Eigen::Matrix<double, D, D> f =
        Eigen::Matrix<double, D, D>::Identity() + displacement_gradient<D>(rest, d);
    const double j = f.determinant();
    if (!(j > 0))
        return false;
    const Eigen::Matrix<double, D, D> inverse_transpose = f.inverse().transpose();
    const double mu = rest.lame.mu, lambda = rest.lame.lambda, v = rest.volume;
    const Eigen::Matrix<double, D, D> p =
        mu * (f - inverse_transpose) + (lambda * (j - 1) * j) * inverse_transpose;
    corner_forces<D>(rest, (v * p).eval(), out);
    energy =
        v * 0.5 * (mu * (f.squaredNorm() - D) - 2 * mu * std::log(j) + lambda * (j - 1) * (j - 1));
    return true;
}

}  // namespace sxk::elasticity::detail
