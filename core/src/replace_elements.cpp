// Thesis §7.3 replace-elements with face reuse and the matched-pair optimisation.
//
// Order of work: every argument is checked before anything changes (the transaction
// guarantee); then faces that do not survive are detached (their surviving mates go to the
// boundary map), the old elements are freed, new internal face pairs are made already mated
// (so they never visit the boundary map), new elements take over reused faces, and the remaining
// new faces are matched against the boundary map or put on it.
#include <algorithm>
#include <string>
#include <vector>

#include "edit_log.hpp"
#include "mesh_checks.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

using detail::check_simplex;

namespace {

struct NewFace {
    Simplex sigma;
    FaceId face = invalid_id;  // reused old face, or pre-made matched-pair face
    bool reused = false;
    bool paired = false;
};

template <class T>
bool sorted_contains(const std::vector<T>& sorted, const T& value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

}  // namespace

bool Mesh::has_face_outside(const Simplex& sigma, std::span<const ElementId> excluded) const {
    // sigma's elements all contain sigma.vertex(0): walk that vertex's star (face-connected in
    // a valid mesh) and look for sigma in elements that are not excluded.
    const VertexId v = sigma.vertex(0);
    if (m_vertex_element[v] == invalid_id) return false;
    std::vector<ElementId> seen{m_vertex_element[v]};
    for (std::size_t next = 0; next < seen.size(); ++next) {
        const ElementId t = seen[next];
        const Simplex& tau = m_elements[t].simplex;
        const bool counts = std::find(excluded.begin(), excluded.end(), t) == excluded.end();
        // a whole element with sigma's vertices (either orientation) also counts: an element
        // and its mirror image glued along all faces is no simplicial mesh
        if (counts && sigma.count() == m_dimension + 1 && tau.same_vertices(sigma)) return true;
        for (int i = 0; i <= m_dimension; ++i) {
            if (counts && tau.subn(i) == sigma) return true;
            if (tau.vertex(i) == v) continue;  // the face opposite v does not contain v
            const ElementId n = neighbor(t, i);
            if (n != invalid_id && std::find(seen.begin(), seen.end(), n) == seen.end())
                seen.push_back(n);
        }
    }
    return false;
}

Outcome<std::vector<ElementId>> Mesh::replace_elements(std::span<const ElementId> old_elements,
                                                       std::span<const Simplex> new_simplexes,
                                                       std::span<const int> labels) {
    const int k = m_dimension + 1;
    const std::size_t uk = static_cast<std::size_t>(k);
    const std::size_t m = new_simplexes.size();

    // ---- checks: nothing changes before all of them pass ----------------------------------
    for (std::size_t i = 0; i < old_elements.size(); ++i)
        if (!is_element(old_elements[i]))
            return Refusal{"element " + std::to_string(old_elements[i]) + " does not exist", i};
    std::vector<ElementId> old_sorted(old_elements.begin(), old_elements.end());
    std::sort(old_sorted.begin(), old_sorted.end());
    if (auto d = std::adjacent_find(old_sorted.begin(), old_sorted.end()); d != old_sorted.end())
        return Refusal{"element " + std::to_string(*d) + " is listed twice"};
    if (!labels.empty() && labels.size() != m)
        return Refusal{"got " + std::to_string(labels.size()) + " labels for " +
                       std::to_string(m) + " new elements"};
    for (std::size_t i = 0; i < m; ++i)
        if (std::string why = check_simplex(new_simplexes[i], k, vertex_count()); !why.empty())
            return Refusal{std::move(why), i};
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 1; j < m; ++j)
            if (new_simplexes[i].same_vertices(new_simplexes[j]))
                return Refusal{"new elements " + std::to_string(i) + " and " + std::to_string(j) +
                                   " have the same vertices",
                               j};

