#include "sxk/simplex.hpp"

#include <ostream>

namespace sxk {

std::ostream& operator<<(std::ostream& out, const Simplex& simplex) {
    out << (simplex.sign() < 0 ? '-' : '+') << '<';
    for (int j = 0; j < simplex.count(); ++j) out << (j ? "," : "") << simplex.vertex(j);
    return out << '>';
}

}  // namespace sxk
