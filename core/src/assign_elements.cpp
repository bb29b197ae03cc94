// Bulk construction of the connectivity from a simplex soup (what every reader calls).
//
// Building through the boundary map (add-element per simplex) costs a hash probe per face and a
// frontier that can grow to a large fraction of all faces. Here the faces are instead bucketed by
// their smallest vertex (a counting sort), each bucket sorted by the two other vertices, and
// mates are adjacent entries: linear in the number of faces with small sorts, 12 bytes of
// scratch per face, and sequential memory access. It also sees every face at once, so
// duplicates, non-manifold faces and inconsistent orientations are all detected before the mesh
// is touched; so are pinched vertices, by a union-find over element-vertex incidences.
// The buckets and the union-find are split by vertex over TBB's threads (no shared entries, no
// locks); the result and the refusal named are those of one thread.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include "fresh_array.hpp"
#include "mesh_checks.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

using detail::check_simplex;

namespace {

struct FaceEntry {
    VertexId second;  // the face's other vertices, sorted (third is invalid_id for edges)
    VertexId third;
    std::uint32_t face;  // element index * k + slot
};

std::uint64_t sort_key(const FaceEntry& e) { return std::uint64_t{e.second} << 32 | e.third; }

// What one thread of match_faces found in its buckets: every problem makes the soup no oriented
// manifold, and the one kept is that of the smallest element index (the first found of equals).
struct Findings {
    std::optional<Refusal> first;
    std::size_t boundary_count = 0;

