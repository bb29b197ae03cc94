// The boundary map (thesis eq. 7.5): boundary (d-1)-simplexes -> Face ids.
//
// The thesis uses a balanced tree (O(log n) per update). This is an open-addressing table with
// linear probing and backward-shift deletion (no tombstones, so heavy insert/erase traffic at a
// cutting front never degrades it). Keys are the *unoriented* vertex sets: of sigma and -sigma at
// most one is ever on the boundary (if -sigma is a face, sigma is not a boundary face), so the
// orientation is read from the face itself and the caller checks it. 16 bytes per slot, load
// factor at most 1/2.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/detail/large_array.hpp"
#include "sxk/ids.hpp"
#include "sxk/simplex.hpp"

namespace sxk::detail {

class SXK_API BoundaryMap {
public:
    using Key = std::array<VertexId, 3>;

    static Key key_of(const Simplex& s) {
        Key k{invalid_id, invalid_id, invalid_id};
        for (int j = 0; j < s.count() && j < 3; ++j) k[static_cast<std::size_t>(j)] = s.vertex(j);
        return k;
    }

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    std::size_t capacity() const { return m_slots.size(); }
    std::size_t memory_bytes() const { return m_slots.capacity() * sizeof(Slot); }

    // The face stored under sigma's vertex set (either orientation), or invalid_id.
    FaceId find(const Simplex& sigma) const { return find(key_of(sigma)); }
    FaceId find(const Key& key) const;
    // Stores face under sigma's vertex set; the key must not be present.
    void insert(const Simplex& sigma, FaceId face);
    // Points an existing key at another face (the key must be present).
    void assign(const Simplex& sigma, FaceId face);
    // Removes sigma's vertex set; returns false when it was not present.
    bool erase(const Simplex& sigma);
    void clear();
    void reserve(std::size_t count);

    template <class Visit>
    void for_each(Visit&& visit) const {
        for (const Slot& slot : m_slots)
            if (slot.face != invalid_id) visit(slot.key, slot.face);
    }

private:
    struct Slot {
        Key key{invalid_id, invalid_id, invalid_id};
        FaceId face = invalid_id;
    };
    std::size_t home(const Key& key) const;
    void grow();

    LargeVector<Slot> m_slots;  // size is zero or a power of two
    std::size_t m_size = 0;
};

}  // namespace sxk::detail
