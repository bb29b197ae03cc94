// libFuzzer target for the TetGen reader: the input is X.node, a line "---", then X.ele
// (split at the first "\n---\n"; without one, all of it is the .node and the .ele is empty).
// The oracle is in oracle.hpp.
#include <sstream>
#include <string>

#include "oracle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t split = text.find("\n---\n");
    const std::string node = split == std::string::npos ? text : text.substr(0, split + 1);
    const std::string ele = split == std::string::npos ? std::string() : text.substr(split + 5);
    return sxk::fuzz::run(
        [&](const sxk::ReadOptions& options, sxk::ReadReport* report) {
            std::istringstream node_in(node), ele_in(ele);
            return sxk::read_tetgen(node_in, "fuzz.node", ele_in, "fuzz.ele", options, report);
        },
        ".node");
}
