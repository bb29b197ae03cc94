// Small hand-made meshes and comparisons shared by the io tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk::test {

// Two tetrahedra glued along triangle 0 1 2 (0-based ids; the fixture files number from 1):
//
//            3 (0,0,1)
//            |
//            |  2 (0,1,0)
//            | /
//            |/
//            0 ------ 1 (1,0,0)
//            |
//            4 (0,0,-1)
//
//   A = +<0,1,2,3> label 1 (above z = 0), B = <0,2,1,4> label 2 (below): both positive.
//   Face labels: boundary triangle {0,1,3} -> 7, interface triangle {0,1,2} -> 5.
// Coordinates are perturbed by values that have no short decimal form (1/3, 0.1, a denormal,
// -0.0) so the round trips prove that positions survive bit for bit.
inline Mesh two_tetrahedra() {
    Mesh mesh(3, 3);
    mesh.add_vertex({0.1, 1.0 / 3.0, -0.0});
    mesh.add_vertex({1.0 + 1.0 / 7.0, 5e-324, 2.0 / 3.0 * 1e-5});
    mesh.add_vertex({0.1, 1.0 + 1e-17, 1.0 / 9.0 * 1e-3});
    mesh.add_vertex({0.2, 1.0 / 3.0, 1.0 + 1.0 / 11.0});
    mesh.add_vertex({1.0 / 13.0, 0.3, -1.0 - 1.0 / 17.0});
    const Simplex simplexes[] = {Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {0, 2, 1, 4})};
    const int labels[] = {1, 2};
    EXPECT_TRUE(mesh.assign_elements(simplexes, labels).ok());
    mesh.face_labels()[Simplex(+1, {0, 1, 3})] = 7;
    mesh.face_labels()[Simplex(+1, {0, 1, 2})] = 5;
    return mesh;
}

// A planar unit square of two triangles plus one more (ambient dimension 2):
//
//   3 ------ 2 ------ 4
//   |      / |      /
//   |  B  /  |  C  /        A = <0,1,2> label 1, B = <0,2,3> label 2, C = <1,4,2> label 3,
//   |   /  A |   /          all counter-clockwise
//   | /      | /
//   0 ------ 1              edge labels: boundary {0,1} -> 10, interior {0,2} -> 11
inline Mesh planar_triangles() {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({1, 1.0 / 3.0, 0});
    mesh.add_vertex({0.1, 1, 0});
    mesh.add_vertex({2 + 1e-9, 1, 0});
    const Simplex simplexes[] = {Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3}),
                                 Simplex(+1, {1, 4, 2})};
    const int labels[] = {1, 2, 3};
    EXPECT_TRUE(mesh.assign_elements(simplexes, labels).ok());
    mesh.face_labels()[Simplex(+1, {0, 1})] = 10;
    mesh.face_labels()[Simplex(+1, {0, 2})] = 11;
    return mesh;
}

// The closed surface of a tetrahedron in 3D (topological dimension 2, ambient 3), outward:
//
//        3
//       /|\          triangles <1,2,3>, <0,3,2>, <0,1,3>, <0,2,1>
//      / | \         (the boundary of the positive tetrahedron <0,1,2,3>)
//     0--|--2
//      \ | /
//        1
inline Mesh tetrahedron_surface() {
    Mesh mesh(2, 3);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0.25});
    mesh.add_vertex({0, 1, 1.0 / 3.0});
    mesh.add_vertex({0, 0, 1});
    const Simplex simplexes[] = {Simplex(+1, {1, 2, 3}), Simplex(+1, {0, 3, 2}),
                                 Simplex(+1, {0, 1, 3}), Simplex(+1, {0, 2, 1})};
    EXPECT_TRUE(mesh.assign_elements(simplexes).ok());
    return mesh;
}

// Elements as (simplex, label), sorted: equal lists mean identical connectivity and labels.
inline std::vector<std::pair<Simplex, int>> element_list(const Mesh& mesh) {
    std::vector<std::pair<Simplex, int>> list;
    for (ElementId t : elements(mesh))
        list.emplace_back(mesh.simplex(t), mesh.label(t));
    std::sort(list.begin(), list.end());
    return list;
}

inline std::vector<std::pair<Simplex, int>> face_label_list(const Mesh& mesh) {
    std::vector<std::pair<Simplex, int>> list(mesh.face_labels().begin(), mesh.face_labels().end());
    std::sort(list.begin(), list.end());
    return list;
}

// Positions compared as bit patterns: -0.0 != 0.0 and every last bit counts.
inline std::vector<std::uint64_t> position_bits(const Mesh& mesh) {
    std::vector<std::uint64_t> bits;
    for (const Point& p : mesh.deformed_positions())
        for (double c : p)
            bits.push_back(std::bit_cast<std::uint64_t>(c));
    return bits;
}

inline void expect_same_mesh(const Mesh& expected, const Mesh& actual, bool labels = true) {
    EXPECT_EQ(expected.topological_dimension(), actual.topological_dimension());
    EXPECT_EQ(expected.ambient_dimension(), actual.ambient_dimension());
    EXPECT_EQ(expected.vertex_count(), actual.vertex_count());
    EXPECT_EQ(position_bits(expected), position_bits(actual));
    if (labels) {
        EXPECT_EQ(element_list(expected), element_list(actual));
        EXPECT_EQ(face_label_list(expected), face_label_list(actual));
    } else {
        auto strip = [](std::vector<std::pair<Simplex, int>> list) {
            for (auto& item : list)
                item.second = 0;
            return list;
        };
        EXPECT_EQ(strip(element_list(expected)), strip(element_list(actual)));
    }
    EXPECT_TRUE(actual.validate().ok()) << actual.validate().reason();
}

// A fresh folder per test under the build tree (tests run in parallel under ctest).
inline std::filesystem::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::path(SXK_BINARY_DIR) / "test-io-scratch" /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::filesystem::path data_file(const std::string& name) {
    return std::filesystem::path(SXK_TEST_DATA_DIR) / name;
}

// A file's bytes as they are (binary formats included).
inline std::string file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace sxk::test
