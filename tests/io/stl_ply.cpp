// STL and PLY (core/src/io/stl.cpp, ply.cpp): round trips in every encoding, the welding of STL
// corners, what VTK and meshio write, and malformed files with their exact messages.
//
// The peer files in tests/data/io were written once by tests/data/io/stl_ply_peers.py with
// Debian 12's python3-vtk9 9.1 (vtkSTLWriter binary and ASCII; vtkPLYWriter little-endian,
// big-endian and ASCII, with a colour per face) and python3-meshio 5.0 (meshio.write with
// binary=True and False), all of one sphere: vtkSphereSource, 14 points, 24 triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>
#include <string>
#include <vector>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

using test::data_file;
using test::file_bytes;
using test::expect_same_mesh;
using test::planar_triangles;
using test::scratch_dir;
using test::tetrahedron_surface;
using test::two_tetrahedra;

Mesh read_bytes(const std::string& bytes, Format format, ReadReport* report = nullptr) {
    std::istringstream in(bytes);
    return read_mesh(in, format, format == Format::stl ? "in.stl" : "in.ply", {}, report);
}

// The exact message, "in.stl:LINE: reason" (or in.ply).
void expect_refused(const std::string& bytes, Format format, const std::string& expected) {
    try {
        const Mesh mesh = read_bytes(bytes, format);
        ADD_FAILURE() << "read " << mesh.element_count() << " elements, expected " << expected;
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  std::string(format == Format::stl ? "in.stl:" : "in.ply:") + expected);
    }
}

// The triangles as the positions of their corners, bit patterns, each oriented triangle turned
// to start at its smallest corner, sorted: equal lists are the same surface, whatever the vertex
// numbering (STL renumbers: vertices come in order of first use).
// x rounded to float and back, through a volatile: GCC 12.2 at -O2 dropped a plain
// `c = static_cast<float>(c)` over a Point copied from Mesh::deformed (its value-range pass did:
// -fno-tree-vrp kept the rounding), and the comparisons below then saw unrounded positions.
double float_rounded(double x) {
    volatile float rounded = static_cast<float>(x);
    return rounded;
}

using Corner = std::array<std::uint64_t, 3>;
using CornerTriangle = std::array<Corner, 3>;
Corner bits(const Point& p) {
    return {std::bit_cast<std::uint64_t>(p[0]), std::bit_cast<std::uint64_t>(p[1]),
            std::bit_cast<std::uint64_t>(p[2])};
}
std::vector<CornerTriangle> corner_triangles(const Mesh& mesh,
                                             const std::vector<Simplex>& triangles,
                                             bool to_float = false) {
    std::vector<CornerTriangle> list;
    for (const Simplex& s : triangles) {
        std::array<VertexId, 3> v{s.vertex(0), s.vertex(1), s.vertex(2)};
        if (s.sign() < 0)
            std::swap(v[0], v[1]);
        CornerTriangle t;
        for (std::size_t i = 0; i < 3; ++i) {
            Point p = mesh.deformed(v[i]);
            if (to_float)
                for (double& c : p)
                    c = float_rounded(c);
            t[i] = bits(p);
        }
        while (!(t[0] <= t[1] && t[0] <= t[2]))
            std::rotate(t.begin(), t.begin() + 1, t.end());
        list.push_back(t);
    }
    std::sort(list.begin(), list.end());
    return list;
}
std::vector<CornerTriangle> corner_triangles(const Mesh& mesh, bool to_float = false) {
    std::vector<Simplex> triangles;
    if (mesh.topological_dimension() == 2) {
        for (ElementId t : elements(mesh))
            triangles.push_back(mesh.simplex(t));
    } else {
        for (FaceId f : mesh.boundary_faces())
            triangles.push_back(mesh.face_simplex(f));  // outward
    }
    return corner_triangles(mesh, triangles, to_float);
}

Mesh write_then_read(const Mesh& mesh, const std::string& file_name, Encoding encoding) {
    const auto path = scratch_dir() / file_name;
    WriteOptions options;
    options.encoding = encoding;
    write_mesh(mesh, path, options);
    return read_mesh(path);
}

// A binary file's bytes, little-endian unless `big`.
struct Bytes {
    std::string data;
    bool big = false;
    template <class T>
    Bytes& put(T value) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if (big == (std::endian::native == std::endian::little))
            std::reverse(raw, raw + sizeof(T));
        data.append(raw, sizeof(T));
        return *this;
    }
};

