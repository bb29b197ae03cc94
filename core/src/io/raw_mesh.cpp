#include "raw_mesh.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "../fresh_array.hpp"
#include "sxk/predicates.hpp"

namespace sxk::io {

void CellList::reserve(std::size_t n, bool numbered) {
    detail::reserve_fresh(vertices, n * static_cast<std::size_t>(size));
    detail::reserve_fresh(labels, n);
    detail::reserve_fresh(lines, n);
    if (numbered) detail::reserve_fresh(numbers, n);
}

void RawMesh::reserve_points(std::size_t n, bool numbered) {
    detail::reserve_fresh(points, n);
    detail::reserve_fresh(point_lines, n);
    if (numbered) detail::reserve_fresh(point_numbers, n);
}

std::size_t plausible_count(std::int64_t wanted, std::size_t bytes_left,
                            std::size_t bytes_per_record) {
    if (wanted <= 0)
        return 0;
    return std::min(static_cast<std::size_t>(wanted), bytes_left / bytes_per_record + 1);
}

namespace {

[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& reason) {
    throw InputError(file, line, reason);
}

const char* cell_name(int size) {
    return size == 4 ? "tetrahedron" : size == 3 ? "triangle" : "edge";
}

// "(3 7 9)": the vertices of a face in the file's numbering, sorted.
std::string describe_face(const RawMesh& raw, std::span<const VertexId> vertices) {
    std::vector<std::int64_t> numbers;
    for (VertexId v : vertices)
        numbers.push_back(raw.vertex_number(v));
    std::sort(numbers.begin(), numbers.end());
    std::string text = "(";
    for (std::size_t i = 0; i < numbers.size(); ++i)
        text += (i ? " " : "") + std::to_string(numbers[i]);
    return text + ")";
}

// assign_elements refused because of element `item`; say why in the file's terms. The kernel's
// own reason speaks of list indices, which mean nothing to the author of the file, so the
// element is looked at again here (linear scans: this runs once, on the error path).
[[noreturn]] void explain_refusal(const RawMesh& raw, const CellList& cells,
                                  std::span<const Simplex> simplexes, std::size_t item,
                                  const std::string& kernel_reason) {
    const std::string element = "element " + std::to_string(cells.number(item));
    const Simplex& mine = simplexes[item];
    for (std::size_t j = 0; j < simplexes.size(); ++j)
        if (j != item && simplexes[j].same_vertices(mine))
            fail(cells.file, cells.lines[item],
                 element + " repeats element " + std::to_string(cells.number(j)));
    for (int i = 0; i < mine.count(); ++i) {
        const Simplex face = mine.subn(i);
        std::vector<std::size_t> sharers;
        for (std::size_t j = 0; j < simplexes.size(); ++j) {
            if (j == item)
                continue;
            int common = 0;
            for (VertexId v : face.vertices())
                common += simplexes[j].contains(v) ? 1 : 0;
            if (common == face.count())
                sharers.push_back(j);
        }
        const std::string where = describe_face(raw, face.vertices());
        if (sharers.size() >= 2)
            fail(cells.file, cells.lines[item],
                 element + " makes face " + where + " non-manifold: it is shared by " +
                     std::to_string(sharers.size() + 1) + " elements");
        if (sharers.size() == 1) {
            const Simplex& other = simplexes[sharers[0]];
            VertexId apex = invalid_id;
            for (VertexId v : other.vertices())
                if (!face.contains(v))
                    apex = v;
            if (other.subv(apex) == face)
                fail(cells.file, cells.lines[item],
                     element + " is oriented inconsistently with element " +
                         std::to_string(cells.number(sharers[0])) + " across face " + where);
        }
    }
    fail(cells.file, cells.lines[item], element + ": " + kernel_reason);
}

// The kernel's invariant of face-connected vertex stars (end of thesis §7.3), which the bulk
// build does not check: two tetrahedra touching only at a vertex must be refused.
//
// Walking each star through Mesh mates was the obvious way, and took 40% of reading the femur:
// every step is a random access into the element and face pools. Instead the link of every
// vertex (each element around v without v: a triangle in 3D, an edge in 2D) is gathered into
// one array by a counting sort on v, and the star is connected exactly when its link is
// connected through shared (d-2)-faces: two elements v+L1 and v+L2 share a face containing v
// iff L1 and L2 share d-1 vertices. Each link is small (about 20 triangles) and contiguous,
// so the union-find below stays in cache.
void check_vertex_stars(const RawMesh& raw, std::span<const Simplex> simplexes, int k) {
    const std::size_t vertex_count = raw.points.size();
    const std::size_t m = static_cast<std::size_t>(k - 1);  // vertices of a link simplex
    std::vector<std::uint32_t> start(vertex_count + 1, 0);
    for (const Simplex& s : simplexes)
        for (VertexId v : s.vertices())
            ++start[v + 1];
    for (std::size_t v = 0; v < vertex_count; ++v)
        start[v + 1] += start[v];
    std::vector<VertexId> links(static_cast<std::size_t>(start[vertex_count]) * m);
    {
        std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
        for (const Simplex& s : simplexes)
            for (int j = 0; j < k; ++j) {
                VertexId* link = links.data() + static_cast<std::size_t>(cursor[s.vertex(j)]++) * m;
                for (int i = 0; i < k; ++i)
                    if (i != j)
                        *link++ = s.vertex(i);  // sorted, as the simplex is canonical
            }
    }
    // union-find over the link simplices of one vertex, and a small open-addressing table from
    // link ridge (an edge of a link triangle, a vertex of a link edge) to the first link simplex
    // seen with it: each ridge occurs at most twice, the second occurrence joins the two
    constexpr std::uint64_t empty = ~std::uint64_t{0};
    std::vector<std::uint32_t> parent;
    std::vector<std::uint64_t> slot_key(64, empty);
    std::vector<std::uint32_t> slot_value(64);
    std::vector<std::size_t> used;
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    for (std::size_t v = 0; v < vertex_count; ++v) {
        const std::uint32_t n = start[v + 1] - start[v];
        if (n <= 1)
            continue;
        const VertexId* link = links.data() + static_cast<std::size_t>(start[v]) * m;
        parent.resize(n);
        for (std::uint32_t i = 0; i < n; ++i)
            parent[i] = i;
        std::size_t capacity = slot_key.size();
        while (capacity < 4 * m * n)
            capacity *= 2;
        if (capacity != slot_key.size()) {
            slot_key.assign(capacity, empty);
            slot_value.resize(capacity);
        }
        std::uint32_t components = n;
        auto ridge = [&](std::uint64_t key, std::uint32_t i) {
            std::size_t h =
                static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ULL) >> 40) & (capacity - 1);
            while (slot_key[h] != empty && slot_key[h] != key)
                h = (h + 1) & (capacity - 1);
            if (slot_key[h] == empty) {
                slot_key[h] = key;
                slot_value[h] = i;
                used.push_back(h);
                return;
            }
            const std::uint32_t a = find(i), b = find(slot_value[h]);
            if (a != b) {
                parent[a] = b;
                --components;
            }
        };
        for (std::uint32_t i = 0; i < n; ++i) {
            const VertexId* l = link + i * m;
            if (m == 3) {
                ridge(std::uint64_t{l[0]} << 32 | l[1], i);
                ridge(std::uint64_t{l[0]} << 32 | l[2], i);
                ridge(std::uint64_t{l[1]} << 32 | l[2], i);
            } else {
                ridge(l[0], i);
                ridge(l[1], i);
            }
        }
        for (std::size_t h : used)
            slot_key[h] = empty;
        used.clear();
        if (components != 1)
            fail(raw.vertex_file, raw.point_lines[v],
                 "vertex " + std::to_string(raw.vertex_number(static_cast<VertexId>(v))) +
                     " is non-manifold: the elements around it are not connected through faces");
    }
}

