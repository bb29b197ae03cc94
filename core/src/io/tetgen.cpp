// TetGen (and Triangle) .node / .ele / .face (.edge): one record per line, '#' comments.
//
//   X.node   "N dim #attributes markers(0|1)"        then "id x y [z] attributes... [marker]"
//   X.ele    "M nodes(3|4) #attributes"              then "id a b c [d] attributes..."
//   X.face   "F markers(0|1)"                        then "id a b c [marker] [adjacent tets]"
//   X.edge   (triangle meshes, as Triangle writes it) "id a b [marker]"
//
// Numbering starts at 0 or 1, as the first node says; nodes must then be numbered
// consecutively, and the .ele and .face indices use the same base. The first element attribute
// (TetGen's region attribute) is the element label; .face (.edge) markers are face labels, kept
// only when the header says markers are present. A 2-dimensional .node file makes a planar
// mesh. Second-order elements (6 or 10 nodes) are refused.
//
// The writer ends each file of a set with the same stamp, "# written by simplexkit, set ID"
// (ID: 16 hex digits of a hash of the set's three texts). Its files replace their targets one
// rename after another (sxk/atomic_write.hpp, write_files_atomically), so a writer killed between
// the renames leaves files of two writes side by side; the reader refuses stamped files whose
// stamps differ, naming both. Files without a stamp (TetGen's own) are read as they are.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include <tbb/parallel_invoke.h>

#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

void start(Cursor& in, const char* what) {
    if (!in.next_line())
        in.fail(std::string("truncated file: expected ") + what);
}

// The record count a header starts with ("the number of THINGS").
std::int64_t header_count(Cursor& in, const std::string& things) {
    start(in, ("the number of " + things).c_str());
    const std::string what = "number of " + things;
    return in.to_integer(in.need_in_line(what.c_str()), what.c_str(), 0,
                         static_cast<std::int64_t>(invalid_id) - 1);
}

// Header fields after the first may be left out; they default as in TetGen's own reader.
std::int64_t optional_field(Cursor& in, const char* what, std::int64_t fallback, std::int64_t low,
                            std::int64_t high) {
    const std::string_view token = in.next_in_line();
    return token.empty() ? fallback : in.to_integer(token, what, low, high);
}

void end_of_line(Cursor& in) {
    if (!in.line_done())
        in.fail("unexpected value " + quote(in.next_in_line()) + " at the end of the line");
}

// Next record line, or "truncated file" when the header promised more.
void record(Cursor& in, const char* things, std::int64_t declared, std::int64_t index) {
    if (!in.next_line())
        in.fail("truncated file: the header declares " + std::to_string(declared) + " " + things +
                ", found " + std::to_string(index));
}

void no_more_records(Cursor& in, const char* things, std::int64_t declared) {
    if (in.next_line())
        in.fail("more " + std::string(things) + " than the " + std::to_string(declared) +
                " the header declares");
}

// An attribute as a label: TetGen writes region attributes as numbers that may carry a
// fraction ("1" or "1.0"); the label is that number when it is an integer.
int attribute_label(Cursor& in, std::string_view token) {
    const double value = in.to_double(token, "attribute");
    if (value != std::floor(value) || value < INT_MIN || value > INT_MAX)
        in.fail("region attribute " + quote(token) + " is not an integer");
    return static_cast<int>(value);
}

// Reads "a b c" vertex indices of a record into `cells`, checking them against the node range.
void read_indices(Cursor& in, CellList& cells, int count, std::int64_t base,
                  std::size_t vertex_count) {
    for (int j = 0; j < count; ++j) {
        const std::int64_t index = in.to_integer(in.need_in_line("vertex index"), "vertex index");
        if (index == 0 && base == 1)
            in.fail("vertex index 0: indices start at 1");
        if (index < base || index - base >= static_cast<std::int64_t>(vertex_count))
            in.fail("vertex index " + std::to_string(index) + " out of range (" +
                    std::to_string(base) + ".." +
                    std::to_string(base + static_cast<std::int64_t>(vertex_count) - 1) + ")");
        cells.vertices.push_back(static_cast<VertexId>(index - base));
    }
}

