// validate(): invariants 7.1-7.5 of the thesis, uniqueness, vertex anchors and face-connected
// vertex stars. Messages name the invariant first so that tools and tests can match on it.
#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "star_walk.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"

namespace sxk {


namespace {

std::string element_name(ElementId t, const Simplex& s) {
    return "element " + std::to_string(t) + " " + to_text(s);
}

// Geometry after connectivity: the reference positions first (the shape the solver's stiffness
// comes from), then the deformed ones.
Outcome<Done> check_orientation(const Mesh& mesh, bool flat_is_invalid) {
    for (const Positions positions : {Positions::reference, Positions::deformed}) {
        const char* which = positions == Positions::reference ? "reference" : "deformed";
        for (ElementId t : elements(mesh)) {
            const Sign sign = element_orientation(mesh, t, positions);
            if (sign == Sign::negative)
                return Refusal{RefusalCode::invalid_mesh,
                               "element " + std::to_string(t) + " is inverted in the " + which +
                                   " positions",
                               t};
            if (sign == Sign::zero && flat_is_invalid)
                return Refusal{RefusalCode::invalid_mesh,
                               "element " + std::to_string(t) + " is flat in the " + which +
                                   " positions",
                               t};
        }
    }
    return Done{};
}

}  // namespace

Outcome<Done> Mesh::validate(const ValidateOptions& options) const {
    const int k = m_dimension + 1;
    const std::size_t uk = static_cast<std::size_t>(k);

    // attributes: a row for every vertex, and for every id of the element pool
    for (const auto& [table, rows, kind] :
         {std::tuple{&m_attributes, vertex_count(), "vertex"}, std::tuple{&m_element_attributes, m_elements.size(), "element"}})
        for (const detail::AttributeColumn& a : *table)
            if (a.components > 0 && a.values.size() < rows * static_cast<std::size_t>(a.components))
                return Refusal{RefusalCode::invalid_mesh, std::string(kind) + " attribute \"" + a.name + "\" has " +
                                                              std::to_string(a.values.size()) + " values for " +
                                                              std::to_string(rows) + " rows of " +
                                                              std::to_string(a.components)};

    // elements: well-formed simplexes whose faces point back at them (7.1, 7.2)
    std::size_t live_elements = 0;
    for (ElementId t = 0; t < m_elements.size(); ++t) {
        if (!is_element(t)) continue;
        ++live_elements;
        const ElementRecord& e = m_elements[t];
        if (std::string why = detail::check_simplex(e.simplex, k, vertex_count()); !why.empty())
            return Refusal{RefusalCode::invalid_mesh,
                           "element " + std::to_string(t) + ": " + why, t};
        for (std::size_t i = 0; i < uk; ++i) {
            const FaceId f = e.faces[i];
            if (!is_face(f))
                return Refusal{RefusalCode::invalid_mesh,
                               "invariant 7.1 (faces of an element): " +
                                   element_name(t, e.simplex) + " lists face " +
                                   (f == invalid_id ? std::string("none") : std::to_string(f)) +
                                   " in slot " + std::to_string(i) + ", which does not exist",
                               t};
            if (m_faces[f].element != t)
                return Refusal{RefusalCode::invalid_mesh,
                               "invariant 7.2 (face element): face " + std::to_string(f) +
                                   " in slot " + std::to_string(i) + " of " +
                                   element_name(t, e.simplex) + " names element " +
                                   std::to_string(m_faces[f].element),
                               t};
            for (std::size_t j = 0; j < i; ++j)
                if (e.faces[j] == f)
                    return Refusal{
                        RefusalCode::invalid_mesh,
                        "invariant 7.1 (faces of an element): " + element_name(t, e.simplex) +
                            " lists face " + std::to_string(f) + " twice",
                        t};
        }
    }
    if (live_elements != m_element_count)
        return Refusal{RefusalCode::invalid_mesh,
                       "element count " + std::to_string(m_element_count) + " but " +
                       std::to_string(live_elements) + " live elements"};

    // faces: owned (7.2), mates mutual and opposite (7.3)
    std::size_t mateless = 0;
    for (FaceId f = 0; f < m_faces.size(); ++f) {
        if (!is_face(f)) continue;
        const ElementId t = m_faces[f].element;
        if (!is_element(t) || face_slot(f) < 0)
            return Refusal{RefusalCode::invalid_mesh,
                           "invariant 7.2 (face element): face " + std::to_string(f) +
                           " is not among the faces of its element " + std::to_string(t)};
        const FaceId g = m_faces[f].mate;
        if (g == invalid_id) {
            ++mateless;
            continue;
        }
        const Simplex sigma = face_simplex(f);
        if (!is_face(g))
            return Refusal{RefusalCode::invalid_mesh, "invariant 7.3 (mate): face " +
                                                          std::to_string(f) + " " + to_text(sigma) +
                                                          " has mate " + std::to_string(g) +
                                                          ", which does not exist"};
        if (m_faces[g].mate != f)
            return Refusal{RefusalCode::invalid_mesh,
                           "invariant 7.3 (mate): face " + std::to_string(f) + " " +
                               to_text(sigma) + " has mate " + std::to_string(g) +
                               " whose mate is " +
                               (m_faces[g].mate == invalid_id ? std::string("none")
                                                              : std::to_string(m_faces[g].mate))};
        if (!(face_simplex(g) == sigma.mate()))
            return Refusal{RefusalCode::invalid_mesh,
                           "invariant 7.3 (mate): face " + std::to_string(f) + " " +
                               to_text(sigma) + " has mate " + std::to_string(g) + " " +
                               to_text(face_simplex(g)) + ", expected " + to_text(sigma.mate())};
    }

    // the neighbour cache: neighbors[i] is the element of the mate of faces[i]
    for (ElementId t = 0; t < m_elements.size(); ++t) {
        if (!is_element(t)) continue;
        const ElementRecord& e = m_elements[t];
        for (std::size_t i = 0; i < uk; ++i) {
            const FaceId g = m_faces[e.faces[i]].mate;
            const ElementId expected = g == invalid_id ? ElementId{invalid_id} : m_faces[g].element;
            if (e.neighbors[i] != expected)
                return Refusal{RefusalCode::invalid_mesh,
                               "neighbour cache: " + element_name(t, e.simplex) + " names " +
                                   (e.neighbors[i] == invalid_id ? std::string("none") : std::to_string(e.neighbors[i])) +
                                   " across slot " + std::to_string(i) + ", but its mate is in " +
                                   (expected == invalid_id ? std::string("none") : std::to_string(expected)),
                               t};
        }
    }

    // uniqueness (7.4): no two elements with the same vertices, no simplex in two faces
    {
        std::vector<std::pair<Simplex, ElementId>> all;
        all.reserve(m_element_count);
        for (ElementId t = 0; t < m_elements.size(); ++t)
            if (is_element(t)) all.emplace_back(Simplex(+1, m_elements[t].simplex.vertices()), t);
        std::sort(all.begin(), all.end());
        for (std::size_t i = 1; i < all.size(); ++i)
            if (all[i].first == all[i - 1].first)
                return Refusal{RefusalCode::invalid_mesh,
                               "invariant 7.4 (uniqueness): elements " +
                                   std::to_string(all[i - 1].second) + " and " +
                                   std::to_string(all[i].second) + " have the same vertices " +
                                   to_text(all[i].first),
                               all[i].second};
    }
    {
        std::vector<std::pair<Simplex, FaceId>> all;
        all.reserve(m_element_count * uk);
        for (FaceId f = 0; f < m_faces.size(); ++f)
            if (is_face(f)) all.emplace_back(face_simplex(f), f);
        std::sort(all.begin(), all.end());
        for (std::size_t i = 1; i < all.size(); ++i)
            if (all[i].first == all[i - 1].first)
                return Refusal{RefusalCode::invalid_mesh,
                               "invariant 7.4 (uniqueness): simplex " + to_text(all[i].first) +
                                   " is represented by faces " + std::to_string(all[i - 1].second) +
                                   " (element " + std::to_string(m_faces[all[i - 1].second].element) +
                                   ") and " + std::to_string(all[i].second) + " (element " +
                                   std::to_string(m_faces[all[i].second].element) + ")",
                               m_faces[all[i].second].element};
    }

    // face labels name faces of the mesh: a label keyed by a vertex set that no face has would
    // be written into files that readers (ours included) refuse
    if (!m_face_labels.empty()) {
        std::vector<Simplex> keys;
        keys.reserve(m_element_count * uk);
        for (FaceId f = 0; f < m_faces.size(); ++f)
            if (is_face(f)) keys.emplace_back(+1, face_simplex(f).vertices());
        std::sort(keys.begin(), keys.end());
        for (const auto& [key, label] : m_face_labels)
            if (!std::binary_search(keys.begin(), keys.end(), Simplex(+1, key.vertices())))
                return Refusal{RefusalCode::invalid_mesh,
                               "face label: label " + std::to_string(label) + " names " +
                               to_text(key) + ", which is not a face of the mesh"};
    }

    // boundary map (7.5): exactly the faces without mate, under their own simplex
    if (m_boundary.size() != mateless)
        return Refusal{RefusalCode::invalid_mesh, "invariant 7.5 (boundary map): it holds " +
                                                      std::to_string(m_boundary.size()) +
                                                      " faces but " + std::to_string(mateless) +
                                                      " faces have no mate"};
    std::string boundary_problem;
    m_boundary.for_each([&](const detail::BoundaryMap::Key& key, FaceId f) {
        if (!boundary_problem.empty()) return;
        if (!is_face(f)) {
            boundary_problem = "invariant 7.5 (boundary map): it holds face " + std::to_string(f) +
                               ", which does not exist";
        } else if (m_faces[f].mate != invalid_id) {
            boundary_problem = "invariant 7.5 (boundary map): it holds face " + std::to_string(f) + " " +
                               to_text(face_simplex(f)) + ", which has a mate";
        } else if (detail::BoundaryMap::key_of(face_simplex(f)) != key) {
            boundary_problem = "invariant 7.5 (boundary map): face " + std::to_string(f) + " " +
                               to_text(face_simplex(f)) + " is filed under other vertices";
        }
    });
    if (!boundary_problem.empty()) return Refusal{RefusalCode::invalid_mesh, boundary_problem};
    for (FaceId f = 0; f < m_faces.size(); ++f)
        if (is_face(f) && m_faces[f].mate == invalid_id && m_boundary.find(face_simplex(f)) != f)
            return Refusal{RefusalCode::invalid_mesh,
                           "invariant 7.5 (boundary map): boundary face " + std::to_string(f) +
                               " " + to_text(face_simplex(f)) + " of element " +
                               std::to_string(m_faces[f].element) +
                               " is missing from the boundary map",
                           m_faces[f].element};

    // vertex anchors and face-connected stars (§7.3: star(v) must be (v, {})-connected)
    std::vector<std::uint32_t> incidence(vertex_count(), 0);
    for (ElementId t = 0; t < m_elements.size(); ++t)
        if (is_element(t))
            for (VertexId v : m_elements[t].simplex.vertices()) ++incidence[v];
    // The walks' list marks each element with the vertex whose star it was last listed in (and
    // its position there), so that walking every star costs O(1) per element met.
    struct MarkedStar {
        std::vector<std::pair<VertexId, std::uint32_t>>& marks;  // per element of the pool
        VertexId v;
        std::vector<ElementId>& elements;
        std::size_t size() const { return elements.size(); }
        ElementId operator[](std::size_t i) const { return elements[i]; }
        std::size_t insert(ElementId t) {
            if (marks[t].first == v) return marks[t].second;
            marks[t] = {v, static_cast<std::uint32_t>(elements.size())};
            elements.push_back(t);
            return elements.size() - 1;
        }
    };
    std::vector<std::pair<VertexId, std::uint32_t>> marks(m_elements.size(), {invalid_id, 0});
    std::vector<ElementId> listed;
    for (VertexId v = 0; v < vertex_count(); ++v) {
        const ElementId a = m_vertex_element[v];
        if (incidence[v] == 0) {
            if (a != invalid_id)
                return Refusal{RefusalCode::invalid_mesh,
                               "vertex anchor: vertex " + std::to_string(v) +
                               " is in no element but names element " + std::to_string(a)};
            continue;
        }
        if (!is_element(a) || !m_elements[a].simplex.contains(v))
            return Refusal{RefusalCode::invalid_mesh,
                           "vertex anchor: vertex " + std::to_string(v) + " names element " +
                           (a == invalid_id ? std::string("none") : std::to_string(a)) +
                           ", which does not contain it"};
        listed.clear();
        MarkedStar listing{marks, v, listed};
        detail::for_each_in_star(*this, v, a, listing, [](std::size_t, ElementId, const Simplex&) { return false; });
        const std::size_t reached = listed.size();
        if (reached != incidence[v])
            return Refusal{RefusalCode::invalid_mesh,
                           "star connectivity: the star of vertex " + std::to_string(v) +
                               " is not face-connected (" + std::to_string(reached) + " of its " +
                               std::to_string(incidence[v]) +
                               " elements are reachable from element " + std::to_string(a) +
                               "; the mesh is pinched at this vertex)"};
    }
    // every anchor checked above names an element exactly when its vertex is in one
    const auto in_elements = static_cast<std::size_t>(
        std::count_if(incidence.begin(), incidence.end(), [](auto count) { return count != 0; }));
    if (m_vertices_in_elements != in_elements)
        return Refusal{RefusalCode::invalid_mesh, "vertex count: " + std::to_string(m_vertices_in_elements) +
                                                      " vertices counted in elements, " +
                                                      std::to_string(in_elements) + " are"};
    if (options.orientation && m_dimension == m_ambient)
        return check_orientation(*this, options.flat_is_invalid);
    return Done{};
}

}  // namespace sxk
