// The CGAL Delaunay tetrahedralisation the flip benchmarks start from: vertices carry our vertex
// id as their info.
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cstdint>

namespace sxk_bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using DataStructure =
    CGAL::Triangulation_data_structure_3<VertexBase, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;

}  // namespace sxk_bench
