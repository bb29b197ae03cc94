// The oracle every reader's fuzz target shares (CONTRIBUTING.md "Tests": the fuzzers use the validator as their oracle).
//
// For any input a reader must either throw InputError or return a mesh that
//   1. passes Mesh::validate(),
//   2. has no negatively oriented element where orientation is defined (it reorients or refuses),
//   3. reads the same with and without ReadOptions::reorient when nothing had to be flipped, and
//   4. survives write -> read in its own format unchanged: same dimensions, elements, labels,
//      face labels and positions bit for bit (this checks the writers too).
// Anything else (another exception, a crash, a sanitizer report, a broken rule) is a finding:
// the oracle prints what broke and aborts, which libFuzzer and the replay driver both report.
#pragma once

#include <unistd.h>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sxk/io.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"

namespace sxk::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz oracle: %s\n", what.c_str());
    std::abort();
}

using Reader = std::function<Mesh(const ReadOptions&, ReadReport*)>;

inline std::optional<Mesh> try_read(const Reader& read, const ReadOptions& options,
                                    ReadReport* report) {
    try {
        return read(options, report);
    } catch (const InputError& error) {
        // the message must name a line within reason and a non-empty reason
        if (error.reason().empty())
            finding("InputError without a reason");
        return std::nullopt;
    }
}

inline std::vector<std::pair<Simplex, int>> element_list(const Mesh& mesh) {
    std::vector<std::pair<Simplex, int>> list;
    for (ElementId t : elements(mesh))
        list.emplace_back(mesh.simplex(t), mesh.label(t));
    std::sort(list.begin(), list.end());
    return list;
}

inline bool same_mesh(const Mesh& a, const Mesh& b) {
    if (a.topological_dimension() != b.topological_dimension() ||
        a.ambient_dimension() != b.ambient_dimension() || a.vertex_count() != b.vertex_count())
        return false;
    for (VertexId v = 0; v < a.vertex_count(); ++v)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::bit_cast<std::uint64_t>(a.deformed(v)[c]) !=
                std::bit_cast<std::uint64_t>(b.deformed(v)[c]))
                return false;
    return element_list(a) == element_list(b) && a.face_labels() == b.face_labels();
}

inline void check_mesh(const Mesh& mesh) {
    if (const auto valid = mesh.validate(); !valid)
        finding("invalid mesh returned: " + valid.reason());
    if (mesh.topological_dimension() == mesh.ambient_dimension())
        for (ElementId t : elements(mesh))
            if (element_orientation(mesh, t) == Sign::negative)
                finding("inverted element " + std::to_string(t) + " returned");
}

inline std::optional<Mesh> write_and_read(const Mesh& mesh, const std::filesystem::path& path,
                                          const WriteOptions& options, bool reorient) {
    try {
        write_mesh(mesh, path, options);
    } catch (const OutputError& error) {
        finding(std::string("cannot write what was read: ") + error.what());
    }
    ReadOptions read_options;
    read_options.reorient = reorient;
    try {
        return read_mesh(path, read_options);
    } catch (const InputError&) {
        return std::nullopt;
    }
}

inline bool all_z_zero(const Mesh& mesh) {
    for (const Point& p : mesh.deformed_positions())
        if (p[2] != 0.0)
            return false;
    return true;
}

// The positions of each triangle's corners (a tetrahedral mesh: of each boundary face,
// outward), as bit patterns, each triangle turned to start at its smallest corner, sorted; with
// `to_float` every coordinate rounded to float first. Equal lists are the same surface whatever
// the vertex numbering, which STL does not keep (its reader numbers vertices by first use).
using CornerTriangle = std::array<std::array<std::uint64_t, 3>, 3>;
// x rounded to float and back, through a volatile: GCC 12.2 at -O2 was seen to drop a plain
// `(double)(float)x` over a copied Point (tests/io/stl_ply.cpp, float_rounded).
inline double float_rounded(double x) {
    volatile float rounded = static_cast<float>(x);
    return rounded;
}
inline std::vector<CornerTriangle> corner_triangles(const Mesh& mesh, bool to_float) {
    std::vector<Simplex> triangles;
    if (mesh.topological_dimension() == 2)
        for (ElementId t : elements(mesh))
            triangles.push_back(mesh.simplex(t));
    else
        for (FaceId f : mesh.boundary_faces())
            triangles.push_back(mesh.face_simplex(f));
    std::vector<CornerTriangle> list;
    for (const Simplex& s : triangles) {
        std::array<VertexId, 3> v{s.vertex(0), s.vertex(1), s.vertex(2)};
        if (s.sign() < 0)
            std::swap(v[0], v[1]);
        CornerTriangle t;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t c = 0; c < 3; ++c) {
                const double x = mesh.deformed(v[i])[c];
                t[i][c] = std::bit_cast<std::uint64_t>(to_float ? float_rounded(x) : x);
            }
        while (!(t[0] <= t[1] && t[0] <= t[2]))
            std::rotate(t.begin(), t.begin() + 1, t.end());
        list.push_back(t);
    }
    std::sort(list.begin(), list.end());
    return list;
}

