// Legacy VTK (.vtk) unstructured grids, read and written.
//
// Reading: "# vtk DataFile Version x.y", a title line, ASCII or BINARY (big-endian, as the
// format prescribes), DATASET UNSTRUCTURED_GRID. Sections: POINTS n TYPE (float, double or
// integer types); CELLS in the classic layout (`CELLS n size`, each cell its point count then
// its points; int32 in binary) and in the layout of version 5.1 that VTK 9 writes (`CELLS n+1 m`,
// then `OFFSETS TYPE` with n+1 offsets from 0 and `CONNECTIVITY TYPE` with m points);
// CELL_TYPES; CELL_DATA with SCALARS (LOOKUP_TABLE optional), FIELD arrays and the other
// attributes (read past); POINT_DATA read past; METADATA blocks (up to their blank line) read
// past. Cells and labels then as in the .vtu reader (vtu_read.cpp, vtk_arrays.hpp add_cells):
// labels from the cell data named `label`, `gmsh:physical`, `medit:ref` or `CellEntityIds`.
// Keywords are case-insensitive, as VTK's reader takes them. `long` is 8 bytes, as VTK writes it
// on 64-bit Linux. Lines in messages: the keyword's line (1 + the newlines before it, binary
// data included).
//
// Writing: version 4.2 in the classic layout, which every VTK reader since VTK 5 and meshio
// read; ASCII for Encoding::standard and ascii, BINARY for Encoding::binary. The cells and cell
// data of the .vtu writer (vtk_arrays.hpp Grid): the active array as SCALARS (VTK's legacy reader
// reads only the first SCALARS of a section by default), every other as a FIELD array;
// displacement as VECTORS of the point data. In ASCII, NaN quality (faces, degenerate elements)
// is written as -1: VTK's legacy ASCII reader cannot read "nan".
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "binary_numbers.hpp"
#include "formats.hpp"
#include "text.hpp"
#include "vtk_arrays.hpp"