// Splits every pinched vertex of the element list (thesis §7.3: the (v,C)-components of
// dissection with C empty, i.e. the pieces of star(v) that are joined through faces containing
// v). Runs only after assign_elements refused a star, so the face matching it repeats costs
// nothing on files without pinched vertices. The piece holding the element that comes first in
// the file keeps v; the others get new vertices, appended after the file's own in order of v and
// then of each piece's first element, copying v's position, line and number (so that messages
// still name the file's vertex). Elements keep their order, orientation and labels; a labelled
// face containing v takes the copy of the element it is a face of (a face containing v lies in
// one piece: its elements are joined through it). Returns the (original, copy) pairs.
std::vector<std::pair<VertexId, VertexId>> split_pinched_vertices(RawMesh& raw, CellList& cells,
                                                                  CellList& faces,
                                                                  detail::LargeVector<Simplex>& simplexes) {
    const std::size_t k = static_cast<std::size_t>(cells.size);
    const std::size_t n = simplexes.size();
    const std::size_t total = n * k;  // (element, slot) incidences
    const std::size_t vertex_count = raw.points.size();

    // Every face of every element, keyed by its sorted vertices (a simplex is canonical, so
    // dropping one slot keeps the rest sorted); equal keys are the two sides of one face.
    struct FaceEntry {
        std::array<VertexId, 3> key;
        std::uint32_t incidence;  // element * k + the slot opposite the face
    };
    detail::LargeVector<FaceEntry> entries(total);
    for (std::size_t t = 0; t < n; ++t)
        for (std::size_t j = 0; j < k; ++j) {
            FaceEntry& e = entries[t * k + j];
            e.key = {invalid_id, invalid_id, invalid_id};
            for (std::size_t i = 0, r = 0; i < k; ++i)
                if (i != j)
                    e.key[r++] = simplexes[t].vertex(static_cast<int>(i));
            e.incidence = static_cast<std::uint32_t>(t * k + j);
        }
    std::sort(entries.begin(), entries.end(), [](const FaceEntry& a, const FaceEntry& b) {
        return a.key != b.key ? a.key < b.key : a.incidence < b.incidence;
    });

    // Union-find over the incidences: two elements sharing a face join, for each vertex of the
    // face, that vertex's incidences in both.
    detail::LargeVector<std::uint32_t> parent(total);
    for (std::size_t s = 0; s < total; ++s)
        parent[s] = static_cast<std::uint32_t>(s);
    auto find = [&parent](std::uint32_t s) {
        while (parent[s] != s)
            s = parent[s] = parent[parent[s]];
        return s;
    };
    auto slot_of = [&](std::size_t t, VertexId w) {
        std::size_t i = 0;
        while (simplexes[t].vertex(static_cast<int>(i)) != w)
            ++i;
        return i;
    };
    for (std::size_t a = 0, b = 1; b < total; ++b) {
        if (entries[b].key != entries[a].key) {
            a = b;
            continue;
        }
        const std::size_t t = entries[a].incidence / k, u = entries[b].incidence / k;
        for (std::size_t r = 0; r + 1 < k; ++r) {
            const VertexId w = entries[a].key[r];
            const std::uint32_t x = find(static_cast<std::uint32_t>(t * k + slot_of(t, w)));
            const std::uint32_t y = find(static_cast<std::uint32_t>(u * k + slot_of(u, w)));
            if (x != y)
                parent[std::max(x, y)] = std::min(x, y);
        }
    }

    // Number the pieces of each star in order of their first incidence (element order).
    constexpr std::uint32_t unnumbered = ~std::uint32_t{0};
    std::vector<std::uint32_t> piece_of_root(total, unnumbered);
    std::vector<std::uint32_t> pieces(vertex_count, 0);
    for (std::size_t s = 0; s < total; ++s) {
        const std::uint32_t r = find(static_cast<std::uint32_t>(s));
        if (piece_of_root[r] == unnumbered)
            piece_of_root[r] = pieces[simplexes[s / k].vertex(static_cast<int>(s % k))]++;
    }
    std::vector<std::pair<VertexId, VertexId>> copies;
    std::vector<VertexId> first_copy(vertex_count, invalid_id);
    if (raw.point_numbers.empty()) {
        raw.point_numbers.resize(vertex_count);
        for (std::size_t v = 0; v < vertex_count; ++v)
            raw.point_numbers[v] = raw.vertex_number(static_cast<VertexId>(v));
    }
    for (std::size_t v = 0; v < vertex_count; ++v) {
        if (pieces[v] <= 1)
            continue;
        if (raw.points.size() + pieces[v] - 1 >= invalid_id)
            fail(raw.vertex_file, raw.point_lines[v], "too many vertices after splitting");
        first_copy[v] = static_cast<VertexId>(raw.points.size());
        for (std::uint32_t p = 1; p < pieces[v]; ++p) {
            copies.emplace_back(static_cast<VertexId>(v), static_cast<VertexId>(raw.points.size()));
            raw.points.push_back(raw.points[v]);
            raw.point_lines.push_back(raw.point_lines[v]);
            raw.point_numbers.push_back(raw.point_numbers[v]);
        }
    }
    auto renamed = [&](std::size_t s) {
        const VertexId v = simplexes[s / k].vertex(static_cast<int>(s % k));
        const std::uint32_t p = piece_of_root[find(static_cast<std::uint32_t>(s))];
        return p == 0 ? v : first_copy[v] + p - 1;
    };

    // Labelled faces first, while the elements still hold the original ids.
    const std::size_t m = k - 1;
    for (std::size_t i = 0; i < faces.count(); ++i) {
        VertexId* vertices = faces.vertices.data() + i * m;
        if (std::none_of(vertices, vertices + m, [&](VertexId w) { return pieces[w] > 1; }))
            continue;
        FaceEntry probe{{invalid_id, invalid_id, invalid_id}, 0};
        std::copy(vertices, vertices + m, probe.key.begin());
        // m <= 3 keys sorted by compare-and-swap (std::sort here trips g++ 12's -Warray-bounds)
        for (std::size_t a = 0; a + 1 < m; ++a)
            for (std::size_t b = a + 1; b < m; ++b)
                if (probe.key[b] < probe.key[a])
                    std::swap(probe.key[a], probe.key[b]);
        const auto at =
            std::lower_bound(entries.begin(), entries.end(), probe,
                             [](const FaceEntry& a, const FaceEntry& b) { return a.key < b.key; });
        if (at == entries.end() || at->key != probe.key)
            continue;  // not a face of any element: add_face_labels says so
        const std::size_t t = at->incidence / k;
        for (std::size_t r = 0; r < m; ++r)
            if (pieces[vertices[r]] > 1)
                vertices[r] = renamed(t * k + slot_of(t, vertices[r]));
    }
    for (std::size_t t = 0; t < n; ++t) {
        std::array<VertexId, 4> now{};
        bool changed = false;
        for (std::size_t j = 0; j < k; ++j) {
            now[j] = renamed(t * k + j);
            changed = changed || now[j] != simplexes[t].vertex(static_cast<int>(j));
        }
        if (!changed)
            continue;
        // the file's order too, so that every list speaks of the same vertices
        VertexId* listed = cells.vertices.data() + t * k;
        for (std::size_t j = 0; j < k; ++j)
            listed[j] = now[slot_of(t, listed[j])];
        // the canonical order with the new ids in place: same orientation, re-sorted
        simplexes[t] = Simplex(simplexes[t].sign(), std::span<const VertexId>(now.data(), k));
    }
    return copies;
}

