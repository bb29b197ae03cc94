// Stick-slip friction along the needle (thesis §6.3.2): each needle node's dynamic threshold is
// the friction force (Fig. 6.4's profile, Friction) over its share of the shaft, the stretch
// between the midpoints to its neighbours along the needle ("the distance along the needle shaft
// between nodes, d_needle, is used as a basis for friction computations", §6.4).
#pragma once

#include <vector>

#include "needle.hpp"

namespace sxk::needle {

// Sets every node's threshold. Shares run from the tip (the node nearest it takes the bulge) back
// to the midpoints between nodes; the last node's reaches `spacing` / 2 beyond it.
void share_thresholds(std::vector<NeedleNode>& nodes, const Friction& friction, double spacing);

}  // namespace sxk::needle
