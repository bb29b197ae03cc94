// VTK XML (.vtu) and legacy (.vtk) files: round trips in every encoding, the cells and data the
// writers put in (faces as cells, pieces, displacement, active scalars), files written by VTK
// 9.1 and meshio 5.0 (tests/data/io/peer_*, made by make_vtk_peers.py), and malformed files.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "io_fixtures.hpp"
#include "sxk/io.hpp"

namespace sxk {
namespace {

using test::expect_same_mesh;
using test::file_bytes;
using test::scratch_dir;

std::string written(const Mesh& mesh, const std::string& name, Encoding encoding,
                    bool quality = true) {
    const auto path = scratch_dir() / name;
    WriteOptions options;
    options.encoding = encoding;
    options.quality_cell_data = quality;
    write_mesh(mesh, path, options);
    return file_bytes(path);
}

Mesh read_text(const std::string& text, Format format, const std::string& name) {
    std::istringstream in(text);
    return read_mesh(in, format, name);
}

std::string read_error(const std::string& text, Format format, const std::string& name) {
    try {
        (void)read_text(text, format, name);
    } catch (const InputError& error) {
        return error.what();
    }
    return "read without error";
}

constexpr Encoding encodings[] = {Encoding::standard, Encoding::ascii, Encoding::binary};

TEST(VtkFormats, RoundTripsInEveryEncoding) {
    const Mesh meshes[] = {test::two_tetrahedra(), test::planar_triangles(),
                           test::tetrahedron_surface()};
    for (const Mesh& mesh : meshes)
        for (const char* extension : {".vtu", ".vtk"})
            for (Encoding encoding : encodings) {
                SCOPED_TRACE(std::string(extension) + " " + std::string(to_string(encoding)));
                const auto path = scratch_dir() / (std::string("m") + extension);
                WriteOptions options;
                options.encoding = encoding;
                write_mesh(mesh, path, options);
                expect_same_mesh(mesh, read_mesh(path));
            }
}

TEST(VtkFormats, EncodingsAreWhatTheirNamesSay) {
    const Mesh mesh = test::two_tetrahedra();
    const std::string standard = written(mesh, "s.vtu", Encoding::standard);
    EXPECT_NE(standard.find("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\""),
              std::string::npos);
    EXPECT_NE(standard.find("<AppendedData encoding=\"raw\">\n   _"), std::string::npos);
    const std::string binary = written(mesh, "b.vtu", Encoding::binary);
    EXPECT_EQ(binary.find("compressor"), std::string::npos);
    // the appended arrays in the reverse of the document's order, for meshio (vtu.cpp finish)
    EXPECT_NE(binary.find("Name=\"types\" format=\"appended\" offset=\"0\"/>"), std::string::npos);
    EXPECT_NE(binary.find("Name=\"label\" format=\"appended\" offset=\""), std::string::npos);
    const std::string ascii = written(mesh, "a.vtu", Encoding::ascii);
    EXPECT_EQ(ascii.find("AppendedData"), std::string::npos);
    EXPECT_EQ(ascii.find("format=\"appended\""), std::string::npos);
    EXPECT_EQ(written(mesh, "a.vtk", Encoding::standard).substr(0, 55),
              "# vtk DataFile Version 4.2\nwritten by simplexkit\nASCII\n");
    EXPECT_EQ(written(mesh, "b.vtk", Encoding::binary).substr(0, 56),
              "# vtk DataFile Version 4.2\nwritten by simplexkit\nBINARY\n");
}

TEST(VtkFormats, FacesAreCellsWithTheirLabels) {
    const Mesh mesh = test::two_tetrahedra();
    const std::string vtu = written(mesh, "two.vtu", Encoding::ascii);
    // 2 tetrahedra, then the 2 labelled triangles sorted: interface {0,1,2} (label 5), boundary
    // {0,1,3} outward (label 7)
    EXPECT_NE(vtu.find("NumberOfPoints=\"5\" NumberOfCells=\"4\""), std::string::npos);
    EXPECT_NE(vtu.find(">\n          0 1 2 3\n          1 0 2 4\n          0 1 2\n          0 1 3\n"),
              std::string::npos)
        << vtu;
    EXPECT_NE(vtu.find("Name=\"types\" format=\"ascii\">\n          10\n          10\n          5\n"
                       "          5\n"),
              std::string::npos);
    EXPECT_NE(vtu.find("Name=\"label\" format=\"ascii\">\n          1\n          2\n          5\n"
                       "          7\n"),
              std::string::npos);
    EXPECT_NE(vtu.find("Name=\"piece\" format=\"ascii\">\n          0\n          0\n          0\n"
                       "          0\n"),
              std::string::npos);
    // quality in degrees, NaN for the faces
    EXPECT_NE(vtu.find("Name=\"min_angle_deg\""), std::string::npos);
    EXPECT_EQ(vtu.find("\"min_angle\""), std::string::npos);
    EXPECT_NE(vtu.find("          nan\n          nan\n        </DataArray>"), std::string::npos);
    // the labels differ and there is one piece: coloured by label
    EXPECT_NE(vtu.find("<CellData Scalars=\"label\">"), std::string::npos);
    EXPECT_EQ(vtu.find("displacement"), std::string::npos);

    const std::string vtk = written(mesh, "two.vtk", Encoding::ascii);
    EXPECT_NE(vtk.find("CELLS 4 18\n4 0 1 2 3\n4 1 0 2 4\n3 0 1 2\n3 0 1 3\nCELL_TYPES 4\n10\n10\n5\n5\n"
                       "CELL_DATA 4\nSCALARS label int 1\nLOOKUP_TABLE default\n1\n2\n5\n7\n"
                       "FIELD FieldData 4\npiece 1 4 int\n0\n0\n0\n0\naspect_ratio 1 4 double\n"),
              std::string::npos)
        << vtk;
    // VTK's legacy ASCII reader cannot read "nan": the faces' quality is -1 there
    EXPECT_NE(vtk.find("\n-1\n-1\nradius_ratio 1 4 double\n"),
              std::string::npos)
        << vtk;

    const Mesh planar = test::planar_triangles();
    const std::string lines = written(planar, "planar.vtu", Encoding::ascii);
    EXPECT_NE(lines.find("Name=\"types\" format=\"ascii\">\n          5\n          5\n          5\n"
                         "          3\n          3\n"),
              std::string::npos);
}

TEST(VtkFormats, ActiveScalarsShowSomething) {
    // two tetrahedra apart: two pieces
    Mesh apart(3, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1},
                           Point{5, 0, 0}, Point{6, 0, 0}, Point{5, 1, 0}, Point{5, 0, 1}})
        apart.add_vertex(p);
    const Simplex two[] = {Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {4, 5, 6, 7})};
    ASSERT_TRUE(apart.assign_elements(two).ok());
    const std::string vtu = written(apart, "apart.vtu", Encoding::ascii);
    EXPECT_NE(vtu.find("<CellData Scalars=\"piece\">"), std::string::npos);
    EXPECT_NE(vtu.find("Name=\"piece\" format=\"ascii\">\n          0\n          1\n"),
              std::string::npos);
    EXPECT_NE(written(apart, "apart.vtk", Encoding::ascii).find("SCALARS piece int 1\n"),
              std::string::npos);

    // one piece, one label: the quality; without quality, the label
    const Mesh one = test::tetrahedron_surface();
    EXPECT_NE(written(one, "one.vtu", Encoding::ascii).find("<CellData Scalars=\"min_angle_deg\">"),
              std::string::npos);
    EXPECT_NE(written(one, "one.vtk", Encoding::ascii).find("SCALARS min_angle_deg double 1\n"),
              std::string::npos);
    const std::string plain = written(one, "plain.vtu", Encoding::ascii, false);
    EXPECT_NE(plain.find("<CellData Scalars=\"label\">"), std::string::npos);
    EXPECT_EQ(plain.find("aspect_ratio"), std::string::npos);
    EXPECT_TRUE(apart.validate().ok());
}

