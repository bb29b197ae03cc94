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
// names the case in words and may change wording; the codes and their names are stable. The
// table in docs/kernel.md ("Refusal codes") lists the operations that return each.
enum class RefusalCode : std::uint8_t {
    // malformed call: wrong sizes or counts, an id twice, a bad simplex, a parameter out of range
    bad_argument,
    // an argument names nothing: no such vertex, element, face, edge, attribute, plug-in service
    not_found,
    // the mesh has another dimension than the operation needs (2D ops on tetrahedra, and so on)
    wrong_dimension,
    // a new or reshaped element would be inverted, a surface would fold (splits, flips, collapse)
    would_invert,
    // a new or reshaped element would be flat or collinear (splits, flips, collapse, bisections)
    would_flatten,
    // collapse_edge: the edge violates the link condition (the result would not be a manifold)
    link_condition,
    // the edit would change the domain: the boundary would move (collapse_edge, remove_node)
    moves_boundary,
    // a simplex twice (7.4), a non-manifold or misoriented face (edit primitives, flips, building)
    not_manifold,
    // a vertex star would not be face-connected, "star connectivity" (edit primitives, building)
    pinched_star,
    // labels forbid it: a material interface, a labelled face would vanish (flips, remove_node)
    label_conflict,
    // the configuration does not allow it: a boundary edge (flips), no valid ear (remove_node), ...
    not_applicable,
    // the bisection marks do not fit the mesh: inconsistent, or a recursion that does not end
    bad_marking,
    // a state beside the mesh is out of date, the mesh was edited outside it (TetBisection, undo)
    stale,
    // Mesh::validate found a broken invariant or an inverted (flat_is_invalid: flat) element
    invalid_mesh,
    // the mesh would pass a size limit: 32-bit face ids (assign_elements)
    too_large,
    // a step the operation had planned and checked was refused after all: a bug, mesh unchanged
    internal_error,
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
