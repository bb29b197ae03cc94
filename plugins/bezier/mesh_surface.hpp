// The surface `sxk render` draws for a mesh: its boundary triangles as a TriangleSoup for
// Scene::from_triangles, each with the keys a colour is chosen by (the quality and label of the
// element it bounds, and whether it lies on a cut).
//
//   tetrahedral mesh: one triangle per boundary face, oriented as invariant 7.1 orients the face
//   of its element (outward for a positive tetrahedron: the right-hand normal of v0 -> v1 -> v2
//   points away from the element)
//
//          v2                         triangle mesh (planar or a surface in 3D): every
//         /  \      normal out of     element itself, as the element orients it; a ray
//        /    \     the page, away    sees it from both sides
//      v0 ---- v1   from the element
//
// Cuts. The kernel does not mark a cut face: dissect() (sxk/ops/dissect.hpp, thesis §7.3) gives
// the vertices of a separating face copies with bit-identical positions, so the face becomes two
// boundary faces (one per side) over the same three points; cutting free in the degeneracy
// plug-in does the same. A boundary face is therefore a cut face when another boundary face has
// exactly the same vertex positions in the REFERENCE configuration: a deformation may pull the
// two sides apart, the reference positions of the copies stay equal. Two separate pieces touching
// along a face (an internal surface that was never glued) are flagged the same way: for a picture
// they are a cut. A file holds one set of positions, so a cut whose sides were moved apart before
// writing, or one side of which was removed, no longer coincides with anything: label the cut
// faces before dissecting (a dissection gives both sides the label of a labelled cut face, and
// the formats with face labels keep it) and name the label as MeshSurfaceOptions::cut_label.
// For a triangle mesh a cut is a pair of coinciding (or labelled) boundary edges; the triangles
// along it are flagged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "patch_scene.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"  // sxk::Positions

namespace sxk::bezier {

// What a surface triangle's colour may depend on.
struct SurfaceTriangleKeys {
    ElementId element = invalid_id;  // the element the triangle bounds (triangle meshes: is)
    // The element's thesis aspect ratio (sxk/quality.hpp) divided by that of the regular simplex
    // (sqrt(2/3) for tetrahedra, sqrt(3)/2 for triangles), clamped to [0, 1]: 1 regular, 0 flat.
    double quality = 0;
    int label = 0;     // the element's label
    bool cut = false;  // on a cut (see above)
    // The element's piece: its connected component (sxk/components.hpp), numbered in order of
    // each piece's smallest element id, so that the piece a body keeps after a cut keeps its colour.
    std::uint32_t piece = 0;
};

struct MeshSurface {
    // Only the vertices the triangles use, renumbered in increasing id order.
    TriangleSoup soup;
    std::vector<SurfaceTriangleKeys> keys;  // one per soup.triangles entry
    std::size_t cut_count() const;          // triangles flagged cut
    std::uint32_t pieces = 0;               // connected components of the mesh
};

struct MeshSurfaceOptions {
    // Where the triangles' vertices are; cuts are found in the reference positions whatever
    // this says.
    Positions positions = Positions::deformed;
    // Boundary faces with this face label (Mesh::face_labels()) are cut faces too.
    std::optional<int> cut_label;
};

// The boundary surface of a tetrahedral mesh, or the triangles of a triangle mesh. An empty mesh
// gives an empty surface.
MeshSurface mesh_surface(const Mesh& mesh, const MeshSurfaceOptions& options = {});

}  // namespace sxk::bezier