Simplex unoriented_key(std::span<const VertexId> vertices) {
    const Simplex s(+1, vertices);
    return s.sign() > 0 ? s : s.mate();
}

// The labelled faces, each listed once, as the map the mesh keeps; what a reading says of them
// before the mesh exists (a repeated vertex, a repeat; ReadReport's label conflicts).
struct CollectedLabels {
    FaceLabels labels;
    std::size_t conflicts = 0;
    std::string first_conflict;
};

CollectedLabels collect_face_labels(const CellList& faces) {
    const std::size_t d = static_cast<std::size_t>(faces.size);
    const char* kind = cell_name(faces.size);
    CollectedLabels collected;
    FaceLabels& labels = collected.labels;
    labels.reserve(faces.count());
    for (std::size_t i = 0; i < faces.count(); ++i) {
        const std::span<const VertexId> vertices(faces.vertices.data() + i * d, d);
        const Simplex key = unoriented_key(vertices);
        if (!key.has_distinct_vertices())
            fail(faces.file, faces.lines[i],
                 std::string(kind) + " " + std::to_string(faces.number(i)) +
                     " has a repeated vertex");
        if (const auto [at, fresh] = labels.emplace(key, faces.labels[i]); !fresh) {
            if (faces.repeats_are_one_face && at->second == faces.labels[i])
                continue;
            // listed before: find where (rare, so a scan rather than a second map)
            std::size_t first = 0;
            while (unoriented_key({faces.vertices.data() + first * d, d}) != key)
                ++first;
            const std::string repeat = std::string(kind) + " " + std::to_string(faces.number(i)) +
                                       " repeats " + kind + " " +
                                       std::to_string(faces.number(first));
            if (!faces.repeats_are_one_face)
                fail(faces.file, faces.lines[i], repeat);
            // the same face with another reference (CGAL: the subdomains on its two sides):
            // the first listed is kept, and the caller hears of it
            if (collected.conflicts++ == 0)
                collected.first_conflict =
                    InputError(faces.file, faces.lines[i],
                               repeat + " with reference " + std::to_string(faces.labels[i]) +
                                   ", not " + std::to_string(at->second))
                        .what();
        }
    }
    return collected;
}