namespace sxk::io {

namespace {

std::string lower(std::string_view text) {
    std::string result(text);
    std::transform(result.begin(), result.end(), result.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return result;
}

bool blank_char(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

class LegacyReader {
public:
    LegacyReader(std::string_view bytes, const std::string& name) : m_bytes(bytes), m_name(name) {}

    RawMesh read() {
        read_header();
        RawMesh raw;
        raw.vertex_file = raw.edges.file = raw.triangles.file = raw.tetrahedra.file = m_name;
        raw.vertex_base = 0;
        raw.ambient_from_z = true;
        bool have_points = false, have_cells = false, have_types = false;
        std::size_t points = 0;
        std::size_t cells_line = 0, types_line = 0;
        std::vector<std::int64_t> connectivity, offsets, types, labels;
        std::size_t labels_rank = std::size(vtk::label_names);
        std::size_t labels_line = 0;
        Data data = Data::none;
        std::size_t data_count = 0;

        for (std::string_view token = next(); !token.empty(); token = next()) {
            const std::string keyword = lower(token);
            const std::size_t line = this->line();
            if (keyword == "points") {
                if (have_points)
                    fail("a second POINTS section");
                points = count("number of points", std::size_t{invalid_id} - 1);
                const Scalar type = data_type(need("point type"));
                end_of_line();
                const std::vector<double> xyz = coordinates(3 * points, type, "POINTS");
                raw.reserve_points(points);
                for (std::size_t v = 0; v < points; ++v) {
                    raw.points.push_back({xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]});
                    raw.point_lines.push_back(line);
                }
                have_points = true;
            } else if (keyword == "cells") {
                if (have_cells)
                    fail("a second CELLS section");
                const std::size_t first = count("number of cells", max_count);
                const std::size_t second = count("size of the cell list", max_count);
                end_of_line();
                cells_line = line;
                if (peek_keyword("offsets"))
                    read_cells_51(first, second, connectivity, offsets);
                else
                    read_cells_classic(first, second, connectivity, offsets);
                have_cells = true;
            } else if (keyword == "cell_types") {
                if (have_types)
                    fail("a second CELL_TYPES section");
                const std::size_t n = count("number of cells", max_count);
                end_of_line();
                types_line = line;
                types = integers(n, Scalar::int32, "CELL_TYPES");
                have_types = true;
            } else if (keyword == "cell_data" || keyword == "point_data") {
                data_count = count("number of values", max_count);
                data = keyword == "cell_data" ? Data::cells : Data::points;
                if (data == Data::cells && have_types && data_count != types.size())
                    fail("CELL_DATA declares " + std::to_string(data_count) + " values for " +
                         std::to_string(types.size()) + " cells");
            } else if (keyword == "field") {
                need("field name");
                const std::size_t arrays = count("number of arrays", max_count);
                end_of_line();
                for (std::size_t a = 0; a < arrays; ++a) {
                    const std::string_view array_name = need("array name");
                    const std::size_t array_line = this->line();
                    if (array_name == "NULL_ARRAY")  // VTK's mark of an empty slot
                        continue;
                    const std::string array(array_name);
                    const std::size_t components = count("number of components", max_count);
                    const std::size_t tuples = count("number of tuples", max_count);
                    const Scalar type = data_type(need("array type"));
                    end_of_line();
                    const std::size_t rank = label_rank(array);
                    if (data == Data::cells && components == 1 && rank < labels_rank) {
                        if (tuples != data_count)
                            fail_at(array_line, "array " + quote(array) + " holds " +
                                                    std::to_string(tuples) + " values for " +
                                                    std::to_string(data_count) + " cells");
                        labels = integers(tuples, type, "array " + quote(array));
                        labels_rank = rank;
                        labels_line = array_line;
                    } else {
                        skip(checked_product(components, tuples), type, "array " + quote(array));
                    }
                    skip_metadata();
                }
            } else if (keyword == "scalars") {
                require_data(data, keyword);
                const std::string array(need("array name"));
                const Scalar type = data_type(need("array type"));
                std::size_t components = 1;
                if (!line_done())
                    components = count("number of components", 4);
                end_of_line();
                if (peek_keyword("lookup_table")) {
                    next();
                    need("lookup table name");
                    end_of_line();
                }
                const std::size_t rank = label_rank(array);
                if (data == Data::cells && components == 1 && rank < labels_rank) {
                    labels = integers(data_count, type, "SCALARS " + quote(array));
                    labels_rank = rank;
                    labels_line = line;
                } else {
                    skip(checked_product(components, data_count), type,
                         "SCALARS " + quote(array));
                }
                skip_metadata();
            } else if (keyword == "vectors" || keyword == "normals" || keyword == "tensors" ||
                       keyword == "tensors6" || keyword == "global_ids" ||
                       keyword == "pedigree_ids") {
                require_data(data, keyword);
                need("array name");
                const Scalar type = data_type(need("array type"));
                end_of_line();
                const std::size_t per = keyword == "tensors"    ? 9
                                        : keyword == "tensors6" ? 6
                                        : keyword == "global_ids" || keyword == "pedigree_ids"
                                            ? 1
                                            : 3;
                skip(checked_product(per, data_count), type, std::string(token));
                skip_metadata();
            } else if (keyword == "texture_coordinates") {
                require_data(data, keyword);
                need("array name");
                const std::size_t dimension = count("dimension", 3);
                const Scalar type = data_type(need("array type"));
                end_of_line();
                skip(checked_product(dimension, data_count), type, "TEXTURE_COORDINATES");
                skip_metadata();
            } else if (keyword == "color_scalars" || keyword == "lookup_table") {
                require_data(data, keyword);
                need("array name");
                const std::size_t per = count("number of values", 4);
                end_of_line();
                // bytes in binary files, numbers between 0 and 1 in ASCII ones
                const std::size_t n = keyword == "lookup_table" ? checked_product(per, 4)
                                                                : checked_product(per, data_count);
                skip(n, m_binary ? Scalar::uint8 : Scalar::float64, std::string(token));
            } else if (keyword == "metadata") {
                skip_metadata_body();
            } else {
                fail("unknown keyword " + quote(token));
            }
        }

        if (!have_points)
            fail_at(0, "no POINTS section");
        if (have_cells != have_types)
            fail_at(have_cells ? cells_line : types_line,
                    have_cells ? "CELLS without CELL_TYPES" : "CELL_TYPES without CELLS");
        if (types.size() != offsets.size())
            fail_at(types_line, "CELL_TYPES declares " + std::to_string(types.size()) +
                                    " cells, CELLS " + std::to_string(offsets.size()));
        if (!labels.empty() && labels.size() != types.size())
            fail_at(labels_line, "the labels are " + std::to_string(labels.size()) + " for " +
                                     std::to_string(types.size()) + " cells");
        vtk::Cells list;
        list.connectivity = connectivity;
        list.offsets = offsets;
        list.types = types;
        list.labels = labels;
        list.connectivity_line = cells_line;
        list.types_line = types_line;
        vtk::add_cells(raw, list, points, vtk::Where{m_name, labels_line});
        return raw;
    }

private:
    static constexpr std::size_t max_count = std::numeric_limits<std::uint32_t>::max() - 1;

    // ---- the text around the data ------------------------------------------------------------
    // Lines are counted on from the last place asked for (words only move forward), so that a
    // file of many short sections costs its length once, not once per section.
    std::size_t line_at(std::size_t at) const {
        if (at < m_counted_at) {
            m_counted_at = 0;
            m_counted_lines = 1;
        }
        const auto begin = m_bytes.begin();
        m_counted_lines += static_cast<std::size_t>(
            std::count(begin + static_cast<std::ptrdiff_t>(m_counted_at),
                       begin + static_cast<std::ptrdiff_t>(at), '\n'));
        m_counted_at = at;
        return m_counted_lines;
    }
    std::size_t line() const { return line_at(m_token); }
    [[noreturn]] void fail(const std::string& reason) const {
        throw InputError(m_name, line(), reason);
    }
    [[noreturn]] void fail_at(std::size_t line, const std::string& reason) const {
        throw InputError(m_name, line, reason);
    }

    std::string_view next() {
        while (m_at < m_bytes.size() && blank_char(m_bytes[m_at]))
            ++m_at;
        const std::size_t start = m_at;
        while (m_at < m_bytes.size() && !blank_char(m_bytes[m_at]))
            ++m_at;
        const std::string_view token = m_bytes.substr(start, m_at - start);
        // at the end of the file a complaint names the line of the last word
        if (!token.empty())
            m_token = start;
        if (m_binary)  // the words of a binary file are text; its data is read by size
            check_text(token, m_name);
        return token;
    }
    std::string_view need(const char* what) {
        const std::string_view token = next();
        if (token.empty())
            fail(std::string("truncated file: expected ") + what);
        return token;
    }
    // True when only blanks are left on the current line.
    bool line_done() const {
        std::size_t at = m_at;
        while (at < m_bytes.size() && (m_bytes[at] == ' ' || m_bytes[at] == '\t' || m_bytes[at] == '\r'))
            ++at;
        return at == m_bytes.size() || m_bytes[at] == '\n';
    }
    // Binary data starts right after the newline that ends its keyword's line.
    void end_of_line() {
        while (m_at < m_bytes.size() && (m_bytes[m_at] == ' ' || m_bytes[m_at] == '\t' || m_bytes[m_at] == '\r'))
            ++m_at;
        if (m_at < m_bytes.size()) {
            if (m_bytes[m_at] != '\n') {
                m_token = m_at;
                fail("unexpected " + quote(m_bytes.substr(m_at, std::min<std::size_t>(8, m_bytes.size() - m_at))) +
                     " at the end of the line");
            }
            ++m_at;
        }
    }
    // Whether the next word is `keyword` (case-insensitive); nothing is consumed.
    bool peek_keyword(std::string_view keyword) const {
        std::size_t at = m_at;
        while (at < m_bytes.size() && blank_char(m_bytes[at]))
            ++at;
        if (m_bytes.size() - at < keyword.size())
            return false;
        const std::size_t end = at + keyword.size();
        return lower(m_bytes.substr(at, keyword.size())) == keyword &&
               (end == m_bytes.size() || blank_char(m_bytes[end]));
    }

    void read_header() {
        const std::string_view magic = "# vtk DataFile Version";
        const std::size_t first_end = std::min(m_bytes.find('\n'), m_bytes.size());
        if (lower(m_bytes.substr(0, magic.size())) != lower(magic))
            fail_at(1, "not a legacy VTK file: the first line is not '# vtk DataFile Version x.y'");
        check_text(m_bytes.substr(0, first_end), m_name);
        const std::size_t title_end = m_bytes.find('\n', first_end + 1);
        if (first_end == m_bytes.size() || title_end == std::string_view::npos)
            fail_at(1, "truncated file: expected the title and ASCII or BINARY");
        check_text(m_bytes.substr(first_end + 1, title_end - first_end - 1), m_name);
        m_at = title_end + 1;
        const std::string encoding = lower(need("ASCII or BINARY"));
        if (encoding == "binary") {
            m_binary = true;
        } else if (encoding == "ascii") {
            check_text(m_bytes, m_name);
        } else {
            fail("expected ASCII or BINARY, found " + quote(encoding));
        }
        const std::string_view dataset = need("DATASET");
        if (lower(dataset) != "dataset")
            fail("expected DATASET, found " + quote(dataset));
        const std::string_view kind = need("dataset type");
        if (lower(kind) != "unstructured_grid")
            fail("DATASET " + quote(kind) + " is not read; only UNSTRUCTURED_GRID");
        end_of_line();
    }

    std::size_t count(const char* what, std::size_t maximum) {
        const std::string_view token = need(what);
        std::size_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size() || value > maximum)
            fail(std::string("expected ") + what + " (0.." + std::to_string(maximum) + "), found " +
                 quote(token));
        return value;
    }

    std::size_t checked_product(std::size_t a, std::size_t b) const {
        if (a != 0 && b > std::numeric_limits<std::size_t>::max() / 16 / a)
            fail("too many values");
        return a * b;
    }

    Scalar data_type(std::string_view token) const {
        const std::optional<Scalar> type = vtk::legacy_scalar(token);
        if (!type)
            fail("unsupported data type " + quote(token));
        return *type;
    }

    static std::size_t label_rank(std::string_view name) {
        for (std::size_t rank = 0; rank < std::size(vtk::label_names); ++rank)
            if (vtk::label_names[rank] == name)
                return rank;
        return std::size(vtk::label_names);
    }

    enum class Data { none, cells, points };
    void require_data(Data data, const std::string& keyword) const {
        if (data == Data::none)
            fail(quote(lower(keyword)) + " outside CELL_DATA and POINT_DATA");
    }

    // ---- data ----------------------------------------------------------------------------------
    // The bytes of n binary values; "WHAT declares N values but only M bytes remain".
    std::span<const unsigned char> binary(std::size_t n, Scalar type, const std::string& what) {
        const std::size_t size = size_of(type);
        const std::size_t left = m_bytes.size() - m_at;
        if (n > left / size)
            fail(what + " declares " + std::to_string(n) + " values but only " +
                 std::to_string(left) + " bytes remain");
        const auto* data = reinterpret_cast<const unsigned char*>(m_bytes.data() + m_at);
        m_at += n * size;
        return {data, n * size};
    }

    std::vector<double> coordinates(std::size_t n, Scalar type, const std::string& what) {
        const vtk::Where where{m_name, line()};
        if (m_binary) {
            std::vector<double> values = vtk::to_doubles(binary(n, type, what), type, true);
            vtk::check_coordinates(values, where, what);
            return values;
        }
        std::vector<double> values;
        values.reserve(plausible_count(static_cast<std::int64_t>(n), m_bytes.size() - m_at, 2));
        for (std::size_t i = 0; i < n; ++i)
            values.push_back(vtk::parse_coordinate(need("a coordinate"), type, where, what));
        return values;
    }

    std::vector<std::int64_t> integers(std::size_t n, Scalar type, const std::string& what) {
        const vtk::Where where{m_name, line()};
        if (m_binary)
            return vtk::to_integers(binary(n, type, what), type, true, where, what);
        std::vector<std::int64_t> values;
        values.reserve(plausible_count(static_cast<std::int64_t>(n), m_bytes.size() - m_at, 2));
        for (std::size_t i = 0; i < n; ++i)
            values.push_back(vtk::parse_integer(need("an integer"), type, i, where, what));
        return values;
    }

    void skip(std::size_t n, Scalar type, const std::string& what) {
        if (m_binary) {
            binary(n, type, what);
            return;
        }
        for (std::size_t i = 0; i < n; ++i)
            if (next().empty())
                fail(what + " declares " + std::to_string(n) + " values but holds " +
                     std::to_string(i));
    }

    // METADATA after an array (VTK 8.1 and later): its lines up to a blank one.
    void skip_metadata() {
        if (!peek_keyword("metadata"))
            return;
        next();
        skip_metadata_body();
    }
    void skip_metadata_body() {
        end_of_line();
        for (;;) {
            const std::size_t end = m_bytes.find('\n', m_at);
            const std::string_view text =
                m_bytes.substr(m_at, end == std::string_view::npos ? m_bytes.size() - m_at : end - m_at);
            m_token = m_at;
            if (m_binary)
                check_text(text, m_name);
            m_at = end == std::string_view::npos ? m_bytes.size() : end + 1;
            if (std::all_of(text.begin(), text.end(), blank_char) || end == std::string_view::npos)
                return;
        }
    }

    void read_cells_classic(std::size_t cells, std::size_t size,
                            std::vector<std::int64_t>& connectivity,
                            std::vector<std::int64_t>& offsets) {
        const std::size_t line = this->line();
        const std::vector<std::int64_t> list = integers(size, Scalar::int32, "CELLS");
        connectivity.reserve(size);
        offsets.reserve(std::min(cells, size));
        std::size_t at = 0;
        for (std::size_t c = 0; c < cells; ++c) {
            if (at == list.size())
                fail_at(line, "CELLS lists " + std::to_string(c) + " cells in " +
                                  std::to_string(size) + " values, " + std::to_string(cells) +
                                  " declared");
            const std::int64_t k = list[at++];
            if (k < 0 || static_cast<std::size_t>(k) > list.size() - at)
                fail_at(line, "cell " + std::to_string(c) + " has " + std::to_string(k) +
                                  " points, more than the list holds");
            connectivity.insert(connectivity.end(), list.begin() + static_cast<std::ptrdiff_t>(at),
                                list.begin() + static_cast<std::ptrdiff_t>(at) + k);
            at += static_cast<std::size_t>(k);
            offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
        }
        if (at != list.size())
            fail_at(line, "CELLS declares " + std::to_string(size) + " values but its " +
                              std::to_string(cells) + " cells use " + std::to_string(at));
    }

    void read_cells_51(std::size_t offset_count, std::size_t size,
                       std::vector<std::int64_t>& connectivity,
                       std::vector<std::int64_t>& offsets) {
        next();  // OFFSETS
        const Scalar offset_type = data_type(need("offset type"));
        end_of_line();
        const std::size_t line = this->line();
        std::vector<std::int64_t> all = integers(offset_count, offset_type, "OFFSETS");
        if (!all.empty() && all.front() != 0)
            fail_at(line, "OFFSETS starts at " + std::to_string(all.front()) + ", not 0");
        if (!all.empty() && all.back() != static_cast<std::int64_t>(size))
            fail_at(line, "OFFSETS ends at " + std::to_string(all.back()) + ", not at the " +
                              std::to_string(size) + " entries CELLS declares");
        if (!all.empty())
            all.erase(all.begin());
        offsets = std::move(all);
        const std::string_view keyword = need("CONNECTIVITY");
        if (lower(keyword) != "connectivity")
            fail("expected CONNECTIVITY, found " + quote(keyword));
        const Scalar type = data_type(need("connectivity type"));
        end_of_line();
        connectivity = integers(size, type, "CONNECTIVITY");
    }

    std::string_view m_bytes;
    const std::string& m_name;
    std::size_t m_at = 0;
    std::size_t m_token = 0;  // where the last word started
    bool m_binary = false;
    mutable std::size_t m_counted_at = 0, m_counted_lines = 1;  // line_at's place
};

// ---- writing ------------------------------------------------------------------------------------

struct LegacyWriter {
    bool binary;
    std::string out;

