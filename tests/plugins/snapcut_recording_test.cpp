// What `sxk cut snap` records of a replay (cli/tool_frames.hpp): --series, a ParaView
// collection of one .vtu per step, and --frames, pictures in which the cut can be seen growing.
// The command runs in-process, with the snapcut, degeneracy and bezier plug-ins linked in.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "image.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/plugin_host.hpp"

extern "C" const sxk_plugin_info* sxk_plugin_entry_snapcut();
extern "C" const sxk_plugin_info* sxk_plugin_entry_degeneracy();
extern "C" const sxk_plugin_info* sxk_plugin_entry_bezier();

namespace sxk::test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The thesis' cube (8 x 8 x 8 cells of 1) and a blade standing in x = 3.3 from z = 4 up, crossing
// it along y in 5 movements: a cut inside the body, which no picture of the outside shows.
struct Replay {
    fs::path folder;
    fs::path cube, path, out;
    PluginHost host;
    Replay() {
        folder = fs::temp_directory_path() / ("sxk-recording-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder);
        fs::create_directories(folder);
        cube = folder / "cube.mesh";
        path = folder / "plane.path";
        out = folder / "out.vtu";
        write_mesh(make_kuhn_cube(8).value(), cube);
        std::ofstream(path) << "0.0  3.3 -1 10  3.3 -1 4\n0.1  3.3  1 10  3.3  1 4\n0.2  3.3  3 10  3.3  3 4\n"
                               "0.3  3.3  5 10  3.3  5 4\n0.4  3.3  7 10  3.3  7 4\n0.5  3.3  9 10  3.3  9 4\n";
        EXPECT_TRUE(host.add_static(sxk_plugin_entry_snapcut(), "linked-in snapcut"));
        EXPECT_TRUE(host.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy"));
        EXPECT_TRUE(host.add_static(sxk_plugin_entry_bezier(), "linked-in bezier"));
    }
    ~Replay() { fs::remove_all(folder); }
    int cut(std::vector<std::string> options, std::string* errors = nullptr) {
        std::vector<std::string> args{"cut", "snap", cube.string(), path.string(), out.string()};
        args.insert(args.end(), options.begin(), options.end());
        const FoundCommand found = host.find_command(args);
        EXPECT_NE(found.command, nullptr);
        if (found.command == nullptr) return -1;
        std::ostringstream text, err;
        const int code = found.command->run(std::span(args).subspan(found.words), text, err);
        if (errors) *errors = err.str();
        return code;
    }
};

struct SeriesEntry {
    std::string time, file;
};

// The DataSet entries of a .pvd, in order; the test fails on anything else in the file.
std::vector<SeriesEntry> read_collection(const fs::path& pvd) {
    const std::string text = slurp(pvd);
    const std::string head =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <Collection>\n";
    const std::string tail = "  </Collection>\n</VTKFile>\n";
    EXPECT_EQ(text.substr(0, head.size()), head);
    EXPECT_GE(text.size(), head.size() + tail.size());
    EXPECT_EQ(text.substr(text.size() - std::min(text.size(), tail.size())), tail);
    std::vector<SeriesEntry> entries;
    const std::regex line("    <DataSet timestep=\"([^\"]+)\" group=\"\" part=\"0\" file=\"([^\"]+)\"/>\n");
    const std::string body = text.substr(head.size(), text.size() - head.size() - tail.size());
    std::size_t at = 0;
    for (std::sregex_iterator it(body.begin(), body.end(), line), end; it != end; ++it) {
        EXPECT_EQ(static_cast<std::size_t>(it->position()), at) << "unexpected text in " << pvd;
        at = static_cast<std::size_t>(it->position() + it->length());
        entries.push_back({(*it)[1], (*it)[2]});
    }
    EXPECT_EQ(at, body.size()) << "unexpected text in " << pvd;
    return entries;
}

TEST(ToolRecording, TheSeriesListsOneFilePerStepAtItsTimeAndTheLastIsOut) {
    Replay replay;
    const fs::path pvd = replay.folder / "cut.pvd";
    ASSERT_EQ(replay.cut({"--series", pvd.string()}), 0);
    const std::vector<SeriesEntry> entries = read_collection(pvd);
    ASSERT_EQ(entries.size(), 6u);
    const char* times[] = {"0", "0.1", "0.2", "0.3", "0.4", "0.5"};
    for (std::size_t i = 0; i < entries.size(); ++i) {
        EXPECT_EQ(entries[i].time, times[i]);
        EXPECT_EQ(entries[i].file, "cut_00000" + std::to_string(i + 1) + ".vtu");  // relative to the .pvd
        const Mesh step = read_mesh(replay.folder / entries[i].file);
        EXPECT_TRUE(step.validate()) << entries[i].file;
    }
    // the last step is OUT, byte for byte: the same writer with the same options
    EXPECT_EQ(slurp(replay.folder / entries.back().file), slurp(replay.out));
    // the steps differ: the dissections add vertices (36 in all, tests/cli/cut_snap_test.cpp)
    EXPECT_LT(read_mesh(replay.folder / entries.front().file).vertices_in_elements(),
              read_mesh(replay.out).vertices_in_elements());
}

TEST(ToolRecording, EveryNthStepAndAlwaysTheLast) {
    Replay replay;
    const fs::path pvd = replay.folder / "every.pvd";
    ASSERT_EQ(replay.cut({"--series", pvd.string(), "--series-every", "4"}), 0);
    const std::vector<SeriesEntry> entries = read_collection(pvd);
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[0].file, "every_000004.vtu");
    EXPECT_EQ(entries[1].file, "every_000006.vtu");
    EXPECT_EQ(entries[1].time, "0.5");
    EXPECT_FALSE(fs::exists(replay.folder / "every_000005.vtu"));
    EXPECT_EQ(slurp(replay.folder / "every_000006.vtu"), slurp(replay.out));
}

// A command that fails after its steps (here: --undo asks for more steps than were taken) leaves a
// collection of the steps it took, every file in it whole; OUT is not written.
TEST(ToolRecording, TheSeriesStaysValidWhenTheCommandFails) {
    Replay replay;
    const fs::path pvd = replay.folder / "failed.pvd";
    std::string errors;
    EXPECT_EQ(replay.cut({"--series", pvd.string(), "--undo", "7"}, &errors), 2);
    EXPECT_EQ(errors, "sxk: cut snap: --undo 7: only 6 steps were taken\n");
    EXPECT_FALSE(fs::exists(replay.out));
    const std::vector<SeriesEntry> entries = read_collection(pvd);
    ASSERT_EQ(entries.size(), 6u);
    for (const SeriesEntry& entry : entries) EXPECT_TRUE(read_mesh(replay.folder / entry.file).validate());
}

TEST(ToolRecording, BadSeriesOptionsAreUsageErrors) {
    Replay replay;
    std::string errors;
    EXPECT_EQ(replay.cut({"--series", (replay.folder / "cut.txt").string()}, &errors), 2);
    EXPECT_EQ(errors, "sxk: cut snap: --series " + (replay.folder / "cut.txt").string() +
                          ": the series is a ParaView collection; name it *.pvd\n");
    const fs::path nowhere = replay.folder / "nowhere" / "cut.pvd";
    EXPECT_EQ(replay.cut({"--series", nowhere.string()}, &errors), 2);
    EXPECT_EQ(errors, "sxk: cut snap: --series " + nowhere.string() + ": no such folder " +
                          (replay.folder / "nowhere").string() + "\n");
    EXPECT_EQ(replay.cut({"--animation", (replay.folder / "a.gif").string()}, &errors), 2);
    EXPECT_EQ(errors, "sxk: cut snap: --animation needs --frames (it is made of the pictures)\n");
    EXPECT_EQ(replay.cut({"--frames", (replay.folder / "f").string(), "--animation", (replay.folder / "a.avi").string()},
                         &errors),
              2);
    EXPECT_EQ(errors, "sxk: cut snap: --animation " + (replay.folder / "a.avi").string() + ": name it *.gif or *.mp4\n");
    EXPECT_FALSE(fs::exists(replay.out));
}

// Pixels in the cut's magenta (render_plugin.hpp cut_colour, drawn over the surface or seen
// through it): red and blue well above green. No piece colour, the grey of nothing, the tool's
// near black or the white background is.
std::size_t cut_pixels(const pictures::Image& image) {
    std::size_t count = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        const int r = image.rgb[i], g = image.rgb[i + 1], b = image.rgb[i + 2];
        if (r - g > 60 && b - g > 60) ++count;
    }
    return count;
}