// The .node file from its first record on: the points, their lines and the numbering base
// (0 or 1, as the first node says).
void read_nodes(Cursor& node, std::int64_t nodes, std::int64_t dimension,
                std::int64_t node_attributes, std::int64_t node_markers, std::size_t text_size,
                RawMesh& raw) {
    const std::size_t reserve = plausible_count(nodes, text_size, 8);
    raw.reserve_points(reserve);
    std::int64_t base = 0;
    static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
    for (std::int64_t i = 0; i < nodes; ++i) {
        record(node, "nodes", nodes, i);
        const std::string_view id_token = node.need_in_line("node number");
        const std::int64_t id = node.to_integer(id_token, "node number");
        if (i == 0) {
            if (id != 0 && id != 1)
                node.fail("the first node must be numbered 0 or 1, found " + quote(id_token));
            base = id;
        } else if (id != base + i) {
            node.fail("node " + std::to_string(id) + " out of sequence: expected " +
                      std::to_string(base + i));
        }
        Point p{0, 0, 0};
        for (std::int64_t c = 0; c < dimension; ++c)
            p[static_cast<std::size_t>(c)] = node.to_double(node.need_in_line(axes[c]), axes[c]);
        for (std::int64_t a = 0; a < node_attributes; ++a)
            node.to_double(node.need_in_line("attribute"), "attribute");
        if (node_markers)
            node.to_integer(node.need_in_line("boundary marker"), "boundary marker");
        end_of_line(node);
        raw.points.push_back(p);
        raw.point_lines.push_back(node.line());
    }
    no_more_records(node, "nodes", nodes);
    raw.vertex_base = base;
}

// The .ele file: triangles or tetrahedra with their region attribute as label. Indices are
// checked against the `vertex_count` nodes numbered from `base`.
void read_elements(const TetgenText& text, std::int64_t dimension, std::int64_t base,
                   std::size_t vertex_count, RawMesh& raw) {
    Cursor ele(text.ele, text.ele_name, '#');
    const std::int64_t count = header_count(ele, "elements");
    const std::string_view per_token = ele.next_in_line();
    const std::int64_t per_element =
        per_token.empty() ? 4 : ele.to_integer(per_token, "nodes per element");
    if (per_element == 6 || per_element == 10)
        ele.fail("second-order elements (" + std::to_string(per_element) +
                 " nodes) are not supported");
    if (per_element != 3 && per_element != 4)
        ele.fail("nodes per element must be 3 or 4, found " + quote(per_token));
    if (per_element == 4 && dimension == 2)
        ele.fail("tetrahedra need a 3-dimensional .node file");
    const std::int64_t attributes = optional_field(ele, "number of attributes", 0, 0, INT_MAX);
    end_of_line(ele);
    CellList& cells = per_element == 4 ? raw.tetrahedra : raw.triangles;
    cells.reserve(plausible_count(count, text.ele.size(), 10), true);
    for (std::int64_t i = 0; i < count; ++i) {
        record(ele, "elements", count, i);
        cells.numbers.push_back(
            ele.to_integer(ele.need_in_line("element number"), "element number"));
        cells.lines.push_back(ele.line());
        read_indices(ele, cells, static_cast<int>(per_element), base, vertex_count);
        int label = 0;
        for (std::int64_t a = 0; a < attributes; ++a) {
            const std::string_view token = ele.need_in_line("attribute");
            if (a == 0)
                label = attribute_label(ele, token);
            else
                ele.to_double(token, "attribute");
        }
        cells.labels.push_back(label);
        end_of_line(ele);
    }
    no_more_records(ele, "elements", count);
}

// The .face (.edge) file into `faces` (triangles of a tetrahedral mesh, edges of a triangle
// mesh); its markers are kept only when the header says they are present.
void read_faces(const TetgenText& text, std::int64_t base, std::size_t vertex_count,
                CellList& faces) {
    faces.file = text.face_name;
    Cursor in(*text.face, text.face_name, '#');
    const std::int64_t face_count = header_count(in, "faces");
    const std::int64_t markers = optional_field(in, "boundary marker flag", 0, 0, 1);
    end_of_line(in);
    const std::size_t n = plausible_count(face_count, text.face->size(), 8);
    CellList scratch(faces.size);  // the faces are checked but not kept without markers
    CellList& target = markers ? faces : scratch;
    target.reserve(n, true);
    for (std::int64_t i = 0; i < face_count; ++i) {
        record(in, "faces", face_count, i);
        target.numbers.push_back(in.to_integer(in.need_in_line("face number"), "face number"));
        target.lines.push_back(in.line());
        read_indices(in, target, faces.size, base, vertex_count);
        target.labels.push_back(
            markers ? static_cast<int>(in.to_integer(in.need_in_line("boundary marker"),
                                                     "boundary marker", INT_MIN, INT_MAX))
                    : 0);
        // tetgen -nn appends the two tetrahedra adjacent to the face
        if (!in.line_done()) {
            in.to_integer(in.next_in_line(), "adjacent element");
            in.to_integer(in.need_in_line("adjacent element"), "adjacent element");
        }
        end_of_line(in);
    }
    no_more_records(in, "faces", face_count);
}