// Gives the mesh its face labels: every labelled face must be a face of some element (a
// boundary face, or an interface between materials).
void place_face_labels(CollectedLabels collected, const CellList& faces, Mesh& mesh,
                       const ReadOptions& options, ReadReport* report) {
    const int d = mesh.topological_dimension();
    const char* kind = cell_name(faces.size);
    if (report && collected.conflicts > 0) {
        if (report->label_conflicts == 0)
            report->first_label_conflict = std::move(collected.first_conflict);
        report->label_conflicts += collected.conflicts;
    }
    FaceLabels& labels = mesh.face_labels();
    labels = std::move(collected.labels);
    std::unordered_map<Simplex, std::size_t, SimplexHash> interior;  // not on the boundary
    for (std::size_t i = 0; i < faces.count(); ++i) {
        const Simplex key = unoriented_key(
            {faces.vertices.data() + i * static_cast<std::size_t>(d), static_cast<std::size_t>(d)});
        // a label belongs to the vertex set: either side of a boundary face will do, so one
        // probe of the boundary map, no visit to the face and element pools (docs/performance.md,
        // "io")
        if (mesh.find_boundary_face_unoriented(key) == invalid_id)
            interior.emplace(key, i);
    }
    if (interior.empty())
        return;
    // interfaces between materials: rare and few, so one pass over all element faces
    for (ElementId t : elements(mesh))
        for (int j = 0; j <= d; ++j)
            interior.erase(unoriented_key(mesh.simplex(t).subn(j).vertices()));
    if (interior.empty())
        return;
    std::size_t first = faces.count();
    for (const auto& [key, i] : interior)
        first = std::min(first, i);
    const std::string stray = std::string(kind) + " " + std::to_string(faces.number(first)) +
                              " is not a face of any " + cell_name(d + 1);
    // a lenient read keeps the labels, and validate() names the first ("face label: ...")
    if (options.lenient)
        return;
    if (!options.drop_stray_faces)
        fail(faces.file, faces.lines[first], stray);
    // CGAL's Mesh_3 writes surface facets whose cells are outside the complex: a label of no
    // face cannot be held (validate() refuses it), so it goes, and the caller hears of it
    for (const auto& [key, i] : interior)
        labels.erase(key);
    if (report) {
        report->stray_faces = interior.size();
        report->first_stray_face = InputError(faces.file, faces.lines[first], stray).what();
    }
}