    void report(std::size_t item, std::string why) {
        if (!first || item < first->item) first.emplace(RefusalCode::not_manifold, std::move(why), item);
    }
    void duplicate(std::size_t a, std::size_t b) {
        report(std::max(a, b), "element " + std::to_string(std::max(a, b)) + " repeats element " +
                                   std::to_string(std::min(a, b)) + " (duplicate element)");
    }
};

// Finds the mate of every face of the soup (invalid_id on the boundary), for k = d+1 vertices
// per element known at compile time (divisions by k become shifts and multiplications).
// Returns a refusal naming the smallest offending element index, or nothing.
template <int k>
std::optional<Refusal> match_faces(std::span<const Simplex> simplexes, std::size_t vertex_count,
                    detail::LargeVector<FaceId>& mates, std::size_t& boundary_count) {
    constexpr std::uint32_t ku = static_cast<std::uint32_t>(k);
    const std::size_t n = simplexes.size();
    const std::size_t face_total = n * ku;

    // Counting sort of all faces by their smallest vertex. Face j omits vertex j of the sorted
    // simplex, so face 0 starts at vertex 1 and the others at vertex 0.
    detail::LargeVector<std::uint32_t> bucket_start(vertex_count + 1, 0);
    for (const Simplex& s : simplexes) {
        ++bucket_start[s.vertex(1) + 1];
        bucket_start[s.vertex(0) + 1] += ku - 1;
    }
    for (std::size_t v = 0; v < vertex_count; ++v) bucket_start[v + 1] += bucket_start[v];
    detail::LargeVector<FaceEntry> entries = detail::fresh_vector<FaceEntry>(face_total);
    detail::LargeVector<std::int8_t> signs(n);
    {
        detail::LargeVector<std::uint32_t> cursor(bucket_start.begin(), bucket_start.end() - 1);
        for (std::size_t i = 0; i < n; ++i) {
            const Simplex& s = simplexes[i];
            const std::uint32_t base = static_cast<std::uint32_t>(i) * ku;
            signs[i] = static_cast<std::int8_t>(s.sign());
            const VertexId v0 = s.vertex(0), v1 = s.vertex(1), v2 = s.vertex(2);
            const VertexId v3 = k == 4 ? s.vertex(3) : invalid_id;
            std::uint32_t c = cursor[v0];
            if constexpr (k == 4) {
                entries[cursor[v1]++] = FaceEntry{v2, v3, base};
                entries[c] = FaceEntry{v2, v3, base + 1};
                entries[c + 1] = FaceEntry{v1, v3, base + 2};
                entries[c + 2] = FaceEntry{v1, v2, base + 3};
            } else {
                entries[cursor[v1]++] = FaceEntry{v2, invalid_id, base};
                entries[c] = FaceEntry{v2, invalid_id, base + 1};
                entries[c + 1] = FaceEntry{v1, invalid_id, base + 2};
            }
            cursor[v0] = c + ku - 1;
        }
    }

    detail::assign_fresh(mates, face_total, FaceId{invalid_id});
    // face j of a simplex with sign p has sign p (-1)^j
    auto face_sign = [&](std::uint32_t f) { return ((f % ku) & 1) ? -signs[f / ku] : signs[f / ku]; };
    auto face_simplex_of = [&](std::uint32_t f) { return simplexes[f / ku].subn(static_cast<int>(f % ku)); };

    // The buckets are independent: one range of vertices per thread, cut where the faces are
    // halved (so the threads get equal work), each with its own findings, merged in vertex order
    // afterwards so that the refusal is the one a single thread would give.
    const std::size_t parts =
        static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    std::vector<std::size_t> first_vertex(parts + 1, vertex_count);
    for (std::size_t part = 0; part < parts; ++part)
        first_vertex[part] = static_cast<std::size_t>(
            std::lower_bound(bucket_start.begin(), bucket_start.end() - 1,
                             static_cast<std::uint32_t>(face_total * part / parts)) -
            bucket_start.begin());
    std::vector<Findings> found(parts + 1);
    tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
        Findings& mine = found[part];
        for (std::size_t v = first_vertex[part]; v < first_vertex[part + 1]; ++v) {
            FaceEntry* begin = entries.data() + bucket_start[v];
            FaceEntry* end = entries.data() + bucket_start[v + 1];
            if (end - begin <= 48) {  // buckets are small: about 20 faces per vertex in a tet mesh
                for (FaceEntry* i = begin + 1; i < end; ++i) {
                    const FaceEntry x = *i;
                    FaceEntry* j = i;
                    for (; j > begin && sort_key(x) < sort_key(*(j - 1)); --j) *j = *(j - 1);
                    *j = x;
                }
            } else {
                std::sort(begin, end, [](const FaceEntry& a, const FaceEntry& b) { return sort_key(a) < sort_key(b); });
            }
            for (FaceEntry* run = begin; run < end;) {
                FaceEntry* run_end = run + 1;
                while (run_end < end && sort_key(*run_end) == sort_key(*run)) ++run_end;
                const std::size_t size = static_cast<std::size_t>(run_end - run);
                if (size == 1) {
                    ++mine.boundary_count;
                } else if (size == 2) {
                    const std::uint32_t a = run[0].face, b = run[1].face;
                    const std::size_t ea = a / ku, eb = b / ku;
                    if (face_sign(a) != face_sign(b)) {
                        mates[a] = b;
                        mates[b] = a;
                    } else if (simplexes[ea].same_vertices(simplexes[eb])) {
                        mine.duplicate(ea, eb);
                    } else {
                        mine.report(std::max(ea, eb),
                                    "elements " + std::to_string(std::min(ea, eb)) + " and " +
                                        std::to_string(std::max(ea, eb)) + " share face " +
                                        to_text(face_simplex_of(a)) +
                                        " with the same orientation (inconsistently oriented)");
                    }
                } else {
                    std::size_t last = 0;
                    for (FaceEntry* e = run; e < run_end; ++e) last = std::max<std::size_t>(last, e->face / ku);
                    mine.report(last, "face " + to_text(Simplex(+1, face_simplex_of(run->face).vertices())) +
                                          " is shared by " + std::to_string(size) + " elements (non-manifold)");
                }
                run = run_end;
            }
        }
    });
    // Distinct simplexes share at most one face; two faces of one element mated into the same
    // element mean a mirror-image duplicate (same signs were caught above). Found after the
    // buckets' findings, as a single thread would.
    Findings& mirrors = found[parts];
    for (std::size_t i = 0; i < n; ++i)
        for (std::uint32_t j = 1; j < ku; ++j) {
            const FaceId mj = mates[i * ku + j];
            if (mj == invalid_id) continue;
            for (std::uint32_t l = 0; l < j; ++l) {
                const FaceId ml = mates[i * ku + l];
                if (ml != invalid_id && ml / ku == mj / ku) mirrors.duplicate(i, mj / ku);
            }
        }
    boundary_count = 0;
    std::optional<Refusal> first_problem;
    for (Findings& part : found) {
        boundary_count += part.boundary_count;
        if (part.first && (!first_problem || part.first->item < first_problem->item))
            first_problem = std::move(part.first);
    }
    return first_problem;
}

