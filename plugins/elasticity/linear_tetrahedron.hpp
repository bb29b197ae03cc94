// The linear tetrahedron of thesis §3.1: its rest shape, and its elastic forces for given corner
// displacements.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "elastic_body.hpp"

namespace sxk::elasticity::detail {

// Z of simplex s in reference positions: the edges from its corner 3 to corners 0, 1, 2 as
// columns (§3.1).
inline Eigen::Matrix3d edge_matrix(const Mesh& mesh, const Simplex& s) {
    Eigen::Matrix3d z;
    const Point& origin = mesh.reference(s.vertex(3));
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
            z(k, j) = mesh.reference(s.vertex(j))[static_cast<std::size_t>(k)] - origin[static_cast<std::size_t>(k)];
    return z;
}

// The rest shape (without its material) of the element whose edge matrix is z.
inline RestShape rest_shape(const Eigen::Matrix3d& z) {
    const Eigen::Matrix3d inverse = z.inverse();
    RestShape rest;
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) rest.gradient[static_cast<std::size_t>(3 * j + k)] = inverse(j, k);
    rest.volume = std::abs(z.determinant()) / 6;
    return rest;
}

// K_t d for one element (of material rest.lame): out[3j..3j+2] is the force on corner j that the
// displacements d (d[3j..3j+2]: corner j's) call for, i.e. the elastic force of eq. 3.4 with its
// sign reversed:
//
//     G = U Z^-1 = sum_j (d_j - d_3) b_j^T, E = (G + G^T) / 2, T = 2 mu E + lambda trace(E) I,
//     out_j = volume T b_j (j = 0, 1, 2), out_3 = -(out_0 + out_1 + out_2).
//
// (The thesis numbers the corners 1..4 and measures from corner 4; here corner 3.) Written out
// on scalars with the symmetry of T: the same product with Eigen's 3 x 3 matrices (G = U Z^-1,
// volume T Z^-T) took 60% of a CG iteration on the thesis' cube and was not inlined; this form
// is about twice as fast (docs/elasticity.md "Speed").
inline void linear_tetrahedron_forces(const RestShape& rest, const double* d, double* out) {
    const Lame& lame = rest.lame;
    const double* b = rest.gradient.data();
    double g[3][3] = {};
    for (int j = 0; j < 3; ++j) {
        const double w[3] = {d[3 * j] - d[9], d[3 * j + 1] - d[10], d[3 * j + 2] - d[11]};
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) g[i][k] += w[i] * b[3 * j + k];
    }
    const double v = rest.volume, trace = g[0][0] + g[1][1] + g[2][2];
    const double two_mu = 2 * lame.mu * v, lambda = lame.lambda * trace * v, mu = lame.mu * v;
    const double t[3][3] = {{two_mu * g[0][0] + lambda, mu * (g[0][1] + g[1][0]), mu * (g[0][2] + g[2][0])},
                            {mu * (g[0][1] + g[1][0]), two_mu * g[1][1] + lambda, mu * (g[1][2] + g[2][1])},
                            {mu * (g[0][2] + g[2][0]), mu * (g[1][2] + g[2][1]), two_mu * g[2][2] + lambda}};
    double last[3] = {0, 0, 0};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const double f = t[i][0] * b[3 * j] + t[i][1] * b[3 * j + 1] + t[i][2] * b[3 * j + 2];
            out[3 * j + i] = f;
            last[i] -= f;
        }
    for (int i = 0; i < 3; ++i) out[9 + i] = last[i];
}

}  // namespace sxk::elasticity::detail