TEST(VtkFormats, DisplacementWhenTheMeshMoved) {
    Mesh mesh = test::two_tetrahedra();
    const Point moved{0.2, 1.0 / 3.0, 1.5};
    const Point reference = mesh.reference(3);
    mesh.set_deformed(3, moved);
    const std::string vtu = written(mesh, "moved.vtu", Encoding::ascii);
    EXPECT_NE(vtu.find("<PointData Vectors=\"displacement\">\n        <DataArray type=\"Float64\" "
                       "Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n"
                       "          0 0 0\n          0 0 0\n          0 0 0\n          0 0 "),
              std::string::npos)
        << vtu;
    std::string expected_z;
    {
        std::ostringstream text;
        text.precision(17);
        text << moved[2] - reference[2];
        expected_z = text.str();
    }
    EXPECT_NE(vtu.find("          0 0 " + expected_z + "\n"), std::string::npos) << expected_z;
    const std::string vtk = written(mesh, "moved.vtk", Encoding::ascii);
    EXPECT_NE(vtk.find("POINT_DATA 5\nVECTORS displacement double\n0 0 0\n"), std::string::npos);
    // read back: the positions written are the mesh's (deformed) positions
    const Mesh again = read_text(vtu, Format::vtu, "moved.vtu");
    EXPECT_EQ(again.deformed(3), moved);
    EXPECT_TRUE(again.validate().ok());
    mesh.set_deformed(3, reference);
    EXPECT_EQ(written(mesh, "still.vtu", Encoding::ascii).find("displacement"), std::string::npos);
    EXPECT_TRUE(mesh.validate().ok());
}

