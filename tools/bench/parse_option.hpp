// The benchmarks' own options, given after Google Benchmark has taken its flags.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string>

namespace sxk_bench {

// True, with `value` set, when `argument` is "--NAME=N".
inline bool parse_option(const char* argument, const char* name, std::uint64_t& value) {
    const std::string prefix = std::string("--") + name + "=";
    if (std::string(argument).rfind(prefix, 0) != 0) return false;
    value = std::strtoull(argument + prefix.size(), nullptr, 10);
    return true;
}

}  // namespace sxk_bench
