// Thesis §7.3 replace-elements with face reuse and the matched-pair optimisation.
//
// Order of work, one function a phase (Mesh::replace_elements_impl calls them in turn, with a
// detail::ReplacePlan carrying what one phase hands the next): every argument is checked before
// anything changes (the transaction guarantee: refuse_arguments, plan_faces, and
// refuse_star_conflicts unless the operation proved them); then faces that do not survive are
// detached (their surviving mates go to the boundary map) and the old elements are freed
// (remove_old_elements), new internal face pairs are made already mated (so they never visit the
// boundary map: pair_new_faces), new elements take over reused faces (add_new_elements) and
// inherit their origin's attributes, the remaining new faces are matched against the boundary
// map or put on it (add_remaining_faces), and the neighbour cache and the anchors are set before
// the watchers hear of the change.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "edit_log.hpp"
#include "mesh_checks.hpp"
#include "star_walk.hpp"
#include "sxk/mesh.hpp"
#include "undo_log.hpp"

namespace sxk {

using detail::check_simplex;

// The faces ReplacePlan (below) lists: in detail, not in an anonymous namespace, because the plan
// is named in mesh.hpp (a class of a named namespace may not hold an anonymous one's types).
namespace detail {

struct NewFace {
    Simplex sigma;
    FaceId face = invalid_id;  // reused old face, or pre-made matched-pair face
    bool reused = false;
    bool paired = false;
    ElementId across = invalid_id;  // reused: the neighbour across it before the edit
};

struct OldFace {
    Simplex sigma;
    FaceId face;
    ElementId across;  // the neighbour across the face (the cache of Mesh::neighbor)
};

}  // namespace detail

using detail::NewFace;
using detail::OldFace;

namespace {

template <class Sorted, class T>
bool sorted_contains(const Sorted& sorted, const T& value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

// Scratch sizes: a flip or split touches a handful of elements; a vertex star in a 3D mesh has
// some 20-30 elements (rarely above 100). Beyond these the lists move to the heap.
constexpr std::size_t small_edit = 16;
constexpr std::size_t star_inline = 256;

// The stars of every vertex an edit touches, each walked ONCE (for_each_in_star, star_walk.hpp)
// and used both for the invariant 7.4 checks and for the star connectivity check.
// star(vertices[k]) before the edit is elements[offsets[k] .. offsets[k+1]); pieces[k] is the
// number of face-connected pieces it would have after the edit.
//
// Star pieces without sorting the whole star: two elements that stay and are mates across a
// face containing v are joined as the walk meets them; only faces that lose their mate (to a
// removed element or the boundary) and the faces of added elements are matched, by the
// vertices other than v (one or two of them, packed into 64 bits), sign opposite.
struct TouchedStars {
    detail::SmallVector<VertexId, 32> vertices;
    detail::SmallVector<std::uint32_t, 33> offsets;
    detail::SmallVector<ElementId, star_inline> elements;
    detail::SmallVector<std::uint32_t, 32> pieces;

    std::span<const ElementId> star(VertexId v) const {
        const auto k = static_cast<std::size_t>(
            std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
        return {elements.data() + offsets[k], offsets[k + 1] - offsets[k]};
    }
};

struct OpenFace {
    std::uint64_t key;  // the face's vertices other than v
    int sign;
    std::uint32_t node;
};

// Packs the vertices of tau other than v and tau.vertex(i) (in canonical order).
std::uint64_t face_key(const Simplex& tau, int i, VertexId v) {
    std::uint64_t key = 0;
    for (int j = 0; j < tau.count(); ++j)
        if (j != i && tau.vertex(j) != v) key = (key << 32) | tau.vertex(j);
    return key;
}

int face_sign(const Simplex& tau, int i) { return (i & 1) ? -tau.sign() : tau.sign(); }

// Walks star(v) of `mesh`, appends its elements to stars.elements and returns the number of
// pieces it would have after removing `removed` (sorted) and adding `added`.
std::uint32_t walk_star(const Mesh& mesh, VertexId v, std::span<const ElementId> removed,
                        std::span<const Simplex> added, TouchedStars& stars,
                        detail::SmallVector<std::uint32_t, star_inline>& parent,
                        detail::SmallVector<OpenFace, star_inline>& open) {
    parent.clear();
    open.clear();
    std::uint32_t nodes = 0, unions = 0;
    auto root = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    auto join = [&](std::uint32_t a, std::uint32_t b) {
        a = root(a);
        b = root(b);
        if (a != b) {
            parent[a] = b;
            ++unions;
        }
    };
    detail::StarList around;
    // every element of the star is a node of its own until joined
    auto add_listed_nodes = [&] {
        while (parent.size() < around.size()) parent.push_back(static_cast<std::uint32_t>(parent.size()));
    };
    bool stays = false;  // of the element whose faces are crossed
    detail::for_each_in_star(
        mesh, v, mesh.vertex_element(v), around,
        [&](std::size_t, ElementId t, const Simplex&) {
            stays = !sorted_contains(removed, t);
            nodes += stays;
            return false;
        },
        [&](std::size_t position, const Simplex& tau, int i, ElementId n, std::size_t n_position) {
            add_listed_nodes();
            if (!stays) return;
            const auto local = static_cast<std::uint32_t>(position);
            if (n != invalid_id && !sorted_contains(removed, n))
                join(local, static_cast<std::uint32_t>(n_position));
            else
                open.push_back({face_key(tau, i, v), face_sign(tau, i), local});
        });
    add_listed_nodes();
    for (const ElementId t : around) stars.elements.push_back(t);
    const int k = mesh.element_vertex_count();
    for (const Simplex& tau : added) {
        if (!tau.contains(v)) continue;
        const auto node = static_cast<std::uint32_t>(parent.size());
        parent.push_back(node);
        ++nodes;
        for (int i = 0; i < k; ++i)
            if (tau.vertex(i) != v) open.push_back({face_key(tau, i, v), face_sign(tau, i), node});
    }
    std::sort(open.begin(), open.end(),
              [](const OpenFace& a, const OpenFace& b) { return a.key < b.key; });
    for (std::size_t i = 1; i < open.size(); ++i)
        if (open[i].key == open[i - 1].key && open[i].sign != open[i - 1].sign)
            join(open[i].node, open[i - 1].node);
    return nodes - unions;
}

// True when sigma (a face, or a whole element by its vertices in either orientation) is
// represented by an element of `star` (the star of sigma.vertex(0)) that is not removed:
// has_face_outside on a star walked once.
bool exists_outside(const Mesh& mesh, const Simplex& sigma, std::span<const ElementId> star,
                    std::span<const ElementId> removed) {
    const bool whole = sigma.count() == mesh.element_vertex_count();
    for (const ElementId t : star) {
        const Simplex& tau = mesh.simplex(t);
        if (whole) {
            if (tau.same_vertices(sigma) && !sorted_contains(removed, t)) return true;
            continue;
        }
        // tau has sigma's vertices and one more, `missing`: then sigma can only be tau.subv
        VertexId missing = invalid_id;
        int shared = 0;
        for (const VertexId x : tau.vertices()) {
            if (sigma.contains(x))
                ++shared;
            else
                missing = x;
        }
        if (shared == sigma.count() && tau.subv(missing) == sigma && !sorted_contains(removed, t))
            return true;
    }
    return false;
}

}  // namespace

namespace detail {

// What replace_elements works out before it changes anything, handed from phase to phase
// (Mesh::replace_elements_impl): the arguments, the old elements sorted, oldfacemap and
// newfacemap of the thesis (§7.3) as sorted vectors (edits are small), and, read before the old
// elements go, what the new elements inherit and what the anchor repair needs. Every list keeps
// its first elements in place (SmallVector): a flip or a split allocates only its result
// (docs/performance.md "tet_flips").
struct ReplacePlan {
    ReplacePlan(std::span<const ElementId> old_elements_, std::span<const Simplex> new_simplexes_,
                std::span<const int> labels_, std::span<const std::uint32_t> origins_, std::size_t k_)
        : old_elements(old_elements_), new_simplexes(new_simplexes_), labels(labels_), origins(origins_), k(k_) {}
    ReplacePlan(const ReplacePlan&) = delete;
    ReplacePlan& operator=(const ReplacePlan&) = delete;

    // the arguments
    const std::span<const ElementId> old_elements;
    const std::span<const Simplex> new_simplexes;
    const std::span<const int> labels;
    const std::span<const std::uint32_t> origins;
    const std::size_t k;  // vertices, and faces, per element

    // planned before the change
    SmallVector<ElementId, small_edit> old_sorted;
    SmallVector<OldFace, 4 * small_edit> old_faces;    // sorted by sigma
    SmallVector<NewFace, 4 * small_edit> new_faces;    // face j of new element i at i * k + j
    SmallVector<std::size_t, 4 * small_edit> order;    // positions in new_faces, by sigma
    SmallVector<FaceId, 4 * small_edit> reused_faces;  // sorted

    // read when the change starts, before the old elements go
    SmallVector<int, small_edit> new_labels;
    SmallVector<double, 4 * small_edit> inherited;  // per new element, every attribute's value
    std::size_t inherited_width = 0;                // values per new element in `inherited`
    SmallVector<VertexId, 4 * small_edit> old_vertices;
    SmallVector<ElementId, 4 * small_edit> neighbours;

    std::vector<ElementId> created;  // the result: the ids of the new elements

    std::size_t new_count() const { return new_simplexes.size(); }
    bool is_old(ElementId t) const { return sorted_contains(old_sorted, t); }
    NewFace& new_face(std::size_t i, std::size_t j) { return new_faces[i * k + j]; }
    const NewFace& new_face(std::size_t i, std::size_t j) const { return new_faces[i * k + j]; }
    // the old element whose values new element i inherits
    ElementId origin_of(std::size_t i) const { return old_elements[origins.empty() ? 0 : origins[i]]; }
    const OldFace* find_old(const Simplex& s) const {
        auto it = std::lower_bound(old_faces.begin(), old_faces.end(), s,
                                   [](const OldFace& a, const Simplex& b) { return a.sigma < b; });
        return (it != old_faces.end() && it->sigma == s) ? it : nullptr;
    }
    NewFace* find_new(const Simplex& s) {
        auto it = std::lower_bound(order.begin(), order.end(), s,
                                   [&](std::size_t a, const Simplex& b) { return new_faces[a].sigma < b; });
        return (it != order.end() && new_faces[*it].sigma == s) ? &new_faces[*it] : nullptr;
    }
};

}  // namespace detail

namespace {

// ---- checks: nothing changes before all of them pass ------------------------------------------

// The arguments on their own: ids, sizes, vertices, repeats. Fills plan.old_sorted.
std::optional<Refusal> refuse_arguments(const Mesh& mesh, detail::ReplacePlan& plan) {
    const std::span<const ElementId> old_elements = plan.old_elements;
    const std::span<const Simplex> new_simplexes = plan.new_simplexes;
    const std::size_t m = plan.new_count();
    for (std::size_t i = 0; i < old_elements.size(); ++i)
        if (!mesh.is_element(old_elements[i]))
            return Refusal{RefusalCode::not_found,
                           "element " + std::to_string(old_elements[i]) + " does not exist", i};
    for (ElementId t : old_elements) plan.old_sorted.push_back(t);
    std::sort(plan.old_sorted.begin(), plan.old_sorted.end());
    if (auto d = std::adjacent_find(plan.old_sorted.begin(), plan.old_sorted.end()); d != plan.old_sorted.end())
        return Refusal{RefusalCode::bad_argument,
                       "element " + std::to_string(*d) + " is listed twice"};
    if (!plan.labels.empty() && plan.labels.size() != m)
        return Refusal{RefusalCode::bad_argument,
                       "got " + std::to_string(plan.labels.size()) + " labels for " +
                       std::to_string(m) + " new elements"};
    if (!plan.origins.empty() && plan.origins.size() != m)
        return Refusal{RefusalCode::bad_argument,
                       "got " + std::to_string(plan.origins.size()) + " origins for " + std::to_string(m) +
                           " new elements"};
    for (std::size_t i = 0; i < plan.origins.size(); ++i)
        if (plan.origins[i] >= old_elements.size())
            return Refusal{RefusalCode::bad_argument,
                           "origin " + std::to_string(plan.origins[i]) + " of new element " + std::to_string(i) +
                               " is not an index into the " + std::to_string(old_elements.size()) +
                               " old elements",
                           i};
    for (std::size_t i = 0; i < m; ++i)
        if (std::string why = check_simplex(new_simplexes[i], mesh.element_vertex_count(), mesh.vertex_count());
            !why.empty())
            return Refusal{RefusalCode::bad_argument, std::move(why), i};
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 1; j < m; ++j)
            if (new_simplexes[i].same_vertices(new_simplexes[j]))
                return Refusal{RefusalCode::not_manifold,
                               "new elements " + std::to_string(i) + " and " + std::to_string(j) +
                                   " have the same vertices",
                               j};
    return std::nullopt;
}

// oldfacemap and newfacemap of the thesis: the faces of the old and of the new elements, which
// new face reuses which old one, and the refusal of a face that two new elements would share
// with the same orientation.
std::optional<Refusal> plan_faces(const Mesh& mesh, detail::ReplacePlan& plan) {
    const std::size_t m = plan.new_count(), uk = plan.k;
    for (ElementId t : plan.old_elements)
        for (std::size_t j = 0; j < uk; ++j) {
            const int i = static_cast<int>(j);
            plan.old_faces.push_back({mesh.simplex(t).subn(i), mesh.face(t, i), mesh.neighbor(t, i)});
        }
    std::sort(plan.old_faces.begin(), plan.old_faces.end(),
              [](const OldFace& a, const OldFace& b) { return a.sigma < b.sigma; });

    plan.new_faces.resize(m * uk);
    plan.order.resize(m * uk);
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < uk; ++j) {
            const std::size_t index = i * uk + j;
            plan.new_faces[index].sigma = plan.new_simplexes[i].subn(static_cast<int>(j));
            plan.order[index] = index;
        }
    const auto& new_faces = plan.new_faces;
    std::sort(plan.order.begin(), plan.order.end(),
              [&](std::size_t a, std::size_t b) { return new_faces[a].sigma < new_faces[b].sigma; });
    for (std::size_t i = 1; i < plan.order.size(); ++i)
        if (new_faces[plan.order[i]].sigma == new_faces[plan.order[i - 1]].sigma)
            return Refusal{RefusalCode::not_manifold,
                           "face " + to_text(new_faces[plan.order[i]].sigma) +
                               " would belong to two new elements (invariant 7.4)",
                           std::max(plan.order[i], plan.order[i - 1]) / uk};
    for (NewFace& nf : plan.new_faces) {
        const OldFace* old = plan.find_old(nf.sigma);
        nf.reused = old != nullptr;
        if (!nf.reused) continue;
        nf.face = old->face;
        nf.across = old->across;
        plan.reused_faces.push_back(nf.face);
    }
    std::sort(plan.reused_faces.begin(), plan.reused_faces.end());
    return std::nullopt;
}

// The checks that walk vertex stars (skipped for a ProvenEdit, mesh_checks.hpp): the stars of
// all touched vertices, walked once each (see TouchedStars), answer the questions of
// has_face_outside and refuse_pinched_stars, in the same order and with the same reasons.
std::optional<Refusal> refuse_star_conflicts(const Mesh& mesh, const detail::ReplacePlan& plan) {
    const std::span<const Simplex> new_simplexes = plan.new_simplexes;
    const std::size_t m = plan.new_count();
    TouchedStars stars;
    detail::SmallVector<VertexId, 64> touched;
    for (ElementId t : plan.old_elements)
        for (VertexId v : mesh.simplex(t).vertices()) touched.push_back(v);
    for (const Simplex& tau : new_simplexes)
        for (VertexId v : tau.vertices()) touched.push_back(v);
    std::sort(touched.begin(), touched.end());
    const VertexId* last = std::unique(touched.begin(), touched.end());
    detail::SmallVector<std::uint32_t, star_inline> parent;
    detail::SmallVector<OpenFace, star_inline> open;
    stars.offsets.push_back(0);
    for (const VertexId* v = touched.begin(); v != last; ++v) {
        stars.vertices.push_back(*v);
        stars.pieces.push_back(walk_star(mesh, *v, plan.old_sorted, new_simplexes, stars, parent, open));
        stars.offsets.push_back(static_cast<std::uint32_t>(stars.elements.size()));
    }

    // A face that is not reused must not exist in an element that stays (invariant 7.4); nor
    // may a new element have the vertices of one that stays.
    for (std::size_t i = 0; i < m; ++i) {
        if (exists_outside(mesh, new_simplexes[i], stars.star(new_simplexes[i].vertex(0)), plan.old_sorted))
            return Refusal{RefusalCode::not_manifold,
                           "element " + to_text(new_simplexes[i]) +
                               " already exists as an element that stays (invariant 7.4)",
                           i};
        for (std::size_t j = 0; j < plan.k; ++j) {
            const NewFace& nf = plan.new_face(i, j);
            if (nf.reused) continue;
            const FaceId b = mesh.find_boundary_face(nf.sigma);
            const bool on_boundary = b != invalid_id && !plan.is_old(mesh.face_element(b));
            if (on_boundary ||
                exists_outside(mesh, nf.sigma, stars.star(nf.sigma.vertex(0)), plan.old_sorted))
                return Refusal{RefusalCode::not_manifold,
                               "face " + to_text(nf.sigma) +
                                   " already exists in an element that stays (invariant 7.4)",
                               i};
        }
    }

    // Every vertex the edit touches must keep a face-connected star.
    for (std::size_t i = 0; i < stars.vertices.size(); ++i)
        if (stars.pieces[i] > 1)
            return Refusal{RefusalCode::pinched_star,
                           "star connectivity: vertex " + std::to_string(stars.vertices[i]) +
                           " would be pinched (its star would fall into " +
                           std::to_string(stars.pieces[i]) + " pieces)"};
    return std::nullopt;
}

}  // namespace

bool Mesh::has_face_outside(const Simplex& sigma, std::span<const ElementId> excluded) const {
    // sigma's elements all contain sigma.vertex(0): walk that vertex's star and look for sigma
    // in elements that are not excluded.
    const VertexId v = sigma.vertex(0);
    detail::StarList around;
    return detail::for_each_in_star(*this, v, m_vertex_element[v], around, [&](std::size_t, ElementId t, const Simplex& tau) {
        if (std::find(excluded.begin(), excluded.end(), t) != excluded.end()) return false;
        // a whole element with sigma's vertices (either orientation) also counts: an element
        // and its mirror image glued along all faces is no simplicial mesh
        if (sigma.count() == m_dimension + 1 && tau.same_vertices(sigma)) return true;
        for (int i = 0; i <= m_dimension; ++i)
            if (tau.subn(i) == sigma) return true;
        return false;
    });
}

Outcome<std::vector<ElementId>> Mesh::replace_elements(std::span<const ElementId> old_elements,
                                                       std::span<const Simplex> new_simplexes,
                                                       std::span<const int> labels,
                                                       std::span<const std::uint32_t> origins) {
    return replace_elements_impl(old_elements, new_simplexes, labels, origins, false);
}

Outcome<std::vector<ElementId>> Mesh::replace_elements(std::span<const ElementId> old_elements,
                                                       std::span<const Simplex> new_simplexes,
                                                       std::span<const int> labels,
                                                       std::span<const std::uint32_t> origins, StarChecksProof) {
    return replace_elements_impl(old_elements, new_simplexes, labels, origins, true);
}

Outcome<std::vector<ElementId>> Mesh::replace_elements_impl(std::span<const ElementId> old_elements,
                                                            std::span<const Simplex> new_simplexes,
                                                            std::span<const int> labels,
                                                            std::span<const std::uint32_t> origins,
                                                            bool proven) {
    detail::ReplacePlan plan(old_elements, new_simplexes, labels, origins, static_cast<std::size_t>(m_dimension + 1));
    if (auto refused = refuse_arguments(*this, plan)) return *refused;
    if (auto refused = plan_faces(*this, plan)) return *refused;
    if (!proven)
        if (auto refused = refuse_star_conflicts(*this, plan)) return *refused;

    // ---- the change -------------------------------------------------------------------------
    // Room for the worst case before anything changes, growing geometrically: reserving
    // exactly size + m made every edit that adds elements copy the whole pool (a split of a
    // 180k-triangle surface took milliseconds).
    auto make_room = [](auto& pool, std::size_t extra) {
        if (pool.size() + extra > pool.capacity())
            pool.reserve(std::max(pool.size() + extra, 2 * pool.capacity()));
    };
    const std::size_t m = plan.new_count();
    make_room(m_elements, m);
    make_room(m_faces, m * plan.k);
    m_boundary.reserve(m_boundary.size() + m * plan.k);
    note_pools();
    ++m_revision;
    detail::EditLog log(!m_watchers.empty());
    read_before_removal(plan);
    remove_old_elements(plan, log);
    pair_new_faces(plan, log);
    add_new_elements(plan, log);
    give_inherited_attributes(plan);
    add_remaining_faces(plan, log);
    link_new_elements(plan);
    repair_anchors(new_simplexes, plan.created, plan.old_vertices, plan.neighbours, plan.old_sorted);

    log.publish(*this, m_watchers);
    return std::move(plan.created);
}

void Mesh::read_before_removal(detail::ReplacePlan& plan) const {
    const std::size_t m = plan.new_count();
    // what each new element inherits from its origin, read before the old elements go (a new
    // element may take the id, and so the attribute rows, of an old one)
    for (std::size_t i = 0; i < m; ++i)
        plan.new_labels.push_back(!plan.labels.empty()        ? plan.labels[i]
                                  : plan.old_elements.empty() ? 0
                                                              : m_elements[plan.origin_of(i)].label);
    for (const detail::AttributeColumn& a : m_element_attributes)
        plan.inherited_width += static_cast<std::size_t>(a.components);
    if (plan.inherited_width != 0 && !plan.old_elements.empty())
        for (std::size_t i = 0; i < m; ++i)
            for (AttributeId a = 0; a < m_element_attributes.size(); ++a)
                if (m_element_attributes[a].components > 0)
                    for (double x : element_attribute(a, plan.origin_of(i))) plan.inherited.push_back(x);

    // vertices whose anchor may die, and surviving elements next to the old ones; the
    // neighbours are only needed for a vertex that is in no new element (repair_anchors gives
    // every vertex of a new element an anchor first), so edits that keep all their vertices
    // (flips, splits) skip those lookups
    bool every_old_vertex_stays = true;
    for (ElementId t : plan.old_elements)
        for (const VertexId v : m_elements[t].simplex.vertices()) {
            plan.old_vertices.push_back(v);
            if (every_old_vertex_stays &&
                std::none_of(plan.new_simplexes.begin(), plan.new_simplexes.end(),
                             [&](const Simplex& tau) { return tau.contains(v); }))
                every_old_vertex_stays = false;
        }
    if (!every_old_vertex_stays)
        for (ElementId t : plan.old_elements)
            for (std::size_t j = 0; j < plan.k; ++j) {
                const ElementId n = m_elements[t].neighbors[j];
                if (n != invalid_id && !plan.is_old(n)) plan.neighbours.push_back(n);
            }
}

void Mesh::remove_old_elements(detail::ReplacePlan& plan, detail::EditLog& log) {
    for (FaceId f : plan.reused_faces) log.touch(*this, f);
    auto discarded = [&](FaceId f) {
        return plan.is_old(m_faces[f].element) && !sorted_contains(plan.reused_faces, f);
    };
    detail::SmallVector<FaceId, 4 * small_edit> discard;
    for (const OldFace& old : plan.old_faces)
        if (!sorted_contains(plan.reused_faces, old.face)) discard.push_back(old.face);
    for (FaceId g : discard) {
        const FaceId mate_face = m_faces[g].mate;
        if (mate_face == invalid_id) {
            boundary_erase(face_simplex(g));
        } else if (!discarded(mate_face)) {
            // the mate stays (in an element that stays, or reused): it is boundary for now
            log.touch(*this, mate_face);
            face_for_write(mate_face).mate = invalid_id;
            boundary_insert(face_simplex(mate_face), mate_face);
            unlink_neighbor(mate_face);
        }
        log.freed(*this, g);
    }
    for (FaceId g : discard) free_face(g);
    for (ElementId t : plan.old_elements) {
        log.element_removed(t, m_elements[t].simplex);
        free_element(t);
    }
}

void Mesh::pair_new_faces(detail::ReplacePlan& plan, detail::EditLog& log) {
    // matched pairs: sigma and -sigma both new and not reused are made mates at once
    for (NewFace& nf : plan.new_faces) {
        if (nf.reused || nf.paired || nf.sigma.sign() < 0) continue;
        NewFace* other = plan.find_new(nf.sigma.mate());
        if (other == nullptr || other->reused) continue;
        nf.face = allocate_face();
        other->face = allocate_face();
        log.created(nf.face);
        log.created(other->face);
        face_for_write(nf.face).mate = other->face;
        face_for_write(other->face).mate = nf.face;
        nf.paired = other->paired = true;
    }
}

void Mesh::add_new_elements(detail::ReplacePlan& plan, detail::EditLog& log) {
    // new elements take over reused and paired faces first, so that every face the boundary
    // map can return below already belongs to a live element
    const std::size_t m = plan.new_count();
    plan.created.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
        const ElementId t = allocate_element();
        plan.created[i] = t;
        ElementRecord& e = element_for_write(t);
        e.simplex = plan.new_simplexes[i];
        e.label = plan.new_labels[i];
        for (std::size_t j = 0; j < plan.k; ++j) {
            const NewFace& nf = plan.new_face(i, j);
            e.faces[j] = nf.face;
            if (nf.face != invalid_id) face_for_write(nf.face).element = t;
        }
        log.element_added(t);
    }
}

