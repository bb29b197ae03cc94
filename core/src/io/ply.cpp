// PLY (the Stanford polygon format): a text header that declares elements and their
// properties, then the elements' values, as text or binary.
//
//   ply
//   format ascii 1.0              or binary_little_endian 1.0, binary_big_endian 1.0
//   comment ...                   comment and obj_info lines are skipped
//   element vertex 8              N vertices, each with these values in this order:
//   property float x              scalar types: char uchar short ushort int uint float double,
//   property float y              or int8 uint8 int16 uint16 int32 uint32 float32 float64
//   property float z
//   property uchar red            (anything else is skipped)
//   element face 12
//   property list uchar int vertex_indices    a count, then that many 0-based vertex indices
//   end_header                    (vertex_index also names it); ASCII: one element a line
//
// Used: x y z of `vertex` (z may be absent: 0), and the index list of `face`, whose faces must
// be triangles (as OBJ, polygons are refused). Every other property and element (normals,
// colours, edge, material, other lists) is skipped by its size, in all three encodings. Every
// read is bounded by the bytes present: a header's count only limits what is reserved before
// the data runs out (plausible_count). Trailing blanks after the last element are allowed
// (writers end a binary file with a newline at times); anything else is more data than the
// header declares.
//
// Messages, as OFF: vertices are numbered from 0 (as the faces index them), faces and other
// elements from 1. Text parts give their line; the binary data has none, so there the line is
// 0 and the message names the element ("vertex 3: coordinate is not finite").
// Always x y z: a mesh whose z are all 0 is planar (RawMesh::ambient_from_z). No labels.
//
// Writing: the triangle surface (writing.hpp: a tetrahedral mesh gives its boundary, outward),
// vertices as double x y z and faces as `list uchar int vertex_indices`: binary_little_endian
// for Encoding::standard and ::binary, text with shortest round-trip doubles for ::ascii. Both
// read back bit for bit.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "binary_numbers.hpp"
#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

struct ScalarName {
    std::string_view name;
    Scalar type;
};
constexpr std::array<ScalarName, 16> scalar_names{{{"char", Scalar::int8},
                                                   {"int8", Scalar::int8},
                                                   {"uchar", Scalar::uint8},
                                                   {"uint8", Scalar::uint8},
                                                   {"short", Scalar::int16},
                                                   {"int16", Scalar::int16},
                                                   {"ushort", Scalar::uint16},
                                                   {"uint16", Scalar::uint16},
                                                   {"int", Scalar::int32},
                                                   {"int32", Scalar::int32},
                                                   {"uint", Scalar::uint32},
                                                   {"uint32", Scalar::uint32},
                                                   {"float", Scalar::float32},
                                                   {"float32", Scalar::float32},
                                                   {"double", Scalar::float64},
                                                   {"float64", Scalar::float64}}};

bool is_integer(Scalar type) {
    return !is_float(type);
}

// The value at `bytes` (the caller checked that size_of(type) bytes are there).
double load_double(Scalar type, const char* bytes, bool big_endian) {
    switch (type) {
        case Scalar::int8:
            return load_number<std::int8_t>(bytes, big_endian);
        case Scalar::uint8:
            return load_number<std::uint8_t>(bytes, big_endian);
        case Scalar::int16:
            return load_number<std::int16_t>(bytes, big_endian);
        case Scalar::uint16:
            return load_number<std::uint16_t>(bytes, big_endian);
        case Scalar::int32:
            return load_number<std::int32_t>(bytes, big_endian);
        case Scalar::uint32:
            return load_number<std::uint32_t>(bytes, big_endian);
        case Scalar::int64:  // no PLY type name gives these (binary_numbers.hpp is shared with VTK)
            return static_cast<double>(load_number<std::int64_t>(bytes, big_endian));
        case Scalar::uint64:
            return static_cast<double>(load_number<std::uint64_t>(bytes, big_endian));
        case Scalar::float32:
            return load_number<float>(bytes, big_endian);
        case Scalar::float64:
            break;
    }
    return load_number<double>(bytes, big_endian);
}

