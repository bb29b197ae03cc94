// Where a scalpel may be placed: within ScalpelReach::farthest mean edges of the mesh's bounding
// box (the box as the session began, grown by a mean edge). Both cutters find a movement's pieces
// along it in doubles, where the box must be wider than a rounding step of the movement: samples
// at 1e17 around a unit square made the whole square one step, the movement one piece entered at
// a point ~16 units off, and the cut a dent (the hostile trial, issue 47). At 1e12 mean edges a
// rounding step is still below 1e-3 of a mean edge.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "sxk/mesh.hpp"

namespace sxk::delaunaycut {

class ScalpelReach {
public:
    static constexpr double farthest = 1e12;  // mean edges

    // The box of the elements' deformed positions in the first `dimensions` coordinates (2: a
    // planar mesh, 3: a surface in space), grown by `mean_edge`.
    ScalpelReach(const Mesh& mesh, double mean_edge, std::size_t dimensions);

    // nullopt when p is near enough; else why not, naming the point `what` ("the scalpel", "the
    // blade's tip"): "delaunaycut: the scalpel at (1e+17, 0) is 1e+17 from the mesh, more than
    // 1e12 mean edges (...): so far away a movement cannot be placed on the mesh in doubles".
    std::optional<std::string> too_far(const Point& p, std::string_view what) const;

    double low(std::size_t k) const { return m_low[k]; }
    double high(std::size_t k) const { return m_high[k]; }

private:
    double m_mean_edge;
    std::size_t m_dimensions;
    std::array<double, 3> m_low{}, m_high{};
};

}  // namespace sxk::delaunaycut
