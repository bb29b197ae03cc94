// Open-addressing boundary map (see detail/boundary_map.hpp for why not a tree).
#include "sxk/detail/boundary_map.hpp"

#include <bit>
#include <utility>

namespace sxk::detail {

namespace {

std::uint64_t mix(std::uint64_t h) {
    // splitmix64 finaliser: vertex ids are small consecutive integers; the table needs all of
    // their bits spread over the low bits it masks with.
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    return h ^ (h >> 31);
}

}  // namespace

std::size_t BoundaryMap::home(const Key& key) const {
    const std::uint64_t h = mix((std::uint64_t{key[0]} << 32 | key[1]) ^ mix(key[2]));
    return static_cast<std::size_t>(h) & (m_slots.size() - 1);
}

FaceId BoundaryMap::find(const Key& key) const {
    if (m_slots.empty()) return invalid_id;
    const std::size_t mask = m_slots.size() - 1;
    for (std::size_t i = home(key);; i = (i + 1) & mask) {
        const Slot& slot = m_slots[i];
        if (slot.face == invalid_id) return invalid_id;
        if (slot.key == key) return slot.face;
    }
}

void BoundaryMap::insert(const Simplex& sigma, FaceId face) {
    if (2 * (m_size + 1) > m_slots.size()) grow();
    const Key key = key_of(sigma);
    const std::size_t mask = m_slots.size() - 1;
    std::size_t i = home(key);
    while (m_slots[i].face != invalid_id) i = (i + 1) & mask;
    m_slots[i] = Slot{key, face};
    ++m_size;
}

void BoundaryMap::assign(const Simplex& sigma, FaceId face) {
    const Key key = key_of(sigma);
    const std::size_t mask = m_slots.size() - 1;
    for (std::size_t i = home(key);; i = (i + 1) & mask) {
        if (m_slots[i].key == key) {
            m_slots[i].face = face;
            return;
        }
    }
}

bool BoundaryMap::erase(const Simplex& sigma) {
    if (m_slots.empty()) return false;
    const Key key = key_of(sigma);
    const std::size_t mask = m_slots.size() - 1;
    std::size_t i = home(key);
    while (true) {
        if (m_slots[i].face == invalid_id) return false;
        if (m_slots[i].key == key) break;
        i = (i + 1) & mask;
    }
    // Backward-shift deletion: move later members of the probe run into the hole when their
    // home position lies cyclically at or before the hole, so no tombstones are needed.
    std::size_t hole = i;
    for (std::size_t j = (hole + 1) & mask; m_slots[j].face != invalid_id; j = (j + 1) & mask) {
        const std::size_t h = home(m_slots[j].key);
        const bool movable = (j > hole) ? (h <= hole || h > j) : (h <= hole && h > j);
        if (movable) {
            m_slots[hole] = m_slots[j];
            hole = j;
        }
    }
    m_slots[hole] = Slot{};
    --m_size;
    return true;
}

void BoundaryMap::clear() {
    m_slots.clear();
    m_slots.shrink_to_fit();
    m_size = 0;
}

void BoundaryMap::reserve(std::size_t count) {
    const std::size_t wanted = std::bit_ceil(std::max<std::size_t>(16, 2 * count));
    if (wanted <= m_slots.size()) return;
    LargeVector<Slot> old = std::exchange(m_slots, LargeVector<Slot>(wanted));
    const std::size_t mask = m_slots.size() - 1;
    for (const Slot& slot : old) {
        if (slot.face == invalid_id) continue;
        std::size_t i = home(slot.key);
        while (m_slots[i].face != invalid_id) i = (i + 1) & mask;
        m_slots[i] = slot;
    }
}

void BoundaryMap::grow() { reserve(std::max<std::size_t>(16, m_slots.size())); }

}  // namespace sxk::detail
