// read_bpt (read_bpt.hpp).
#include "read_bpt.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "sxk/io.hpp"

namespace sxk::bezier {
namespace {

constexpr int max_degree = 20;
constexpr long max_patches = 1000000;

class Lines {
public:
    Lines(std::istream& in, std::string name) : m_file(std::move(name)), m_in(in) {}
    // The next non-empty line as a stream; throws at the end of the file.
    std::istringstream next(const char* what) {
        std::string text;
        while (std::getline(m_in, text)) {
            ++m_line;
            if (text.find_first_not_of(" \t\r") != std::string::npos) return std::istringstream(text);
        }
        throw InputError(m_file, m_line, std::string("unexpected end of file, expected ") + what);
    }
    bool more() {
        std::string text;
        while (std::getline(m_in, text)) {
            ++m_line;
            if (text.find_first_not_of(" \t\r") != std::string::npos) return true;
        }
        return false;
    }
    [[noreturn]] void fail(const std::string& reason) const { throw InputError(m_file, m_line, reason); }

private:
    std::string m_file;
    std::istream& m_in;
    std::size_t m_line = 0;
};

// Reads exactly `count` values of type T from the line, nothing after them.
template <class T, std::size_t count>
std::array<T, count> values(Lines& lines, const char* what) {
    std::istringstream line = lines.next(what);
    std::array<T, count> result{};
    for (T& value : result)
        if (!(line >> value)) lines.fail(std::string("expected ") + what);
    std::string rest;
    if (line >> rest) lines.fail(std::string("unexpected '") + rest + "' after " + what);
    return result;
}

// The patches of the text of a .bpt file (read_text_file or read_text_stream: binary data
// refused, a byte order mark dropped).
std::vector<TensorPatch> read_bpt_text(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    Lines lines(in, name);
    const long count = values<long, 1>(lines, "the patch count")[0];
    if (count < 1 || count > max_patches) lines.fail("patch count " + std::to_string(count) + " is not in 1.." + std::to_string(max_patches));
    std::vector<TensorPatch> patches;
    for (long p = 0; p < count; ++p) {
        const auto [m, n] = values<int, 2>(lines, "two degrees");
        if (m < 0 || n < 0 || m > max_degree || n > max_degree)
            lines.fail("degrees " + std::to_string(m) + " " + std::to_string(n) + " are not in 0.." + std::to_string(max_degree));
        TensorPatch patch{m, n, {}};
        for (int i = 0; i < (m + 1) * (n + 1); ++i) {
            const auto xyz = values<double, 3>(lines, "a point x y z");
            if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) lines.fail("coordinate is not finite");
            patch.points.push_back({xyz[0], xyz[1], xyz[2]});
        }
        patches.push_back(std::move(patch));
    }
    if (lines.more()) lines.fail("trailing data after " + std::to_string(count) + " patches");
    return patches;
}

}  // namespace

std::vector<TensorPatch> read_bpt(const std::filesystem::path& path) {
    return read_bpt_text(read_text_file(path), path.string());
}

std::vector<TensorPatch> read_bpt(std::istream& in, const std::string& name) {
    return read_bpt_text(read_text_stream(in, name), name);
}

}  // namespace sxk::bezier
