// SpatialIndex: building the trees and keeping them in step with the mesh's events
// (sxk/locate.hpp; the events are those of sxk/watcher.hpp, thesis §7.4).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <functional>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// Which cells of the grid an element's box offers to seed: those it overlaps (building the grid:
// every cell an element reaches gets a seed), or only those whose centre it holds (an edit: a
// cell's seed is the element holding its centre, centre_seeds, so the new element holding it is
// the replacement; a Kuhn tetrahedron's box overlaps 27 cells of the grid but holds 8 centres,
// and each cell read is a cache miss at 1M elements, docs/performance.md "locate").
enum class SeedCells { overlapped, centred };

// Element t, whose box in the trees is `box`, becomes the seed of the cells `which` whose seed is
// not a live element (an empty cell, or one whose seed an edit removed): the children of a split
// seed the cells their parent seeded, so a locate there walks from them instead of asking the
// tree. The box is the one the event computed for the tree (padded a millionth, which may reach
// one more cell: any element near a cell is a correct start).
template <int D>
void reseed(detail::SeedGrid& grid, const Mesh& mesh, ElementId t, const typename detail::BoxTree<D>::Box& box,
            SeedCells which) {
    if (grid.empty()) return;
    // centres sit half a cell in: cell i's centre is in [lo, hi] when i is in [lo - 1/2, hi - 1/2]
    const double shift = which == SeedCells::centred ? 0.5 : 0.0;
    std::array<std::size_t, 3> first{0, 0, 0}, last{0, 0, 0};
    for (int k = 0; k < D; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        const double lo = (detail::BoxTree<D>::corner(box.min_corner(), k) - grid.low[uk]) / grid.cell[uk] - shift;
        const double hi = (detail::BoxTree<D>::corner(box.max_corner(), k) - grid.low[uk]) / grid.cell[uk] - shift;
        if (!(hi >= lo)) return;  // non-finite positions: no cell
        const double top = static_cast<double>(grid.cells[uk] - 1);
        const double from = which == SeedCells::centred ? std::ceil(lo) : std::floor(lo);
        const double to = std::floor(hi);
        if (which == SeedCells::centred && (from > to || to < 0 || from > top)) return;  // no centre inside
        first[uk] = static_cast<std::size_t>(std::clamp(from, 0.0, top));
        last[uk] = static_cast<std::size_t>(std::clamp(to, 0.0, top));
    }
    for (std::size_t z = first[2]; z <= last[2]; ++z)
        for (std::size_t y = first[1]; y <= last[1]; ++y)
            for (std::size_t x = first[0]; x <= last[0]; ++x) {
                const std::size_t cell = (z * grid.cells[1] + y) * grid.cells[0] + x;
                if (!mesh.is_element(grid.seeds[cell].load(std::memory_order_relaxed)))
                    grid.seeds[cell].store(t, std::memory_order_relaxed);
            }
}

// Each seed becomes the element holding its cell's centre, found by a short walk from it: a
// locate at a point of the cell then walks fewer steps than from the element whose centroid fell
// in the cell (on a Kuhn cube with 1.5 elements per cell, 1.95 against 2.36 elements visited on
// average, and each step at 1M elements is a cache miss: docs/performance.md "locate"). Cells
// whose walk fails keep their seed. The walks only read the mesh and each writes its own cell,
// so they run in parallel (the 1M Kuhn cube's index built in 0.66-1.20 s without them, 0.72-1.12
// s with them).
void centre_seeds(detail::SeedGrid& grid, const Mesh& mesh, Positions positions) {
    constexpr std::size_t steps = 16;
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, grid.seeds.size()), [&](const Range& r) {
        for (std::size_t cell = r.begin(); cell != r.end(); ++cell) {
            // an empty cell's invalid seed makes the walk fail at once
            const ElementId seed = grid.seeds[cell].load(std::memory_order_relaxed);
            const ElementId centre = walk_to_point(mesh, grid.centre(cell), seed, positions, steps);
            if (centre != invalid_id) grid.seeds[cell].store(centre, std::memory_order_relaxed);
        }
    });
}

