// The real test mesh of tests/real: the femur of CGAL's data set tetrahedralised by TetGen
// (tools/make-data, docs/performance.md), made on first use and cached in the build folder.
#pragma once

#include <array>
#include <cstdio>
#include <memory>
#include <string>

namespace sxk::test {

// Runs tools/make-data and returns the .ele path it prints (empty when it could not run).
inline std::string make_femur() {
    const std::string command = std::string(SXK_SOURCE_DIR "/tools/make-data femur ") + SXK_GENERATED_DATA_DIR;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), &pclose);
    if (!pipe) return {};
    std::string output;
    std::array<char, 512> buffer{};
    while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe.get())) output += buffer.data();
    while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
    return output;
}

}  // namespace sxk::test
