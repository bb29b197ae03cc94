// Roth's flatness split (thesis §6.4, Fig. 6.11): a patch is cut into four sub-patches at its
// edge midpoints until each is flat, its height h below a bound. Internal to the plug-in: the
// Embree scene (patch_scene.cpp) registers the pieces as its leaves.
//
//            C = (0,0,1)                 the four children of the domain triangle A B C:
//              /\                        corner A: A, AB, CA      corner B: AB, B, BC
//          CA /__\ BC                    corner C: CA, BC, C      middle:   BC, CA, AB
//            /\  /\                      each listed counterclockwise like A B C, so every
//           /__\/__\                     child keeps the patch's orientation (its normal
//          A   AB   B = (0,1,0)          D_u x D_v points the same way).
//     (1,0,0)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "triangular_patch.hpp"

namespace sxk::bezier {

// A piece of patch `patch` (an index into the list given to flat_subdivision): the same surface
// over the domain triangle with corners `corners` (barycentric in the original patch), as a
// patch of its own whose (r, s, t) map to r corners[0] + s corners[1] + t corners[2].
struct SubPatch {
    TriangularPatch surface;
    std::uint32_t patch = 0;
    std::array<Barycentric, 3> corners{};
};

// Roth's height of a patch: the extent of its control points along the unit normal of the
// plane through its corner control points b_n00, b_0n0, b_00n, measured from b_n00 and
// including that corner (h = max{0, max n.(b - b_n00)} - min{0, min n.(b - b_n00)}). Where the
// corner points span no plane (a collapsed corner, as at the teapot's knob and bottom) n is the
// patch's own normal at the centroid instead (any unit n makes h the width of a slab holding the
// patch), and where that is missing too (a patch flat to a line or point) h is the diagonal of
// the control points' bounding box, an upper bound of any extent.
double roth_height(const TriangularPatch& patch);

// The memory a piece of degree n is counted with against flat_subdivision's max_bytes: its
// (n+1)(n+2)/2 control points of 24 bytes and 256 bytes for the SubPatch itself and its share
// of Embree's BVH.
std::size_t leaf_bytes(int degree);

// flat_subdivision stopped because the pieces would take more than max_bytes: a small input can
// ask for 4^max_depth pieces per patch (a tiny max_height, or patches too wiggly to become flat
// soon), which is more memory than the machine has. `pieces` were made when it stopped.
class SubdivisionTooLarge : public std::length_error {
public:
    SubdivisionTooLarge(std::size_t max_bytes, std::size_t pieces);
    std::size_t max_bytes() const { return m_max_bytes; }
    std::size_t pieces() const { return m_pieces; }

private:
    std::size_t m_max_bytes, m_pieces;
};

// Every patch split into four, recursively, until roth_height <= max_height or `max_depth`
// splits were made; the pieces in patch order, each patch's pieces in depth-first order.
// Throws std::invalid_argument for max_depth < 0 or a negative or NaN max_height, and
// SubdivisionTooLarge as soon as the pieces made would take more than max_bytes (leaf_bytes
// each): then every patch's split stops, so the memory held stays near max_bytes.
std::vector<SubPatch> flat_subdivision(
    const std::vector<TriangularPatch>& patches, double max_height, int max_depth,
    std::size_t max_bytes = std::numeric_limits<std::size_t>::max());

}  // namespace sxk::bezier
