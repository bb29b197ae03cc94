// The result of an edit or a check: either a value, or a refusal that says why.
//
// An operation returns what survives or what was created, or a refusal with a
// reason, never a bool plus out-parameters. std::expected is C++23; this is the small subset
// the toolkit needs.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <variant>

namespace sxk {

// Why an operation was refused. `item` optionally names the offending input (for example the
// index of a simplex in the list handed to replace_elements); npos when there is none.
struct Refusal {
    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
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
    const std::string& reason() const { return refusal().reason; }

private:
    std::variant<T, Refusal> m_state;
};

// Outcome of an operation that creates nothing worth returning.
struct Done {};

}  // namespace sxk
