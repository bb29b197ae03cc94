// The one place CGAL enters the toolkit: the exact-predicates kernel and the
// conversion from sxk::Point. Include only from .cpp files in core/src.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"

namespace sxk::detail {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// For the few tests that are no predicate of Kernel (signs of constructed quantities): lazy
// exact arithmetic behind an interval filter.
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;

inline Kernel::Point_2 to_cgal_2(const Point& p) { return {p[0], p[1]}; }
inline Kernel::Point_3 to_cgal_3(const Point& p) { return {p[0], p[1], p[2]}; }

inline Sign to_sign(CGAL::Sign s) {
    return s == CGAL::NEGATIVE ? Sign::negative : (s == CGAL::POSITIVE ? Sign::positive : Sign::zero);
}

}  // namespace sxk::detail
