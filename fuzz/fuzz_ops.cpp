// libFuzzer target for the local operations: the first bytes pick a start mesh (planar grid,
// planar random points, octahedron surface in space, Kuhn cube of tetrahedra), every following
// group of bytes one operation and its arguments (ids modulo the current counts). The oracle
// (fuzz/ops_driver.hpp) checks validate(), bit-identical state after refusals, exact positive
// orientation after successes and the interpolated vertex attribute after every step; a broken
// rule prints the step and aborts, which libFuzzer and the replay driver both report.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ops_driver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::size_t position = 0;
    sxk::ops_driver::Choices choices([&]() -> int {
        return position < size ? data[position++] : -1;
    });
    sxk::Mesh mesh = sxk::ops_driver::start_mesh(choices);
    if (const auto valid = mesh.validate(); !valid.ok()) {
        std::fprintf(stderr, "fuzz_ops: start mesh invalid: %s\n", valid.reason().c_str());
        std::abort();
    }
    if (const std::string bad = sxk::ops_driver::first_bad_element(mesh, sxk::ops_driver::live_elements(mesh));
        !bad.empty()) {
        std::fprintf(stderr, "fuzz_ops: start mesh: %s\n", bad.c_str());
        std::abort();
    }
    for (int step = 0; !choices.exhausted && step < 400; ++step) {
        const auto result = sxk::ops_driver::run_step(mesh, choices, 2000);
        if (!result.finding.empty()) {
            std::fprintf(stderr, "fuzz_ops: step %d: %s\n", step, result.finding.c_str());
            std::abort();
        }
    }
    return 0;
}
