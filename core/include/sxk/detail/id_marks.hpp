// IdMarks: "was this id met already in this round?" over ids that grow with the mesh, for the
// scratch of searches that run again and again on a large mesh (the elements around a move, the
// star walks a move takes over: Mesh::elements_around_moved, Mesh::walk_star). Nothing is cleared
// between rounds: each id keeps the number of the last round that marked it, so a round costs
// what it marks, not the mesh's size (but once in 2^32 rounds, when the number wraps).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "sxk/detail/large_array.hpp"

namespace sxk::detail {

class IdMarks {
public:
    // A new round over ids below n: nothing is marked.
    void new_round(std::size_t n) {
        grow(n);
        if (++m_round == 0) {  // wrapped: marks of 2^32 rounds ago would look fresh
            std::fill(m_round_of.begin(), m_round_of.end(), 0);
            m_round = 1;
        }
    }
    // Room for ids below n, the round's marks kept.
    void grow(std::size_t n) { grow_doubling(m_round_of, n, std::uint32_t{0}); }
    // Marks id (below the room made); true when this round had not marked it yet.
    bool mark(std::size_t id) {
        if (m_round_of[id] == m_round) return false;
        m_round_of[id] = m_round;
        return true;
    }
    bool marked(std::size_t id) const { return m_round != 0 && id < m_round_of.size() && m_round_of[id] == m_round; }

private:
    LargeVector<std::uint32_t> m_round_of;  // per id: the round that last marked it (0: none)
    std::uint32_t m_round = 0;
};

}  // namespace sxk::detail