// No two vertices at one position (-0 == +0, as the STL reader welds), after rounding to
// float with `to_float`.
inline bool distinct_positions(const Mesh& mesh, bool to_float) {
    std::vector<Point> points(mesh.deformed_positions().begin(), mesh.deformed_positions().end());
    for (Point& p : points)
        for (double& c : p)
            c = (to_float ? float_rounded(c) : c) + 0.0;
    std::sort(points.begin(), points.end());
    return std::adjacent_find(points.begin(), points.end()) == points.end();
}

// STL in both encodings, and PLY as text (check_writers' list has binary PLY). PLY is held to
// what OFF is held to. STL lists corners, not vertices: its reader welds equal positions and
// drops triangles whose corners weld, and binary STL rounds to float (a coordinate beyond
// float's range cannot be written: skipped). So a triangle mesh whose vertices are apart (after
// the rounding) must come back with the same corner positions, unless it becomes planar by the
// z rule (a 3D surface at z = 0, or whose z all round to 0), which may be refused as inverted;
// a planar mesh read back from binary STL may be refused so too.
inline void check_surface_encodings(const Mesh& mesh, const std::filesystem::path& base,
                                    bool planar_by_z) {
    const std::filesystem::path stl = std::filesystem::path(base).replace_extension(".stl");
    for (bool binary : {false, true}) {
        const bool fits = std::all_of(
            mesh.deformed_positions().begin(), mesh.deformed_positions().end(),
            [](const Point& p) {
                return std::all_of(p.begin(), p.end(), [](double c) {
                    return std::abs(c) <= std::numeric_limits<float>::max();
                });
            });
        if (binary && !fits)
            continue;
        WriteOptions options;
        options.encoding = binary ? Encoding::binary : Encoding::ascii;
        const std::optional<Mesh> again = write_and_read(mesh, stl, options, false);
        if (again)
            check_mesh(*again);
        bool rounded_planar = binary;  // planar meshes too: rounding may turn a triangle over
        for (const Point& p : mesh.deformed_positions())
            rounded_planar = rounded_planar && float_rounded(p[2]) == 0.0;
        if (mesh.topological_dimension() == 3 || planar_by_z || rounded_planar ||
            !distinct_positions(mesh, binary))
            continue;
        const std::string what = binary ? ".stl (binary)" : ".stl (ASCII)";
        if (!again)
            finding("cannot read what was written as " + what);
        if (corner_triangles(*again, false) != corner_triangles(mesh, binary))
            finding("write -> read as " + what + " changed the triangles");
    }
    WriteOptions ascii;
    ascii.encoding = Encoding::ascii;
    const std::optional<Mesh> again =
        write_and_read(mesh, std::filesystem::path(base).replace_extension(".ply"), ascii,
                       mesh.topological_dimension() == 3);
    if (again)
        check_mesh(*again);
    if (mesh.topological_dimension() == 3 || planar_by_z)
        return;
    if (!again)
        finding("cannot read what was written as .ply (ASCII)");
    Mesh unlabelled = mesh;
    for (ElementId t : elements(unlabelled))
        unlabelled.set_label(t, 0);
    unlabelled.face_labels().clear();
    if (!same_mesh(unlabelled, *again))
        finding("write -> read as .ply (ASCII) changed the triangles");
}

