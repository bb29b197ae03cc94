// The assembled reference: K from the element stiffnesses, reduced to the allowed motions and
// solved with Eigen's ConjugateGradient (solve.hpp).
#include <chrono>
#include <cmath>

#include <Eigen/IterativeLinearSolvers>

#include "solve.hpp"

namespace sxk::elasticity {

Eigen::SparseMatrix<double> assemble_stiffness(const ElasticBody& body) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(144 * body.elements().size());
    for (const ElementId t : body.elements()) {
        const Eigen::Matrix<double, 12, 12> k = body.element_stiffness(t);
        const Simplex& s = body.mesh().simplex(t);
        const int size = 3 * s.count();
        for (int a = 0; a < size; ++a)
            for (int b = 0; b < size; ++b)
                entries.emplace_back(static_cast<int>(3 * s.vertex(a / 3)) + a % 3,
                                     static_cast<int>(3 * s.vertex(b / 3)) + b % 3, k(a, b));
    }
    const auto n = static_cast<Eigen::Index>(body.dof_count());
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());  // sums the duplicates
    return matrix;
}

Outcome<SolveReport> solve_assembled_cg(ElasticBody& body, const SolveOptions& options) {
    if (auto ready = detail::prepare_solve(body); !ready)
        return ready.refusal();
    const auto start = std::chrono::steady_clock::now();
    // B: one orthonormal column per allowed motion (3 for a free vertex, 2 in a planar body, its
    // line for a line vertex, none for a fixed one or one in no element, whose rows of K are
    // empty), so that ||B^T r|| = ||P r||
    std::vector<Eigen::Triplet<double>> basis;
    int columns = 0;
    for (VertexId v = 0; v < body.vertex_count(); ++v) {
        if (v >= body.mesh().vertex_count() || body.mesh().vertex_element(v) == invalid_id)
            continue;
        const auto row = static_cast<int>(3 * v);
        switch (body.freedom(v)) {
            case Freedom::free:
                for (int k = 0; k < body.dimension(); ++k)
                    basis.emplace_back(row + k, columns++, 1.0);
                break;
            case Freedom::line: {
                const Vector3 l = body.line_direction(v);
                for (int k = 0; k < 3; ++k)
                    basis.emplace_back(row + k, columns, l[static_cast<std::size_t>(k)]);
                ++columns;
                break;
            }
            case Freedom::fixed:
                break;
        }
    }
    const auto n = static_cast<Eigen::Index>(body.dof_count());
    Eigen::SparseMatrix<double> b(n, columns);
    b.setFromTriplets(basis.begin(), basis.end());
    const Eigen::SparseMatrix<double> k = assemble_stiffness(body);
    const Eigen::SparseMatrix<double> reduced = Eigen::SparseMatrix<double>(b.transpose() * k) * b;
    auto u = body.displacements();
    Eigen::VectorXd ku = k * u;
    SolveReport report;
    report.threshold = detail::stop_threshold(body, options, ku);
    const Eigen::VectorXd rhs = b.transpose() * (body.forces() - ku);
    report.history.push_back(rhs.norm());
    if (rhs.norm() > report.threshold) {
        Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
        cg.setMaxIterations(static_cast<Eigen::Index>(options.max_iterations));
        cg.setTolerance(report.threshold / rhs.norm());
        cg.compute(reduced);
        const Eigen::VectorXd s = cg.solve(rhs);
        u += b * s;
        report.iterations = static_cast<std::size_t>(cg.iterations());
        ku = k * u;
    }
    Eigen::VectorXd r = body.forces() - ku;
    body.project(r);
    report.residual = r.norm();
    report.history.push_back(report.residual);
    // Eigen stops on its own residual, recomputed here: allow its last rounding
    report.converged = report.residual <= report.threshold * (1 + 1e-6);
    report.energy = 0.5 * u.dot(ku) - body.forces().dot(u);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace sxk::elasticity
