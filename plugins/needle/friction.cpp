// The friction profile and the nodes' thresholds (friction.hpp, needle.hpp).
#include "friction.hpp"

#include <algorithm>
#include <numeric>

namespace sxk::needle {

void share_thresholds(std::vector<NeedleNode>& nodes, const Friction& friction, double spacing) {
    std::vector<std::size_t> order(nodes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // nearest the tip first; ties by vertex id, so shares do not depend on the order of interception
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
        return nodes[i].along != nodes[j].along ? nodes[i].along > nodes[j].along
                                                : nodes[i].vertex < nodes[j].vertex;
    });
    double upper = 0;  // the share's end nearer the tip, as distance behind the tip
    for (std::size_t k = 0; k < order.size(); ++k) {
        const double behind = std::max(-nodes[order[k]].along, 0.0);
        const double lower = k + 1 < order.size()
                                 ? std::max(0.5 * (behind + std::max(-nodes[order[k + 1]].along, 0.0)), upper)
                                 : std::max(behind + 0.5 * spacing, upper);
        nodes[order[k]].threshold = friction.force(upper, lower);
        upper = lower;
    }
}

}  // namespace sxk::needle