// An integer type's value (lists' counts and indices; the header refuses other types there).
std::int64_t load_integer(Scalar type, const char* bytes, bool big_endian) {
    switch (type) {
        case Scalar::int8:
            return load_number<std::int8_t>(bytes, big_endian);
        case Scalar::uint8:
            return load_number<std::uint8_t>(bytes, big_endian);
        case Scalar::int16:
            return load_number<std::int16_t>(bytes, big_endian);
        case Scalar::uint16:
            return load_number<std::uint16_t>(bytes, big_endian);
        case Scalar::int32:
            return load_number<std::int32_t>(bytes, big_endian);
        default:
            break;
    }
    return load_number<std::uint32_t>(bytes, big_endian);
}

enum class Role : std::uint8_t { skipped, x, y, z, indices };

struct Property {
    std::string name;
    std::string missing;  // "value of property NAME", for Cursor::need_in_line
    Scalar type = Scalar::float64;  // a list's items
    bool list = false;
    Scalar count_type = Scalar::uint8;
    Role role = Role::skipped;
};

struct Element {
    std::string name;
    std::int64_t count = 0;
    std::size_t line = 0;
    std::vector<Property> properties;
};

// (not sxk::Encoding, the writers' choice)
enum class DataEncoding : std::uint8_t { ascii, little_endian, big_endian };

struct Header {
    DataEncoding encoding = DataEncoding::ascii;
    std::vector<Element> elements;
    std::size_t lines = 0;  // lines holding tokens, end_header included
};

// Where the binary data starts: just past the line "end_header" and its line break; npos when
// no line is "end_header" (the header is then read to its end, and says what is wrong).
std::size_t data_start(std::string_view bytes) {
    std::size_t start = 0;
    while (start < bytes.size()) {
        std::size_t end = bytes.find('\n', start);
        const std::size_t next = end == std::string_view::npos ? bytes.size() : end + 1;
        if (end == std::string_view::npos)
            end = bytes.size();
        // blanks as the header's cursor sees them (text.hpp)
        std::string_view line = bytes.substr(start, end - start);
        const std::size_t first = line.find_first_not_of(" \t\r\v\f");
        line = first == std::string_view::npos
                   ? std::string_view{}
                   : line.substr(first, line.find_last_not_of(" \t\r\v\f") - first + 1);
        if (line == "end_header")
            return next;
        start = next;
    }
    return std::string_view::npos;
}

Scalar scalar_type(Cursor& in, std::string_view token) {
    for (const ScalarName& entry : scalar_names)
        if (entry.name == token)
            return entry.type;
    in.fail("unknown property type " + quote(token));
}

void expect_line_done(Cursor& in) {
    if (!in.line_done())
        in.fail("unexpected value " + quote(in.next_in_line()) + " at the end of the line");
}

