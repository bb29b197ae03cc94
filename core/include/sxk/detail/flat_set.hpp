// A map and a set of integer keys by open addressing with linear probing in one array, for the
// short-lived collections of a step's hot loops: a few hundred keys, each looked up from several
// places (the snap cut's edges and elements, met from each of their neighbours; the faces an edit
// touched). std::unordered_set allocates a node per key, and on the 1.2M femur at 1 kHz its
// inserts cost the snap cut's closure over crossed edges more than the exact edge tests they saved
// (docs/performance.md "Proven dissection and each node's own reach"). No erase. The key with
// every bit set (invalid_id for ids) is reserved: it marks an empty slot.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace sxk::detail {

template <class Key, class Value>
class FlatMap {
    static_assert(std::is_unsigned_v<Key> && sizeof(Key) <= 8, "FlatMap's keys are unsigned integers");

public:
    FlatMap() = default;

    bool contains(Key key) const { return find(key) != nullptr; }
    // The value of key, or null; valid until the next insert.
    const Value* find(Key key) const {
        if (m_keys.empty()) return nullptr;
        for (std::size_t slot = home(key);; slot = (slot + 1) & m_mask) {
            if (m_keys[slot] == key) {
                if constexpr (has_values) return &m_values[slot];
                return &m_no_value;
            }
            if (m_keys[slot] == vacant) return nullptr;
        }
    }
    Value* find(Key key) { return const_cast<Value*>(std::as_const(*this).find(key)); }
    // Adds key (not the reserved one) with value; true when it was not there (else the value
    // stays as it was).
    bool insert(Key key, const Value& value) {
        if (2 * (m_count + 1) > m_keys.size()) grow();
        for (std::size_t slot = home(key);; slot = (slot + 1) & m_mask) {
            if (m_keys[slot] == key) return false;
            if (m_keys[slot] == vacant) {
                m_keys[slot] = key;
                if constexpr (has_values) m_values[slot] = value;
                ++m_count;
                return true;
            }
        }
    }
    std::size_t size() const { return m_count; }
    bool empty() const { return m_count == 0; }

private:
    static constexpr Key vacant = ~Key{0};
    // a set (FlatSet: an empty Value) keeps no values, only its keys
    static constexpr bool has_values = !std::is_empty_v<Value>;
    static inline const Value m_no_value{};
    static constexpr std::size_t first_capacity = 256;

    // Fibonacci hashing: the high bits of the key times 2^64 / phi, so that ids in runs (the
    // ends of edges, elements made together) spread over the table.
    std::size_t home(Key key) const {
        return static_cast<std::size_t>((std::uint64_t{key} * 0x9E3779B97F4A7C15ull) >> m_shift);
    }
    // Doubles the table (at most half full after), placing every key again.
    void grow() {
        std::vector<Key> old_keys = std::move(m_keys);
        std::vector<Value> old_values = std::move(m_values);
        const std::size_t capacity = old_keys.empty() ? first_capacity : 2 * old_keys.size();
        m_keys.assign(capacity, vacant);
        if constexpr (has_values) m_values.assign(capacity, Value{});
        m_mask = capacity - 1;
        m_shift = 64;
        for (std::size_t c = capacity; c > 1; c /= 2) --m_shift;
        m_count = 0;
        for (std::size_t i = 0; i < old_keys.size(); ++i)
            if (old_keys[i] != vacant) insert(old_keys[i], has_values ? old_values[i] : Value{});
    }

    std::vector<Key> m_keys;
    std::vector<Value> m_values;
    std::size_t m_count = 0;
    std::size_t m_mask = 0;
    unsigned m_shift = 64;
};

template <class Key>
class FlatSet {
public:
    bool contains(Key key) const { return m_map.contains(key); }
    // Adds key (not the reserved one); true when it was not there.
    bool insert(Key key) { return m_map.insert(key, Nothing{}); }
    std::size_t size() const { return m_map.size(); }
    bool empty() const { return m_map.empty(); }

private:
    struct Nothing {};
    FlatMap<Key, Nothing> m_map;
};

}  // namespace sxk::detail