// The elements as canonical simplexes, each judged on its own in parallel (the exact
// orientation tests are a sizeable part of a read; docs/performance.md "io"): a repeated vertex,
// and when the topological dimension is the ambient one, the orientation. An inverted element is
// refused, or turned over with ReadOptions::reorient (counted in `reoriented`), or kept by a
// lenient read. The element named in a refusal is the first in file order, as a single thread
// would find it.
detail::LargeVector<Simplex> oriented_simplexes(const RawMesh& raw, const CellList& cells,
                                                int ambient, const ReadOptions& options,
                                                std::size_t& reoriented) {
    enum class Verdict : std::uint8_t { fine, reoriented, repeated_vertex, inverted };
    const std::size_t k = static_cast<std::size_t>(cells.size);
    const std::size_t n = cells.count();
    const bool oriented_here = cells.size - 1 == ambient;
    auto judge = [&](std::size_t i, Simplex& s) {
        const std::span<const VertexId> vertices(cells.vertices.data() + i * k, k);
        s = Simplex(+1, vertices);
        if (!s.has_distinct_vertices())
            return Verdict::repeated_vertex;
        if (!oriented_here)
            return Verdict::fine;
        const auto& p = raw.points;
        const Sign sign =
            k == 4 ? orient3d(p[vertices[0]], p[vertices[1]], p[vertices[2]], p[vertices[3]])
                   : orient2d(p[vertices[0]], p[vertices[1]], p[vertices[2]]);
        if (sign != Sign::negative || !(options.reorient || !options.lenient))
            return Verdict::fine;
        if (!options.reorient)
            return Verdict::inverted;
        s = s.mate();
        return Verdict::reoriented;
    };
    detail::LargeVector<Simplex> simplexes = detail::fresh_vector<Simplex>(n);
    std::atomic<std::size_t> first_refused{n};
    std::atomic<std::size_t> turned_over{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          std::size_t turned = 0;
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              const Verdict verdict = judge(i, simplexes[i]);
                              turned += verdict == Verdict::reoriented ? 1 : 0;
                              if (verdict != Verdict::repeated_vertex &&
                                  verdict != Verdict::inverted)
                                  continue;
                              std::size_t seen = first_refused.load(std::memory_order_relaxed);
                              while (i < seen && !first_refused.compare_exchange_weak(
                                                     seen, i, std::memory_order_relaxed)) {
                              }
                              break;  // later elements of this range cannot come first
                          }
                          turned_over.fetch_add(turned, std::memory_order_relaxed);
                      });
    if (const std::size_t i = first_refused.load(); i < n) {
        Simplex ignored;
        fail(cells.file, cells.lines[i],
             "element " + std::to_string(cells.number(i)) +
                 (judge(i, ignored) == Verdict::repeated_vertex ? " has a repeated vertex"
                                                               : " is inverted"));
    }
    reoriented = turned_over.load();
    return simplexes;
}

}  // namespace

