// Loose pieces (loose_pieces.hpp): searches from both sides of a cut, racing.
#include "loose_pieces.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <unordered_map>

namespace sxk::snapcut {

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
    for (const ElementId t : seeds) {
        if (!mesh.is_element(t) || owner.contains(t)) continue;
        const auto s = static_cast<std::uint32_t>(searches.size());
        owner.emplace(t, s);
        searches.push_back({{t}, {t}, true});
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
