// segment_meets_tetrahedron (sxk/predicates.hpp): a closed segment against a closed tetrahedron,
// decided by orientation signs.
//
// Why not triangle_meets_tetrahedron with a collinear triangle, as the snap cutter's blade track
// first asked: a collinear triangle has no plane, its four signs against the tetrahedron are exact
// zeros, which the static filter cannot certify (each goes to exact arithmetic), and then CGAL's
// segment test runs. Keeping the elements a blade lies in (plugins/snapcut/blade_track.hpp) was
// 14 % of a 1 kHz cut's selection rounds on the 1.2M femur that way (docs/performance.md "Looking
// again only where something changed"). And why not CGAL's do_intersect(Segment_3,
// Tetrahedron_3): on the 1.2M femur's blade slivers (tools/bench/sweep_tests, the moved blade
// against the elements a sliver meets and their neighbours, ns per test) ours 156 and 190, CGAL's
// 166 and 336, the collinear triangle 1316 and 1471.
//
// Why these steps suffice. If neither end of the segment lies in the tetrahedron and the two
// meet, the segment enters it at a point X of some face, not an end. Where the segment crosses
// that face's plane there (its ends strictly on either side), the crossing is X and lies in the
// face. Otherwise the segment lies in the face's plane and enters the face through an edge,
// where it crosses the plane of the face on the other side of that edge, or runs along the
// edge's line into a corner, where it crosses the plane of the face opposite the edge's other
// end: either way some face's plane is crossed strictly, at a point of that face.
#include <array>

#include "cgal_kernel.hpp"
#include "sxk/predicates.hpp"
#include "tetrahedron_signs.hpp"

namespace sxk {

bool segment_meets_tetrahedron(const Point& a, const Point& b, const Point& p0, const Point& p1, const Point& p2,
                               const Point& p3) {
    using P = detail::Kernel::Point_3;
    using detail::faces;
    using detail::orientation_sign;
    const std::array<P, 2> s{detail::to_cgal_3(a), detail::to_cgal_3(b)};
    const std::array<P, 4> p{detail::to_cgal_3(p0), detail::to_cgal_3(p1), detail::to_cgal_3(p2),
                             detail::to_cgal_3(p3)};
    const int volume = orientation_sign(p[0], p[1], p[2], p[3]);
    if (volume == 0) return false;  // a flat tetrahedron: no element to meet (as the index has it)
    // inside[i][x] > 0 when end x is on the inner side of face i's plane
    std::array<std::array<int, 2>, 4> inside{};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto& f = faces[i];
        for (std::size_t x = 0; x < 2; ++x) inside[i][x] = volume * orientation_sign(p[f[0]], p[f[1]], p[f[2]], s[x]);
        if (inside[i][0] < 0 && inside[i][1] < 0) return false;  // both ends beyond one face
    }
    for (std::size_t x = 0; x < 2; ++x)
        if (inside[0][x] >= 0 && inside[1][x] >= 0 && inside[2][x] >= 0 && inside[3][x] >= 0) return true;
    for (std::size_t i = 0; i < 4; ++i) {
        if (inside[i][0] * inside[i][1] >= 0) continue;
        const auto& f = faces[i];
        if (detail::line_through_triangle(s[0], s[1], p[f[0]], p[f[1]], p[f[2]])) return true;
    }
    return false;
}

}  // namespace sxk