Header read_header(Cursor& in) {
    Header header;
    if (!in.next_line())
        in.fail("truncated file: expected ply");
    if (const std::string_view magic = in.next_in_line(); magic != "ply")
        in.fail("expected ply, found " + quote(magic));
    expect_line_done(in);
    header.lines = 1;
    bool format = false;
    for (;;) {
        if (!in.next_line())
            in.fail("truncated file: expected end_header");
        ++header.lines;
        const std::string_view keyword = in.next_in_line();
        if (keyword == "end_header") {
            expect_line_done(in);
            break;
        }
        if (keyword == "comment" || keyword == "obj_info") {
            while (!in.line_done())
                in.next_in_line();
        } else if (keyword == "format") {
            if (format)
                in.fail("a second format line");
            format = true;
            const std::string_view kind = in.need_in_line("format");
            if (kind == "ascii")
                header.encoding = DataEncoding::ascii;
            else if (kind == "binary_little_endian")
                header.encoding = DataEncoding::little_endian;
            else if (kind == "binary_big_endian")
                header.encoding = DataEncoding::big_endian;
            else
                in.fail("unknown PLY format " + quote(kind) +
                        " (ascii, binary_little_endian and binary_big_endian are supported)");
            const std::string_view version = in.need_in_line("format version");
            if (version != "1.0")
                in.fail("unsupported PLY version " + quote(version) + " (1.0 is supported)");
            expect_line_done(in);
        } else if (keyword == "element") {
            Element element;
            element.name = in.need_in_line("element name");
            element.line = in.line();
            const bool used = element.name == "vertex" || element.name == "face";
            for (const Element& earlier : header.elements)
                if (used && earlier.name == element.name)
                    in.fail("a second element " + element.name);
            const std::string what = "number of " + element.name + " elements";
            element.count = in.to_integer(in.need_in_line(what.c_str()), what.c_str(), 0,
                                          used ? static_cast<std::int64_t>(invalid_id) - 1
                                               : std::numeric_limits<std::int64_t>::max());
            expect_line_done(in);
            header.elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (header.elements.empty())
                in.fail("property before any element");
            Element& element = header.elements.back();
            Property property;
            const std::string_view type = in.need_in_line("property type");
            if (type == "list") {
                property.list = true;
                property.count_type = scalar_type(in, in.need_in_line("list count type"));
                if (!is_integer(property.count_type))
                    in.fail("a list count must have an integer type");
                property.type = scalar_type(in, in.need_in_line("list item type"));
            } else {
                property.type = scalar_type(in, type);
            }
            property.name = in.need_in_line("property name");
            property.missing = "value of property " + property.name;
            expect_line_done(in);
            if (element.name == "vertex" &&
                (property.name == "x" || property.name == "y" || property.name == "z")) {
                if (property.list)
                    in.fail("property " + property.name + " of element vertex is a list");
                property.role = property.name == "x"   ? Role::x
                                : property.name == "y" ? Role::y
                                                       : Role::z;
            }
            if (element.name == "face" &&
                (property.name == "vertex_indices" || property.name == "vertex_index")) {
                if (!property.list)
                    in.fail("property " + property.name + " of element face is not a list");
                if (!is_integer(property.type))
                    in.fail("vertex indices must have an integer type");
                property.role = Role::indices;
            }
            for (const Property& earlier : element.properties)
                if (property.role == Role::indices && earlier.role == Role::indices)
                    in.fail("a second vertex index list in element face");
            for (const Property& earlier : element.properties)
                if (earlier.name == property.name)
                    in.fail("a second property " + property.name + " in element " +
                            element.name);
            element.properties.push_back(std::move(property));
        } else {
            in.fail("unknown keyword " + quote(keyword));
        }
    }
    if (!format)
        in.fail("the header has no format line");
    for (const Element& element : header.elements) {
        auto has = [&](Role role) {
            return std::any_of(element.properties.begin(), element.properties.end(),
                               [role](const Property& p) { return p.role == role; });
        };
        if (element.name == "vertex")
            for (const auto& [role, name] : {std::pair{Role::x, "x"}, std::pair{Role::y, "y"}})
                if (!has(role))
                    in.fail_at(element.line, std::string("element vertex has no property ") + name);
        if (element.name == "face" && !has(Role::indices))
            in.fail_at(element.line, "element face has no property vertex_indices");
    }
    return header;
}

std::string declared(const Element& element, std::int64_t found) {
    return "truncated file: the header declares " + std::to_string(element.count) + " " +
           element.name + " elements, found " + std::to_string(found);
}

std::string polygon(std::int64_t face, std::int64_t size) {
    const std::string what = "face " + std::to_string(face) + " has " + std::to_string(size) +
                             " vertices: ";
    return size > 3 ? what + "only triangles are supported (triangulate the polygons first)"
                    : what + "a face needs 3";
}

// Element `k` (0-based) of `element` as messages name it: vertices from 0, the rest from 1.
std::string item(const Element& element, std::int64_t k) {
    return element.name + " " + std::to_string(element.name == "vertex" ? k : k + 1);
}

class Reading {
public:
    Reading(const std::string& name, RawMesh& raw) : m_name(name), m_raw(raw) {}

