// Splitting the crossings far from the mesh's nodes (split_far_crossings.hpp).
#include "split_far_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include <Eigen/Dense>

#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"

namespace sxk::snapcut {

namespace {

struct Crossing {
    VertexId a = invalid_id, b = invalid_id;
    double t = 0;  // where the sweep crosses, as the fraction of the way from a to b
};

using Vec = Eigen::Vector3d;

Vec vec(const Point& p) { return {p[0], p[1], p[2]}; }

}  // namespace

FarCrossings split_far_crossings(Mesh& mesh, CutMarks& marks, std::uint32_t sweep_index,
                                 std::vector<ElementId>& candidates, double beyond) {
    const Sweep sweep = marks.sweeps()[sweep_index];
    const Vec corner = vec(sweep.a), normal = (vec(sweep.b) - corner).cross(vec(sweep.c) - corner);
    std::vector<Crossing> far;
    std::unordered_set<std::uint64_t> seen;
    for (const ElementId t : candidates) {
        if (!mesh.is_element(t)) continue;
        const Simplex s = mesh.simplex(t);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const VertexId a = s.vertex(i), b = s.vertex(j);  // a < b: the simplex is sorted
                if (!seen.insert((std::uint64_t{a} << 32) | b).second) continue;
                if (marks.snapped(a) || marks.snapped(b)) continue;
                if (marks.has_marked_edge(a) && marks.has_marked_edge(b) && marks.mark(a, b)) continue;
                const Point &pa = mesh.deformed(a), &pb = mesh.deformed(b);
                // the signed distances (times |normal|) locate the crossing; an edge with both ends
                // on one side in doubles meets the sweep, if at all, within rounding of an end,
                // which is then on the sweep: nothing to split
                const double da = normal.dot(vec(pa) - corner), db = normal.dot(vec(pb) - corner);
                if (!(da * db < 0)) continue;
                if (!segment_meets_triangle(pa, pb, sweep.a, sweep.b, sweep.c)) continue;
                if (!(std::min(std::abs(da), std::abs(db)) > beyond * normal.norm())) continue;
                far.push_back({a, b, da / (da - db)});
            }
    }
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