std::size_t pixels_not_white(const pictures::Image& image) {
    std::size_t count = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
        if (image.rgb[i] < 250 || image.rgb[i + 1] < 250 || image.rgb[i + 2] < 250) ++count;
    return count;
}

// The frames of a cut inside the cube: the cut's pixels grow with the steps (the cut is hidden
// inside the body, so they are its faces seen through the surface), one size for all, the body
// filling most of each picture.
TEST(ToolRecording, TheCutGrowsOverTheFrames) {
    Replay replay;
    const fs::path frames = replay.folder / "frames";
    ASSERT_EQ(replay.cut({"--frames", frames.string()}), 0);
    std::vector<std::size_t> cut;
    for (int step = 0; step <= 6; ++step) {
        const pictures::Image image = pictures::read_png(frames / ("step-000" + std::to_string(step) + ".png"));
        cut.push_back(cut_pixels(image));
        const pictures::Image first = pictures::read_png(frames / "step-0000.png");
        EXPECT_EQ(image.width, first.width);
        EXPECT_EQ(image.height, first.height);
        // the cube seen from above a corner covers half of a picture fitted to it (0.50-0.51 measured)
        EXPECT_GT(pixels_not_white(image) * 10, image.rgb.size() / 3 * 4) << "step " << step;
    }
    for (std::size_t step = 1; step < cut.size(); ++step) EXPECT_GE(cut[step], cut[step - 1]) << "step " << step;
    EXPECT_GT(cut.back(), cut.front() + 1000);
    std::ostringstream counts;
    for (const std::size_t c : cut) counts << c << ' ';
    RecordProperty("cut_pixels", counts.str());
}

}  // namespace
}  // namespace sxk::test
