// The real test mesh of tests/real: the femur of CGAL's data set tetrahedralised by TetGen
// (tools/make-data, docs/performance.md), made on first use and cached in the build folder.
#pragma once

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace sxk::test {

// Runs tools/make-data and returns the .ele path it prints (empty when it could not run). With
// SXK_FEMUR set, that mesh instead: the femur tests that check properties, not the 213k femur's
// own figures, run on another (SXK_FEMUR=.../_pq1.4a0.00000005/femur.1.ele ctest -R
// RandomThroughCuts: the random through cuts on the 1.2M femur, docs/snapcut.md).
inline std::string make_femur() {
    if (const char* other = std::getenv("SXK_FEMUR"); other != nullptr && *other != 0) return other;
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