// The seed grid of locate (locate_trees.hpp) for planar and tetrahedral meshes: cells of about
// SeedGrid::elements_per_cell elements over the bounding box, each seeded with an element whose
// centroid lies in it, else one whose bounding box overlaps it (cells that no element's box
// reaches stay empty: a locate there uses the tree); then each seed walks to its cell's centre.
template <int D>
void build_seeds(detail::SeedGrid& grid, const Mesh& mesh, Positions positions) {
    grid = detail::SeedGrid{};
    constexpr int d = D;  // the ambient dimension; surfaces in space have no grid
    if (mesh.topological_dimension() != d || mesh.element_count() == 0) return;
    std::array<double, 3> high{};
    for (int k = 0; k < 3; ++k) {
        grid.low[static_cast<std::size_t>(k)] = std::numeric_limits<double>::infinity();
        high[static_cast<std::size_t>(k)] = -std::numeric_limits<double>::infinity();
    }
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == invalid_id) continue;
        const Point& p = position(mesh, v, positions);
        for (std::size_t k = 0; k < 3; ++k) {
            grid.low[k] = std::min(grid.low[k], p[k]);
            high[k] = std::max(high[k], p[k]);
        }
    }
    double volume = 1;
    for (std::size_t k = 0; k < static_cast<std::size_t>(d); ++k) volume *= std::max(high[k] - grid.low[k], 0.0);
    const double wanted = std::max(1.0, static_cast<double>(mesh.element_count()) / detail::SeedGrid::elements_per_cell);
    if (!(volume > 0) || !std::isfinite(volume)) return;  // flat or unbounded: the tree alone
    const double side = std::pow(volume / wanted, 1.0 / d);
    std::size_t total = 1;
    for (std::size_t k = 0; k < static_cast<std::size_t>(d); ++k) {
        const double extent = high[k] - grid.low[k];
        grid.cells[k] = static_cast<std::size_t>(std::clamp(std::ceil(extent / side), 1.0, 1e6));
        grid.cell[k] = extent / static_cast<double>(grid.cells[k]);
        total *= grid.cells[k];
    }
    if (total > 4 * static_cast<std::size_t>(wanted) + 16) return;  // a needle-shaped box: not worth it
    grid.seeds = std::vector<std::atomic<std::uint32_t>>(total);
    for (auto& seed : grid.seeds) seed.store(invalid_id, std::memory_order_relaxed);
    for (const ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        Point centroid{0, 0, 0};
        for (int j = 0; j < s.count(); ++j)
            for (std::size_t k = 0; k < 3; ++k) centroid[k] += position(mesh, s.vertex(j), positions)[k] / s.count();
        if (const std::size_t cell = grid.cell_of(centroid, d); cell != detail::SeedGrid::npos)
            grid.seeds[cell].store(t, std::memory_order_relaxed);
    }
    // Cells that hold no centroid (at 1.5 elements per cell, about one in nine on a Kuhn cube)
    // get an element whose box overlaps them: a locate there walks a step or two instead of
    // descending the tree, which sent 12% of the queries on a fresh 1M cube to the tree
    // (docs/performance.md "locate").
    for (const ElementId t : elements(mesh))
        reseed<D>(grid, mesh, t, detail::element_box<D>(mesh, t, positions), SeedCells::overlapped);
    centre_seeds(grid, mesh, positions);
}

