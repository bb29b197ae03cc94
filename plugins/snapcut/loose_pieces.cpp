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
struct SeedGroups {
    std::vector<std::vector<ElementId>> groups;
    std::unordered_map<VertexId, std::uint32_t> group_of_vertex;  // a vertex of some seed -> its group
};

SeedGroups seed_groups(const Mesh& mesh, std::span<const ElementId> seeds) {
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
    SeedGroups result;
    std::unordered_map<std::uint32_t, std::uint32_t> group_of;  // root -> its group
    for (std::uint32_t i = 0; i < elements.size(); ++i) {
        const auto [found, fresh] = group_of.emplace(root(i), static_cast<std::uint32_t>(result.groups.size()));
        if (fresh) result.groups.emplace_back();
        result.groups[found->second].push_back(elements[i]);
    }
    for (const auto& [v, seed] : first_with) result.group_of_vertex.emplace(v, group_of.at(root(seed)));
    return result;
}

// The groups' bodies, as a union-find forest over the n groups and one more (n) whose roots name
// the bodies: groups joined by a pair of cut nodes (an original and its copy, whose
// stars were one before the dissection) lie on one body as it was before the step. A group that
// no pair reaches (a degeneracy collapse may have removed both ends' elements from the seeds, or
// the removal cut free the elements that held a piece on) lies on the step's one body when the
// pairs reach one body only: a step's seeds surround its edits, and the edits of a step that cut
// one body lie on it. (A random through cut of the femur, SXK_SEED=3289562137 cut 5, separated 5
// elements by the removal's cutting free 2; put in a body of their own, they raced nothing and
// stayed in the mesh as a third piece.) When the pairs reach several bodies, the groups they do
// not reach are put together in one body, the rule before bodies were told apart.
std::vector<std::uint32_t> bodies_of(const SeedGroups& seeds, std::span<const std::pair<VertexId, VertexId>> cut_pairs) {
    const std::size_t n = seeds.groups.size();
    std::vector<std::uint32_t> parent(n + 1);  // n: the body of the groups no pair reaches
    for (std::uint32_t i = 0; i <= n; ++i) parent[i] = i;
    auto root = [&](std::uint32_t s) {
        while (parent[s] != s) s = parent[s] = parent[parent[s]];
        return s;
    };
    std::vector<char> reached(n, 0);
    for (const auto& [original, copy] : cut_pairs) {
        const auto a = seeds.group_of_vertex.find(original), b = seeds.group_of_vertex.find(copy);
        if (a == seeds.group_of_vertex.end() || b == seeds.group_of_vertex.end()) continue;
        reached[a->second] = reached[b->second] = 1;
        parent[root(a->second)] = root(b->second);
    }
    // the body the unreached groups join: the pairs' one body, or n
    std::uint32_t unreached_body = static_cast<std::uint32_t>(n);
    bool several = false;
    for (std::uint32_t i = 0; i < n && !several; ++i) {
        if (!reached[i]) continue;
        if (unreached_body == n) unreached_body = root(i);
        else several = root(i) != unreached_body;
    }
    if (several) unreached_body = static_cast<std::uint32_t>(n);
    for (std::uint32_t i = 0; i < n; ++i)
        if (!reached[i]) parent[root(i)] = root(unreached_body);
    for (std::uint32_t i = 0; i <= n; ++i) parent[i] = root(i);
    return parent;
}

}  // namespace

LoosePieces find_loose_pieces(const Mesh& mesh, std::span<const ElementId> seeds,
                              std::span<const std::pair<VertexId, VertexId>> cut_pairs) {
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
    const SeedGroups groups = seed_groups(mesh, seeds);
    for (const std::vector<ElementId>& group : groups.groups) {
        const auto s = static_cast<std::uint32_t>(searches.size());
        for (const ElementId t : group) owner.emplace(t, s);
        searches.push_back({{group.begin(), group.end()}, group, true});
        parent.push_back(s);
    }
    // Each search belongs to a body as it was before the step (bodies_of), and races only the
    // searches of its body: with two bodies cut in one step, the last search left on each is
    // that body's, not loose (the race over all searches once removed three of the four halves).
    // body_parent joins bodies whose searches meet; running counts each body's running searches.
    std::vector<std::uint32_t> body_parent = bodies_of(groups, cut_pairs);
    std::vector<std::size_t> running_in(body_parent.size(), 0);
    auto body_root = [&](std::uint32_t b) {
        while (body_parent[b] != b) b = body_parent[b] = body_parent[body_parent[b]];
        return b;
    };
    for (std::uint32_t s = 0; s < searches.size(); ++s) ++running_in[body_root(s)];
    std::size_t racing = 0;  // searches in bodies with more than one running
    for (std::uint32_t s = 0; s < searches.size(); ++s) racing += running_in[body_root(s)] > 1;
    LoosePieces result;
    const int faces = mesh.element_vertex_count();
    while (racing > 0) {
        racing = 0;
        for (std::uint32_t s = 0; s < searches.size(); ++s) {
            if (parent[s] != s || !searches[s].running || running_in[body_root(s)] < 2) continue;
            ++racing;
            if (searches[s].queue.empty()) {  // a whole component, and not its body's last one: loose
                std::vector<ElementId> piece = std::move(searches[s].members);
                std::sort(piece.begin(), piece.end());
                result.pieces.push_back(std::move(piece));
                searches[s].running = false;
                --running_in[body_root(s)];
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
                // the two searches met: one component, so one body; the smaller joins the larger
                std::uint32_t big = me, small = other;
                if (searches[big].members.size() < searches[small].members.size()) std::swap(big, small);
                parent[small] = big;
                Search& from = searches[small];
                Search& into = searches[big];
                into.queue.insert(into.queue.end(), from.queue.begin(), from.queue.end());
                into.members.insert(into.members.end(), from.members.begin(), from.members.end());
                from = Search{{}, {}, false};
                const std::uint32_t kept = body_root(big), joined = body_root(small);
                if (kept != joined) {  // (a body that met another was one with it before the step)
                    body_parent[joined] = kept;
                    running_in[kept] += running_in[joined];
                }
                --running_in[kept];
                me = big;
            }
        }
    }
    return result;
}

}  // namespace sxk::snapcut
