// Helpers shared by the split_edge / split_face / split_element / collapse_edge tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"

namespace sxk::test {

// Sorted oriented simplexes of all elements: what a split followed by the collapse of the new
// vertex must restore (element ids may differ).
inline std::vector<Simplex> sorted_simplexes(const Mesh& mesh) {
    std::vector<Simplex> all;
    for (ElementId t : elements(mesh)) all.push_back(mesh.simplex(t));
    std::sort(all.begin(), all.end());
    return all;
}

inline std::string text(const Simplex& sigma) {
    std::ostringstream out;
    out << sigma;
    return out.str();
}

// Every element strictly positive by exact orientation in both position sets.
inline bool all_strictly_positive(const Mesh& mesh) {
    for (ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::reference) != Sign::positive ||
            element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            return false;
    return true;
}

}  // namespace sxk::test
