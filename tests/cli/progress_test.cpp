// The CLI's Progress indicator: quiet for short work, a redrawn line for long work, erased at
// the end.
#include <gtest/gtest.h>

#include <sstream>
#include <thread>

#include "progress.hpp"

namespace sxk::cli {
namespace {

using namespace std::chrono_literals;

TEST(Progress, QuietWhenTheWorkEndsBeforeTheDelay) {
    std::ostringstream out;
    { Progress progress("reading", out, 10s, 10ms); }
    EXPECT_EQ(out.str(), "");
}

TEST(Progress, DrawsAfterTheDelayAndErasesItsLine) {
    std::ostringstream out;
    {
        Progress progress("reading big.mesh", out, 0ms, 5ms);
        std::this_thread::sleep_for(60ms);
    }
    const std::string text = out.str();
    EXPECT_EQ(text.rfind("\r| reading big.mesh  0.", 0), 0u) << text;
    EXPECT_NE(text.find("\r/ reading big.mesh"), std::string::npos) << text;
    EXPECT_TRUE(text.ends_with(" s\033[K\r\033[K")) << text;
}

}  // namespace
}  // namespace sxk::cli
