// Thesis §7.3 change-elements: a vertex substitution per element that keeps every element and
// face identity (Fig. 7.5: after cutting and stitching, bd and be' are the same Face object).
//
// Faces are detached from their mates (surviving mates go to the boundary map), the elements get
// their substituted simplexes with each face moved to the slot of its substituted simplex
// (invariant 7.1), and every face is matched again against the boundary map.
#include <algorithm>
#include <string>
#include <vector>

#include "edit_log.hpp"
#include "mesh_checks.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

using detail::check_simplex;

Outcome<Done> Mesh::change_elements(std::span<const ElementSubstitution> substitution) {
    return change_elements_impl(substitution, false);
}

Outcome<Done> Mesh::change_elements(std::span<const ElementSubstitution> substitution, StarChecksProof) {
    return change_elements_impl(substitution, true);
}

Outcome<Done> Mesh::change_elements_impl(std::span<const ElementSubstitution> substitution, bool proven) {
    const int k = m_dimension + 1;
    const std::size_t uk = static_cast<std::size_t>(k);
    const std::size_t m = substitution.size();

    // ---- checks ---------------------------------------------------------------------------------
    for (std::size_t i = 0; i < m; ++i)
        if (!is_element(substitution[i].element))
            return Refusal{RefusalCode::not_found,
                           "element " + std::to_string(substitution[i].element) + " does not exist",
                           i};
    std::vector<ElementId> changed_in_order;
    changed_in_order.reserve(m);
    for (const ElementSubstitution& s : substitution) changed_in_order.push_back(s.element);
    std::vector<ElementId> changed_sorted = changed_in_order;
    std::sort(changed_sorted.begin(), changed_sorted.end());
    if (auto d = std::adjacent_find(changed_sorted.begin(), changed_sorted.end());
        d != changed_sorted.end())
        return Refusal{RefusalCode::bad_argument,
                       "element " + std::to_string(*d) + " is listed twice"};

    std::vector<Simplex> substituted(m);
    for (std::size_t i = 0; i < m; ++i) {
        const Simplex& tau = m_elements[substitution[i].element].simplex;
        substituted[i] = Simplex(tau.sign(), std::span<const VertexId>(substitution[i].new_vertices.data(), uk));
        if (std::string why = check_simplex(substituted[i], k, vertex_count()); !why.empty())
            return Refusal{RefusalCode::bad_argument,
                           "substitution of element " + std::to_string(substitution[i].element) +
                               ": " + why,
                           i};
    }
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 1; j < m; ++j)
            if (substituted[i].same_vertices(substituted[j]))
                return Refusal{RefusalCode::not_manifold,
                               "elements " + std::to_string(substitution[i].element) + " and " +
                                   std::to_string(substitution[j].element) +
                                   " would get the same vertices",
                               j};
    std::vector<Simplex> new_faces;
    new_faces.reserve(m * uk);
    for (const Simplex& tau : substituted)
        for (int j = 0; j < k; ++j) new_faces.push_back(tau.subn(j));
    std::sort(new_faces.begin(), new_faces.end());
    if (auto d = std::adjacent_find(new_faces.begin(), new_faces.end()); d != new_faces.end())
        return Refusal{
            RefusalCode::not_manifold,
            "face " + to_text(*d) + " would belong to two changed elements (invariant 7.4)"};
    // The checks that walk vertex stars (skipped for a ProvenEdit, mesh_checks.hpp): no face or
    // element represented twice (invariant 7.4), no star pinched.
    for (std::size_t i = 0; i < m && !proven; ++i) {
        if (has_face_outside(substituted[i], changed_sorted))
            return Refusal{RefusalCode::not_manifold,
                           "element " + to_text(substituted[i]) +
                               " already exists as an unchanged element (invariant 7.4)",
                           i};
        for (int j = 0; j < k; ++j) {
            const Simplex sigma = substituted[i].subn(j);
            const FaceId b = m_boundary.find(sigma);
            const bool on_boundary =
                b != invalid_id && face_simplex(b) == sigma &&
                !std::binary_search(changed_sorted.begin(), changed_sorted.end(), m_faces[b].element);
            if (on_boundary || has_face_outside(sigma, changed_sorted))
                return Refusal{RefusalCode::not_manifold,
                               "face " + to_text(sigma) +
                                   " already exists in an unchanged element (invariant 7.4)",
                               i};
        }
    }

    // Every vertex the edit touches must keep a face-connected star.
    if (!proven) {
        std::vector<VertexId> touched;
        for (std::size_t i = 0; i < m; ++i) {
            for (VertexId v : m_elements[substitution[i].element].simplex.vertices()) touched.push_back(v);
            for (VertexId v : substituted[i].vertices()) touched.push_back(v);
        }
        if (auto refused = refuse_pinched_stars(std::move(touched), changed_sorted, substituted))
            return *refused;
    }

    // ---- the change -----------------------------------------------------------------------------
    m_boundary.reserve(m_boundary.size() + m * uk);
    ++m_revision;
    detail::EditLog log(!m_watchers.empty());
    auto is_changed = [&](ElementId t) {
        return std::binary_search(changed_sorted.begin(), changed_sorted.end(), t);
    };
    std::vector<VertexId> old_vertices;
    std::vector<ElementId> neighbours;
    for (const ElementSubstitution& s : substitution)
        for (int j = 0; j < k; ++j) {
            old_vertices.push_back(m_elements[s.element].simplex.vertex(j));
            const ElementId n = neighbor(s.element, j);
            if (n != invalid_id && !is_changed(n)) neighbours.push_back(n);
            log.touch(*this, m_elements[s.element].faces[static_cast<std::size_t>(j)]);
        }

    // detach: boundary faces leave the map first (their simplexes are still the old ones), then
    // mates are split; a mate in an unchanged element is on the boundary for now
    for (const ElementSubstitution& s : substitution)
        for (int j = 0; j < k; ++j) {
            const FaceId f = m_elements[s.element].faces[static_cast<std::size_t>(j)];
            if (m_faces[f].mate == invalid_id) boundary_erase(m_elements[s.element].simplex.subn(j));
        }
    for (const ElementSubstitution& s : substitution)
        for (int j = 0; j < k; ++j) {
            const FaceId f = m_elements[s.element].faces[static_cast<std::size_t>(j)];
            const FaceId mate_face = m_faces[f].mate;
            if (mate_face == invalid_id) continue;
            if (!is_changed(m_faces[mate_face].element)) {
                log.touch(*this, mate_face);
                boundary_insert(face_simplex(mate_face), mate_face);
                unlink_neighbor(mate_face);
            }
            face_for_write(mate_face).mate = invalid_id;
            face_for_write(f).mate = invalid_id;
        }

    // substitute: the face opposite vertex a_j is opposite pi(a_j) afterwards
    for (std::size_t i = 0; i < m; ++i) {
        ElementRecord& e = element_for_write(substitution[i].element);
        log.element_changed(substitution[i].element, e.simplex);
        std::array<FaceId, 4> faces{invalid_id, invalid_id, invalid_id, invalid_id};
        for (int j = 0; j < k; ++j)
            faces[static_cast<std::size_t>(substituted[i].index(substitution[i].new_vertices[static_cast<std::size_t>(j)]))] =
                e.faces[static_cast<std::size_t>(j)];
        e.simplex = substituted[i];
        e.faces = faces;
    }

    // reattach
    for (std::size_t i = 0; i < m; ++i) {
        const ElementRecord& e = m_elements[substitution[i].element];
        for (int j = 0; j < k; ++j) {
            const FaceId f = e.faces[static_cast<std::size_t>(j)];
            if (m_faces[f].mate != invalid_id) continue;  // matched from its partner's side
            const Simplex sigma = e.simplex.subn(j);
            const FaceId b = m_boundary.find(sigma);
            if (b != invalid_id && face_simplex(b) == sigma.mate()) {
                log.touch(*this, b);
                face_for_write(f).mate = b;
                face_for_write(b).mate = f;
                boundary_erase(sigma);
            } else {
                boundary_insert(sigma, f);
            }
        }
    }

    for (const ElementSubstitution& s : substitution) link_neighbors(s.element);
    repair_anchors(substituted, changed_in_order, old_vertices, neighbours, changed_sorted);

    log.publish(*this, m_watchers);
    return Done{};
}

}  // namespace sxk