// The element and boundary-face trees, each by one bulk load.
template <int D>
void build_trees(SpatialIndex::Trees& trees, const Mesh& mesh, Positions positions) {
    using Value = typename detail::BoxTree<D>::Value;
    std::vector<Value> values;
    values.reserve(mesh.element_count());
    for (const ElementId t : elements(mesh)) values.emplace_back(detail::element_box<D>(mesh, t, positions), t);
    detail::element_tree<D>(trees).load(values);
    values.clear();
    values.reserve(mesh.boundary_face_count());
    mesh.for_each_boundary_face([&](FaceId f) { values.emplace_back(detail::face_box<D>(mesh, f, positions), f); });
    detail::face_tree<D>(trees).load(values);
}

template <int D>
void build(SpatialIndex::Trees& trees, const Mesh& mesh, Positions positions) {
    build_trees<D>(trees, mesh, positions);
    build_seeds<D>(trees.seeds, mesh, positions);
}

// Re-boxes the elements around the moved vertices (Mesh::elements_around_moved) and their
// boundary faces (a face's box depends on its vertices only, so the boundary faces of those
// elements are all that can move).
template <int D>
void rebox_around(SpatialIndex::Trees& trees, const Mesh& mesh, Positions positions) {
    const std::span<const ElementId> around = mesh.elements_around_moved();
    detail::BoxTree<D>& element_boxes = detail::element_tree<D>(trees);
    detail::BoxTree<D>& face_boxes = detail::face_tree<D>(trees);
    for (const ElementId t : around) {
        element_boxes.follow(t, detail::element_extent<D>(mesh, t, positions));
        for (int i = 0; i < mesh.element_vertex_count(); ++i)
            if (mesh.neighbor(t, i) == invalid_id) {
                const FaceId f = mesh.face(t, i);
                face_boxes.follow(f, detail::face_extent<D>(mesh, f, positions));
            }
    }
}

// Both trees after a move of most vertices (BoxTree::refit): every element and boundary face
// re-boxed, re-entered only where it left its entry's box.
template <int D>
void refit_trees(SpatialIndex::Trees& trees, const Mesh& mesh, Positions positions) {
    detail::element_tree<D>(trees).refit(
        [&](std::uint32_t t) { return detail::element_extent<D>(mesh, t, positions); });
    detail::face_tree<D>(trees).refit([&](std::uint32_t f) { return detail::face_extent<D>(mesh, f, positions); });
}

// The box `stored` holds the tight box `tight` (boxes are conservative, locate_trees.hpp).
template <int D>
bool covers(const typename detail::BoxTree<D>::Box& stored, const typename detail::BoxTree<D>::Box& tight) {
    for (int k = 0; k < D; ++k)
        if (detail::BoxTree<D>::corner(tight.min_corner(), k) < detail::BoxTree<D>::corner(stored.min_corner(), k) ||
            detail::BoxTree<D>::corner(tight.max_corner(), k) > detail::BoxTree<D>::corner(stored.max_corner(), k))
            return false;
    return true;
}