// Face-connected vertex stars (§7.3), the one invariant the face matching cannot see. Every
// (element, vertex) incidence is a node of a union-find; two mated faces join, for each of the
// face's vertices, its incidences in the two elements. star(v) is face-connected iff the
// incidences of v form one set. Unlike one walk per star (which measured 2/3 of the whole build
// on the femur: random loads through `mates` and a stamp array), the unions follow the element
// order of the input, which is what makes the face matching fast too.
//
// A union only ever joins two incidences of one vertex, so the sets of different vertices never
// meet: the vertices are cut into one range per thread, and each thread runs the unions of its
// own vertices over the whole face list. No parent entry is touched by two threads, so there
// are no locks, and the result is the same for any number of threads.
// Returns the refusal for the smallest pinched vertex, or nothing.
std::optional<Refusal> find_pinched_star(std::span<const Simplex> simplexes,
                                         std::span<const FaceId> mates, std::size_t vertex_count,
                                         int k) {
    const std::uint32_t ku = static_cast<std::uint32_t>(k);
    const std::uint32_t face_total = static_cast<std::uint32_t>(mates.size());
    detail::LargeVector<std::uint32_t> parent = detail::fresh_vector<std::uint32_t>(face_total);
    detail::LargeVector<std::uint32_t> pieces(vertex_count, 0);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, face_total),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                          for (std::uint32_t s = r.begin(); s < r.end(); ++s) parent[s] = s;
                      });
    auto find = [&parent](std::uint32_t s) {
        while (parent[s] != s) {
            parent[s] = parent[parent[s]];  // path halving
            s = parent[s];
        }
        return s;
    };
    const std::size_t parts =
        static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t part) {
        const std::size_t low = vertex_count * part / parts;
        const std::size_t high = vertex_count * (part + 1) / parts;
        auto mine = [&](VertexId v) { return v >= low && v < high; };
        // The mate's incidences are a random load each (20 MB of parents on the femur-1226k):
        // ask for them a few faces ahead, so the loads overlap instead of waiting one after the
        // other (docs/performance.md "io": prefetch).
        constexpr std::uint32_t ahead = 16;
        for (std::uint32_t f = 0; f < face_total; ++f) {
            if (f + ahead < face_total) {
                const FaceId later = mates[f + ahead];
                if (later != invalid_id) __builtin_prefetch(&parent[later.value() / ku * ku]);
            }
            const FaceId m = mates[f];
            if (m == invalid_id || m < f) continue;  // each mated pair once
            // Both elements list their vertices sorted, so the face's vertices come in the same
            // order in both once the opposite slot is skipped: the r-th vertex of the face is
            // slot i of t and slot i2 of u without looking at u's vertices.
            const std::uint32_t t = f / ku, j = f % ku, u = m / ku, j2 = m % ku;
            for (std::uint32_t i = 0, i2 = 0; i < ku; ++i, ++i2) {
                if (i == j) ++i;
                if (i2 == j2) ++i2;
                if (i == ku) break;
                if (parts > 1 && !mine(simplexes[t].vertex(static_cast<int>(i)))) continue;
                const std::uint32_t a = find(t * ku + i), b = find(u * ku + i2);
                if (a != b) parent[std::max(a, b)] = std::min(a, b);
            }
        }
        // one root per piece of each star: count them per vertex
        for (std::uint32_t s = 0; s < face_total; ++s) {
            if (parent[s] != s) continue;
            const VertexId v = simplexes[s / ku].vertex(static_cast<int>(s % ku));
            if (mine(v)) ++pieces[v];
        }
    });
    for (VertexId v = 0; v < vertex_count; ++v) {
        if (pieces[v] <= 1) continue;
        std::size_t first = 0;
        while (!simplexes[first].contains(v)) ++first;
        return Refusal{RefusalCode::pinched_star,
                       "star connectivity: the elements around vertex " + std::to_string(v) +
                           " are not connected through faces (the mesh is pinched there)",
                       first};
    }
    return std::nullopt;
}

}  // namespace