    void ascii(Cursor& in, const Header& header, std::size_t bytes) {
        static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
        for (const Element& element : header.elements) {
            if (element.properties.empty())
                continue;  // no values, so no lines (the cursor skips blank ones)
            reserve(element, bytes, 2);
            for (std::int64_t k = 0; k < element.count; ++k) {
                if (!in.next_line())
                    in.fail(declared(element, k));
                Point p{0, 0, 0};
                for (const Property& property : element.properties) {
                    if (!property.list) {
                        const std::string_view token = in.need_in_line(property.missing.c_str());
                        if (property.role != Role::skipped) {
                            const auto axis = static_cast<std::size_t>(property.role) - 1;
                            p[axis] = in.to_double(token, axes[axis]);
                        }
                        continue;
                    }
                    const std::int64_t size =
                        in.to_integer(in.need_in_line("list length"), "list length", 0,
                                      std::numeric_limits<std::int64_t>::max());
                    if (property.role == Role::indices) {
                        if (size != 3)
                            in.fail(polygon(k + 1, size));
                        for (int j = 0; j < 3; ++j)
                            m_indices.push_back(
                                in.to_integer(in.need_in_line("vertex index"), "vertex index"));
                        continue;
                    }
                    for (std::int64_t j = 0; j < size; ++j)
                        in.need_in_line(property.missing.c_str());
                }
                expect_line_done(in);
                keep(element, p, in.line());
            }
        }
        if (in.next_line())
            in.fail("more data than the header declares");
    }

    void binary(std::string_view data, const Header& header) {
        const bool big_endian = header.encoding == DataEncoding::big_endian;
        ByteCursor in(data);
        for (const Element& element : header.elements) {
            if (element.properties.empty())
                continue;  // its elements take no bytes
            // the fewest bytes an element takes: its scalars, and its lists' counts
            std::size_t least = 0;
            bool lists = false;
            for (const Property& property : element.properties) {
                least += size_of(property.list ? property.count_type : property.type);
                lists = lists || property.list;
            }
            if (!lists && element.name != "vertex" && element.name != "face") {
                // skipped in one step
                const std::uint64_t whole = in.left() / least;
                if (static_cast<std::uint64_t>(element.count) > whole)
                    fail(0, declared(element, static_cast<std::int64_t>(whole)));
                in.take(static_cast<std::size_t>(element.count) * least);
                continue;
            }
            reserve(element, in.left(), least);
            for (std::int64_t k = 0; k < element.count; ++k) {
                auto take = [&](std::size_t n) {
                    if (!in.has(n))
                        fail(0, declared(element, k));
                    return in.take(n);
                };
                Point p{0, 0, 0};
                for (const Property& property : element.properties) {
                    if (!property.list) {
                        const char* bytes = take(size_of(property.type));
                        if (property.role != Role::skipped) {
                            const double value = load_double(property.type, bytes, big_endian);
                            if (!std::isfinite(value))
                                fail(0, item(element, k) + ": coordinate is not finite");
                            p[static_cast<std::size_t>(property.role) - 1] = value;
                        }
                        continue;
                    }
                    const std::int64_t size = load_integer(
                        property.count_type, take(size_of(property.count_type)), big_endian);
                    if (size < 0)
                        fail(0, item(element, k) + ": list length out of range: " +
                                    std::to_string(size));
                    if (property.role == Role::indices) {
                        if (size != 3)
                            fail(0, polygon(k + 1, size));
                        for (int j = 0; j < 3; ++j)
                            m_indices.push_back(load_integer(
                                property.type, take(size_of(property.type)), big_endian));
                        continue;
                    }
                    const std::uint64_t item_size = size_of(property.type);
                    if (static_cast<std::uint64_t>(size) > in.left() / item_size)
                        fail(0, declared(element, k));
                    in.take(static_cast<std::size_t>(size) * item_size);
                }
                keep(element, p, 0);
            }
        }
        const std::string_view rest = in.rest();
        if (rest.find_first_not_of(" \t\r\n") != std::string_view::npos)
            fail(0, "more data than the header declares (" + std::to_string(rest.size()) +
                        " bytes left)");
    }