// A binary STL: the header's 80 bytes, the count, then per triangle a normal and three corners.
std::string binary_stl(const std::vector<std::array<Point, 3>>& triangles,
                       std::string header = "made by tests/io/stl_ply.cpp",
                       std::uint32_t count = ~std::uint32_t{0}) {
    header.resize(80, '\0');
    Bytes out{header};
    out.put(count == ~std::uint32_t{0} ? static_cast<std::uint32_t>(triangles.size()) : count);
    for (const auto& t : triangles) {
        for (int c = 0; c < 3; ++c)
            out.put(0.0f);
        for (const Point& p : t)
            for (double c : p)
                out.put(static_cast<float>(c));
        out.put(std::uint16_t{0});
    }
    return out.data;
}

// A closed surface: the tetrahedron with corners 0 (origin), 1 (x), 2 (y), 3 (z), outward.
const std::vector<std::array<Point, 3>> tetrahedron_corners{
    {Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}},
    {Point{0, 0, 0}, Point{0, 0, 1}, Point{0, 1, 0}},
    {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 0, 1}},
    {Point{0, 0, 0}, Point{0, 1, 0}, Point{1, 0, 0}}};

std::string ascii_facet(const std::array<Point, 3>& t) {
    std::ostringstream out;
    out.precision(17);
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (const Point& p : t)
        out << "      vertex " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    out << "    endloop\n  endfacet\n";
    return out.str();
}

std::string ascii_stl(const std::vector<std::array<Point, 3>>& triangles) {
    std::string out = "solid tetra\n";
    for (const auto& t : triangles)
        out += ascii_facet(t);
    return out + "endsolid tetra\n";
}

// ---- STL: round trips --------------------------------------------------------------------------

TEST(StlRoundTrip, AsciiGivesEveryTriangleBackExactly) {
    for (const Mesh& mesh : {tetrahedron_surface(), planar_triangles(), two_tetrahedra()}) {
        const Mesh again = write_then_read(mesh, "surface.stl", Encoding::ascii);
        EXPECT_EQ(again.topological_dimension(), 2);
        EXPECT_EQ(again.ambient_dimension(), mesh.ambient_dimension());
        // two_tetrahedra: its boundary, all five vertices on it, its -0.0 kept
        EXPECT_EQ(again.vertex_count(), mesh.vertex_count());
        EXPECT_EQ(corner_triangles(again), corner_triangles(mesh));
        EXPECT_EQ(again.boundary_face_count(), mesh.topological_dimension() == 3 ? 0u : mesh.boundary_face_count());
        EXPECT_TRUE(again.validate().ok()) << again.validate().reason();
    }
}

TEST(StlRoundTrip, BinaryRoundsEveryCoordinateToFloat) {
    for (Encoding encoding : {Encoding::standard, Encoding::binary}) {
        for (const Mesh& mesh : {tetrahedron_surface(), planar_triangles(), two_tetrahedra()}) {
            const Mesh again = write_then_read(mesh, "surface.stl", encoding);
            EXPECT_EQ(again.ambient_dimension(), mesh.ambient_dimension());
            EXPECT_EQ(again.vertex_count(), mesh.vertex_count());
            EXPECT_EQ(corner_triangles(again), corner_triangles(mesh, true));
            EXPECT_TRUE(again.validate().ok()) << again.validate().reason();
        }
        // 1/3 is not a float: binary STL loses it
        const Mesh planar = planar_triangles();
        EXPECT_NE(corner_triangles(write_then_read(planar, "square.stl", encoding)),
                  corner_triangles(planar));
    }
}

TEST(StlRoundTrip, BinaryIsEightyFourBytesAndFiftyPerTriangleWithUnitNormals) {
    const Mesh mesh = tetrahedron_surface();
    const auto path = scratch_dir() / "surface.stl";
    write_mesh(mesh, path);
    const std::string bytes = file_bytes(path);
    ASSERT_EQ(bytes.size(), 84u + 50u * 4u);
    EXPECT_NE(bytes.substr(0, 5), "solid");  // readers that look no further take it as ASCII
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    EXPECT_EQ(count, 4u);
    for (std::size_t t = 0; t < 4; ++t) {
        std::array<float, 12> values{};
        std::memcpy(values.data(), bytes.data() + 84 + 50 * t, 48);
        // the normal is the unit normal of the corners in their order
        const Point a{values[3], values[4], values[5]}, b{values[6], values[7], values[8]},
            c{values[9], values[10], values[11]};
        const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (std::size_t i = 0; i < 3; ++i)
            EXPECT_NEAR(values[i], n[i] / length, 1e-6);
    }
}

