// Loose pieces (loose_pieces.hpp): searches from both sides of a cut, racing.
#include "loose_pieces.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <unordered_map>

namespace sxk::snapcut {
namespace {

// The seeds in groups known connected without a search: seeds that share a vertex, as the star
// of a vertex is face-connected in a valid mesh (Mesh::validate, thesis §7.3). Dissection gives
// each side of a cut its own copies of the cut's nodes, so the sides share only the nodes of the
// cut's rim: the two sides of a cut that separates nothing meet there at once, and the race below
// runs only when the seeds are in several groups (on the 1.2M femur the searches' meeting around
// the rim cost 0.28 ms per step, docs/performance.md "snapcut").
std::vector<std::vector<ElementId>> seed_groups(const Mesh& mesh, std::span<const ElementId> seeds) {
    std::vector<ElementId> elements(seeds.begin(), seeds.end());
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    std::erase_if(elements, [&](ElementId t) { return !mesh.is_element(t); });
    std::vector<std::uint32_t> parent(elements.size());
    for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto root = [&](std::uint32_t s) {
        while (parent[s] != s) s = parent[s] = parent[parent[s]];
        return s;
    };
    std::unordered_map<std::uint32_t, std::uint32_t> first_with;  // vertex -> the first seed holding it
    for (std::uint32_t i = 0; i < elements.size(); ++i)
        for (const VertexId v : mesh.simplex(elements[i]).vertices()) {
            const auto [found, fresh] = first_with.emplace(v, i);
            if (!fresh) parent[root(found->second)] = root(i);
        }
    std::vector<std::vector<ElementId>> groups;
    std::unordered_map<std::uint32_t, std::size_t> group_of;  // root -> its group
    for (std::uint32_t i = 0; i < elements.size(); ++i) {
        const auto [found, fresh] = group_of.emplace(root(i), groups.size());
        if (fresh) groups.emplace_back();
        groups[found->second].push_back(elements[i]);
    }
    return groups;
}

}  // namespace

LoosePieces find_loose_pieces(const Mesh& mesh, std::span<const ElementId> seeds) {
    struct Search {
        std::deque<ElementId> queue;
        std::vector<ElementId> members;
        bool running = true;
    };
    std::vector<Search> searches;
    std::vector<std::uint32_t> parent;  // union-find over searches: the ones that met
    std::unordered_map<std::uint32_t, std::uint32_t> owner;  // element -> the search that reached it
    auto root = [&](std::uint32_t s) {
        while (parent[s] != s) s = parent[s] = parent[parent[s]];
        return s;
    };
    for (const std::vector<ElementId>& group : seed_groups(mesh, seeds)) {
        const auto s = static_cast<std::uint32_t>(searches.size());
        for (const ElementId t : group) owner.emplace(t, s);
        searches.push_back({{group.begin(), group.end()}, group, true});
        parent.push_back(s);
    }
    LoosePieces result;
    std::size_t running = searches.size();
    const int faces = mesh.element_vertex_count();
    while (running > 1) {
        for (std::uint32_t s = 0; s < searches.size() && running > 1; ++s) {
            if (parent[s] != s || !searches[s].running) continue;
            if (searches[s].queue.empty()) {  // a whole component, and not the last one: loose
                std::vector<ElementId> piece = std::move(searches[s].members);
                std::sort(piece.begin(), piece.end());
                result.pieces.push_back(std::move(piece));
                searches[s].running = false;
                --running;
                continue;
            }
            std::uint32_t me = s;
            const ElementId t = searches[me].queue.front();
            searches[me].queue.pop_front();
            for (int i = 0; i < faces; ++i) {
                const ElementId n = mesh.neighbor(t, i);
                if (n == invalid_id) continue;
                const auto [found, fresh] = owner.emplace(n, me);
                if (fresh) {
                    searches[me].queue.push_back(n);
                    searches[me].members.push_back(n);
                    continue;
                }
                const std::uint32_t other = root(found->second);
                if (other == me) continue;
                // the two searches met: one component; the smaller joins the larger
                std::uint32_t big = me, small = other;
                if (searches[big].members.size() < searches[small].members.size()) std::swap(big, small);
                parent[small] = big;
                Search& from = searches[small];
                Search& into = searches[big];
                into.queue.insert(into.queue.end(), from.queue.begin(), from.queue.end());
                into.members.insert(into.members.end(), from.members.begin(), from.members.end());
                from = Search{{}, {}, false};
                --running;
                me = big;
            }
        }
    }
    return result;
}

}  // namespace sxk::snapcut