void Mesh::give_inherited_attributes(const detail::ReplacePlan& plan) {
    if (plan.inherited_width == 0) return;
    // recorded like every store, so that a rollback puts back the rows of reused ids
    std::size_t at = 0;
    for (const ElementId t : plan.created)
        for (AttributeId a = 0; a < m_element_attributes.size(); ++a) {
            if (m_element_attributes[a].components == 0) continue;
            const std::span<double> row = element_attribute(a, t);
            if (m_undo != nullptr) m_undo->element_attribute(*this, a, t);
            if (plan.old_elements.empty())
                std::copy(m_element_attributes[a].default_value.begin(),
                          m_element_attributes[a].default_value.end(), row.begin());
            else
                std::copy_n(plan.inherited.begin() + at, row.size(), row.begin());
            at += row.size();
        }
}

void Mesh::add_remaining_faces(detail::ReplacePlan& plan, detail::EditLog& log) {
    // the faces neither reused nor paired: mated with a boundary face that is their mirror
    // image, or put on the boundary
    for (std::size_t i = 0; i < plan.new_count(); ++i) {
        const ElementId t = plan.created[i];
        for (std::size_t j = 0; j < plan.k; ++j) {
            const NewFace& nf = plan.new_face(i, j);
            if (nf.face != invalid_id) continue;
            const FaceId f = allocate_face();
            log.created(f);
            face_for_write(f).element = t;
            element_for_write(t).faces[j] = f;
            const FaceId b = m_boundary.find(nf.sigma);
            if (b != invalid_id && face_simplex(b) == nf.sigma.mate()) {
                log.touch(*this, b);
                face_for_write(f).mate = b;
                face_for_write(b).mate = f;
                boundary_erase(nf.sigma);
            } else {
                boundary_insert(nf.sigma, f);
            }
        }
    }
}

void Mesh::link_new_elements(const detail::ReplacePlan& plan) {
    // the neighbour cache: a reused face whose neighbour stays keeps that neighbour (known
    // without loading the mate's face record), whose slot holding the mate now points back at
    // the new element; every other slot is derived from its face's mate
    for (std::size_t i = 0; i < plan.new_count(); ++i) {
        const ElementId t = plan.created[i];
        for (std::size_t j = 0; j < plan.k; ++j) {
            const NewFace& nf = plan.new_face(i, j);
            if (nf.reused && nf.across != invalid_id && !plan.is_old(nf.across)) {
                element_for_write(t).neighbors[j] = nf.across;
                const FaceId g = m_faces[nf.face].mate;
                ElementRecord& across = element_for_write(nf.across);
                for (std::size_t s = 0; s < plan.k; ++s)
                    if (across.faces[s] == g) across.neighbors[s] = t;
            } else {
                link_neighbor(t, static_cast<int>(j));
            }
        }
    }
}

}  // namespace sxk