TEST(StlRoundTrip, BinaryRefusesCoordinatesBeyondFloat) {
    Mesh mesh = tetrahedron_surface();
    Point far = mesh.deformed(3);
    far[2] = 1e300;
    mesh.set_deformed(3, far);
    const auto path = scratch_dir() / "far.stl";
    try {
        write_mesh(mesh, path);
        ADD_FAILURE() << "written";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "coordinate 1e+300 of vertex 3 is beyond the range of binary STL's 32-bit "
                  "floats (ASCII STL holds it)");
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    // ASCII holds it
    EXPECT_EQ(corner_triangles(write_then_read(mesh, "far.stl", Encoding::ascii)),
              corner_triangles(mesh));
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(StlRoundTrip, AsciiNormalsAreUnitOrZero) {
    const auto path = scratch_dir() / "surface.stl";
    WriteOptions options;
    options.encoding = Encoding::ascii;
    write_mesh(tetrahedron_surface(), path, options);
    const std::string text = file_bytes(path);
    EXPECT_EQ(text.substr(0, 17), "solid simplexkit\n");
    // <1,2,3>: corners (1,0,1/4) (0,1,1/3) (0,0,1), normal (9,8,12)/17; <0,3,2> and <0,1,3>
    // in the planes x = 0 and y = 0, outward
    EXPECT_NE(text.find("facet normal 0.5294117647058824 0.4705882352941177 0.7058823529411764\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("facet normal -1 0 0\n"), std::string::npos) << text;
    EXPECT_NE(text.find("facet normal 0 -1 0\n"), std::string::npos) << text;
    EXPECT_EQ(text.substr(text.size() - 20), "endsolid simplexkit\n");

    // a flat triangle (three corners on a line) has no normal
    Mesh flat(2, 3);
    flat.add_vertex({0, 0, 0});
    flat.add_vertex({1, 0, 0});
    flat.add_vertex({3, 0, 0});
    const Simplex triangle[] = {Simplex(+1, {0, 1, 2})};
    ASSERT_TRUE(flat.assign_elements(triangle).ok());
    write_mesh(flat, path, options);
    EXPECT_NE(file_bytes(path).find("facet normal 0 0 0\n"), std::string::npos);
    EXPECT_EQ(read_mesh(path).element_count(), 1u);
    write_mesh(flat, path);
    const std::string binary = file_bytes(path);
    EXPECT_EQ(binary.substr(84, 12), std::string(12, '\0'));
}

// ---- STL: reading ------------------------------------------------------------------------------

TEST(StlRead, WeldsEqualCornersInOrderOfFirstUse) {
    // -0 and 0 are equal corners; the first written form is kept
    const std::string text =
        "solid two\n"
        "facet normal 0 0 1\nouter loop\nvertex -0 0 5\nvertex 1 0 5\nvertex 0 1 5\nendloop\n"
        "endfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex 1 0 5\nvertex 1 1 5\nvertex 0 1 5\nendloop\n"
        "endfacet\n"
        "endsolid two\n";
    const Mesh mesh = read_bytes(text, Format::stl);
    EXPECT_EQ(mesh.ambient_dimension(), 3);
    ASSERT_EQ(mesh.vertex_count(), 4u);
    EXPECT_EQ(bits(mesh.deformed(0)), bits(Point{-0.0, 0, 5}));
    EXPECT_EQ(mesh.deformed(1), (Point{1, 0, 5}));
    EXPECT_EQ(mesh.deformed(2), (Point{0, 1, 5}));
    EXPECT_EQ(mesh.deformed(3), (Point{1, 1, 5}));
    ASSERT_EQ(mesh.element_count(), 2u);
    EXPECT_EQ(mesh.simplex(0), Simplex(+1, {0, 1, 2}));
    EXPECT_EQ(mesh.simplex(1), Simplex(+1, {1, 3, 2}));
    EXPECT_TRUE(mesh.validate().ok());

    // the same corners with +0 welded to a -0 written later: one vertex, +0 kept
    std::string swapped = text;
    swapped.replace(swapped.find("-0 0 5"), 6, "0 0 5");
    swapped.replace(swapped.find("vertex 0 1 5"), 12, "vertex -0 1 5");
    const Mesh again = read_bytes(swapped, Format::stl);
    EXPECT_EQ(again.vertex_count(), 4u);
    EXPECT_EQ(bits(again.deformed(0)), bits(Point{0, 0, 5}));
    EXPECT_EQ(bits(again.deformed(2)), bits(Point{-0.0, 1, 5}));
}

TEST(StlRead, AllZInZeroIsPlanarAndMustBeCounterClockwise) {
    std::vector<std::array<Point, 3>> square{{Point{0, 0, 0}, Point{1, 0, 0}, Point{1, 1, 0}},
                                             {Point{0, 0, 0}, Point{1, 1, 0}, Point{0, 1, 0}}};
    const Mesh mesh = read_bytes(ascii_stl(square), Format::stl);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_EQ(mesh.element_count(), 2u);
    EXPECT_TRUE(mesh.validate(ValidateOptions{true}).ok());
    std::swap(square[1][1], square[1][2]);
    expect_refused(ascii_stl(square), Format::stl, "9: element 2 is inverted");
    expect_refused(binary_stl(square), Format::stl, "0: element 2 is inverted");
}

TEST(StlRead, DropsTrianglesWhoseCornersWeldAndNamesTrianglesAsTheFileDoes) {
    // triangle 2 is a sliver: two equal corners, and a third corner (9,9,9) no one else uses
    const std::vector<std::array<Point, 3>> with_sliver{
        tetrahedron_corners[0],
        {Point{1, 0, 0}, Point{1, 0, 0}, Point{9, 9, 9}},
        tetrahedron_corners[1],
        {Point{0, 0, 1}, Point{0, 0, 1}, Point{0, 0, 1}},
        tetrahedron_corners[2],
        tetrahedron_corners[3]};
    for (const std::string& bytes : {ascii_stl(with_sliver), binary_stl(with_sliver)}) {
        const Mesh mesh = read_bytes(bytes, Format::stl);
        EXPECT_EQ(mesh.vertex_count(), 4u);  // not (9,9,9)
        EXPECT_EQ(mesh.element_count(), 4u);
        EXPECT_EQ(mesh.boundary_face_count(), 0u);
        EXPECT_EQ(corner_triangles(mesh), corner_triangles(read_bytes(
                                              binary_stl(tetrahedron_corners), Format::stl)));
        EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    }
    // file numbering in messages: triangle 5 (the fourth kept) turned over meets triangle 3 (the
    // second kept) along the edge of vertices 3 (0,0,1) and 4 (0,0,0), numbered by first use
    std::vector<std::array<Point, 3>> turned = with_sliver;
    std::swap(turned[4][0], turned[4][1]);
    expect_refused(ascii_stl(turned), Format::stl,
                   "30: element 5 is oriented inconsistently with element 3 across face (3 4)");
    expect_refused(binary_stl(turned), Format::stl,
                   "0: element 5 is oriented inconsistently with element 3 across face (3 4)");
    // the report says what was dropped, and where the first one stands
    for (const auto& [bytes, first] :
         {std::pair{ascii_stl(with_sliver), std::string("s.stl:9: triangle 2 has two corners at one position")},
          std::pair{binary_stl(with_sliver), std::string("s.stl:0: triangle 2 has two corners at one position")}}) {
        std::istringstream in(bytes);
        ReadReport report;
        (void)read_mesh(in, Format::stl, "s.stl", {}, &report);
        EXPECT_EQ(report.dropped_triangles, 2u);
        EXPECT_EQ(report.first_dropped_triangle, first);
    }
    // nothing but slivers
    const std::vector<std::array<Point, 3>> slivers{with_sliver[1], with_sliver[3]};
    expect_refused(ascii_stl(slivers), Format::stl, "0: no triangles or tetrahedra");
}

TEST(StlRead, SeveralSolidsAndNamesAndIndentation) {
    std::string text = ascii_stl({tetrahedron_corners[0], tetrahedron_corners[1]});
    text += "solid second part\n" + ascii_facet(tetrahedron_corners[2]) +
            ascii_facet(tetrahedron_corners[3]) + "endsolid\n\n";
    text.replace(text.find("solid tetra"), 11, "  solid");
    const Mesh mesh = read_bytes(text, Format::stl);
    EXPECT_EQ(mesh.vertex_count(), 4u);
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_EQ(mesh.boundary_face_count(), 0u);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(StlRead, BinaryWhoseHeaderSaysSolid) {
    // many binary writers start the header with "solid": the size decides
    const Mesh mesh = read_bytes(binary_stl(tetrahedron_corners, "solid tetra"), Format::stl);
    EXPECT_EQ(mesh.vertex_count(), 4u);
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_TRUE(mesh.validate().ok());
}

// ---- PLY: round trips --------------------------------------------------------------------------

TEST(PlyRoundTrip, EveryEncodingGivesTheTrianglesBackBitForBit) {
    for (Encoding encoding : {Encoding::standard, Encoding::binary, Encoding::ascii}) {
        SCOPED_TRACE(std::string(to_string(encoding)));
        for (const Mesh& mesh : {tetrahedron_surface(), planar_triangles()})
            expect_same_mesh(mesh, write_then_read(mesh, "surface.ply", encoding), false);
        // a tetrahedral mesh: its boundary, vertices in their order (all five are on it)
        const Mesh tets = two_tetrahedra();
        const Mesh boundary = write_then_read(tets, "boundary.ply", encoding);
        EXPECT_EQ(test::position_bits(boundary), test::position_bits(tets));
        EXPECT_EQ(corner_triangles(boundary), corner_triangles(tets));
        std::vector<Simplex> expected, actual;
        for (FaceId f : tets.boundary_faces())
            expected.push_back(tets.face_simplex(f));
        for (ElementId t : elements(boundary))
            actual.push_back(boundary.simplex(t));
        std::sort(expected.begin(), expected.end());
        std::sort(actual.begin(), actual.end());
        EXPECT_EQ(expected, actual);
        EXPECT_TRUE(boundary.validate().ok());
    }
}

TEST(PlyRoundTrip, HeadersAsWritten) {
    const auto dir = scratch_dir();
    WriteOptions options;
    write_mesh(tetrahedron_surface(), dir / "b.ply", options);
    options.encoding = Encoding::ascii;
    write_mesh(tetrahedron_surface(), dir / "a.ply", options);
    const std::string body =
        "comment written by simplexkit\nelement vertex 4\nproperty double x\nproperty double "
        "y\nproperty double z\nelement face 4\nproperty list uchar int vertex_indices\n"
        "end_header\n";
    const std::string binary = file_bytes(dir / "b.ply");
    EXPECT_EQ(binary.substr(0, binary.size() - 4 * 24 - 4 * 13),
              "ply\nformat binary_little_endian 1.0\n" + body);
    const std::string ascii = file_bytes(dir / "a.ply");
    EXPECT_EQ(ascii.substr(0, ascii.find("end_header\n") + 11), "ply\nformat ascii 1.0\n" + body);
    EXPECT_EQ(ascii.substr(ascii.find("end_header\n") + 11, 12), "0 0 0\n1 0 0.");
}

// ---- PLY: reading what others write ---------------------------------------------------------------

// A header that uses every scalar type's names, x y z of three kinds, and elements and
// properties to skip before, between and after what is used.
const char* const busy_header =
    "ply\n"
    "format FORMAT 1.0\n"
    "comment made by tests/io/stl_ply.cpp\n"
    "obj_info anything at all\n"
    "element header_only 0\n"
    "property float unused\n"
    "element vertex 4\n"
    "property char a\n"
    "property float x\n"
    "property uchar b\n"
    "property double y\n"
    "property short c\n"
    "property int16 z\n"
    "property ushort d\n"
    "property list uint8 float32 e\n"
    "property int f\n"
    "property uint g\n"
    "element edge 2\n"
    "property int32 vertex1\n"
    "property uint32 vertex2\n"
    "property float64 length\n"
    "element face 4\n"
    "property uint16 flags\n"
    "property list int8 uint32 vertex_index\n"
    "property list int16 int8 texnumber\n"
    "property uint8 red\n"
    "element material 1\n"
    "property list uchar uchar name\n"
    "property int8 kind\n"
    "end_header\n";

std::string busy_ascii() {
    std::string header = busy_header;
    header.replace(header.find("FORMAT"), 6, "ascii");
    return header +
           "-1 0.5 200 -0 -3 -3 65535 2 0 1.5 -7 4000000000\n"
           "2 1.5 0 0 9 0 1 0 0 0\n"
           "3 0 0 1.25 1 2 3 1 7 8 9\n"
           "4 0 0 0 0 0 4 3 1 2 3 0 0\n"
           "0 1 0.5\n"
           "1 2 1e300\n"
           "0 3 1 2 3 0 255\n"
           "1 3 0 3 2 2 1 2 0\n"
           "2 3 0 1 3 1 -5 0\n"
           "3 3 0 2 1 0 9\n"
           "4 1 2 3 4 7\n";
}

std::string busy_binary(bool big) {
    std::string header = busy_header;
    header.replace(header.find("FORMAT"), 6, big ? "binary_big_endian" : "binary_little_endian");
    Bytes out{header, big};
    struct Vertex {
        float x;
        double y;
        std::int16_t z;
        std::uint8_t list;
    };
    const Vertex vertices[] = {{0.5f, -0.0, -3, 2}, {1.5f, 0, 0, 0}, {0, 1.25, 2, 1}, {0, 0, 0, 3}};
    for (const Vertex& v : vertices) {
        out.put(std::int8_t{-1}).put(v.x).put(std::uint8_t{200}).put(v.y).put(std::int16_t{-3});
        out.put(v.z).put(std::uint16_t{65535}).put(v.list);
        for (std::uint8_t i = 0; i < v.list; ++i)
            out.put(1.5f * i);
        out.put(std::int32_t{-7}).put(std::uint32_t{4000000000u});
    }
    for (int e = 0; e < 2; ++e)
        out.put(std::int32_t{0}).put(std::uint32_t{1}).put(1e300);
    const std::array<std::array<std::uint32_t, 3>, 4> faces{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
    for (std::size_t f = 0; f < 4; ++f) {
        out.put(std::uint16_t{7}).put(std::int8_t{3});
        for (std::uint32_t v : faces[f])
            out.put(v);
        out.put(static_cast<std::int16_t>(f));
        for (std::size_t i = 0; i < f; ++i)
            out.put(std::int8_t{-5});
        out.put(std::uint8_t{255});
    }
    out.put(std::uint8_t{4}).put(std::uint32_t{0x01020304}).put(std::int8_t{7});
    return out.data;
}

TEST(PlyRead, SkipsEveryOtherElementAndPropertyInEveryEncoding) {
    const Mesh expected = tetrahedron_surface();
    for (const std::string& bytes : {busy_ascii(), busy_binary(false), busy_binary(true)}) {
        const Mesh mesh = read_bytes(bytes, Format::ply);
        EXPECT_EQ(mesh.ambient_dimension(), 3);
        ASSERT_EQ(mesh.vertex_count(), 4u);
        EXPECT_EQ(bits(mesh.deformed(0)), bits(Point{0.5, -0.0, -3}));
        EXPECT_EQ(mesh.deformed(1), (Point{1.5, 0, 0}));
        EXPECT_EQ(mesh.deformed(2), (Point{0, 1.25, 2}));
        EXPECT_EQ(mesh.deformed(3), (Point{0, 0, 0}));
        ASSERT_EQ(mesh.element_count(), 4u);
        EXPECT_EQ(test::element_list(mesh), test::element_list(expected));
        EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    }
}

TEST(PlyRead, WithoutZIsPlanar) {
    const Mesh mesh = read_bytes(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0\n1 0\n0 1\n3 0 1 2\n",
        Format::ply);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_EQ(mesh.element_count(), 1u);
    EXPECT_TRUE(mesh.validate(ValidateOptions{true}).ok());
}

TEST(PlyRead, CrLfHeaderAndTrailingNewlineAfterBinaryData) {
    const std::string bytes = busy_binary(false);
    const std::size_t data = bytes.find("end_header\n") + 11;
    std::string crlf;
    for (char c : bytes.substr(0, data))
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const Mesh mesh = read_bytes(crlf + bytes.substr(data) + "\r\n", Format::ply);
    EXPECT_EQ(test::element_list(mesh), test::element_list(tetrahedron_surface()));
    EXPECT_TRUE(mesh.validate().ok());
}

// ---- the peers' files ---------------------------------------------------------------------------

TEST(PeerFiles, VtkAndMeshioFilesReadAsTheSameSphere) {
    // the sphere's points are floats (vtkSphereSource), so every encoding holds them exactly and
    // all nine files are the same surface, bit for bit
    const std::vector<CornerTriangle> sphere =
        corner_triangles(read_mesh(data_file("io/vtk_sphere_binary.stl")));
    ASSERT_EQ(sphere.size(), 24u);
    for (const char* name :
         {"vtk_sphere_binary.stl", "vtk_sphere_ascii.stl", "meshio_sphere_binary.stl",
          "meshio_sphere_ascii.stl", "vtk_sphere_binary.ply", "vtk_sphere_big_endian.ply",
          "vtk_sphere_ascii.ply", "meshio_sphere_binary.ply", "meshio_sphere_ascii.ply"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = read_mesh(data_file(std::string("io/") + name));
        EXPECT_EQ(mesh.topological_dimension(), 2);
        EXPECT_EQ(mesh.ambient_dimension(), 3);
        EXPECT_EQ(mesh.vertex_count(), 14u);
        EXPECT_EQ(mesh.element_count(), 24u);
        EXPECT_EQ(mesh.boundary_face_count(), 0u);  // closed
        EXPECT_EQ(corner_triangles(mesh), sphere);
        EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    }
}

// ---- malformed files -----------------------------------------------------------------------------

TEST(StlMalformed, BinarySizesAndValues) {
    const std::string good = binary_stl(tetrahedron_corners);
    expect_refused(good.substr(0, good.size() - 10), Format::stl,
                   "0: truncated file: the header declares 4 triangles (284 bytes), found 274 "
                   "bytes");
    expect_refused(binary_stl(tetrahedron_corners, "solid", 1000), Format::stl,
                   "0: truncated file: the header declares 1000 triangles (50084 bytes), found "
                   "284 bytes");
    expect_refused(binary_stl(tetrahedron_corners, "x", 2), Format::stl,
                   "0: the header declares 2 triangles (184 bytes), found 284 bytes");
    expect_refused(good.substr(0, 40), Format::stl,
                   "0: truncated file: a binary STL starts with 84 bytes of header and count, "
                   "found 40 bytes");
    for (double bad : {std::numeric_limits<double>::quiet_NaN(),
                       -std::numeric_limits<double>::infinity()}) {
        std::vector<std::array<Point, 3>> triangles = tetrahedron_corners;
        triangles[2][1][2] = bad;
        expect_refused(binary_stl(triangles), Format::stl,
                       "0: triangle 3: coordinate is not finite");
    }
}

TEST(StlMalformed, AsciiStructure) {
    const std::string good = ascii_stl(tetrahedron_corners);
    auto with = [&](const std::string& from, const std::string& to, std::size_t nth = 0) {
        std::string text = good;
        std::size_t at = text.find(from);
        for (std::size_t i = 0; i < nth; ++i)
            at = text.find(from, at + 1);
        return text.replace(at, from.size(), to);
    };
    expect_refused("facet normal 0 0 1\n", Format::stl, "1: expected solid, found 'facet'");
    expect_refused(with("endsolid tetra\n", ""), Format::stl,
                   "29: truncated file: expected endsolid");
    expect_refused(with("    endloop\n", "      vertex 1 1 1\n    endloop\n", 1), Format::stl,
                   "14: facet 2 has 4 vertices: only triangles are supported (triangulate the "
                   "polygons first)");
    expect_refused(with("      vertex 0 1 0\n", ""), Format::stl,
                   "6: facet 1 has 2 vertices: a facet needs 3");
    expect_refused(with("vertex 0 0 1", "vertex 0 0 nan"), Format::stl,
                   "6: coordinate is not finite");
    expect_refused(with("vertex 0 0 1", "vertex 0 0 1e999"), Format::stl,
                   "6: coordinate is not finite");
    expect_refused(with("vertex 0 0 1", "vertex 0 0"), Format::stl, "6: missing z coordinate");
    expect_refused(with("vertex 0 0 1", "vertex 0 0 1 1"), Format::stl,
                   "6: unexpected value '1' at the end of the line");
    expect_refused(with("outer loop", "loop"), Format::stl,
                   "3: expected outer loop, found 'loop'");
    expect_refused(with("facet normal 0 0 0", "facet 0 0 0"), Format::stl,
                   "2: expected normal, found '0'");
    expect_refused(with("  endfacet\n", "", 3), Format::stl,
                   "29: expected endfacet, found 'endsolid'");
    expect_refused(with("facet normal", "face normal", 1), Format::stl,
                   "9: expected facet or endsolid, found 'face'");
    expect_refused(good + "extra\n", Format::stl, "31: expected solid, found 'extra'");
    // a byte that cannot be text in what starts as ASCII, as check_text names it
    expect_refused(with("vertex 0 0 1", std::string("vertex 0 0 \x01")), Format::stl,
                   "6: binary data (byte 0x01)");
    expect_refused("solid\n\x01", Format::stl, "2: binary data (byte 0x01)");
}

std::string triangle_ply(const std::string& format, const std::string& data,
                         const std::string& face = "property list uchar int vertex_indices\n") {
    return "ply\nformat " + format +
           " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\n" +
           face + "end_header\n" + data;
}

TEST(PlyMalformed, Header) {
    expect_refused("PLY\n", Format::ply, "1: expected ply, found 'PLY'");
    expect_refused(triangle_ply("binary", ""), Format::ply,
                   "2: unknown PLY format 'binary' (ascii, binary_little_endian and "
                   "binary_big_endian are supported)");
    std::string text = triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expect_refused(std::string(text).replace(text.find("1.0"), 3, "2.0"), Format::ply,
                   "2: unsupported PLY version '2.0' (1.0 is supported)");
    expect_refused(std::string(text).replace(text.find("float y"), 5, "real"), Format::ply,
                   "5: unknown property type 'real'");
    expect_refused(std::string(text).replace(text.find("property float z"), 16, "elements 2"),
                   Format::ply, "6: unknown keyword 'elements'");
    expect_refused(std::string(text).replace(text.find("property float x"), 16, "property float w"),
                   Format::ply, "3: element vertex has no property x");
    expect_refused(std::string(text).replace(text.find("vertex_indices"), 14, "corners"),
                   Format::ply, "7: element face has no property vertex_indices");
    expect_refused(std::string(text).replace(text.find("format ascii 1.0\n"), 17, ""),
                   Format::ply, "8: the header has no format line");
    const std::string header = triangle_ply("ascii", "");
    expect_refused(std::string(header).replace(header.find("end_header"), 10, "comment"),
                   Format::ply, "9: truncated file: expected end_header");
    expect_refused(std::string(text).replace(text.find("list uchar int"), 14, "list float int"),
                   Format::ply, "8: a list count must have an integer type");
    expect_refused(std::string(text).replace(text.find("list uchar int"), 14, "list uchar float"),
                   Format::ply, "8: vertex indices must have an integer type");
    expect_refused(std::string(text).replace(text.find("element vertex 3"), 16,
                                             "element vertex -3"),
                   Format::ply, "3: number of vertex elements out of range: '-3'");
    expect_refused(std::string(text).replace(text.find(" 1.0\n") + 4, 0, " x"), Format::ply,
                   "2: unexpected value 'x' at the end of the line");
    expect_refused(triangle_ply("binary_little_endian", "", std::string("comment \0\n", 10)),
                   Format::ply, "8: binary data (byte 0x00)");
}

TEST(PlyMalformed, AsciiData) {
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 0\n"), Format::ply,
                   "13: face 1 has 4 vertices: only triangles are supported (triangulate the "
                   "polygons first)");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), Format::ply,
                   "13: face 1 has 2 vertices: a face needs 3");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), Format::ply,
                   "13: vertex index 3 out of range (0..2)");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"), Format::ply,
                   "13: vertex index -1 out of range (0..2)");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"), Format::ply,
                   "11: coordinate is not finite");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0\n0 1 0\n3 0 1 2\n"), Format::ply,
                   "11: missing value of property z");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n"), Format::ply,
                   "12: truncated file: the header declares 1 face elements, found 0");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n"),
                   Format::ply, "14: more data than the header declares");
    expect_refused(triangle_ply("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n"), Format::ply,
                   "13: element 1 has a repeated vertex");
    expect_refused("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                   "end_header\n3 0 1 2\n",
                   Format::ply, "6: vertex index 0 out of range (there are no vertices)");
}

