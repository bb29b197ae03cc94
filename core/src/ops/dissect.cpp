// dissect (thesis §7.3, dissection by (v,C)-connected components; edit by change-elements).
#include "sxk/ops/dissect.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "mesh_checks.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// C is a set of unoriented faces: a face in C counts with its mate (thesis §7.3).
Simplex unoriented(const Simplex& sigma) { return Simplex(+1, sigma.vertices()); }

// A face of the mesh with sigma's vertices (either orientation), or invalid_id.
FaceId find_mesh_face(const Mesh& mesh, const Simplex& sigma) {
    const VertexId v = sigma.vertex(0);
    if (mesh.vertex_element(v) == invalid_id) return invalid_id;
    for (ElementId t : star(mesh, v)) {
        const Simplex& tau = mesh.simplex(t);
        for (int j = 0; j < tau.count(); ++j)
            if (tau.subn(j).same_vertices(sigma)) return mesh.face(t, j);
    }
    return invalid_id;
}

bool is_mesh_face(const Mesh& mesh, const Simplex& sigma) { return find_mesh_face(mesh, sigma) != invalid_id; }

// Union-find over the positions of star(v); star sizes are small, so path halving suffices.
std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

Outcome<DissectResult> dissect(Mesh& mesh, std::span<const Simplex> cut_faces, const DissectOptions& options) {
    const int d = mesh.topological_dimension();
    std::unordered_set<Simplex, SimplexHash> cut;
    std::vector<std::pair<FaceId, FaceId>> joined;  // the interior faces of C with their mates
    std::vector<VertexId> cut_vertices;
    for (std::size_t i = 0; i < cut_faces.size(); ++i) {
        const Simplex& sigma = cut_faces[i];
        const std::string name = "dissect: cut face " + std::to_string(i);
        if (sigma.count() != d)
            return Refusal{RefusalCode::bad_argument,
                           name + " has " + std::to_string(sigma.count()) + " vertices, not " +
                               std::to_string(d),
                           i};
        bool known = sigma.has_distinct_vertices();
        for (VertexId v : sigma.vertices()) known = known && v < mesh.vertex_count();
        if (!known)
            return Refusal{RefusalCode::bad_argument,
                           name + " " + to_text(sigma) + " has a repeated or unknown vertex", i};
        const FaceId face = find_mesh_face(mesh, sigma);
        if (face == invalid_id)
            return Refusal{RefusalCode::not_found,
                           name + " " + to_text(sigma) + " is not a face of the mesh", i};
        // an interior face of C: it opens when its two sides end up without a mate
        if (cut.insert(unoriented(sigma)).second && mesh.mate(face) != invalid_id) joined.emplace_back(face, mesh.mate(face));
        cut_vertices.insert(cut_vertices.end(), sigma.vertices().begin(), sigma.vertices().end());
    }
    std::sort(cut_vertices.begin(), cut_vertices.end());
    cut_vertices.erase(std::unique(cut_vertices.begin(), cut_vertices.end()), cut_vertices.end());

    // Per changed element, the substituted canonical vertices (start: unchanged).
    std::unordered_map<ElementId, ElementSubstitution> substitution;
    DissectResult result;
    VertexId next_vertex = static_cast<VertexId>(mesh.vertex_count());

    for (VertexId v : cut_vertices) {
        std::vector<ElementId> around = star(mesh, v);
        std::sort(around.begin(), around.end());
        std::vector<std::size_t> parent(around.size());
        std::iota(parent.begin(), parent.end(), std::size_t{0});
        auto position = [&](ElementId t) {
            return static_cast<std::size_t>(std::lower_bound(around.begin(), around.end(), t) -
                                            around.begin());
        };
        // (v,C)-connected: joined across a face that contains v (slot j with vertex(j) != v)
        // and is not in C.
        for (std::size_t a = 0; a < around.size(); ++a) {
            const ElementId t = around[a];
            const Simplex& tau = mesh.simplex(t);
            for (int j = 0; j < tau.count(); ++j) {
                if (tau.vertex(j) == v) continue;
                const ElementId u = mesh.neighbor(t, j);
                if (u == invalid_id || cut.contains(unoriented(tau.subn(j)))) continue;
                parent[find_root(parent, a)] = find_root(parent, position(u));
            }
        }
        // around is sorted, so classes are met in order of their smallest element; the first
        // keeps v.
        std::unordered_map<std::size_t, VertexId> vertex_of_root;
        for (std::size_t a = 0; a < around.size(); ++a) {
            const std::size_t root = find_root(parent, a);
            auto [it, fresh] = vertex_of_root.try_emplace(root, v);
            if (fresh && vertex_of_root.size() > 1) {
                it->second = next_vertex++;
                result.new_vertices.emplace_back(v, it->second);
            }
            if (it->second == v) continue;
            const ElementId t = around[a];
            auto [entry, first] = substitution.try_emplace(t);
            if (first) {
                entry->second.element = t;
                const Simplex& tau = mesh.simplex(t);
                for (int j = 0; j < tau.count(); ++j)
                    entry->second.new_vertices[static_cast<std::size_t>(j)] = tau.vertex(j);
            }
            entry->second.new_vertices[static_cast<std::size_t>(mesh.simplex(t).index(v))] =
                it->second;
        }
    }
    if (result.new_vertices.empty()) return result;  // Fig. 7.7: nothing separates

    std::vector<ElementSubstitution> changes;
    changes.reserve(substitution.size());
    for (const auto& [t, s] : substitution) changes.push_back(s);
    std::sort(changes.begin(), changes.end(),
              [](const ElementSubstitution& a, const ElementSubstitution& b) {
                  return a.element < b.element;
              });
    // Face labels (keyed by vertex set) follow the faces whose vertices are replaced: the face
    // with the copies gets the label; the original key keeps it only while some element still
    // has that face (a cut face labelled on both sides labels both new boundary faces).
    struct Relabel {
        Simplex before, after;
        int label;
    };
    std::vector<Relabel> relabel;
    if (!mesh.face_labels().empty())
        for (const ElementSubstitution& change : changes) {
            const Simplex& tau = mesh.simplex(change.element);
            for (int j = 0; j < tau.count(); ++j) {
                const Simplex face = unoriented(tau.subn(j));
                const auto label = mesh.face_labels().find(face);
                if (label == mesh.face_labels().end()) continue;
                std::vector<VertexId> after;
                for (int k = 0; k < tau.count(); ++k)
                    if (k != j) after.push_back(change.new_vertices[static_cast<std::size_t>(k)]);
                std::sort(after.begin(), after.end());
                const Simplex renamed(+1, after);
                if (!(renamed == face)) relabel.push_back({face, renamed, label->second});
            }
        }

    // Each copy takes all of its original's data: both positions and every vertex attribute
    // (one parent with weight 1 copies bit for bit).
    for (const auto& [original, copy] : result.new_vertices) {
        const std::array<VertexId, 1> parent{original};
        const std::array<double, 1> whole{1.0};
        (void)mesh.add_interpolated_vertex(parent, whole);  // original < vertex_count(): cannot refuse
    }
    // the star walks of change_elements are proven (mesh_checks.hpp, ProvenEdit)
    auto changed = ProvenEdit::change(mesh, changes);
    if (!changed.ok()) {
        // cannot happen on a valid mesh (see the header); the copies are in no element yet
        for (std::size_t i = 0; i < result.new_vertices.size(); ++i) (void)mesh.remove_last_vertex();
        return Refusal{changed.code(), "dissect: " + changed.reason(), changed.refusal().item};
    }
    for (const Relabel& r : relabel)
        if (!mesh.face_label(r.after)) mesh.set_face_label(r.after, r.label);
    for (const Relabel& r : relabel)
        if (!is_mesh_face(mesh, r.before)) mesh.erase_face_label(r.before);
    // the cut mark: after the labels that followed their faces, so a labelled face keeps its own
    for (const auto& [f, g] : joined) {
        if (mesh.mate(f) == g) continue;  // Fig. 7.7: still joined
        for (const FaceId side : {f, g}) {
            result.opened.push_back(side);
            const Simplex key = unoriented(mesh.face_simplex(side));
            if (options.cut_label && !mesh.face_label(key)) mesh.set_face_label(key, *options.cut_label);
        }
    }
    std::sort(result.opened.begin(), result.opened.end());
    return result;
}

}  // namespace sxk