// ---- files written by VTK 9.1 and meshio 5.0 ----------------------------------------------------

TEST(VtkFormats, ReadsWhatVtkAndMeshioWrite) {
    for (const char* name :
         {"peer_vtk_ascii.vtu", "peer_vtk_binary_zlib.vtu", "peer_vtk_binary.vtu",
          "peer_vtk_default.vtu", "peer_vtk_base64_float.vtu", "peer_vtk_raw.vtu", "peer_vtk_raw_zlib_big.vtu",
          "peer_vtk_ascii.vtk", "peer_vtk_binary.vtk", "peer_vtk42_ascii.vtk",
          "peer_vtk42_binary.vtk", "peer_meshio_ascii.vtu", "peer_meshio_zlib.vtu",
          "peer_meshio_binary.vtu", "peer_meshio_ascii.vtk", "peer_meshio_binary.vtk"}) {
        SCOPED_TRACE(name);
        Mesh mesh(3, 3);
        try {
            mesh = read_mesh(test::data_file(std::string("io/") + name));
        } catch (const InputError& error) {
            ADD_FAILURE() << error.what();
            continue;
        }
        EXPECT_EQ(mesh.vertex_count(), 5u);
        EXPECT_EQ(mesh.element_count(), 2u);
        EXPECT_EQ(mesh.deformed(4), (Point{0, 0, -1}));
        const std::vector<std::pair<Simplex, int>> elements{{Simplex(+1, {0, 1, 2, 3}), 1},
                                                           {Simplex(+1, {1, 0, 2, 4}), 2}};
        std::vector<std::pair<Simplex, int>> expected = elements;
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(test::element_list(mesh), expected);
        const std::vector<std::pair<Simplex, int>> faces{{Simplex(+1, {0, 1, 3}), 7}};
        EXPECT_EQ(test::face_label_list(mesh), faces);
        EXPECT_TRUE(mesh.validate().ok());
    }
}

// ---- malformed files ----------------------------------------------------------------------------

// One triangle in ASCII; the parts a test changes are arguments.
std::string triangle_vtu(const std::string& points = "format=\"ascii\">0 0 0 1 0 0 0 1 0",
                         const std::string& types = "5", const std::string& root = "",
                         const std::string& tail = "") {
    return "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\"" + root +
           ">\n<UnstructuredGrid><Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n"
           "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" " + points +
           "</DataArray></Points>\n"
           "<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n"
           "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray>\n"
           "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + types +
           "</DataArray></Cells>\n</Piece></UnstructuredGrid>" + tail + "</VTKFile>\n";
}