TEST(PlyMalformed, BinaryData) {
    auto file = [](bool big, std::uint8_t corners, std::int32_t last, float y,
                   const char* count_type = "uchar") {
        Bytes out{triangle_ply(big ? "binary_big_endian" : "binary_little_endian", "",
                               std::string("property list ") + count_type +
                                   " int vertex_indices\n"),
                  big};
        for (const Point& p : {Point{0, 0, 0}, Point{1, y, 0}, Point{0, 1, 0}})
            out.put(static_cast<float>(p[0])).put(static_cast<float>(p[1])).put(static_cast<float>(p[2]));
        out.put(corners).put(std::int32_t{0}).put(std::int32_t{1}).put(last);
        for (int extra = 3; extra < corners; ++extra)
            out.put(std::int32_t{0});
        return out.data;
    };
    for (bool big : {false, true}) {
        ASSERT_EQ(read_bytes(file(big, 3, 2, 0), Format::ply).element_count(), 1u);
        expect_refused(file(big, 4, 2, 0), Format::ply,
                       "0: face 1 has 4 vertices: only triangles are supported (triangulate the "
                       "polygons first)");
        expect_refused(file(big, 3, 3, 0), Format::ply,
                       "0: face 1: vertex index 3 out of range (0..2)");
        expect_refused(file(big, 3, 2, std::numeric_limits<float>::infinity()), Format::ply,
                       "0: vertex 1: coordinate is not finite");
        const std::string good = file(big, 3, 2, 0);
        const std::size_t data = good.size() - 36 - 13;
        expect_refused(good.substr(0, data + 20), Format::ply,
                       "0: truncated file: the header declares 3 vertex elements, found 1");
        expect_refused(good.substr(0, good.size() - 1), Format::ply,
                       "0: truncated file: the header declares 1 face elements, found 0");
        expect_refused(good + "\n\n  x", Format::ply,
                       "0: more data than the header declares (5 bytes left)");
        EXPECT_EQ(read_bytes(good + "\n\n", Format::ply).element_count(), 1u);
        expect_refused(file(big, 255, 2, 0, "char"), Format::ply,
                       "0: face 1: list length out of range: -1");
        EXPECT_EQ(read_bytes(file(big, 3, 2, 0, "int8"), Format::ply).element_count(), 1u);
    }
}

