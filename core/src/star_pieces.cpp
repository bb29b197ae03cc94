// The check that keeps vertex stars face-connected across an edit (§7.3: star(v) must be
// (v, {})-connected, or traversal from an anchor misses elements and dissection is undefined).
#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "star_walk.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

std::size_t Mesh::star_pieces_after(VertexId v, std::span<const ElementId> removed,
                                    std::span<const Simplex> added) const {
    // Nodes: the elements containing v after the edit. Two of them are face-neighbours when one
    // has a face sigma containing v and the other -sigma; count the pieces with union-find.
    struct FaceOfNode {
        Simplex face;
        std::uint32_t node;
    };
    std::vector<FaceOfNode> faces;
    std::uint32_t nodes = 0;
    auto add_node = [&](const Simplex& tau) {
        for (int i = 0; i < tau.count(); ++i)
            if (tau.vertex(i) != v) faces.push_back({tau.subn(i), nodes});
        ++nodes;
    };
    detail::StarList around;
    detail::for_each_in_star(*this, v, m_vertex_element[v], around, [&](std::size_t, ElementId t, const Simplex& tau) {
        if (!std::binary_search(removed.begin(), removed.end(), t)) add_node(tau);
        return false;
    });
    for (const Simplex& tau : added)
        if (tau.contains(v)) add_node(tau);
    if (nodes <= 1) return nodes;

    std::vector<std::uint32_t> parent(nodes);
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::sort(faces.begin(), faces.end(), [](const FaceOfNode& a, const FaceOfNode& b) {
        return Simplex(+1, a.face.vertices()) < Simplex(+1, b.face.vertices());
    });
    std::size_t pieces = nodes;
    for (std::size_t i = 1; i < faces.size(); ++i) {
        if (!faces[i].face.same_vertices(faces[i - 1].face)) continue;
        if (faces[i].face.sign() == faces[i - 1].face.sign()) continue;  // not mates
        const std::uint32_t a = root(faces[i].node), b = root(faces[i - 1].node);
        if (a != b) {
            parent[a] = b;
            --pieces;
        }
    }
    return pieces;
}

std::optional<Refusal> Mesh::refuse_pinched_stars(std::vector<VertexId> touched,
                                                  std::span<const ElementId> removed,
                                                  std::span<const Simplex> added) const {
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (VertexId v : touched)
        if (const std::size_t pieces = star_pieces_after(v, removed, added); pieces > 1)
            return Refusal{RefusalCode::pinched_star,
                           "star connectivity: vertex " + std::to_string(v) +
                           " would be pinched (its star would fall into " + std::to_string(pieces) +
                           " pieces)"};
    return std::nullopt;
}

}  // namespace sxk