    // oldfacemap and newfacemap of the thesis, as sorted vectors (edits are small)
    std::vector<std::pair<Simplex, FaceId>> old_faces;
    old_faces.reserve(old_elements.size() * uk);
    for (ElementId t : old_elements)
        for (int j = 0; j < k; ++j)
            old_faces.emplace_back(m_elements[t].simplex.subn(j), m_elements[t].faces[static_cast<std::size_t>(j)]);
    std::sort(old_faces.begin(), old_faces.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    auto find_old = [&](const Simplex& s) -> FaceId {
        auto it = std::lower_bound(old_faces.begin(), old_faces.end(), s,
                                   [](const auto& a, const Simplex& b) { return a.first < b; });
        return (it != old_faces.end() && it->first == s) ? it->second : invalid_id;
    };

    std::vector<NewFace> new_faces(m * uk);
    std::vector<std::size_t> order(m * uk);
    for (std::size_t i = 0; i < m; ++i)
        for (int j = 0; j < k; ++j) {
            const std::size_t index = i * uk + static_cast<std::size_t>(j);
            new_faces[index].sigma = new_simplexes[i].subn(j);
            order[index] = index;
        }
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return new_faces[a].sigma < new_faces[b].sigma; });
    for (std::size_t i = 1; i < order.size(); ++i)
        if (new_faces[order[i]].sigma == new_faces[order[i - 1]].sigma)
            return Refusal{"face " + to_text(new_faces[order[i]].sigma) +
                               " would belong to two new elements (invariant 7.4)",
                           std::max(order[i], order[i - 1]) / uk};
    auto find_new = [&](const Simplex& s) -> NewFace* {
        auto it = std::lower_bound(order.begin(), order.end(), s,
                                   [&](std::size_t a, const Simplex& b) { return new_faces[a].sigma < b; });
        return (it != order.end() && new_faces[*it].sigma == s) ? &new_faces[*it] : nullptr;
    };
    std::vector<FaceId> reused_faces;
    for (NewFace& nf : new_faces) {
        nf.face = find_old(nf.sigma);
        nf.reused = nf.face != invalid_id;
        if (nf.reused) reused_faces.push_back(nf.face);
    }
    std::sort(reused_faces.begin(), reused_faces.end());

    // A face that is not reused must not exist in an element that stays (invariant 7.4); nor
    // may a new element have the vertices of one that stays.
    for (std::size_t i = 0; i < m; ++i) {
        if (has_face_outside(new_simplexes[i], old_sorted))
            return Refusal{"element " + to_text(new_simplexes[i]) +
                               " already exists as an element that stays (invariant 7.4)",
                           i};
        for (int j = 0; j < k; ++j) {
            const NewFace& nf = new_faces[i * uk + static_cast<std::size_t>(j)];
            if (nf.reused) continue;
            const FaceId b = m_boundary.find(nf.sigma);
            const bool on_boundary = b != invalid_id && face_simplex(b) == nf.sigma &&
                                     !sorted_contains(old_sorted, m_faces[b].element);
            if (on_boundary || has_face_outside(nf.sigma, old_sorted))
                return Refusal{"face " + to_text(nf.sigma) +
                                   " already exists in an element that stays (invariant 7.4)",
                               i};
        }
    }

    // Every vertex the edit touches must keep a face-connected star.
    {
        std::vector<VertexId> touched;
        for (ElementId t : old_elements)
            for (VertexId v : m_elements[t].simplex.vertices()) touched.push_back(v);
        for (const Simplex& tau : new_simplexes)
            for (VertexId v : tau.vertices()) touched.push_back(v);
        if (Refusal pinch = refuse_pinched_stars(std::move(touched), old_sorted, new_simplexes);
            !pinch.reason.empty())
            return pinch;
    }

    // ---- the change -------------------------------------------------------------------------
    m_elements.reserve(m_elements.size() + m);
    m_faces.reserve(m_faces.size() + m * uk);
    m_boundary.reserve(m_boundary.size() + m * uk);
    detail::EditLog log(!m_watchers.empty());
    const int default_label = old_elements.empty() ? 0 : m_elements[old_elements[0]].label;

    // vertices whose anchor may die, and surviving elements next to the old ones
    std::vector<VertexId> old_vertices;
    std::vector<ElementId> neighbours;
    for (ElementId t : old_elements) {
        for (int j = 0; j < k; ++j) {
            old_vertices.push_back(m_elements[t].simplex.vertex(j));
            const ElementId n = neighbor(t, j);
            if (n != invalid_id && !sorted_contains(old_sorted, n)) neighbours.push_back(n);
        }
    }

    for (FaceId f : reused_faces) log.touch(*this, f);
    auto discarded = [&](FaceId f) {
        return sorted_contains(old_sorted, m_faces[f].element) && !sorted_contains(reused_faces, f);
    };
    std::vector<FaceId> discard;
    for (const auto& [sigma, g] : old_faces)
        if (!sorted_contains(reused_faces, g)) discard.push_back(g);
    for (FaceId g : discard) {
        const FaceId mate_face = m_faces[g].mate;
        if (mate_face == invalid_id) {
            m_boundary.erase(face_simplex(g));
        } else if (!discarded(mate_face)) {
            // the mate stays (in an element that stays, or reused): it is boundary for now
            log.touch(*this, mate_face);
            m_faces[mate_face].mate = invalid_id;
            m_boundary.insert(face_simplex(mate_face), mate_face);
        }
        log.freed(*this, g);
    }
    for (FaceId g : discard) free_face(g);
    for (ElementId t : old_elements) {
        log.element_removed(t, m_elements[t].simplex);
        free_element(t);
    }

    // matched pairs: sigma and -sigma both new and not reused are made mates at once
    for (NewFace& nf : new_faces) {
        if (nf.reused || nf.paired || nf.sigma.sign() < 0) continue;
        NewFace* other = find_new(nf.sigma.mate());
        if (other == nullptr || other->reused) continue;
        nf.face = allocate_face();
        other->face = allocate_face();
        log.created(nf.face);
        log.created(other->face);
        m_faces[nf.face].mate = other->face;
        m_faces[other->face].mate = nf.face;
        nf.paired = other->paired = true;
    }

    // new elements take over reused and paired faces first, so that every face the boundary
    // map can return below already belongs to a live element
    std::vector<ElementId> created(m);
    for (std::size_t i = 0; i < m; ++i) {
        const ElementId t = allocate_element();
        created[i] = t;
        m_elements[t].simplex = new_simplexes[i];
        m_elements[t].label = labels.empty() ? default_label : labels[i];
        for (int j = 0; j < k; ++j) {
            const NewFace& nf = new_faces[i * uk + static_cast<std::size_t>(j)];
            m_elements[t].faces[static_cast<std::size_t>(j)] = nf.face;
            if (nf.face != invalid_id) m_faces[nf.face].element = t;
        }
        log.element_added(t);
    }
    for (std::size_t i = 0; i < m; ++i) {
        const ElementId t = created[i];
        for (int j = 0; j < k; ++j) {
            const NewFace& nf = new_faces[i * uk + static_cast<std::size_t>(j)];
            if (nf.face != invalid_id) continue;
            const FaceId f = allocate_face();
            log.created(f);
            m_faces[f].element = t;
            m_elements[t].faces[static_cast<std::size_t>(j)] = f;
            const FaceId b = m_boundary.find(nf.sigma);
            if (b != invalid_id && face_simplex(b) == nf.sigma.mate()) {
                log.touch(*this, b);
                m_faces[f].mate = b;
                m_faces[b].mate = f;
                m_boundary.erase(nf.sigma);
            } else {
                m_boundary.insert(nf.sigma, f);
            }
        }
    }

    repair_anchors(new_simplexes, created, old_vertices, neighbours);

    log.publish(*this, m_watchers);
    return created;
}

}  // namespace sxk
