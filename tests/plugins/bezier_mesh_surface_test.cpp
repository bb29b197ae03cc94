// mesh_surface (plugins/bezier/mesh_surface.hpp): the surface `sxk render` draws for a mesh.
// Kuhn cubes: 2 x 6 x n^2 boundary triangles, closed (signed volume n^3) and outward (each
// normal points away from the element it bounds), keys taken from that element; a cube
// dissected along the plane x = 1 flags exactly the faces of the cut, in the reference positions
// even when a deformation pulls the two sides apart, and by their face label once the sides no
// longer coincide; triangle meshes keep every triangle and flag those along a cut.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "core/fixtures.hpp"
#include "mesh_surface.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/quality.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {


Point centroid(const std::vector<Point>& points) {
    Point sum{0, 0, 0};
    for (const Point& p : points)
        for (std::size_t c = 0; c < 3; ++c)
            sum[c] += p[c] / static_cast<double>(points.size());
    return sum;
}

std::array<Point, 3> corners(const MeshSurface& surface, std::size_t triangle) {
    const auto& t = surface.soup.triangles[triangle];
    return {surface.soup.vertices[t[0]], surface.soup.vertices[t[1]], surface.soup.vertices[t[2]]};
}

// The right-hand normal v0 -> v1 -> v2 (not unit).
Point normal(const std::array<Point, 3>& c) {
    return cross(minus(c[1], c[0]), minus(c[2], c[0]));
}

// The volume the surface encloses: sum of det[v0, v1, v2] / 6 (divergence theorem); n^3 for a
// closed, outward n-cube.
double enclosed_volume(const MeshSurface& surface) {
    double volume = 0;
    for (std::size_t t = 0; t < surface.soup.triangles.size(); ++t) {
        const auto c = corners(surface, t);
        volume += dot(c[0], cross(c[1], c[2])) / 6;
    }
    return volume;
}

// Every triangle's normal points away from the element it bounds, and its keys are that
// element's label and normalised aspect ratio.
void expect_outward_with_element_keys(const Mesh& mesh, const MeshSurface& surface) {
    ASSERT_EQ(surface.keys.size(), surface.soup.triangles.size());
    for (std::size_t t = 0; t < surface.soup.triangles.size(); ++t) {
        const SurfaceTriangleKeys& key = surface.keys[t];
        ASSERT_TRUE(mesh.is_element(key.element)) << "triangle " << t;
        const std::vector<Point> element = element_points(mesh, key.element);
        const auto c = corners(surface, t);
        EXPECT_LT(dot(normal(c), minus(centroid(element), centroid({c[0], c[1], c[2]}))), 0)
            << "triangle " << t << " points into element " << key.element;
        EXPECT_EQ(key.label, mesh.label(key.element));
        EXPECT_DOUBLE_EQ(key.quality, aspect_ratio(element) / std::sqrt(2.0 / 3.0));
    }
}

class KuhnCubeSurface : public ::testing::TestWithParam<int> {};

TEST_P(KuhnCubeSurface, IsClosedOutwardAndKeyedByItsElements) {
    const int n = GetParam();
    const Mesh mesh = test::kuhn_cube(n);  // labels: path 0..5 of each cube
    const MeshSurface surface = mesh_surface(mesh);
    EXPECT_EQ(surface.soup.triangles.size(), static_cast<std::size_t>(2 * 6 * n * n));
    // the vertices on the cube's surface only: (n+1)^3 - (n-1)^3
    EXPECT_EQ(surface.soup.vertices.size(),
              static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1) - (n - 1) * (n - 1) * (n - 1)));
    EXPECT_NEAR(enclosed_volume(surface), n * n * n, 1e-12);
    EXPECT_EQ(surface.cut_count(), 0u);
    expect_outward_with_element_keys(mesh, surface);
    std::set<int> labels;
    for (const SurfaceTriangleKeys& key : surface.keys) {
        labels.insert(key.label);
        // every Kuhn tetrahedron has the thesis aspect ratio 1/sqrt(6): half the regular one
        EXPECT_NEAR(key.quality, 0.5, 1e-12);
    }
    EXPECT_EQ(labels.size(), 6u);  // every path reaches the boundary somewhere
}

INSTANTIATE_TEST_SUITE_P(Sizes, KuhnCubeSurface, ::testing::Values(1, 2, 3));

