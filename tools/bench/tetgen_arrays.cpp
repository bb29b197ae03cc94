#include "tetgen_arrays.hpp"

#include <charconv>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace sxk_bench {
namespace {

std::string read_file(const std::string& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file)
        throw std::runtime_error(path + ": cannot open");
    std::string text;
    char buffer[1 << 16];
    std::size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
        text.append(buffer, got);
    return text;
}

// Whitespace-separated numbers; '#' starts a comment running to the end of the line.
class Tokens {
public:
    Tokens(const std::string& path, const std::string& text)
        : m_path(path), m_begin(text.data()), m_at(m_begin), m_end(m_begin + text.size()) {}

    template <class Number>
    Number next() {
        skip();
        Number value{};
        const auto [stop, error] = std::from_chars(m_at, m_end, value);
        if (error != std::errc() || stop == m_at)
            throw std::runtime_error(m_path + ": expected a number near byte " +
                                     std::to_string(m_at - m_begin));
        m_at = stop;
        return value;
    }
    // Skips the rest of the current line (attributes, markers we do not read).
    void end_line() {
        while (m_at < m_end && *m_at != '\n')
            ++m_at;
    }

private:
    void skip() {
        while (m_at < m_end) {
            if (*m_at == '#') {
                end_line();
            } else if (*m_at == ' ' || *m_at == '\t' || *m_at == '\r' || *m_at == '\n') {
                ++m_at;
            } else {
                break;
            }
        }
    }
    std::string m_path;
    const char* m_begin;
    const char* m_at;
    const char* m_end;
};

}  // namespace

TetArrays load_tetgen(const std::string& ele_path) {
    const std::string suffix = ".ele";
    if (ele_path.size() <= suffix.size() ||
        ele_path.compare(ele_path.size() - suffix.size(), suffix.size(), suffix) != 0)
        throw std::runtime_error(ele_path + ": expected a TetGen .ele file");
    const std::string node_path = ele_path.substr(0, ele_path.size() - suffix.size()) + ".node";

    TetArrays arrays;
    std::uint32_t first_index = 0;
    {
        const std::string text = read_file(node_path);
        Tokens tokens(node_path, text);
        const auto count = tokens.next<std::size_t>();
        const auto dimension = tokens.next<int>();
        tokens.end_line();
        if (dimension != 3)
            throw std::runtime_error(node_path + ": dimension is not 3");
        arrays.points.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const auto index = tokens.next<std::uint32_t>();
            if (i == 0)
                first_index = index;
            for (double& coordinate : arrays.points[i])
                coordinate = tokens.next<double>();
            tokens.end_line();
        }
    }
    {
        const std::string text = read_file(ele_path);
        Tokens tokens(ele_path, text);
        const auto count = tokens.next<std::size_t>();
        const auto nodes_per_tet = tokens.next<int>();
        tokens.end_line();
        if (nodes_per_tet != 4 && nodes_per_tet != 10)
            throw std::runtime_error(ele_path + ": nodes per tetrahedron is not 4 or 10");
        arrays.tets.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            tokens.next<std::uint32_t>();  // the tet's own index
            for (std::uint32_t& vertex : arrays.tets[i]) {
                vertex = tokens.next<std::uint32_t>() - first_index;
                if (vertex >= arrays.points.size())
                    throw std::runtime_error(ele_path + ": tetrahedron " + std::to_string(i) +
                                             " names an unknown node");
            }
            tokens.end_line();
        }
    }
    return arrays;
}

}  // namespace sxk_bench
