// Abstract oriented simplexes in canonical form (thesis §7.1–7.2).
//
// A k-simplex <a0,...,ak> is the class of even permutations of its vertices; the other
// orientation is the class of odd permutations. The canonical representative sorts the vertices
// while counting swaps s and keeps the sign p = (-1)^s of the given order, so that
//
//     Simplex(+1, {c, a, b}) == Simplex(+1, {a, b, c})      (two swaps: even)
//     Simplex(+1, {b, a, c}) == Simplex(-1, {a, b, c})      (one swap: odd)
//
// Simplexes of dimension 0..3 (1..4 vertices) are supported: vertices, edges, triangles and
// tetrahedra. For 0-simplexes the thesis "simply assumes that they exist in two orientations";
// so do we. All operations are O(1) and never allocate.
//
//            a2                   subn(j) removes vertex j and multiplies the sign by (-1)^j:
//           /  \                    <a0,a1,a2>.subn(0) = +<a1,a2>
//          / +  \                   <a0,a1,a2>.subn(1) = -<a0,a2> = <a2,a0>
//        a0 ---- a1                 <a0,a1,a2>.subn(2) = +<a0,a1>
//   (counter-clockwise when the triangle is positive: its boundary edges run around it)
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iosfwd>
#include <span>
#include <string>

#include "sxk/config.hpp"
#include "sxk/ids.hpp"

namespace sxk {

class Simplex {
public:
    static constexpr int max_count = 4;

    // The empty simplex; only useful as a placeholder (count() == 0).
    constexpr Simplex() = default;

    // p<b0,...,bk> for sign p in {-1,+1}, brought into canonical form. 1 <= count <= 4.
    constexpr Simplex(int sign, std::span<const VertexId> vertices) {
        m_count = static_cast<std::uint8_t>(vertices.size());
        for (std::size_t i = 0; i < vertices.size(); ++i) m_vertices[i] = vertices[i];
        m_sign = static_cast<std::int8_t>(sign < 0 ? -1 : 1);
        canonicalize();
    }
    constexpr Simplex(int sign, std::initializer_list<VertexId> vertices)
        : Simplex(sign, std::span<const VertexId>(vertices.begin(), vertices.size())) {}

    // Number of vertices k+1 and dimension k.
    constexpr int count() const { return m_count; }
    constexpr int dimension() const { return static_cast<int>(m_count) - 1; }
    // p in {-1,+1}.
    constexpr int sign() const { return m_sign; }
    // a_j of the canonical (sorted) representation.
    constexpr VertexId vertex(int j) const { return m_vertices[static_cast<std::size_t>(j)]; }
    constexpr std::span<const VertexId> vertices() const { return {m_vertices.data(), m_count}; }
    // j such that a_j == v, or -1 when v is not a vertex of this simplex.
    constexpr int index(VertexId v) const {
        for (int j = 0; j < m_count; ++j)
            if (m_vertices[static_cast<std::size_t>(j)] == v) return j;
        return -1;
    }
    constexpr bool contains(VertexId v) const { return index(v) >= 0; }
    // True when no vertex repeats (a simplex with a repeated vertex is degenerate: it has no
    // well-defined orientation and is never a valid element).
    constexpr bool has_distinct_vertices() const {
        for (int j = 1; j < m_count; ++j)
            if (m_vertices[static_cast<std::size_t>(j - 1)] == m_vertices[static_cast<std::size_t>(j)])
                return false;
        return true;
    }

