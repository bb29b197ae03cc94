// A point in a refusal's reason, "(x, y)" or "(x, y, z)": each coordinate in the shortest text
// that reads back to the same double (io::append_number, as the writers write coordinates), so
// that "point (8.000000000000002, 4, 4) is not in the mesh" is not rounded into "(8, 4, 4)", a
// point that may well be in it. NaN is "nan" whatever its sign bit. number_text: one number so.
#pragma once

#include <cmath>
#include <string>

#include "io/text.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

inline std::string number_text(double value) {
    if (std::isnan(value))
        return "nan";
    std::string text;
    io::append_number(text, value);
    return text;
}

inline std::string point_text(const Point& x, int dimension) {
    std::string text = "(";
    for (int k = 0; k < dimension; ++k)
        text += (k > 0 ? ", " : "") + number_text(x[static_cast<std::size_t>(k)]);
    return text + ")";
}

}  // namespace sxk