    // The faces' indices, each in range, become the triangles.
    void finish() {
        const auto count = static_cast<std::int64_t>(m_raw.points.size());
        CellList& cells = m_raw.triangles;
        for (std::size_t i = 0; i < m_indices.size(); ++i) {
            const std::int64_t index = m_indices[i];
            if (index < 0 || index >= count) {
                const std::string reason =
                    "vertex index " + std::to_string(index) + " out of range " +
                    (count == 0 ? std::string("(there are no vertices)")
                                : "(0.." + std::to_string(count - 1) + ")");
                const std::size_t line = cells.lines[i / 3];
                fail(line, line == 0 ? "face " + std::to_string(i / 3 + 1) + ": " + reason
                                     : reason);
            }
            cells.vertices.push_back(static_cast<VertexId>(index));
        }
    }

private:
    [[noreturn]] void fail(std::size_t line, const std::string& reason) const {
        throw InputError(m_name, line, reason);
    }

    void reserve(const Element& element, std::size_t bytes, std::size_t bytes_per_element) {
        const std::size_t n = plausible_count(element.count, bytes, bytes_per_element);
        if (element.name == "vertex")
            m_raw.reserve_points(n);
        if (element.name == "face") {
            m_raw.triangles.reserve(n);
            m_indices.reserve(3 * n);
        }
    }

    void keep(const Element& element, const Point& p, std::size_t line) {
        if (element.name == "vertex") {
            m_raw.points.push_back(p);
            m_raw.point_lines.push_back(line);
        } else if (element.name == "face") {
            m_raw.triangles.lines.push_back(line);
            m_raw.triangles.labels.push_back(0);
        }
    }

    const std::string& m_name;
    RawMesh& m_raw;
    std::vector<std::int64_t> m_indices;  // three per face, as in the file
};

}  // namespace

Mesh read_ply(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report) {
    RawMesh raw;
    raw.vertex_file = raw.triangles.file = name;
    raw.vertex_base = 0;
    raw.ambient_from_z = true;
    Reading reading(name, raw);

    std::size_t start = data_start(bytes);
    const std::string_view head = bytes.substr(0, start);
    Cursor header_cursor(check_text(head, name), name, '\0');
    const Header header = read_header(header_cursor);
    // read_header stopped at the line data_start found (both see the same lines and blanks);
    // a guard all the same
    start = std::min(start, bytes.size());
    if (header.encoding == DataEncoding::ascii) {
        // the same lines again, now in a cursor over the whole text, whose lines go on counting
        Cursor in(check_text(bytes, name), name, '\0');
        for (std::size_t line = 0; line < header.lines; ++line)
            in.next_line();
        reading.ascii(in, header, bytes.size() - start);
    } else {
        reading.binary(bytes.substr(start), header);
    }
    reading.finish();
    return build_mesh(raw, name, options, report);
}

std::string write_ply(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const Surface surface = triangle_surface(mesh);
    // `int` indices: the format's usual, which every reader takes
    if (surface.vertices.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw OutputError("PLY's int vertex indices reach 2147483647 vertices, the surface has " +
                          std::to_string(surface.vertices.size()));
    const bool ascii = options.encoding == Encoding::ascii;
    std::string out;
    out.reserve(200 + surface.vertices.size() * (ascii ? 60 : 24) +
                surface.triangles.size() * (ascii ? 24 : 13));
    out += ascii ? "ply\nformat ascii 1.0\n" : "ply\nformat binary_little_endian 1.0\n";
    out += "comment written by simplexkit\nelement vertex ";
    append_number(out, surface.vertices.size());
    out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
    append_number(out, surface.triangles.size());
    out += "\nproperty list uchar int vertex_indices\nend_header\n";
    if (ascii) {
        append_surface_lines(out, surface, positions);
        return out;
    }
    for (VertexId v : surface.vertices)
        for (double c : positions[v])
            append_little_endian(out, c);
    for (const auto& t : surface.triangles) {
        append_little_endian(out, std::uint8_t{3});
        for (VertexId v : t)
            append_little_endian(out, static_cast<std::int32_t>(v));
    }
    return out;
}

}  // namespace sxk::io