constexpr std::string_view set_stamp_prefix = "# written by simplexkit, set ";

// The stamp line of a file the writer wrote (its last line that is not blank): where it starts in
// `text`, and the set id it names; an empty id when the file has no stamp.
struct SetStamp {
    std::size_t offset = 0;
    std::string_view id;
};

SetStamp set_stamp(std::string_view text) {
    const std::size_t last = text.find_last_not_of(" \t\r\n");
    if (last == std::string_view::npos)
        return {};
    const std::size_t newline = text.rfind('\n', last);
    const std::size_t begin = newline == std::string_view::npos ? 0 : newline + 1;
    const std::string_view line = text.substr(begin, last + 1 - begin);
    if (line.substr(0, set_stamp_prefix.size()) != set_stamp_prefix)
        return {};
    return {begin, line.substr(set_stamp_prefix.size())};
}

// The files of one set carry one stamp: a file stamped by another write than the files before it
// (in the order .node, .ele, .face) is refused at its stamp line, naming the file it differs from.
void check_one_set(const TetgenText& text) {
    struct Stamped {
        std::string_view text;
        const std::string* name;
        SetStamp stamp;
    };
    std::vector<Stamped> stamped;
    auto add = [&](std::string_view file, const std::string& name) {
        if (const SetStamp stamp = set_stamp(file); !stamp.id.empty())
            stamped.push_back({file, &name, stamp});
    };
    add(text.node, text.node_name);
    add(text.ele, text.ele_name);
    if (text.face)
        add(*text.face, text.face_name);
    for (std::size_t i = 1; i < stamped.size(); ++i) {
        const Stamped& first = stamped.front();
        const Stamped& other = stamped[i];
        if (other.stamp.id == first.stamp.id)
            continue;
        const std::size_t line = 1 + static_cast<std::size_t>(std::count(
                                         other.text.begin(),
                                         other.text.begin() + static_cast<std::ptrdiff_t>(other.stamp.offset),
                                         '\n'));
        throw InputError(*other.name, line,
                         "set " + std::string(other.stamp.id) + ", but " + *first.name + " is of set " +
                             std::string(first.stamp.id) +
                             ": the files come from two writes (one was interrupted between "
                             "replacing them); write the set again");
    }
}

// The set id of a write: 64-bit FNV-1a over the three texts, so that a set written again from
// the same mesh is byte for byte the same files, and two writes of different meshes differ.
std::string set_id(const TetgenFiles& files) {
    std::uint64_t hash = 14695981039346656037ull;
    for (const std::string* part : {&files.node, &files.ele, &files.face}) {
        for (const char c : *part) {
            hash ^= static_cast<unsigned char>(c);
            hash *= 1099511628211ull;
        }
        hash ^= 0xff;  // a separator: moving text from one file to the next changes the id
        hash *= 1099511628211ull;
    }
    char id[17];
    std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(hash));
    return id;
}

}  // namespace

bool tetgen_announces_tetrahedra(std::string_view ele, const std::string& ele_name) {
    Cursor header(ele, ele_name, '#');
    header.next_line();
    header.next_in_line();
    const std::string_view per_element = header.next_in_line();
    return per_element != "3" && per_element != "6";
}