    // (-1)^j p <a0,...,a_{j-1},a_{j+1},...,ak>, the j-th face. Requires count() >= 2.
    constexpr Simplex subn(int j) const {
        Simplex s;
        s.m_count = static_cast<std::uint8_t>(m_count - 1);
        for (int i = 0, o = 0; i < m_count; ++i)
            if (i != j) s.m_vertices[static_cast<std::size_t>(o++)] = m_vertices[static_cast<std::size_t>(i)];
        s.m_sign = static_cast<std::int8_t>((j & 1) ? -m_sign : m_sign);
        return s;
    }
    // subsimplex_v: the face opposite vertex v. Requires contains(v).
    constexpr Simplex subv(VertexId v) const { return subn(index(v)); }
    // -sigma.
    constexpr Simplex mate() const {
        Simplex s = *this;
        s.m_sign = static_cast<std::int8_t>(-m_sign);
        return s;
    }
    // The simplex with vertex v replaced by w (same given order, so the sign follows the swaps
    // needed to sort again). Returns *this unchanged when v is not a vertex.
    constexpr Simplex substituted(VertexId v, VertexId w) const {
        Simplex s = *this;
        const int j = index(v);
        if (j < 0) return s;
        s.m_vertices[static_cast<std::size_t>(j)] = w;
        s.canonicalize();
        return s;
    }
    // p<v,a0,...,ak>: the unique (k+1)-simplex containing v and this simplex, oriented so that
    // sup(v).subv(v) == *this. Requires count() <= 3 and !contains(v).
    constexpr Simplex sup(VertexId v) const {
        Simplex s;
        s.m_count = static_cast<std::uint8_t>(m_count + 1);
        int position = 0;
        while (position < m_count && m_vertices[static_cast<std::size_t>(position)] < v) ++position;
        for (int i = 0, o = 0; i < s.m_count; ++i)
            s.m_vertices[static_cast<std::size_t>(i)] =
                (i == position) ? v : m_vertices[static_cast<std::size_t>(o++)];
        // moving v from the front to `position` takes `position` swaps
        s.m_sign = static_cast<std::int8_t>((position & 1) ? -m_sign : m_sign);
        return s;
    }

    // Signed comparison: lexicographic on (count, vertices, sign). Total order, so simplexes can
    // key ordered maps; equality is equality of oriented simplexes.
    friend constexpr std::strong_ordering operator<=>(const Simplex& a, const Simplex& b) {
        if (auto c = a.m_count <=> b.m_count; c != 0) return c;
        for (int j = 0; j < a.m_count; ++j)
            if (auto c = a.m_vertices[static_cast<std::size_t>(j)] <=> b.m_vertices[static_cast<std::size_t>(j)]; c != 0)
                return c;
        return a.m_sign <=> b.m_sign;
    }
    friend constexpr bool operator==(const Simplex& a, const Simplex& b) {
        return (a <=> b) == 0;
    }
    // -1, 0, +1 as in the thesis' compare(sigma, tau).
    friend constexpr int compare(const Simplex& a, const Simplex& b) {
        const auto c = a <=> b;
        return c < 0 ? -1 : (c > 0 ? 1 : 0);
    }
    // Same vertex set, either orientation.
    constexpr bool same_vertices(const Simplex& other) const {
        if (m_count != other.m_count) return false;
        for (int j = 0; j < m_count; ++j)
            if (m_vertices[static_cast<std::size_t>(j)] != other.m_vertices[static_cast<std::size_t>(j)]) return false;
        return true;
    }

    // Hash of the oriented simplex. unoriented_hash ignores the sign: sigma and -sigma collide,
    // which is what the boundary map wants (it never holds both).
    constexpr std::size_t unoriented_hash() const {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL * (m_count + 1);
        for (int j = 0; j < m_count; ++j) {
            h ^= m_vertices[static_cast<std::size_t>(j)] + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xff51afd7ed558ccdULL;
        }
        return static_cast<std::size_t>(h ^ (h >> 33));
    }
    constexpr std::size_t hash() const {
        return unoriented_hash() ^ (m_sign < 0 ? 0x5bd1e995u : 0u);
    }

private:
    // Insertion sort while counting swaps; at most 6 for four vertices.
    constexpr void canonicalize() {
        for (int i = 1; i < m_count; ++i)
            for (int j = i; j > 0 && m_vertices[static_cast<std::size_t>(j - 1)] > m_vertices[static_cast<std::size_t>(j)]; --j) {
                const VertexId t = m_vertices[static_cast<std::size_t>(j)];
                m_vertices[static_cast<std::size_t>(j)] = m_vertices[static_cast<std::size_t>(j - 1)];
                m_vertices[static_cast<std::size_t>(j - 1)] = t;
                m_sign = static_cast<std::int8_t>(-m_sign);
            }
    }

    std::array<VertexId, max_count> m_vertices{};
    std::uint8_t m_count = 0;
    std::int8_t m_sign = 1;
};

// "+<0,1,2>" / "-<3,4>"
SXK_API std::ostream& operator<<(std::ostream& out, const Simplex& simplex);
// The same text as a string, for messages.
SXK_API std::string to_text(const Simplex& simplex);

struct SimplexHash {
    std::size_t operator()(const Simplex& s) const { return s.hash(); }
};

}  // namespace sxk
