// A set of integer keys by open addressing with linear probing in one array, for the short-lived
// sets of a step's hot loops: a few hundred keys, each looked up from several places (the snap
// cut's edges and elements, met from each of their neighbours). std::unordered_set allocates a
// node per key, and on the 1.2M femur at 1 kHz its inserts cost the snap cut's closure over
// crossed edges more than the exact edge tests they saved (docs/performance.md "Proven dissection
// and each node's own reach"). No erase. The key with every bit set (invalid_id for ids) is
// reserved: it marks an empty slot.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace sxk::detail {

template <class Key>
class FlatSet {
    static_assert(std::is_unsigned_v<Key> && sizeof(Key) <= 8, "FlatSet holds unsigned integers");

public:
    FlatSet() = default;

    bool contains(Key key) const {
        if (m_slots.empty()) return false;
        for (std::size_t slot = home(key);; slot = (slot + 1) & m_mask) {
            if (m_slots[slot] == key) return true;
            if (m_slots[slot] == vacant) return false;
        }
    }
    // Adds key (not the reserved one); true when it was not there.
    bool insert(Key key) {
        if (2 * (m_count + 1) > m_slots.size()) grow();
        for (std::size_t slot = home(key);; slot = (slot + 1) & m_mask) {
            if (m_slots[slot] == key) return false;
            if (m_slots[slot] == vacant) {
                m_slots[slot] = key;
                ++m_count;
                return true;
            }
        }
    }
    std::size_t size() const { return m_count; }
    bool empty() const { return m_count == 0; }

private:
    static constexpr Key vacant = ~Key{0};
    static constexpr std::size_t first_capacity = 256;

    // Fibonacci hashing: the high bits of the key times 2^64 / phi, so that ids in runs (the
    // ends of edges, elements made together) spread over the table.
    std::size_t home(Key key) const {
        return static_cast<std::size_t>((std::uint64_t{key} * 0x9E3779B97F4A7C15ull) >> m_shift);
    }
    // Doubles the table (at most half full after), placing every key again.
    void grow() {
        std::vector<Key> old = std::move(m_slots);
        const std::size_t capacity = old.empty() ? first_capacity : 2 * old.size();
        m_slots.assign(capacity, vacant);
        m_mask = capacity - 1;
        m_shift = 64;
        for (std::size_t c = capacity; c > 1; c /= 2) --m_shift;
        m_count = 0;
        for (const Key key : old)
            if (key != vacant) insert(key);
    }

    std::vector<Key> m_slots;
    std::size_t m_count = 0;
    std::size_t m_mask = 0;
    unsigned m_shift = 64;
};

}  // namespace sxk::detail