// One tree against what it indexes: `items` are the ids that must be live with their tight boxes.
template <int D>
std::string check_tree(const detail::BoxTree<D>& boxes, const std::vector<std::uint32_t>& items,
                       const std::function<typename detail::BoxTree<D>::Box(std::uint32_t)>& tight, const char* what) {
    for (const std::uint32_t id : items) {
        if (!boxes.is_live(id)) return std::string(what) + " " + std::to_string(id) + " is not indexed";
        if (!covers<D>(boxes.box(id), tight(id)))
            return std::string(what) + " " + std::to_string(id) + " has a stale box";
    }
    if (boxes.live_count != items.size())
        return "the tree holds " + std::to_string(boxes.live_count) + " live boxes for " + std::to_string(items.size()) +
               " " + what + "s";
    // the entries: members that name them back, counts that add up, each in the tree once
    std::size_t in_tree = 0, members = 0, empty = 0;
    for (std::uint32_t key = 0; key < boxes.entries.size(); ++key) {
        const auto& entry = boxes.entries[key];
        if (!entry.in_tree) continue;
        ++in_tree;
        std::uint32_t counted = 0;
        boxes.any_member(key, [&](std::uint32_t id) {
            counted += boxes.entry_of[id] == key ? 1 : boxes.max_members + 1;
            return counted > boxes.max_members;
        });
        if (counted != entry.members || counted > boxes.max_members)
            return "tree entry " + std::to_string(key) + " lists " + std::to_string(counted) + " members, counts " +
                   std::to_string(entry.members);
        members += counted;
        empty += counted == 0;
    }
    if (members != boxes.live_count || empty != boxes.empty_count || boxes.tree.size() != in_tree)
        return "the tree holds " + std::to_string(boxes.tree.size()) + " entries for " + std::to_string(in_tree) +
               " in use, " + std::to_string(members) + " members of " + std::to_string(boxes.live_count) +
               " and " + std::to_string(empty) + " empty of " + std::to_string(boxes.empty_count);
    // every tree value is its entry's box (no stale duplicate left behind by a removal)
    for (const auto& value : boxes.tree)
        if (value.second >= boxes.entries.size() || !boxes.entries[value.second].in_tree ||
            !detail::bg::equals(boxes.entries[value.second].box, value.first))
            return "the tree holds a stale box of entry " + std::to_string(value.second);
    return {};
}

template <int D>
Outcome<Done> check(const SpatialIndex::Trees& trees, const Mesh& mesh, Positions positions) {
    std::vector<std::uint32_t> live;
    for (const ElementId t : elements(mesh)) live.push_back(t);
    if (std::string problem = check_tree<D>(
            detail::element_tree<D>(trees), live,
            [&](std::uint32_t t) { return detail::element_box<D>(mesh, t, positions); }, "element");
        !problem.empty())
        return Refusal{RefusalCode::invalid_mesh, "spatial index: " + problem};
    const std::vector<FaceId> boundary = mesh.boundary_faces();
    if (std::string problem = check_tree<D>(
            detail::face_tree<D>(trees), std::vector<std::uint32_t>(boundary.begin(), boundary.end()),
            [&](std::uint32_t f) { return detail::face_box<D>(mesh, f, positions); }, "boundary face");
        !problem.empty())
        return Refusal{RefusalCode::invalid_mesh, "spatial index: " + problem};
    return Done{};
}

bool writes(PositionSet which, Positions positions) {
    return positions == Positions::reference ? writes_reference(which) : writes_deformed(which);
}

}  // namespace

SpatialIndex::SpatialIndex(Mesh& mesh, const SpatialIndexOptions& options)
    : m_mesh(&mesh), m_options(options), m_trees(std::make_unique<Trees>()) {
    mesh.add_watcher(*this);
}

SpatialIndex::~SpatialIndex() { m_mesh->remove_watcher(*this); }

double SpatialIndex::surface_tolerance() const {
    if (m_options.surface_tolerance > 0) return m_options.surface_tolerance;
    const auto& tree = m_trees->elements3.tree;
    if (tree.empty()) return 0;
    const auto bounds = tree.bounds();
    const double diagonal = std::sqrt(detail::bg::comparable_distance(bounds.min_corner(), bounds.max_corner()));
    return 1e-9 * diagonal;
}

std::size_t SpatialIndex::indexed_elements() const {
    return detail::in_dimension(*m_mesh, [&](auto d) { return detail::element_tree<decltype(d)::value>(*m_trees).live_count; });
}

std::size_t SpatialIndex::indexed_boundary_faces() const {
    return detail::in_dimension(*m_mesh, [&](auto d) { return detail::face_tree<decltype(d)::value>(*m_trees).live_count; });
}

std::size_t SpatialIndex::memory_bytes() const {
    return m_trees->elements2.memory_bytes() + m_trees->faces2.memory_bytes() + m_trees->elements3.memory_bytes() +
           m_trees->faces3.memory_bytes() + m_trees->seeds.seeds.size() * sizeof(std::uint32_t);
}

