#include "sxk/simplex.hpp"

#include <ostream>
#include <sstream>

namespace sxk {

std::ostream& operator<<(std::ostream& out, const Simplex& simplex) {
    out << (simplex.sign() < 0 ? '-' : '+') << '<';
    for (int j = 0; j < simplex.count(); ++j) out << (j ? "," : "") << simplex.vertex(j);
    return out << '>';
}

std::string to_text(const Simplex& simplex) {
    std::ostringstream out;
    out << simplex;
    return out.str();
}

}  // namespace sxk