TEST(PlyMalformed, CountsBeyondTheDataAllocateNothingFirst) {
    // 4294967294 vertices of 12 bytes would be 51 GB: only what the data can hold is reserved,
    // and the read stops where the data does
    const std::string huge = "ply\nformat binary_little_endian 1.0\nelement vertex 4294967294\n"
                             "property float x\nproperty float y\nproperty float z\nend_header\n";
    expect_refused(huge + std::string(30, '\0'), Format::ply,
                   "0: truncated file: the header declares 4294967294 vertex elements, found 2");
    expect_refused("ply\nformat ascii 1.0\nelement vertex 4294967294\nproperty float x\n"
                   "property float y\nend_header\n0 0\n",
                   Format::ply,
                   "7: truncated file: the header declares 4294967294 vertex elements, found 1");
    expect_refused("ply\nformat ascii 1.0\nelement vertex 4294967295\nproperty float x\n",
                   Format::ply, "3: number of vertex elements out of range: '4294967295'");
    // a skipped element, of fixed size and with a list
    expect_refused("ply\nformat binary_big_endian 1.0\nelement junk 9223372036854775807\n"
                   "property double a\nend_header\n" + std::string(100, '\0'),
                   Format::ply,
                   "0: truncated file: the header declares 9223372036854775807 junk elements, "
                   "found 12");
    expect_refused("ply\nformat binary_little_endian 1.0\nelement junk 2\n"
                   "property list uint int a\nend_header\n\xFF\xFF\xFF\xFF\0\0\0\0",
                   Format::ply, "0: truncated file: the header declares 2 junk elements, found 0");
}

}  // namespace
}  // namespace sxk