Outcome<Done> Mesh::assign_elements(std::span<const Simplex> simplexes,
                                    std::span<const int> labels) {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable,
                       "assign_elements: not inside an EditJournal step"};
    ++m_revision;
    const int k = m_dimension + 1;
    const std::size_t n = simplexes.size();
    if (m_element_count != 0)
        return Refusal{RefusalCode::not_applicable,
                       "assign_elements needs a mesh without elements"};
    if (!labels.empty() && labels.size() != n)
        return Refusal{RefusalCode::bad_argument,
                       "got " + std::to_string(labels.size()) + " labels for " +
                       std::to_string(n) + " elements"};
    if (n * static_cast<std::size_t>(k) >= invalid_id)
        return Refusal{RefusalCode::too_large, "too many elements for 32-bit face ids"};
    for (std::size_t i = 0; i < n; ++i)
        if (std::string why = check_simplex(simplexes[i], k, vertex_count()); !why.empty())
            return Refusal{RefusalCode::bad_argument, std::move(why), i};

    const std::size_t face_total = n * static_cast<std::size_t>(k);
    detail::LargeVector<FaceId> mates;
    std::size_t boundary_count = 0;
    std::optional<Refusal> problem =
        k == 4 ? match_faces<4>(simplexes, vertex_count(), mates, boundary_count)
               : match_faces<3>(simplexes, vertex_count(), mates, boundary_count);
    if (problem) return *problem;

    if (std::optional<Refusal> pinched = find_pinched_star(simplexes, mates, vertex_count(), k))
        return *pinched;

    // Everything is known to be consistent. The mesh has no elements, so building in place
    // loses nothing but dead pool entries, and uses whatever capacity the caller reserved.
    try {
        // fresh memory backed by all threads first (fresh_array.hpp)
        detail::assign_fresh(m_elements, n, ElementRecord{});
        detail::assign_fresh(m_faces, face_total, FaceRecord{});
        m_boundary.clear();
        m_boundary.reserve(boundary_count);
        std::fill(m_vertex_element.begin(), m_vertex_element.end(), invalid_id);
        // the records, each element on its own (threads write disjoint entries)
        const std::size_t ks = static_cast<std::size_t>(k);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) {
                ElementRecord& e = m_elements[i];
                e.simplex = simplexes[i];
                e.label = labels.empty() ? 0 : labels[i];
                for (std::size_t j = 0; j < ks; ++j) {
                    const std::size_t f = i * ks + j;
                    e.faces[j] = static_cast<FaceId>(f);
                    m_faces[f] = FaceRecord{static_cast<ElementId>(i), mates[f]};
                    // face ids are i * k + j here, so the mate's element is its id / k
                    e.neighbors[j] = mates[f] == invalid_id ? ElementId{invalid_id}
                                                            : static_cast<ElementId>(mates[f] / ks);
                }
            }
        });
        // the boundary map and the anchors (each vertex's first element), in element order, side
        // by side
        tbb::parallel_invoke(
            [&] {
                for (std::size_t f = 0; f < face_total; ++f)
                    if (mates[f] == invalid_id)
                        m_boundary.insert(simplexes[f / ks].subn(static_cast<int>(f % ks)),
                                          static_cast<FaceId>(f));
            },
            [&] {
                for (std::size_t i = 0; i < n; ++i)
                    for (VertexId v : simplexes[i].vertices())
                        if (m_vertex_element[v] == invalid_id) m_vertex_element[v] = static_cast<ElementId>(i);
            });
    } catch (...) {
        // out of memory half-way: leave an empty, valid mesh rather than a torn one
        m_elements.clear();
        m_faces.clear();
        m_boundary.clear();
        std::fill(m_vertex_element.begin(), m_vertex_element.end(), invalid_id);
        m_vertices_in_elements = 0;
        m_free_element = invalid_id;
        m_free_face = invalid_id;
        m_element_count = 0;
        throw;
    }
    recount_anchors();
    m_free_element = invalid_id;
    m_free_face = invalid_id;
    m_element_count = n;
    // every element is new: element attributes start at their defaults
    for (detail::AttributeColumn& a : m_element_attributes) a.values.clear();
    grow_element_attributes();
    for (Watcher* w : m_watchers) w->init(*this);
    return Done{};
}

