// A relaxation confined to the part of a body around where it changed: the vertices within a few
// rings of some seed vertices (where a tool pulls, or an edit happened) are solved for, by the same
// projected CG as solve_linear_cg (thesis §6.6), while every other vertex keeps its displacement.
//
// Why: one step of a tool changes the constraints of a few vertices (the needle's nodes, §6.7),
// and a CG over the whole body costs its size per iteration, so a step on a fine mesh costs as
// many times more as the mesh is larger (docs/performance.md, the needle's latency against the
// start mesh). Confined to a region of at most N vertices, a step's solve costs what N costs on
// any mesh.
// What it gives up: the far field. The vertices outside the region stay where the last solve left
// them, so the region's rim is held and the displacement near the tool comes out somewhat
// smaller (the body is stiffer than it is) until a solve over the whole body settles it, e.g.
// Simulation::relax when the tool rests, or Simulation::relax_far's blocks catch up.
// docs/elasticity.md "Local relaxation" gives measured errors.
//
//     LocalRelaxation local;
//     auto report = local.solve(body, needle_vertices, 2000, {.tolerance = 0.01});
//     body.write_deformed(mesh, local.region());   // only what moved
//
// Nothing in a solve is proportional to the body's size: the region grows by breadth-first search
// over the mesh's stars (Mesh::walk_star, which keeps them for the region's write), the body is
// brought in step by refresh_shapes(), and the scratch is kept between solves (per vertex and per
// element id: grown, never cleared whole).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "elastic_body.hpp"
#include "sxk/detail/large_array.hpp"
#include "solve.hpp"

namespace sxk::elasticity {

struct LocalSolveReport {
    SolveReport solve;                // iterations, residual and threshold over the region
    std::size_t region_vertices = 0;  // the vertices solved for
    std::size_t rim_vertices = 0;     // their neighbours outside the region, held where they were
    std::size_t elements = 0;         // the elements around the region: the product's
    bool kept = false;  // the region and its rows of K were the last solve's (see solve())
};

class LocalRelaxation {
public:
    // At most options.max_iterations CG iterations over the region: the seeds (all of them, even
    // beyond max_vertices), then their neighbours ring by ring while the region has fewer than
    // max_vertices vertices. Seeds out of range or in no element are skipped; no seed left: nothing
    // to do (a report of zeros, converged). The stop threshold is eq. 6.9 over the region (its
    // loads and the reactions at its constrained vertices) with the rounding term of the whole
    // body. A solve for the same seeds and bound as the last, on the same body with the same shape
    // revision (ElasticBody::shape_revision: no edit heard since), keeps the last region and its rows
    // of K: a needle holding the same nodes steps through an unchanged mesh between refinements and
    // interceptions, and on the femur gathering and assembling were half of such a step. Refuses a
    // neo-Hookean body (bad_argument: its forces are not K u; solve the whole body
    // with solve_nonlinear_cg) and as refresh_shapes does; a region without a constrained vertex is
    // solved all the same (its rim holds it). The report's energy is left 0: it is a sum over the
    // whole body.
    Outcome<LocalSolveReport> solve(ElasticBody& body, std::span<const VertexId> seeds, std::size_t max_vertices,
                                    const SolveOptions& options = {});
    // Sizes the scratch kept per vertex and element id for the body's mesh as it is (with room to
    // double), which the first solve would otherwise do inside a tool's step: a setup's cost.
    void reserve(const ElasticBody& body);
    // The region of the last solve: the vertices whose displacements it may have changed.
    std::span<const VertexId> region() const { return {m_vertices.data(), m_region}; }
    // Its rim: the other corners of the region's elements, held where they were.
    std::span<const VertexId> rim() const { return {m_vertices.data() + m_region, m_vertices.size() - m_region}; }

private:
    // the region by breadth-first search from the seeds, then its elements and rim
    void gather(const ElasticBody& body, std::span<const VertexId> seeds, std::size_t max_vertices);
    // the region's rows of K, 3 x 3 blocks by row (a region vertex) and column (a local vertex),
    // summed over the stars that gather() recorded
    void assemble(const ElasticBody& body);
    // out = K d on the region's rows; the rim's rows are left zero (the projection zeroes them
    // anyway). d and out: 3 per local vertex.
    void multiply(const Eigen::VectorXd& d, Eigen::VectorXd& out) const;
    // z = P M^-1 r, M the diagonal blocks of the region's rows (block Jacobi: on the femur, whose
    // slivers make K ill-conditioned, it halves a local solve's CG iterations)
    void block_jacobi(const ElasticBody& body, const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
    // v onto the motions the region allows: the body's constraints, a planar body's z, the rim held
    void project(const ElasticBody& body, Eigen::VectorXd& v) const;
    // forgets the marks of the last gather (in time proportional to its region)
    void unmark();
    // the region and its rows of K are those of `seeds` and `max_vertices` on the body as it is
    bool made_for(const ElasticBody& body, std::span<const VertexId> seeds, std::size_t max_vertices) const;

    static constexpr std::uint32_t none = 0xffffffffu;
    // per body vertex: its local index, or none; per element id: its index in m_elements, or none
    sxk::detail::LargeVector<std::uint32_t> m_local, m_element_index;
    std::vector<VertexId> m_vertices;    // the region (m_region of them), then the rim
    std::size_t m_region = 0;
    std::vector<ElementId> m_elements;
    std::vector<std::array<std::uint32_t, 4>> m_element_corners;  // local indices, per m_elements
    // each region vertex's star: m_star[m_star_start[i] .. m_star_start[i + 1]) (m_elements indices)
    std::vector<std::uint32_t> m_star_start, m_star;
    // the region's rows of K: row i's blocks are m_blocks[m_row_start[i] .. m_row_start[i + 1]),
    // in the columns m_columns (local vertices); m_slot: per local vertex, its block in the row
    // being assembled, or none
    std::vector<std::size_t> m_row_start;
    std::vector<std::uint32_t> m_columns, m_slot;
    std::vector<std::array<double, 9>> m_blocks;
    std::vector<Eigen::Matrix3d> m_inverse_diagonal;  // per region row: its diagonal block inverted
    int m_dimension = 3;
    // what the region and its rows were made for (made_for)
    struct Made {
        const ElasticBody* body = nullptr;
        std::uint64_t shapes = 0;  // the body's shape revision
        std::size_t max_vertices = 0;
        std::vector<VertexId> seeds;
    } m_made;
    // The CG's vectors, kept from solve to solve: a kept region solves without allocating. Freed
    // and allocated again at every solve, they were what glibc trims from the top of its heap
    // and faults in again, and a fifth of a femur needle step that keeps its region, depending on
    // what the process freed before (docs/performance.md "A record per element and stretch").
    struct Vectors {
        Eigen::VectorXd u, f, ku, r, d, q, z;
    } m_cg;
};

}  // namespace sxk::elasticity
