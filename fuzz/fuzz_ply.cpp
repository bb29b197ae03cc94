// libFuzzer target for the ply reader; the oracle is in oracle.hpp.
#include <sstream>
#include <string>

#include "oracle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    return sxk::fuzz::run(
        [&](const sxk::ReadOptions& options, sxk::ReadReport* report) {
            std::istringstream in(text);
            return sxk::read_mesh(in, sxk::Format::ply, "fuzz.ply", options, report);
        },
        ".ply");
}