    template <typename T>
    void values(std::span<const T> data, std::size_t per_line) {
        if (binary) {
            for (const T& value : data)
                append_number_bytes<T>(out, value, true);
            out += '\n';
            return;
        }
        for (std::size_t i = 0; i < data.size(); ++i) {
            if (i % per_line != 0)
                out += ' ';
            if constexpr (std::is_floating_point_v<T>)
                append_number(out, static_cast<double>(data[i]));
            else
                append_number(out, static_cast<std::int64_t>(data[i]));
            if (i % per_line == per_line - 1 || i + 1 == data.size())
                out += '\n';
        }
    }
};

}  // namespace

Mesh read_vtk(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report) {
    RawMesh raw = LegacyReader(bytes, name).read();
    return build_mesh(raw, name, options, report);
}

std::string write_vtk(const Mesh& mesh, const WriteOptions& options) {
    const vtk::Grid grid = vtk::grid_of(mesh, options);
    LegacyWriter w{options.encoding == Encoding::binary, {}};
    std::string& out = w.out;
    out += "# vtk DataFile Version 4.2\nwritten by simplexkit\n";
    out += w.binary ? "BINARY\n" : "ASCII\n";
    out += "DATASET UNSTRUCTURED_GRID\nPOINTS ";
    append_number(out, grid.points.size());
    out += " double\n";
    static_assert(sizeof(Point) == 3 * sizeof(double));
    w.values<double>({reinterpret_cast<const double*>(grid.points.data()), 3 * grid.points.size()}, 3);

    const std::size_t cells = grid.cell_count();
    out += "CELLS ";
    append_number(out, cells);
    out += ' ';
    append_number(out, cells + grid.connectivity.size());
    out += '\n';
    std::vector<std::int32_t> list;
    list.reserve(cells + grid.connectivity.size());
    std::int64_t begin = 0;
    for (std::int64_t end : grid.offsets) {
        list.push_back(static_cast<std::int32_t>(end - begin));
        for (std::int64_t j = begin; j < end; ++j)
            list.push_back(static_cast<std::int32_t>(grid.connectivity[static_cast<std::size_t>(j)]));
        begin = end;
    }
    if (w.binary) {
        w.values<std::int32_t>(list, 1);
    } else {  // one cell per line
        std::size_t at = 0;
        while (at < list.size()) {
            const std::size_t k = static_cast<std::size_t>(list[at]) + 1;
            w.values<std::int32_t>(std::span<const std::int32_t>(list).subspan(at, k), k);
            at += k;
        }
    }
    out += "CELL_TYPES ";
    append_number(out, cells);
    out += '\n';
    const std::vector<std::int32_t> types(grid.types.begin(), grid.types.end());
    w.values<std::int32_t>(types, 1);

    out += "CELL_DATA ";
    append_number(out, cells);
    out += '\n';
    struct Column {
        const char* name;
        const std::vector<std::int32_t>* integers;
        const std::vector<double>* doubles;
    };
    std::vector<Column> columns{{"label", &grid.label, nullptr}, {"piece", &grid.piece, nullptr}};
    if (grid.quality) {
        columns.push_back({"aspect_ratio", nullptr, &grid.aspect_ratio});
        columns.push_back({"radius_ratio", nullptr, &grid.radius_ratio});
        columns.push_back({"min_angle_deg", nullptr, &grid.min_angle_deg});
    }
    const auto write_column = [&](const Column& column) {
        if (column.integers) {
            w.values<std::int32_t>(*column.integers, 1);
        } else if (w.binary) {
            w.values<double>(*column.doubles, 1);
        } else {
            // VTK 9.1's legacy ASCII reader stops at "nan" (and then refuses the file): the
            // quality of faces and of degenerate elements is written as -1, which no quality
            // measure takes
            std::vector<double> finite(*column.doubles);
            for (double& value : finite)
                if (!std::isfinite(value))
                    value = -1;
            w.values<double>(finite, 1);
        }
    };
    for (const Column& column : columns)
        if (grid.active_scalars == column.name) {
            out += "SCALARS ";
            out += column.name;
            out += column.integers ? " int 1\n" : " double 1\n";
            out += "LOOKUP_TABLE default\n";
            write_column(column);
        }
    out += "FIELD FieldData ";
    append_number(out, columns.size() - 1);
    out += '\n';
    for (const Column& column : columns) {
        if (grid.active_scalars == column.name)
            continue;
        out += column.name;
        out += " 1 ";
        append_number(out, cells);
        out += column.integers ? " int\n" : " double\n";
        write_column(column);
    }
    if (!grid.displacement.empty()) {
        out += "POINT_DATA ";
        append_number(out, grid.points.size());
        out += "\nVECTORS displacement double\n";
        w.values<double>(grid.displacement, 3);
    }
    return out;
}

}  // namespace sxk::io
