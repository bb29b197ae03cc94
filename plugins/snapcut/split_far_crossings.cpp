// Splitting the crossings far from the mesh's nodes (split_far_crossings.hpp).
#include "split_far_crossings.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Dense>

#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"

namespace sxk::snapcut {

namespace {

struct Crossing {
    VertexId a = invalid_id, b = invalid_id;
    VertexId nearer = invalid_id;  // the end the selection would mark
    double t = 0;                  // where the sweep crosses, as the fraction of the way from a to b
};

using Vec = Eigen::Vector3d;

Vec vec(const Point& p) { return {p[0], p[1], p[2]}; }

}  // namespace

FarCrossings split_far_crossings(Mesh& mesh, CutMarks& marks, std::uint32_t sweep_index, const SweptSurface& swept,
                                 std::vector<ElementId>& candidates) {
    const double beyond = swept.beyond;
    const Sweep sweep = marks.sweeps()[sweep_index];
    const Vec corner = vec(sweep.a), normal = (vec(sweep.b) - corner).cross(vec(sweep.c) - corner);
    const double reach = beyond * normal.norm();  // `beyond` in the units of the signed distances
    std::vector<Crossing> far;
    for (const ElementId t : candidates) {
        if (!mesh.is_element(t)) continue;
        const Simplex s = mesh.simplex(t);
        // the signed distances (times |normal|) of the corners locate the crossings. An edge is
        // looked at from each of its elements, the double tests first (most edges along the
        // blade have both ends on one side, or the nearer end near this sweep), and repeats are
        // dropped below: with a set of the edges seen, this pass cost 0.3 ms of a 1 kHz step on
        // the 1.2M femur, without it 0.1 ms (docs/performance.md).
        std::array<double, 4> d{};
        for (int i = 0; i < 4; ++i)
            d[static_cast<std::size_t>(i)] = normal.dot(vec(mesh.deformed(s.vertex(i))) - corner);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const double da = d[static_cast<std::size_t>(i)], db = d[static_cast<std::size_t>(j)];
                // both ends on one side in doubles: the edge meets the sweep, if at all, within
                // rounding of an end, which is then on the sweep: nothing to split
                if (!(da * db < 0)) continue;
                const VertexId a = s.vertex(i), b = s.vertex(j);  // a < b: the simplex is sorted
                const VertexId nearer = std::abs(da) <= std::abs(db) ? a : b;
                // within `beyond` of the triangle, the nearer end is on the cut already
                if (std::min(std::abs(da), std::abs(db)) <= reach &&
                    distance_to_sweep(sweep, mesh.deformed(nearer)) <= beyond)
                    continue;
                if (marks.snapped(a) || marks.snapped(b)) continue;
                if (marks.mark(a, b)) continue;
                if (!segment_meets_triangle(mesh.deformed(a), mesh.deformed(b), sweep.a, sweep.b, sweep.c)) continue;
                far.push_back({a, b, nearer, da / (da - db)});
            }
    }
    std::sort(far.begin(), far.end(), [](const Crossing& x, const Crossing& y) {
        return x.a != y.a ? x.a < y.a : x.b < y.b;
    });
    far.erase(std::unique(far.begin(), far.end(), [](const Crossing& x, const Crossing& y) {
                  return x.a == y.a && x.b == y.b;
              }),
              far.end());
    // a nearer end within `beyond` of where the blade has been, or of where this movement takes
    // it, is left to the selection
    std::erase_if(far, [&](const Crossing& crossing) { return swept.near(mesh.deformed(crossing.nearer)); });
    FarCrossings result;
    for (const Crossing& crossing : far) {
        auto split = split_edge(mesh, crossing.a, crossing.b, crossing.t);
        if (!split) {
            ++result.refused;
            continue;
        }
        ++result.split;
        // m is on the sweep, where the exact test would see every edge at m meet it at m (the
        // nearer end): all of them are marked so, whichever side rounding put m on
        const CutMarks::Mark mark{split->vertex, sweep_index};
        for (const ElementId child : split->elements)
            for (const VertexId r : mesh.simplex(child).vertices())
                if (r != split->vertex) marks.add_mark(split->vertex, r, mark);
        candidates.insert(candidates.end(), split->elements.begin(), split->elements.end());
    }
    if (result.split > 0) {
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    }
    return result;
}

}  // namespace sxk::snapcut