Outcome<Done> Mesh::assign_elements_unchecked(std::span<const Simplex> simplexes,
                                              std::span<const int> labels) {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable,
                       "assign_elements: not inside an EditJournal step"};
    ++m_revision;
    const int k = m_dimension + 1;
    if (m_element_count != 0)
        return Refusal{RefusalCode::not_applicable,
                       "assign_elements needs a mesh without elements"};
    if (!labels.empty() && labels.size() != simplexes.size())
        return Refusal{RefusalCode::bad_argument,
                       "got " + std::to_string(labels.size()) + " labels for " +
                       std::to_string(simplexes.size()) + " elements"};
    for (std::size_t i = 0; i < simplexes.size(); ++i)
        if (std::string why = check_simplex(simplexes[i], k, vertex_count()); !why.empty())
            return Refusal{RefusalCode::bad_argument, std::move(why), i};

    m_elements.clear();
    m_faces.clear();
    m_boundary.clear();
    m_free_element = invalid_id;
    m_free_face = invalid_id;
    std::fill(m_vertex_element.begin(), m_vertex_element.end(), invalid_id);
    for (detail::AttributeColumn& a : m_element_attributes) a.values.clear();  // allocate_element grows them
    for (std::size_t i = 0; i < simplexes.size(); ++i) {
        // thesis §7.3 add-element
        const ElementId t = allocate_element();
        m_elements[t].simplex = simplexes[i];
        m_elements[t].label = labels.empty() ? 0 : labels[i];
        for (int j = 0; j < k; ++j) {
            const Simplex sigma = simplexes[i].subn(j);
            const FaceId f = allocate_face();
            m_faces[f].element = t;
            m_elements[t].faces[static_cast<std::size_t>(j)] = f;
            const FaceId other = m_boundary.find(sigma);
            if (other == invalid_id) {
                m_boundary.insert(sigma, f);
            } else if (face_simplex(other) == sigma.mate()) {
                m_faces[f].mate = other;
                m_faces[other].mate = f;
                m_boundary.erase(sigma);
            } else {
                // sigma represented twice: the thesis' map assignment overwrites the entry
                m_boundary.assign(sigma, f);
            }
            if (m_vertex_element[simplexes[i].vertex(j)] == invalid_id)
                m_vertex_element[simplexes[i].vertex(j)] = t;
        }
        link_neighbors(t);
    }
    recount_anchors();
    for (Watcher* w : m_watchers) w->init(*this);
    return Done{};
}

}  // namespace sxk
