#include "raw_mesh.hpp"

#include <algorithm>
#include <span>
#include <unordered_map>

#include "sxk/predicates.hpp"

namespace sxk::io {

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

Simplex unoriented_key(std::span<const VertexId> vertices) {
    const Simplex s(+1, vertices);
    return s.sign() > 0 ? s : s.mate();
}

void add_face_labels(const CellList& faces, Mesh& mesh) {
    const int d = mesh.topological_dimension();
    const char* kind = cell_name(faces.size);
    FaceLabels& labels = mesh.face_labels();
    labels.reserve(faces.count());
    std::unordered_map<Simplex, std::size_t, SimplexHash> interior;  // not on the boundary
    bool listed_first = true;  // try the face as listed before its mate
    for (std::size_t i = 0; i < faces.count(); ++i) {
        const std::span<const VertexId> vertices(
            faces.vertices.data() + i * static_cast<std::size_t>(d), static_cast<std::size_t>(d));
        const Simplex key = unoriented_key(vertices);
        if (!key.has_distinct_vertices())
            fail(faces.file, faces.lines[i],
                 std::string(kind) + " " + std::to_string(faces.number(i)) +
                     " has a repeated vertex");
        if (const auto [at, fresh] = labels.emplace(key, faces.labels[i]); !fresh) {
            // listed before: find where (error path only, so a scan rather than a second map)
            std::size_t first = 0;
            while (unoriented_key({faces.vertices.data() + first * static_cast<std::size_t>(d),
                                   static_cast<std::size_t>(d)}) != key)
                ++first;
            fail(faces.file, faces.lines[i],
                 std::string(kind) + " " + std::to_string(faces.number(i)) + " repeats " + kind +
                     " " + std::to_string(faces.number(first)));
        }
        // Files list their boundary faces oriented one way (all outward, or all inward): ask
        // first for the orientation found last, one boundary-map lookup per face instead of
        // 1.5 (each costs cache misses into the face and element pools; docs/performance.md, "io")
        const Simplex listed(+1, vertices);
        const Simplex first = listed_first ? listed : listed.mate();
        if (mesh.find_boundary_face(first) == invalid_id) {
            if (mesh.find_boundary_face(first.mate()) == invalid_id)
                interior.emplace(key, i);
            else
                listed_first = !listed_first;
        }
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
    fail(faces.file, faces.lines[first],
         std::string(kind) + " " + std::to_string(faces.number(first)) + " is not a face of any " +
             cell_name(d + 1));
}

}  // namespace

Mesh build_mesh(RawMesh& raw, const std::string& fallback_file, const ReadOptions& options,
                ReadReport* report) {
    const int d = !raw.tetrahedra.lines.empty() ? 3 : !raw.triangles.lines.empty() ? 2 : 0;
    if (d == 0)
        fail(fallback_file, 0, "no triangles or tetrahedra");
    CellList& cells = d == 3 ? raw.tetrahedra : raw.triangles;
    const CellList& faces = d == 3 ? raw.triangles : raw.edges;
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

    std::vector<Simplex> simplexes(n);
    std::size_t reoriented = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::span<const VertexId> vertices(cells.vertices.data() + i * k, k);
        Simplex s(+1, vertices);
        if (!s.has_distinct_vertices())
            fail(cells.file, cells.lines[i],
                 "element " + std::to_string(cells.number(i)) + " has a repeated vertex");
        if (d == ambient) {
            const auto& p = raw.points;
            const Sign sign =
                d == 3 ? orient3d(p[vertices[0]], p[vertices[1]], p[vertices[2]], p[vertices[3]])
                       : orient2d(p[vertices[0]], p[vertices[1]], p[vertices[2]]);
            if (sign == Sign::negative && (options.reorient || !options.lenient)) {
                if (!options.reorient)
                    fail(cells.file, cells.lines[i],
                         "element " + std::to_string(cells.number(i)) + " is inverted");
                s = s.mate();
                ++reoriented;
            }
        }
        simplexes[i] = s;
    }

    Mesh mesh(d, ambient);
    mesh.reserve(raw.points.size(), n);
    for (const Point& p : raw.points)
        mesh.add_vertex(p);
    if (options.lenient) {
        // keep duplicates, non-manifold faces and pinched vertices: validate() names them
        if (auto built = mesh.assign_elements_unchecked(simplexes, cells.labels); !built) {
            const std::size_t item = built.refusal().item;
            fail(cells.file, item < n ? cells.lines[item] : 0, built.reason());
        }
    } else {
        if (auto built = mesh.assign_elements(simplexes, cells.labels); !built) {
            // a pinched vertex is best named on the vertex's own line
            if (built.reason().rfind("star connectivity", 0) == 0)
                check_vertex_stars(raw, simplexes, static_cast<int>(k));
            const std::size_t item = built.refusal().item;
            if (item >= n)
                fail(cells.file, 0, built.reason());
            explain_refusal(raw, cells, simplexes, item, built.reason());
        }
    }
    add_face_labels(faces, mesh);
    if (report)
        report->reoriented = reoriented;
    return mesh;
}

}  // namespace sxk::io