// Rule 4, and then every other writer (a crash or sanitizer report in any of them is a
// finding; fuzzing one reader thus exercises all writers on meshes nobody drew by hand):
//   Medit, TetGen, Gmsh 2.2 and 4.1 hold everything and must give the mesh back, except where
//   the ambient-dimension rule legitimately differs (a 3D surface lying in z = 0 becomes planar
//   in Gmsh, and may then be refused as inverted);
//   OFF, OBJ and PLY give triangle meshes back without labels (same exception), and tetrahedral
//   meshes as their boundary, which need not be readable (a pinched boundary is refused); STL
//   gives their corners back (check_surface_encodings);
//   .vtu and .vtk, in each encoding, hold everything and must give the mesh back (the
//   ambient-dimension exception of Gmsh applies: they store x y z too).
inline void check_writers(const Mesh& mesh, const std::filesystem::path& base, const char* own) {
    const bool planar_by_z =
        mesh.topological_dimension() == 2 && mesh.ambient_dimension() == 3 && all_z_zero(mesh);
    struct Target {
        const char* extension;
        int gmsh_version;
        bool labels;
        bool z_rule;
    };
    const Target targets[] = {{".mesh", 41, true, false}, {".msh", 41, true, true},
                              {".msh", 22, true, true},   {".node", 41, true, false},
                              {".off", 41, false, true},  {".obj", 41, false, true},
                              {".ply", 41, false, true}};
    for (const Target& target : targets) {
        const std::string what =
            std::string(target.extension) + (target.gmsh_version == 22 ? " (2.2)" : "");
        WriteOptions options;
        options.gmsh_version = target.gmsh_version;
        const std::filesystem::path path =
            std::filesystem::path(base).replace_extension(target.extension);
        const bool own_format = std::string(own) == target.extension && target.gmsh_version == 41;
        const bool surface = mesh.topological_dimension() == 3 && !target.labels;
        const std::optional<Mesh> again = write_and_read(mesh, path, options, surface);
        if (again)
            check_mesh(*again);
        if (surface || (target.z_rule && planar_by_z))
            continue;  // may be refused; checked above when read
        if (!again)
            finding("cannot read what was written as " + what);
        if (target.labels) {
            if (!same_mesh(mesh, *again))
                finding("write -> read as " + what + " changed the mesh");
        } else {
            Mesh unlabelled = mesh;
            for (ElementId t : elements(unlabelled))
                unlabelled.set_label(t, 0);
            unlabelled.face_labels().clear();
            if (!same_mesh(unlabelled, *again))
                finding("write -> read as " + what + " changed the triangles");
        }
        if (own_format && !same_mesh(mesh, *again))
            finding("write -> read changed the mesh");
    }
    check_surface_encodings(mesh, base, planar_by_z);
    for (const char* extension : {".vtu", ".vtk"})
        for (Encoding encoding : {Encoding::standard, Encoding::ascii, Encoding::binary}) {
            const std::string what =
                std::string(extension) + " (" + std::string(to_string(encoding)) + ")";
            WriteOptions options;
            options.encoding = encoding;
            const std::optional<Mesh> again = write_and_read(
                mesh, std::filesystem::path(base).replace_extension(extension), options, false);
            if (again)
                check_mesh(*again);
            if (planar_by_z)
                continue;  // may be refused, as for Gmsh; checked above when read
            if (!again)
                finding("cannot read what was written as " + what);
            if (!same_mesh(mesh, *again))
                finding("write -> read as " + what + " changed the mesh");
        }
}

// `extension` is the reader's own format (".mesh", ".msh", ".node", ".off", ".obj", ".ply"): a
// mesh read from it must come back from it unchanged, whatever else is true (".stl": see
// check_surface_encodings).
inline int run(const Reader& read, const char* extension) {
    ReadOptions reorient;
    reorient.reorient = true;
    ReadReport report;
    const std::optional<Mesh> repaired = try_read(read, reorient, &report);
    const std::optional<Mesh> strict = try_read(read, {}, nullptr);
    if (strict && !repaired)
        finding("reads without reorient but not with it");
    if (!repaired)
        return 0;
    check_mesh(*repaired);
    if (strict) {
        check_mesh(*strict);
        if (report.reoriented != 0)
            finding("reorient flipped elements of a mesh read without it");
        if (!same_mesh(*strict, *repaired))
            finding("reorient changed a mesh that needed nothing");
    }

    // one scratch name per process: libFuzzer -jobs/-workers run several
    const std::filesystem::path base =
        std::filesystem::temp_directory_path() / ("sxk-fuzz-" + std::to_string(::getpid()) + ".x");
    check_writers(*repaired, base, extension);
    std::error_code ignored;
    for (const char* written :
         {".mesh", ".msh", ".node", ".ele", ".face", ".edge", ".off", ".obj", ".stl", ".ply", ".vtu", ".vtk"})
        std::filesystem::remove(std::filesystem::path(base).replace_extension(written), ignored);
    return 0;
}

}  // namespace sxk::fuzz