Mesh build_mesh(RawMesh& raw, const std::string& fallback_file, const ReadOptions& options,
                ReadReport* report) {
    const int d = !raw.tetrahedra.lines.empty() ? 3 : !raw.triangles.lines.empty() ? 2 : 0;
    if (d == 0)
        fail(fallback_file, 0, "no triangles or tetrahedra");
    CellList& cells = d == 3 ? raw.tetrahedra : raw.triangles;
    CellList& faces = d == 3 ? raw.triangles : raw.edges;
    const std::size_t k = static_cast<std::size_t>(d + 1);
    const std::size_t n = cells.count();

    int ambient = raw.ambient;
    if (raw.ambient_from_z) {
        ambient = d == 2 && std::all_of(raw.points.begin(), raw.points.end(),
                                        [](const Point& p) { return p[2] == 0.0; })
                      ? 2
                      : 3;
    }
    if (ambient < d)
        fail(cells.file, cells.lines[0], "tetrahedra in a 2-dimensional mesh");
    if (ambient == 2)
        for (Point& p : raw.points)
            p[2] = 0.0;  // -0.0 too: a planar mesh has z == +0

    // The labelled faces are gathered into their map while the elements are built: the two share
    // nothing until the labels are placed on the mesh (docs/performance.md "io"). Problems are
    // reported in the order of a sequential reading: the elements' first, then the labels'.
    std::optional<Mesh> mesh;
    std::optional<Outcome<Done>> built;
    std::size_t reoriented = 0;
    detail::LargeVector<Simplex> simplexes;
    std::optional<CollectedLabels> labels;
    std::exception_ptr build_problem, label_problem;
    tbb::parallel_invoke(
        [&] {
            try {
                simplexes = oriented_simplexes(raw, cells, ambient, options, reoriented);
                mesh.emplace(d, ambient);
                mesh->reserve(raw.points.size(), n);
                for (const Point& p : raw.points)
                    mesh->add_vertex(p);
                // lenient: keep duplicates, non-manifold faces and pinched vertices (validate()
                // names them)
                built = options.lenient ? mesh->assign_elements_unchecked(simplexes, cells.labels)
                                        : mesh->assign_elements(simplexes, cells.labels);
            } catch (...) {
                build_problem = std::current_exception();
            }
        },
        [&] {
            try {
                labels = collect_face_labels(faces);
            } catch (...) {
                label_problem = std::current_exception();
            }
        });
    if (build_problem)
        std::rethrow_exception(build_problem);
    if (options.lenient) {
        if (!*built) {
            const std::size_t item = built->refusal().item;
            fail(cells.file, item < n ? cells.lines[item] : 0, built->reason());
        }
    } else {
        const bool pinched = !*built && built->code() == RefusalCode::pinched_star;
        if (pinched && options.split_pinched) {
            const std::size_t file_vertices = raw.points.size();
            std::vector<std::pair<VertexId, VertexId>> copies =
                split_pinched_vertices(raw, cells, faces, simplexes);
            for (std::size_t v = file_vertices; v < raw.points.size(); ++v)
                mesh->add_vertex(raw.points[v]);
            built = mesh->assign_elements(simplexes, cells.labels);
            if (report) {
                for (std::size_t c = 0; c < copies.size(); ++c)
                    if (c == 0 || copies[c].first != copies[c - 1].first)
                        ++report->pinched_vertices;
                report->vertex_copies = std::move(copies);
            }
            // the split renamed vertices of labelled faces: gather them again
            label_problem = nullptr;
            labels = collect_face_labels(faces);
        }
        if (!*built) {
            // a pinched vertex is best named on the vertex's own line
            if (built->code() == RefusalCode::pinched_star)
                check_vertex_stars(raw, simplexes, static_cast<int>(k));
            const std::size_t item = built->refusal().item;
            if (item >= n)
                fail(cells.file, 0, built->reason());
            explain_refusal(raw, cells, simplexes, item, built->reason());
        }
    }
    if (label_problem)
        std::rethrow_exception(label_problem);
    place_face_labels(std::move(*labels), faces, *mesh, options, report);
    if (report)
        report->reoriented = reoriented;
    return std::move(*mesh);
}

}  // namespace sxk::io