RawMesh parse_tetgen_text(const TetgenText& text) {
    check_one_set(text);
    RawMesh raw;
    raw.vertex_file = text.node_name;
    raw.triangles.file = raw.tetrahedra.file = text.ele_name;

    // The .node header and the numbering base come first; then the bodies of the three files,
    // which only share the node count and the base, are read in parallel (the .ele file is
    // most of the text; docs/performance.md "io"). A problem is reported as a reading in file
    // order would: the .node file's first, then the .ele file's, then the .face file's (a later
    // file's reading relies on the node count only once the .node file is known to be sound).
    Cursor node(text.node, text.node_name, '#');
    const std::int64_t nodes = header_count(node, "nodes");
    const std::string_view dim_token = node.next_in_line();
    const std::int64_t dimension = dim_token.empty() ? 3 : node.to_integer(dim_token, "dimension");
    if (dimension != 2 && dimension != 3)
        node.fail("dimension must be 2 or 3, found " + quote(dim_token));
    const std::int64_t node_attributes =
        optional_field(node, "number of attributes", 0, 0, INT_MAX);
    const std::int64_t node_markers = optional_field(node, "boundary marker flag", 0, 0, 1);
    end_of_line(node);
    raw.ambient = static_cast<int>(dimension);
    std::int64_t base = 0;  // as the first node says; a wrong first number fails read_nodes
    {
        Cursor first = node;
        if (nodes > 0 && first.next_line())
            base = first.to_integer(first.need_in_line("node number"), "node number") == 1 ? 1 : 0;
    }
    const std::size_t vertex_count = static_cast<std::size_t>(nodes);

    std::exception_ptr node_problem, element_problem, face_problem;
    auto guarded = [](std::exception_ptr& problem, auto&& read) {
        return [&problem, read] {
            try {
                read();
            } catch (...) {
                problem = std::current_exception();
            }
        };
    };
    CellList faces(tetgen_announces_tetrahedra(text.ele, text.ele_name) ? 3 : 2);
    tbb::parallel_invoke(
        guarded(node_problem,
                [&] {
                    read_nodes(node, nodes, dimension, node_attributes, node_markers,
                               text.node.size(), raw);
                }),
        guarded(element_problem, [&] { read_elements(text, dimension, base, vertex_count, raw); }),
        guarded(face_problem, [&] {
            if (text.face)
                read_faces(text, base, vertex_count, faces);
        }));
    for (const std::exception_ptr& problem : {node_problem, element_problem, face_problem})
        if (problem)
            std::rethrow_exception(problem);
    if (text.face)
        (faces.size == 3 ? raw.triangles : raw.edges) = std::move(faces);
    return raw;
}

TetgenFiles write_tetgen(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const int dimension = mesh.ambient_dimension();
    const int d = mesh.topological_dimension();
    TetgenFiles files;

    std::string& node = files.node;
    node.reserve(mesh.vertex_count() * 64);
    append_number(node, mesh.vertex_count());
    node += ' ';
    append_number(node, dimension);
    node += " 0 0\n";
    for (std::size_t v = 0; v < positions.size(); ++v) {
        append_number(node, v);
        for (int c = 0; c < dimension; ++c) {
            node += ' ';
            append_number(node, positions[v][static_cast<std::size_t>(c)]);
        }
        node += '\n';
    }

    bool labelled = false;
    for (ElementId t : elements(mesh))
        labelled = labelled || mesh.label(t) != 0;
    std::string& ele = files.ele;
    ele.reserve(mesh.element_count() * 40);
    append_number(ele, mesh.element_count());
    ele += ' ';
    append_number(ele, d + 1);
    ele += labelled ? " 1\n" : " 0\n";
    std::size_t number = 0;
    for (ElementId t : elements(mesh)) {
        append_number(ele, number++);
        const auto v = oriented_vertices(mesh.simplex(t));
        for (int j = 0; j <= d; ++j) {
            ele += ' ';
            append_number(ele, v[static_cast<std::size_t>(j)]);
        }
        if (labelled) {
            ele += ' ';
            append_number(ele, mesh.label(t));
        }
        ele += '\n';
    }

    // the labelled faces with their markers; without labels the plain boundary, so the file
    // still is what TetGen users expect (and reads back as no labels)
    std::string& face = files.face;
    auto face_line = [&](std::size_t i, const Simplex& s) {
        append_number(face, i);
        const auto v = oriented_vertices(s);
        for (int j = 0; j < d; ++j) {
            face += ' ';
            append_number(face, v[static_cast<std::size_t>(j)]);
        }
    };
    if (!mesh.face_labels().empty()) {
        const auto faces = sorted_face_labels(mesh);
        append_number(face, faces.size());
        face += " 1\n";
        for (std::size_t i = 0; i < faces.size(); ++i) {
            face_line(i, faces[i].first);
            face += ' ';
            append_number(face, faces[i].second);
            face += '\n';
        }
    } else {
        const std::vector<FaceId> boundary = mesh.boundary_faces();
        append_number(face, boundary.size());
        face += " 0\n";
        for (std::size_t i = 0; i < boundary.size(); ++i) {
            face_line(i, mesh.face_simplex(boundary[i]));
            face += '\n';
        }
    }
    const std::string stamp = std::string(set_stamp_prefix) + set_id(files) + "\n";
    for (std::string* part : {&files.node, &files.ele, &files.face})
        *part += stamp;
    return files;
}

}  // namespace sxk::io
