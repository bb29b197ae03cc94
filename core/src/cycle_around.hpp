// The thesis' cycle-around (§7.2) into any list: sxk::cycle_around (traversal.cpp) returns it as
// a vector, and the 3D flips' checks (ops/tet_flip_checks.hpp) into a SmallVector, without
// allocating, on their hot path. One walk, one order.
#pragma once

#include <algorithm>

#include "sxk/mesh.hpp"

namespace sxk::detail {

// The elements containing sigma = face_simplex(entry).subn(j), in ring order, appended to the
// empty list `ring`. The loop's invariant: f == invalid_id or f's simplex is sigma plus v. Enter e
// through f, leave through the face of e opposite v (sigma plus e's remaining vertex), continue in
// that face's mate. When the walk meets the boundary (the thesis stops there) it walks the other
// way too, entering the neighbour behind entry through entry's mate, so the ring is complete.
template <class List>
void cycle_around_into(const Mesh& mesh, FaceId entry, int j, List& ring) {
    const int faces = mesh.element_vertex_count();
    auto walk = [&](FaceId start, VertexId v, FaceId stop, List& out) {
        for (FaceId f = start; f != invalid_id;) {
            const ElementId e = mesh.face_element(f);
            const Simplex& s = mesh.simplex(e);
            const FaceId exit = mesh.face(e, s.index(v));
            for (int i = 0; i < faces; ++i)
                if (mesh.face(e, i) == f) v = s.vertex(i);  // e's vertex opposite f
            out.push_back(e);
            f = mesh.mate(exit);
            if (f == stop) return true;  // closed ring
        }
        return false;  // reached the boundary
    };
    const VertexId v0 = mesh.face_simplex(entry).vertex(j);
    if (walk(entry, v0, entry, ring)) return;
    List back;
    walk(mesh.mate(entry), v0, invalid_id, back);
    std::reverse(back.begin(), back.end());
    for (const ElementId t : ring) back.push_back(t);
    ring.clear();
    for (const ElementId t : back) ring.push_back(t);
}

}  // namespace sxk::detail