// The 2-cube cut along the plane x = 1 (dissect, thesis §7.3), seen from -z:
//
//     y                         the 8 triangles of the plane x = 1 become 16 boundary
//     2 +-----+-----+           triangles, 8 facing -x (left half) and 8 facing +x (right
//       |     |     |           half); their vertices on the plane are copied, at the
//     1 +-----#-----+           same points: the two sides coincide
//       |     #     |
//     0 +-----#-----+ x
//       0     1     2           # : the cut
std::vector<Simplex> faces_on_plane_x1(const Mesh& mesh) {
    std::set<Simplex> faces;
    for (ElementId t : elements(mesh))
        for (int i = 0; i < 4; ++i) {
            const Simplex face = mesh.simplex(t).subn(i);
            bool on_plane = true;
            for (VertexId v : face.vertices())
                on_plane = on_plane && mesh.reference(v)[0] == 1.0;
            if (on_plane)
                faces.insert(Simplex(+1, face.vertices()));
        }
    return {faces.begin(), faces.end()};
}

bool on_plane_x1(const std::array<Point, 3>& c, double x) {
    return c[0][0] == x && c[1][0] == x && c[2][0] == x;
}

TEST(MeshSurface, DissectedCubeFlagsTheCutFaces) {
    Mesh mesh = test::kuhn_cube(2);
    const std::vector<Simplex> cut = faces_on_plane_x1(mesh);
    ASSERT_EQ(cut.size(), 8u);
    const auto dissected = dissect(mesh, cut);
    ASSERT_TRUE(dissected.ok()) << dissected.reason();
    ASSERT_EQ(dissected->new_vertices.size(), 9u);  // the plane's 3 x 3 vertices
    ASSERT_TRUE(mesh.validate().ok());

    const MeshSurface surface = mesh_surface(mesh);
    EXPECT_EQ(surface.soup.triangles.size(), 48u + 16u);
    EXPECT_EQ(surface.cut_count(), 16u);
    EXPECT_NEAR(enclosed_volume(surface), 8.0, 1e-12);  // two closed halves of volume 4
    expect_outward_with_element_keys(mesh, surface);
    int facing_plus_x = 0, facing_minus_x = 0;
    for (std::size_t t = 0; t < surface.soup.triangles.size(); ++t) {
        const auto c = corners(surface, t);
        EXPECT_EQ(surface.keys[t].cut, on_plane_x1(c, 1.0)) << "triangle " << t;
        if (surface.keys[t].cut)
            (normal(c)[0] > 0 ? facing_plus_x : facing_minus_x) += 1;
    }
    EXPECT_EQ(facing_plus_x, 8);
    EXPECT_EQ(facing_minus_x, 8);
}

// A deformation that opens the cut (the right half moves by +0.5 in x, deformed positions only):
// the cut faces are still found, through the reference positions, and drawn where they are.
TEST(MeshSurface, CutsAreFoundInTheReferencePositions) {
    Mesh mesh = test::kuhn_cube(2);
    ASSERT_TRUE(dissect(mesh, faces_on_plane_x1(mesh)).ok());
    std::set<VertexId> right;
    for (ElementId t : elements(mesh))
        if (centroid(element_points(mesh, t, Positions::reference))[0] > 1)
            for (VertexId v : mesh.simplex(t).vertices())
                right.insert(v);
    for (VertexId v : right) {
        Point p = mesh.deformed(v);
        p[0] += 0.5;
        mesh.set_deformed(v, p);
    }

    const MeshSurface deformed = mesh_surface(mesh);
    EXPECT_EQ(deformed.cut_count(), 16u);
    int at_1 = 0, at_1_5 = 0;
    for (std::size_t t = 0; t < deformed.soup.triangles.size(); ++t) {
        if (!deformed.keys[t].cut)
            continue;
        const auto c = corners(deformed, t);
        at_1 += on_plane_x1(c, 1.0);
        at_1_5 += on_plane_x1(c, 1.5);
    }
    EXPECT_EQ(at_1, 8);    // the left side stays
    EXPECT_EQ(at_1_5, 8);  // the right side moved with its half
    EXPECT_NEAR(enclosed_volume(deformed), 8.0, 1e-12);

    MeshSurfaceOptions in_reference;
    in_reference.positions = Positions::reference;
    const MeshSurface reference = mesh_surface(mesh, in_reference);
    EXPECT_EQ(reference.cut_count(), 16u);
    for (std::size_t t = 0; t < reference.soup.triangles.size(); ++t) {
        if (reference.keys[t].cut) {
            EXPECT_TRUE(on_plane_x1(corners(reference, t), 1.0));
        }
    }
}

