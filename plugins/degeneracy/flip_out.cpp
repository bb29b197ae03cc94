// Removing a flat tetrahedron without a crack by one flip (beyond the thesis, which cuts free
// what does not collapse): the 2-3 flip of one of its faces, the 3-2 flip of one of its edges
// of degree 3, or the 4-4 flip of one of degree 4 (thesis §5.2.2). The flip whose new elements
// have the largest minimum aspect ratio is done, and only when none of them is degenerate, so
// the flip removes a degenerate without making another.
//
//   2-3 on face abc of t = <abc,p>:        3-2 on edge ab (ring c d e):     4-4 on edge ab
//   {pqab, pqbc, pqca}                     {cdea, cdeb}                     (ring v0..v3):
//   (q: the apex across abc)                                                 diagonal v0v2 or v1v3
#include <algorithm>
#include <array>
#include <vector>

#include "removal_steps.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"
#include "sxk/ops/flip_44.hpp"
#include "sxk/traversal.hpp"

namespace sxk::degeneracy::detail {
namespace {

struct Flip {
    enum class Kind { f23, f32, f44 } kind;
    double quality = 0;  // smallest aspect ratio of the new elements
    FaceId face = invalid_id;  // f23: the face; f32/f44: the entry
    int j = 0;
    int diagonal = 0;
};

double worst(const Mesh& mesh, std::span<const std::array<VertexId, 4>> tets, Positions positions) {
    double q = 1;
    for (const auto& tet : tets) q = std::min(q, aspect_ratio_of(mesh, tet, positions));
    return q;
}

std::vector<Flip> flips_for(const Mesh& mesh, ElementId t, const Options& options) {
    const Simplex& tau = mesh.simplex(t);
    std::vector<Flip> flips;
    // 2-3 on each interior face
    for (int i = 0; i < 4; ++i) {
        const FaceId f = mesh.face(t, i);
        if (mesh.mate(f) == invalid_id) continue;
        const VertexId p = tau.vertex(i);
        const VertexId q = mesh.opposite_vertex(mesh.face_element(mesh.mate(f)), mesh.mate(f));
        const Simplex abc = tau.subn(i);
        const VertexId a = abc.vertex(0), b = abc.vertex(1), c = abc.vertex(2);
        const std::array<std::array<VertexId, 4>, 3> created{{{p, q, a, b}, {p, q, b, c}, {p, q, c, a}}};
        flips.push_back({Flip::Kind::f23, worst(mesh, created, options.positions), f});
    }
    // 3-2 and 4-4 on each edge
    for (int k = 0; k < 4; ++k) {  // the face of t opposite vertex k enters the ring
        const FaceId entry = mesh.face(t, k);
        const Simplex face = mesh.face_simplex(entry);
        for (int j = 0; j < 3; ++j) {
            const Simplex edge = face.subn(j);
            // each edge of t lies in two faces of t: take it from the face of smaller k only
            bool first = true;
            for (int other = 0; other < k; ++other)
                if (!edge.contains(tau.vertex(other))) first = false;
            if (!first) continue;
            const std::vector<ElementId> ring = cycle_around(mesh, entry, j);
            if (ring.size() != 3 && ring.size() != 4) continue;
            const VertexId a = edge.vertex(0), b = edge.vertex(1);
            std::array<VertexId, 4> v{};  // v[i]: shared by ring[i] and ring[i+1] besides a, b
            bool closed = true;
            for (std::size_t r = 0; r < ring.size(); ++r) {
                const Simplex& s = mesh.simplex(ring[r]);
                const Simplex& next = mesh.simplex(ring[(r + 1) % ring.size()]);
                v[r] = invalid_id;
                for (const VertexId x : s.vertices())
                    if (x != a && x != b && next.contains(x)) v[r] = x;
                if (v[r] == invalid_id) closed = false;  // an open ring: the edge is on the boundary
            }
            if (!closed) continue;
            if (ring.size() == 3) {
                const std::array<std::array<VertexId, 4>, 2> created{{{v[0], v[1], v[2], a}, {v[0], v[1], v[2], b}}};
                flips.push_back({Flip::Kind::f32, worst(mesh, created, options.positions), entry, j});
                continue;
            }
            for (int diagonal = 0; diagonal < 2; ++diagonal) {
                const auto m = static_cast<std::size_t>(diagonal);
                const VertexId u = v[m], w = v[m + 2], y = v[m + 1], z = v[(m + 3) % 4];
                const std::array<std::array<VertexId, 4>, 4> created{
                    {{u, w, a, y}, {u, w, b, y}, {u, w, a, z}, {u, w, b, z}}};
                flips.push_back({Flip::Kind::f44, worst(mesh, created, options.positions), entry, j, diagonal});
            }
        }
    }
    // Clean flips (no new degenerate) if any; else those that at least raise the worst shape
    // of what they replace above the element's own (a degenerate that a later pass may remove).
    const double own = element_aspect_ratio(mesh, t, options.positions);
    const bool clean = std::any_of(flips.begin(), flips.end(), [&](const Flip& f) { return f.quality >= options.aspect_ratio; });
    std::erase_if(flips, [&](const Flip& f) { return clean ? f.quality < options.aspect_ratio : !(f.quality > own); });
    std::stable_sort(flips.begin(), flips.end(), [](const Flip& x, const Flip& y) { return x.quality > y.quality; });
    return flips;
}

}  // namespace

Refused flip_out(Mesh& mesh, ElementId t, const Options& options, Tally& tally) {
    const std::vector<Flip> flips = flips_for(mesh, t, options);
    if (flips.empty())
        return Refusal(RefusalCode::not_applicable,
                       "no flip removes it without making another degenerate element");
    Refused why;
    for (const Flip& flip : flips) {
        bool done = false;
        switch (flip.kind) {
            case Flip::Kind::f23: {
                const auto r = flip_23(mesh, flip.face);
                done = r.ok();
                if (!done) why = r.refusal();
                break;
            }
            case Flip::Kind::f32: {
                const auto r = flip_32(mesh, flip.face, flip.j);
                done = r.ok();
                if (!done) why = r.refusal();
                break;
            }
            case Flip::Kind::f44: {
                const auto r = flip_44(mesh, flip.face, flip.j, flip.diagonal);
                done = r.ok();
                if (!done) why = r.refusal();
                break;
            }
        }
        if (done) {
            ++tally.flips;
            return std::nullopt;
        }
    }
    return why;
}

}  // namespace sxk::degeneracy::detail
