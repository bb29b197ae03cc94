// The names of the refusal codes: stable, since JSON output and scripts match them.
#include "sxk/outcome.hpp"

namespace sxk {

std::string_view to_string(RefusalCode code) {
    switch (code) {
        case RefusalCode::bad_argument: return "bad_argument";
        case RefusalCode::not_found: return "not_found";
        case RefusalCode::wrong_dimension: return "wrong_dimension";
        case RefusalCode::would_invert: return "would_invert";
        case RefusalCode::would_flatten: return "would_flatten";
        case RefusalCode::link_condition: return "link_condition";
        case RefusalCode::moves_boundary: return "moves_boundary";
        case RefusalCode::not_manifold: return "not_manifold";
        case RefusalCode::pinched_star: return "pinched_star";
        case RefusalCode::label_conflict: return "label_conflict";
        case RefusalCode::not_applicable: return "not_applicable";
        case RefusalCode::bad_marking: return "bad_marking";
        case RefusalCode::stale: return "stale";
        case RefusalCode::invalid_mesh: return "invalid_mesh";
        case RefusalCode::too_large: return "too_large";
        case RefusalCode::internal_error: return "internal_error";
    }
    return "unknown";
}

}  // namespace sxk