// A file holds one set of positions: once the sides of a cut were moved apart in both (as a
// file written after the deformation reads back), nothing coincides any more. Cut faces labelled
// before the dissection keep their label on both sides and are found by it.
TEST(MeshSurface, LabelledCutsAreFoundAfterTheSidesMoved) {
    Mesh mesh = test::kuhn_cube(2);
    const std::vector<Simplex> cut = faces_on_plane_x1(mesh);
    for (const Simplex& face : cut)
        mesh.face_labels()[face] = 9;
    ASSERT_TRUE(dissect(mesh, cut).ok());
    std::set<VertexId> right;
    for (ElementId t : elements(mesh))
        if (centroid(element_points(mesh, t, Positions::reference))[0] > 1)
            for (VertexId v : mesh.simplex(t).vertices())
                right.insert(v);
    for (VertexId v : right) {
        Point p = mesh.reference(v);
        p[0] += 0.5;
        mesh.set_reference(v, p);
        mesh.set_deformed(v, p);
    }

    MeshSurfaceOptions by_label;
    EXPECT_EQ(mesh_surface(mesh, by_label).cut_count(), 0u);
    by_label.cut_label = 8;
    EXPECT_EQ(mesh_surface(mesh, by_label).cut_count(), 0u);
    by_label.cut_label = 9;
    const MeshSurface labelled = mesh_surface(mesh, by_label);
    EXPECT_EQ(labelled.cut_count(), 16u);
    for (std::size_t t = 0; t < labelled.soup.triangles.size(); ++t) {
        const auto c = corners(labelled, t);
        EXPECT_EQ(labelled.keys[t].cut, on_plane_x1(c, 1.0) || on_plane_x1(c, 1.5))
            << "triangle " << t;
    }
}

//   (0,2) +-----+-----+ (2,2)     planar_grid(2): 8 counter-clockwise triangles; cut along the
//         |   / #   / |           two edges on x = 1 (#), the four triangles along the cut
//         | /   # /   |           are flagged
//   (0,1) +-----+-----+
//         |   / #   / |
//         | /   # /   |
//   (0,0) +-----+-----+ (2,0)
TEST(MeshSurface, TriangleMeshKeepsEveryTriangleAndFlagsThoseAlongACut) {
    Mesh mesh = test::planar_grid(2);
    MeshSurface surface = mesh_surface(mesh);
    ASSERT_EQ(surface.soup.triangles.size(), 8u);
    EXPECT_EQ(surface.soup.vertices.size(), 9u);
    EXPECT_EQ(surface.cut_count(), 0u);
    for (std::size_t t = 0; t < 8; ++t) {
        EXPECT_GT(normal(corners(surface, t))[2], 0) << "triangle " << t;  // as the element
        const SurfaceTriangleKeys& key = surface.keys[t];
        EXPECT_DOUBLE_EQ(key.quality,
                         aspect_ratio(element_points(mesh, key.element)) / (std::sqrt(3.0) / 2));
    }

    std::vector<Simplex> cut;
    for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
        if (!mesh.is_face(f))
            continue;
        const Simplex edge = mesh.face_simplex(f);
        if (mesh.reference(edge.vertex(0))[0] == 1.0 && mesh.reference(edge.vertex(1))[0] == 1.0)
            cut.push_back(edge);
    }
    ASSERT_EQ(cut.size(), 4u);  // two edges, each seen from both sides
    ASSERT_TRUE(dissect(mesh, cut).ok());
    surface = mesh_surface(mesh);
    ASSERT_EQ(surface.soup.triangles.size(), 8u);
    EXPECT_EQ(surface.soup.vertices.size(), 12u);  // the three vertices on x = 1 were copied
    EXPECT_EQ(surface.cut_count(), 4u);
    for (std::size_t t = 0; t < 8; ++t) {
        const auto c = corners(surface, t);
        const int on_cut = (c[0][0] == 1.0) + (c[1][0] == 1.0) + (c[2][0] == 1.0);
        EXPECT_EQ(surface.keys[t].cut, on_cut == 2) << "triangle " << t;
    }
}

TEST(MeshSurface, EmptyMeshGivesAnEmptySurface) {
    const Mesh mesh(3, 3);
    const MeshSurface surface = mesh_surface(mesh);
    EXPECT_TRUE(surface.soup.vertices.empty());
    EXPECT_TRUE(surface.soup.triangles.empty());
    EXPECT_TRUE(surface.keys.empty());
}

}  // namespace
}  // namespace sxk::bezier
