// Bulk construction of the connectivity from a simplex soup (what every reader calls).
//
// Building through the boundary map (add-element per simplex) costs a hash probe per face and a
// frontier that can grow to a large fraction of all faces. Here the faces are instead bucketed by
// their smallest vertex (a counting sort), each bucket sorted by the two other vertices, and
// mates are adjacent entries: linear in the number of faces with small sorts, 12 bytes of
// scratch per face, and sequential memory access. It also sees every face at once, so
// duplicates, non-manifold faces and inconsistent orientations are all detected before the mesh
// is touched.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh_checks.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

using detail::check_simplex;
using detail::describe;

namespace {

struct FaceEntry {
    VertexId second;  // the face's other vertices, sorted (third is invalid_id for edges)
    VertexId third;
    std::uint32_t face;  // element index * (d+1) + slot
};

}  // namespace

Outcome<Done> Mesh::assign_elements(std::span<const Simplex> simplexes,
                                    std::span<const int> labels) {
    const int k = m_dimension + 1;
    const std::size_t n = simplexes.size();
    if (m_element_count != 0) return Refusal{"assign_elements needs a mesh without elements"};
    if (!labels.empty() && labels.size() != n)
        return Refusal{"got " + std::to_string(labels.size()) + " labels for " +
                       std::to_string(n) + " elements"};
    if (n * static_cast<std::size_t>(k) >= invalid_id)
        return Refusal{"too many elements for 32-bit face ids"};
    for (std::size_t i = 0; i < n; ++i)
        if (std::string why = check_simplex(simplexes[i], k, vertex_count()); !why.empty())
            return Refusal{std::move(why), i};

    // Counting sort of all faces by smallest vertex. Faces of a canonical simplex are sorted
    // too; face j omits vertex j, so its smallest vertex is vertex(0) unless j == 0.
    const std::size_t face_total = n * static_cast<std::size_t>(k);
    std::vector<std::uint32_t> bucket_start(vertex_count() + 1, 0);
    for (const Simplex& s : simplexes)
        for (int j = 0; j < k; ++j) ++bucket_start[s.vertex(j == 0 ? 1 : 0) + 1];
    for (std::size_t v = 0; v < vertex_count(); ++v) bucket_start[v + 1] += bucket_start[v];
    std::vector<FaceEntry> entries(face_total);
    {
        std::vector<std::uint32_t> cursor(bucket_start.begin(), bucket_start.end() - 1);
        for (std::size_t i = 0; i < n; ++i) {
            const Simplex& s = simplexes[i];
            for (int j = 0; j < k; ++j) {
                const Simplex face = s.subn(j);
                entries[cursor[face.vertex(0)]++] =
                    FaceEntry{face.vertex(1), k == 4 ? face.vertex(2) : invalid_id,
                              static_cast<std::uint32_t>(i * static_cast<std::size_t>(k) + static_cast<std::size_t>(j))};
            }
        }
    }

    std::vector<FaceId> mates(face_total, invalid_id);
    std::size_t boundary_count = 0;
    Refusal first_problem{"", Refusal::npos};
    auto report = [&](std::size_t item, std::string why) {
        if (item < first_problem.item) first_problem = Refusal{std::move(why), item};
    };
    auto face_simplex_of = [&](std::uint32_t face) {
        return simplexes[face / static_cast<std::uint32_t>(k)].subn(static_cast<int>(face % static_cast<std::uint32_t>(k)));
    };
    auto by_vertices = [](const FaceEntry& a, const FaceEntry& b) {
        return a.second != b.second ? a.second < b.second : a.third < b.third;
    };
    for (std::size_t v = 0; v < vertex_count(); ++v) {
        FaceEntry* begin = entries.data() + bucket_start[v];
        FaceEntry* end = entries.data() + bucket_start[v + 1];
        if (end - begin <= 16) {
            for (FaceEntry* i = begin + 1; i < end; ++i)
                for (FaceEntry* j = i; j > begin && by_vertices(*j, *(j - 1)); --j) std::swap(*j, *(j - 1));
        } else {
            std::sort(begin, end, by_vertices);
        }
        for (FaceEntry* run = begin; run < end;) {
            FaceEntry* run_end = run + 1;
            while (run_end < end && run_end->second == run->second && run_end->third == run->third)
                ++run_end;
            const std::size_t size = static_cast<std::size_t>(run_end - run);
            if (size == 1) {
                ++boundary_count;
            } else if (size == 2) {
                const std::uint32_t a = run[0].face, b = run[1].face;
                const std::size_t ea = a / static_cast<std::uint32_t>(k), eb = b / static_cast<std::uint32_t>(k);
                const Simplex fa = face_simplex_of(a), fb = face_simplex_of(b);
                if (simplexes[ea].same_vertices(simplexes[eb])) {
                    report(std::max(ea, eb), "element " + std::to_string(std::max(ea, eb)) +
                                                 " repeats element " + std::to_string(std::min(ea, eb)) +
                                                 " (duplicate element)");
                } else if (fa.sign() == fb.sign()) {
                    report(std::max(ea, eb),
                           "elements " + std::to_string(std::min(ea, eb)) + " and " +
                               std::to_string(std::max(ea, eb)) + " share face " + describe(fa) +
                               " with the same orientation (inconsistently oriented)");
                } else {
                    mates[a] = b;
                    mates[b] = a;
                }
            } else {
                std::size_t last = 0;
                for (FaceEntry* e = run; e < run_end; ++e) last = std::max<std::size_t>(last, e->face / static_cast<std::uint32_t>(k));
                report(last, "face " + describe(Simplex(+1, face_simplex_of(run->face).vertices())) + " is shared by " +
                                 std::to_string(size) + " elements (non-manifold)");
            }
            run = run_end;
        }
    }
    if (first_problem.item != Refusal::npos) return first_problem;
    // release the scratch before the pools grow (assigning {} would keep the capacity)
    std::vector<FaceEntry>().swap(entries);
    std::vector<std::uint32_t>().swap(bucket_start);

    // Everything is known to be consistent. The mesh has no elements, so building in place
    // loses nothing but dead pool entries, and uses whatever capacity the caller reserved.
    try {
        m_elements.assign(n, ElementRecord{});
        m_faces.assign(face_total, FaceRecord{});
        m_boundary.clear();
        m_boundary.reserve(boundary_count);
        std::fill(m_vertex_element.begin(), m_vertex_element.end(), invalid_id);
        for (std::size_t i = 0; i < n; ++i) {
            ElementRecord& e = m_elements[i];
            e.simplex = simplexes[i];
            e.label = labels.empty() ? 0 : labels[i];
            for (int j = 0; j < k; ++j) {
                const std::size_t f = i * static_cast<std::size_t>(k) + static_cast<std::size_t>(j);
                e.faces[static_cast<std::size_t>(j)] = static_cast<FaceId>(f);
                m_faces[f] = FaceRecord{static_cast<ElementId>(i), mates[f]};
                if (mates[f] == invalid_id) m_boundary.insert(e.simplex.subn(j), static_cast<FaceId>(f));
                ElementId& anchor = m_vertex_element[e.simplex.vertex(j)];
                if (anchor == invalid_id) anchor = static_cast<ElementId>(i);
            }
        }
    } catch (...) {
        // out of memory half-way: leave an empty, valid mesh rather than a torn one
        m_elements.clear();
        m_faces.clear();
        m_boundary.clear();
        std::fill(m_vertex_element.begin(), m_vertex_element.end(), invalid_id);
        m_free_element = m_free_face = invalid_id;
        m_element_count = 0;
        throw;
    }
    m_free_element = invalid_id;
    m_free_face = invalid_id;
    m_element_count = n;
    for (Watcher* w : m_watchers) w->init(*this);
    return Done{};
}

Outcome<Done> Mesh::assign_elements_unchecked(std::span<const Simplex> simplexes,
                                              std::span<const int> labels) {
    const int k = m_dimension + 1;
    if (m_element_count != 0) return Refusal{"assign_elements needs a mesh without elements"};
    if (!labels.empty() && labels.size() != simplexes.size())
        return Refusal{"got " + std::to_string(labels.size()) + " labels for " +
                       std::to_string(simplexes.size()) + " elements"};
    for (std::size_t i = 0; i < simplexes.size(); ++i)
        if (std::string why = check_simplex(simplexes[i], k, vertex_count()); !why.empty())
            return Refusal{std::move(why), i};

    m_elements.clear();
    m_faces.clear();
    m_boundary.clear();
    m_free_element = m_free_face = invalid_id;
    std::fill(m_vertex_element.begin(), m_vertex_element.end(), invalid_id);
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
    }
    for (Watcher* w : m_watchers) w->init(*this);
    return Done{};
}

}  // namespace sxk
