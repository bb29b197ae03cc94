// The femur from CGAL's data set, tetrahedralised by TetGen (tools/make-data): a real mesh of
// 47,733 nodes and 212,936 tetrahedra read through the TetGen reader, then through every
// writer/reader pair that can hold it.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "real/femur_data.hpp"
#include "sxk/io.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using test::make_femur;

TEST(IoFemur, ReadsTheTetgenMesh) {
    const std::string ele = make_femur();
    ASSERT_FALSE(ele.empty()) << "tools/make-data femur failed";
    ASSERT_TRUE(std::filesystem::exists(ele)) << ele;

    const auto start = std::chrono::steady_clock::now();
    const Mesh mesh = read_mesh(ele);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("read_seconds", std::to_string(seconds));  // reported, never asserted

    EXPECT_EQ(mesh.vertex_count(), 47733u);
    EXPECT_EQ(mesh.element_count(), 212936u);
    EXPECT_EQ(mesh.topological_dimension(), 3);
    EXPECT_EQ(mesh.ambient_dimension(), 3);
    // TetGen's boundary markers: every listed face carries one
    EXPECT_EQ(mesh.face_labels().size(), 54848u);
    EXPECT_EQ(mesh.boundary_face_count(), 54848u);
    const auto valid = mesh.validate();
    EXPECT_TRUE(valid.ok()) << valid.reason();
    std::size_t positive = 0;
    for (ElementId t : elements(mesh))
        positive += element_orientation(mesh, t) == Sign::positive;
    EXPECT_EQ(positive, 212936u);  // TetGen's output is positive in our convention

    // and back out through Medit and Gmsh, unchanged
    const std::filesystem::path dir =
        std::filesystem::path(SXK_BINARY_DIR) / "test-io-scratch" / "femur";
    std::filesystem::create_directories(dir);
    for (const char* name : {"femur.mesh", "femur.msh"}) {
        write_mesh(mesh, dir / name);
        const Mesh again = read_mesh(dir / name);
        EXPECT_EQ(again.vertex_count(), mesh.vertex_count()) << name;
        EXPECT_EQ(again.element_count(), mesh.element_count()) << name;
        EXPECT_EQ(again.face_labels(), mesh.face_labels()) << name;
        EXPECT_TRUE(std::equal(again.deformed_positions().begin(), again.deformed_positions().end(),
                               mesh.deformed_positions().begin()))
            << name;
        EXPECT_TRUE(again.validate().ok()) << name;
    }
}

}  // namespace
}  // namespace sxk
