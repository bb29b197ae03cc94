// The result of an edit or a check: either a value, or a refusal that says why.
//
// An operation returns what survives or what was created, or a refusal with a
// reason, never a bool plus out-parameters. std::expected is C++23; this is the small subset
// the toolkit needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "sxk/config.hpp"

namespace sxk {

// What kind of refusal: callers branch on the code, people read the reason. The reason text
// names the case in words and may change wording; the codes and their names are stable.
enum class RefusalCode : std::uint8_t {
    bad_argument,     // malformed call: wrong sizes or counts, an id listed twice, a simplex with a repeated or unknown vertex, a parameter out of range (every operation)
    not_found,        // an argument names nothing: no such vertex, element, face, edge or attribute, no element contains the point (every operation, refine_around*)
    wrong_dimension,  // the mesh's topological or ambient dimension is not the one the operation needs (flips, splits, bisections, refine_around*, remove_node, make_delaunay_by_flips, TetBisection)
    would_invert,     // a new or reshaped element would be inverted, or a surface would fold or turn over (splits, flips, collapse_edge, bisections)
    would_flatten,    // a new or reshaped element would be flat: orientation exactly zero, collinear vertices (splits, flips, collapse_edge, bisections)
    link_condition,   // the edge violates the link condition: the collapse would not leave a manifold (collapse_edge)
    moves_boundary,   // the edit would change the domain: a boundary vertex or face would leave its line or plane (collapse_edge, remove_node)
    not_manifold,     // the elements would not form an oriented manifold: an element or face twice (invariant 7.4), a face in more than two elements or twice with one orientation, a flip's new simplex that exists (replace_elements, change_elements, assign_elements, flips)
    pinched_star,     // a vertex star would not be face-connected, "star connectivity" (replace_elements, change_elements, assign_elements)
    label_conflict,   // labels forbid the edit: a material interface, a labelled face that would vanish, different labels around a vertex (flips, remove_node)
    not_applicable,   // the configuration does not allow the operation: an edge on the boundary or of another degree, not the hypotenuse, elements not counter-clockwise, no valid ear, a vertex in use, a mesh with elements, a name taken, not a Kuhn mesh
    bad_marking,      // the bisection marks do not fit the mesh: an inconsistent marking, a recursion that does not end, a stale state (TetBisection, bisect_tetrahedron, refine_around_tetrahedra)
    invalid_mesh,     // validate() found a broken invariant or an inverted (with flat_is_invalid also a flat) element (Mesh::validate)
    too_large,        // the mesh would exceed the 32-bit id range (assign_elements)
    internal_error,   // a step the operation had planned and checked was refused after all: a bug; the mesh is unchanged (bisections, refine_around*, make_kuhn_cube)
};

// The code's stable snake_case name ("not_found"), as written in JSON output.
SXK_API std::string_view to_string(RefusalCode code);

// Why an operation was refused: a code for callers, a reason for people. `item` optionally
// names the offending input (for example the index of a simplex in the list handed to
// replace_elements); npos when there is none. No default: every refusal says what kind it is.
struct Refusal {
    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

    Refusal(RefusalCode code_, std::string reason_, std::size_t item_ = npos)
        : code(code_), reason(std::move(reason_)), item(item_) {}

    // The same kind, the reason behind a prefix: how an operation passes on the refusal of an
    // operation it called ("flip_edge: " + the replace_elements reason). Without the item,
    // which indexes the inner call's input, not the caller's.
    Refusal prefixed(std::string_view prefix) const {
        return Refusal(code, std::string(prefix) + reason);
    }

    RefusalCode code;
    std::string reason;
    std::size_t item = npos;
};

template <class T>
class [[nodiscard]] Outcome {
public:
    Outcome(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Outcome(Refusal refusal) : m_state(std::in_place_index<1>, std::move(refusal)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(m_state); }
    const T& value() const& { return std::get<0>(m_state); }
    T&& value() && { return std::get<0>(std::move(m_state)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Refusal& refusal() const { return std::get<1>(m_state); }
    RefusalCode code() const { return refusal().code; }
    const std::string& reason() const { return refusal().reason; }

private:
    std::variant<T, Refusal> m_state;
};

// Outcome of an operation that creates nothing worth returning.
struct Done {};

}  // namespace sxk