TEST(VtkFormats, TheTriangleTemplateReads) {
    const Mesh mesh = read_text(triangle_vtu(), Format::vtu, "x.vtu");
    EXPECT_EQ(mesh.element_count(), 1u);
    EXPECT_EQ(mesh.ambient_dimension(), 2);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(VtkFormats, MalformedVtu) {
    const auto error = [](const std::string& text) { return read_error(text, Format::vtu, "x.vtu"); };
    EXPECT_EQ(error(triangle_vtu("format=\"ascii\">0 0 0 1 0 0 0 1", "5")),
              "x.vtu:4: DataArray 'Points' holds 8 values, 9 expected");
    EXPECT_EQ(error(triangle_vtu("format=\"ascii\">0 0 0 1 0 0 0 1 nan", "5")),
              "x.vtu:4: DataArray 'Points': coordinate is not finite");
    EXPECT_EQ(error(triangle_vtu(std::string("format=\"ascii\">0 0 0 1 0 0 0 1 0"), "12")),
              "x.vtu:7: cell 0 has VTK type 12 (hexahedron); only simplexes (tetrahedra, "
              "triangles, lines, vertices) are read");
    EXPECT_EQ(error(triangle_vtu("format=\"binary\">SAAAAA")),
              "x.vtu:4: DataArray 'Points': truncated base64 data");
    EXPECT_EQ(error(triangle_vtu("format=\"binary\">SAAA!AAA")),
              "x.vtu:4: DataArray 'Points': invalid base64 character '!'");
    // a header of 1 block of 72 bytes compressed to 4, and 4 bytes that are not zlib
    EXPECT_EQ(error(triangle_vtu("format=\"binary\">AQAAAEgAAABIAAAABAAAAA==eHh4eA==", "5",
                                 " compressor=\"vtkZLibDataCompressor\"")),
              "x.vtu:4: DataArray 'Points': block 1 of 1 is not valid zlib data");
    // 100,000 zero bytes (120 compressed) declared as 72: inflating stops at 72
    EXPECT_EQ(error(triangle_vtu(
                  "format=\"binary\">AQAAAEgAAABIAAAAeAAAAA==eJztwTEBAAAAwqD1T20ND6AAAAAAAAAAAAAAA"
                  "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA"
                  "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAACAVwOGrwAB",
                  "5", " compressor=\"vtkZLibDataCompressor\"")),
              "x.vtu:4: DataArray 'Points': block 1 of 1 inflates to more than its declared 72 "
              "bytes");
    // a header that matches a point count of 89,478,485 with 2 GB from 20 compressed bytes:
    // refused before anything is allocated
    std::string bomb = triangle_vtu("format=\"binary\">AQAAAPj//38AAAAAFAAAAA==AAAAAAAAAAAAAAAAAAAAAAAAAAA=",
                                    "5", " compressor=\"vtkZLibDataCompressor\"");
    bomb.replace(bomb.find("NumberOfPoints=\"3\""), 18, "NumberOfPoints=\"89478485\"");
    EXPECT_EQ(error(bomb), "x.vtu:4: DataArray 'Points': block 1 declares 2147483640 bytes from "
                           "20 compressed, more than zlib can expand");
    // more data declared than the file holds (raw appended, UInt32 header: 72 bytes declared);
    // raw data has no end but the file's, so the 11 bytes of "</VTKFile>\n" count too
    const std::string raw_tail = std::string("<AppendedData encoding=\"raw\">_") +
                                 std::string("\x48\0\0\0", 4) + std::string(10, '\0');
    EXPECT_EQ(error(triangle_vtu("format=\"appended\" offset=\"0\">", "5", "", raw_tail)),
              "x.vtu:4: DataArray 'Points': header declares 72 bytes but only 21 remain");
    EXPECT_EQ(error(triangle_vtu("format=\"appended\" offset=\"900\">", "5", "", raw_tail)),
              "x.vtu:4: DataArray 'Points' offset 900 is beyond the 25 bytes of appended data");
    EXPECT_EQ(error(triangle_vtu("format=\"appended\" offset=\"0\">", "5")),
              "x.vtu:4: DataArray 'Points' is appended but the file has no AppendedData");
    std::string pieces = triangle_vtu();
    pieces.replace(pieces.find("</UnstructuredGrid>"), 0,
                   "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"/>");
    EXPECT_EQ(error(pieces), "x.vtu:3: the file holds 2 pieces; only files of one piece are read");
    std::string outside = triangle_vtu();
    outside.replace(outside.find(">0 1 2<"), 7, ">0 1 3<");
    EXPECT_EQ(error(outside), "x.vtu:5: cell 0 refers to point 3; the file has 3 points");
    // cells are numbered from 0 in every message, as ParaView numbers them
    std::string inverted = triangle_vtu();
    inverted.replace(inverted.find(">0 1 2<"), 7, ">0 2 1<");
    EXPECT_EQ(error(inverted), "x.vtu:5: element 0 is inverted");
    std::string polydata = triangle_vtu();
    polydata.replace(polydata.find("UnstructuredGrid\" "), 16, "PolyData");
    EXPECT_EQ(error(polydata),
              "x.vtu:2: VTKFile type 'PolyData' is not read; only UnstructuredGrid");
    EXPECT_EQ(error(triangle_vtu("format=\"ascii\">0 0 0 1 0 0 0 1 0", "5",
                                 " compressor=\"vtkLZ4DataCompressor\"")),
              "x.vtu:2: compressor 'vtkLZ4DataCompressor' is not supported (only "
              "vtkZLibDataCompressor)");
    // a compression header whose blocks hold 2 x 72 bytes for an array of 72
    EXPECT_EQ(error(triangle_vtu("format=\"binary\">AgAAAEgAAABIAAAABAAAAAQAAAA=", "5",
                                 " compressor=\"vtkZLibDataCompressor\"")),
              "x.vtu:4: DataArray 'Points': compression header declares 144 bytes, 72 expected");
    EXPECT_EQ(error("<VTKFile type=\"UnstructuredGrid\"><Unstructured"),
              "x.vtu:1: XML error: Error parsing start element tag");
}

TEST(VtkFormats, MalformedVtk) {
    const auto error = [](const std::string& text) { return read_error(text, Format::vtk, "x.vtk"); };
    const std::string head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    const std::string triangle = head + "POINTS 3 double\n0 0 0 1 0 0 0 1 0\n";
    EXPECT_EQ(read_text(triangle + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n", Format::vtk, "x.vtk")
                  .element_count(),
              1u);
    EXPECT_EQ(error("# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n"),
              "x.vtk:4: DATASET 'POLYDATA' is not read; only UNSTRUCTURED_GRID");
    EXPECT_EQ(error("hello\n"),
              "x.vtk:1: not a legacy VTK file: the first line is not '# vtk DataFile Version x.y'");
    EXPECT_EQ(error(triangle + "CELLS 1 5\n3 0 1 2 0\nCELL_TYPES 1\n5\n"),
              "x.vtk:7: CELLS declares 5 values but its 1 cells use 4");
    EXPECT_EQ(error(triangle + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n12\n"),
              "x.vtk:9: cell 0 has VTK type 12 (hexahedron); only simplexes (tetrahedra, "
              "triangles, lines, vertices) are read");
    EXPECT_EQ(error(triangle + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\nCELL_DATA 1\nSCALARS label int\n"),
              "x.vtk:12: truncated file: expected an integer");
    EXPECT_EQ(error(triangle + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\nBOGUS 1\n"),
              "x.vtk:11: unknown keyword 'BOGUS'");
    const std::string layout51 = triangle + "CELLS 2 3\nOFFSETS vtktypeint64\n1 3\n";
    EXPECT_EQ(error(layout51), "x.vtk:8: OFFSETS starts at 1, not 0");
    const std::string binary_head =
        "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n";
    EXPECT_EQ(error(binary_head + std::string(10, '\0')),
              "x.vtk:5: POINTS declares 9 values but only 10 bytes remain");
    // labels past POINT_DATA's arrays, in both encodings
    const Mesh labelled = read_text(triangle + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n"
                                    "POINT_DATA 3\nSCALARS label int 1\nLOOKUP_TABLE default\n4 4 4\n"
                                    "VECTORS v float\n0 0 0 0 0 0 0 0 0\n"
                                    "CELL_DATA 1\nFIELD FieldData 2\nother 2 1 double\n1.5 nan\n"
                                    "medit:ref 1 1 float\n3\n",
                                    Format::vtk, "x.vtk");
    ASSERT_EQ(labelled.element_count(), 1u);
    EXPECT_EQ(labelled.label(*elements(labelled).begin()), 3);
}

}  // namespace
}  // namespace sxk