Outcome<Done> SpatialIndex::validate() const {
    return detail::in_dimension(*m_mesh, [&](auto d) { return check<decltype(d)::value>(*m_trees, *m_mesh, m_options.positions); });
}

void SpatialIndex::init(const Mesh& mesh) {
    detail::in_dimension(mesh, [&](auto d) { build<decltype(d)::value>(*m_trees, mesh, m_options.positions); });
}

// Each event touches its own id only: O(log n) per element or face of the edit. Removals come
// before additions within one edit (watcher.hpp), so an id reused by the same edit is removed
// with its old box first.
void SpatialIndex::element_removed(const Mesh& mesh, ElementId element, const Simplex&) {
    detail::in_dimension(mesh, [&](auto d) { detail::element_tree<decltype(d)::value>(*m_trees).erase(element); });
}

void SpatialIndex::element_changed(const Mesh& mesh, ElementId element, const Simplex&) {
    detail::in_dimension(mesh, [&](auto d) {
        constexpr int D = decltype(d)::value;
        const auto box = detail::element_box<D>(mesh, element, m_options.positions);
        detail::element_tree<D>(*m_trees).update(element, box);
        reseed<D>(m_trees->seeds, mesh, element, box, SeedCells::centred);
    });
}

void SpatialIndex::element_added(const Mesh& mesh, ElementId element) {
    detail::in_dimension(mesh, [&](auto d) {
        constexpr int D = decltype(d)::value;
        const auto box = detail::element_box<D>(mesh, element, m_options.positions);
        detail::element_tree<D>(*m_trees).insert(element, box);
        reseed<D>(m_trees->seeds, mesh, element, box, SeedCells::centred);
    });
}

void SpatialIndex::boundary_removed(const Mesh& mesh, FaceId face, const Simplex&) {
    detail::in_dimension(mesh, [&](auto d) { detail::face_tree<decltype(d)::value>(*m_trees).erase(face); });
}

void SpatialIndex::boundary_changed(const Mesh& mesh, FaceId face, const Simplex&) {
    detail::in_dimension(mesh, [&](auto d) {
        detail::face_tree<decltype(d)::value>(*m_trees).update(face, detail::face_box<decltype(d)::value>(mesh, face, m_options.positions));
    });
}

void SpatialIndex::boundary_added(const Mesh& mesh, FaceId face) {
    detail::in_dimension(mesh, [&](auto d) {
        detail::face_tree<decltype(d)::value>(*m_trees).insert(face, detail::face_box<decltype(d)::value>(mesh, face, m_options.positions));
    });
}

// A move of a quarter of the vertices or more (a simulation writing its frame) refits the trees
// (BoxTree::refit): each element and boundary face is tested against the box its entry holds, in
// parallel, and only those that left it are re-entered, with a margin for the frames to come (by
// one bulk load when many left). Re-boxing every element one by one (an rtree removal and
// insertion each, after walking every star) took 2.2 s per frame on the 213k-element femur; the
// bulk load of every frame that came next, 0.093 s; the 1M Kuhn cube bending back and forth
// takes 48 ms a frame against 195 ms for the bulk load (docs/performance.md "A simulation's frame
// and the spatial index"). The seed grid stays: a move changes no element, so every seed is still
// a live element, which is all a walk needs to start from (a seed that no longer holds its cell's
// centre costs a locate a longer walk, or the tree when the walk gives up).
void SpatialIndex::vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices, PositionSet which) {
    if (!writes(which, m_options.positions)) return;
    if (4 * vertices.size() >= mesh.vertex_count()) {
        detail::in_dimension(mesh, [&](auto d) { refit_trees<decltype(d)::value>(*m_trees, mesh, m_options.positions); });
        return;
    }
    detail::in_dimension(mesh, [&](auto d) { rebox_around<decltype(d)::value>(*m_trees, mesh, m_options.positions); });
}

}  // namespace sxk
