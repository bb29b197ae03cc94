// Tool paths (sxk/tool_path.hpp): line mode of the strict text layer, '#' comments.
#include "sxk/tool_path.hpp"

#include <algorithm>

#include "formats.hpp"
#include "raw_mesh.hpp"
#include "sxk/io.hpp"
#include "text.hpp"

namespace sxk {
namespace {

// The time of a sample: the text layer's number with its own words for a time that is not finite
// (the layer says "coordinate").
double read_time(const io::Cursor& cursor, std::string_view token) {
    try {
        return cursor.to_double(token, "a time");
    } catch (const InputError& e) {
        if (e.reason() == "coordinate is not finite")
            throw InputError(e.file(), e.line(), "time is not finite");
        throw;
    }
}

std::string counts_text(std::span<const int> columns) {
    std::string text;
    for (std::size_t i = 0; i < columns.size(); ++i) {
        if (i > 0)
            text += i + 1 == columns.size() ? " or " : ", ";
        text += std::to_string(columns[i]);
    }
    return text;
}

}  // namespace

ToolPath parse_tool_path(std::string_view text, const std::string& name,
                         std::span<const int> columns) {
    io::Cursor cursor(text, name, '#');
    ToolPath path;
    std::string_view previous_time;
    while (cursor.next_line()) {
        ToolSample sample;
        const std::string_view time = cursor.need_in_line("a time");
        sample.time = read_time(cursor, time);
        sample.line = cursor.line();
        int count = 0;
        for (std::string_view token = cursor.next_in_line(); !token.empty();
             token = cursor.next_in_line()) {
            if (count == 6)
                throw InputError(name, cursor.line(), "more than 6 values after the time");
            sample.values[static_cast<std::size_t>(count++)] =
                cursor.to_double(token, "a coordinate");
        }
        if (path.samples.empty()) {
            if (std::find(columns.begin(), columns.end(), count) == columns.end())
                throw InputError(name, cursor.line(),
                                 std::to_string(count) + " values after the time; expected " +
                                     counts_text(columns));
            path.columns = count;
        } else {
            if (count != path.columns)
                throw InputError(name, cursor.line(),
                                 std::to_string(count) +
                                     " values after the time; the first sample has " +
                                     std::to_string(path.columns));
            if (sample.time < path.samples.back().time)
                throw InputError(name, cursor.line(),
                                 "time " + std::string(time) + " is before the previous sample's " +
                                     std::string(previous_time));
        }
        previous_time = time;
        path.samples.push_back(sample);
    }
    if (path.samples.size() < 2)
        throw InputError(name, 0,
                         std::to_string(path.samples.size()) +
                             (path.samples.size() == 1 ? " sample" : " samples") +
                             "; a path needs at least 2 (a tool moves from one to the next)");
    return path;
}

ToolPath read_tool_path(const std::filesystem::path& path, std::span<const int> columns) {
    return parse_tool_path(read_text_file(path), path.string(), columns);
}

std::vector<SweptTriangle> parse_swept_triangles(std::string_view text, const std::string& name) {
    const io::RawMesh raw = io::parse_obj(text, name);
    const io::CellList& cells = raw.triangles;
    if (cells.count() == 0) throw InputError(name, 0, "no face: a swept path is a list of triangles ('f a b c')");
    std::vector<SweptTriangle> triangles(cells.count());
    for (std::size_t i = 0; i < cells.count(); ++i) {
        for (std::size_t j = 0; j < 3; ++j) triangles[i].corners[j] = raw.points[cells.vertices[3 * i + j]];
        triangles[i].line = cells.lines[i];
    }
    return triangles;
}

std::vector<SweptTriangle> read_swept_triangles(const std::filesystem::path& path) {
    return parse_swept_triangles(read_text_file(path), path.string());
}

}  // namespace sxk
