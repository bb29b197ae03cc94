#include "vtk_arrays.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include <zlib.h>

#include "../fresh_array.hpp"
#include "binary_numbers.hpp"
#include "sxk/components.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io::vtk {

void Where::fail(const std::string& reason) const {
    throw InputError(file, line, reason);
}

// ---- scalar types -----------------------------------------------------------------------------

std::optional<Scalar> xml_scalar(std::string_view name) {
    struct Entry {
        std::string_view name;
        Scalar type;
    };
    // the names vtkXMLDataElement accepts, the old Char/Short/... spellings included
    static constexpr Entry entries[] = {
        {"Int8", Scalar::int8},       {"Char", Scalar::int8},     {"UInt8", Scalar::uint8},
        {"UnsignedChar", Scalar::uint8}, {"Int16", Scalar::int16}, {"Short", Scalar::int16},
        {"UInt16", Scalar::uint16},   {"UnsignedShort", Scalar::uint16},
        {"Int32", Scalar::int32},     {"Int", Scalar::int32},     {"UInt32", Scalar::uint32},
        {"UnsignedInt", Scalar::uint32}, {"Int64", Scalar::int64}, {"UInt64", Scalar::uint64},
        {"Float32", Scalar::float32}, {"Float", Scalar::float32}, {"Float64", Scalar::float64},
        {"Double", Scalar::float64}};
    for (const Entry& entry : entries)
        if (entry.name == name)
            return entry.type;
    return std::nullopt;
}

std::string_view xml_name(Scalar type) {
    switch (type) {
        case Scalar::int8:
            return "Int8";
        case Scalar::uint8:
            return "UInt8";
        case Scalar::int16:
            return "Int16";
        case Scalar::uint16:
            return "UInt16";
        case Scalar::int32:
            return "Int32";
        case Scalar::uint32:
            return "UInt32";
        case Scalar::int64:
            return "Int64";
        case Scalar::uint64:
            return "UInt64";
        case Scalar::float32:
            return "Float32";
        case Scalar::float64:
            return "Float64";
    }
    return "";
}

std::optional<Scalar> legacy_scalar(std::string_view name) {
    struct Entry {
        std::string_view name;
        Scalar type;
    };
    static constexpr Entry entries[] = {
        {"char", Scalar::int8},           {"signed_char", Scalar::int8},
        {"unsigned_char", Scalar::uint8}, {"short", Scalar::int16},
        {"unsigned_short", Scalar::uint16}, {"int", Scalar::int32},
        {"unsigned_int", Scalar::uint32}, {"long", Scalar::int64},
        {"unsigned_long", Scalar::uint64}, {"long_long", Scalar::int64},
        {"unsigned_long_long", Scalar::uint64}, {"vtkIdType", Scalar::int64},
        {"float", Scalar::float32},       {"double", Scalar::float64},
        {"vtktypeint8", Scalar::int8},    {"vtktypeuint8", Scalar::uint8},
        {"vtktypeint16", Scalar::int16},  {"vtktypeuint16", Scalar::uint16},
        {"vtktypeint32", Scalar::int32},  {"vtktypeuint32", Scalar::uint32},
        {"vtktypeint64", Scalar::int64},  {"vtktypeuint64", Scalar::uint64},
        {"vtktypefloat32", Scalar::float32}, {"vtktypefloat64", Scalar::float64}};
    for (const Entry& entry : entries)
        if (entry.name == name)
            return entry.type;
    return std::nullopt;
}

namespace {

// Calls f.template operator()<T>() with the C++ type of `type`.
template <typename F>
decltype(auto) with_type(Scalar type, F&& f) {
    switch (type) {
        case Scalar::int8:
            return f.template operator()<std::int8_t>();
        case Scalar::uint8:
            return f.template operator()<std::uint8_t>();
        case Scalar::int16:
            return f.template operator()<std::int16_t>();
        case Scalar::uint16:
            return f.template operator()<std::uint16_t>();
        case Scalar::int32:
            return f.template operator()<std::int32_t>();
        case Scalar::uint32:
            return f.template operator()<std::uint32_t>();
        case Scalar::int64:
            return f.template operator()<std::int64_t>();
        case Scalar::uint64:
            return f.template operator()<std::uint64_t>();
        case Scalar::float32:
            return f.template operator()<float>();
        case Scalar::float64:
            break;
    }
    return f.template operator()<double>();
}

std::string number_text(double value) {
    std::string text;
    append_number(text, value);
    return text;
}

// A double that must be a whole number within int64.
std::int64_t whole(double value, std::size_t item, const Where& where, const std::string& what) {
    // 2^63 is exact in double; every double below it converts without overflow
    if (!(value >= -9223372036854775808.0 && value < 9223372036854775808.0) ||
        value != std::trunc(value))
        where.fail(what + ": value " + number_text(value) + " (item " + std::to_string(item) +
                   ") is not an integer");
    return static_cast<std::int64_t>(value);
}

bool space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// Calls take(token, index) for each whitespace-separated token, exactly `count` of them.
template <typename Take>
void for_tokens(std::string_view text, std::size_t count, const Where& where,
                const std::string& what, Take&& take) {
    const char* p = text.data();
    const char* end = p + text.size();
    std::size_t i = 0;
    for (;;) {
        while (p != end && space(*p))
            ++p;
        if (p == end)
            break;
        const char* start = p;
        while (p != end && !space(*p))
            ++p;
        if (i == count)
            where.fail(what + " holds more than the " + std::to_string(count) +
                       " values expected");
        take(std::string_view(start, static_cast<std::size_t>(p - start)), i);
        ++i;
    }
    if (i != count)
        where.fail(what + " holds " + std::to_string(i) + " values, " + std::to_string(count) +
                   " expected");
}

// A float value of a label array as VTK's ASCII reader takes it (istream, which allows '+').
double parse_double(std::string_view token, Scalar type, const Where& where,
                    const std::string& what) {
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+')
        digits.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range)
        where.fail(what + ": value " + quote(token) + " is too large");
    if (error != std::errc() || end != digits.data() + digits.size())
        where.fail(what + ": expected a number, found " + quote(token));
    return type == Scalar::float32 ? static_cast<double>(static_cast<float>(value)) : value;
}

}  // namespace

std::vector<double> to_doubles(std::span<const unsigned char> bytes, Scalar type, bool big_endian) {
    const std::size_t size = size_of(type);
    const std::size_t count = bytes.size() / size;
    std::vector<double> values(count);
    with_type(type, [&]<typename T>() {
        for (std::size_t i = 0; i < count; ++i)
            values[i] = static_cast<double>(load_number<T>(bytes.data() + i * size, big_endian));
    });
    return values;
}

std::vector<std::int64_t> to_integers(std::span<const unsigned char> bytes, Scalar type,
                                      bool big_endian, const Where& where,
                                      const std::string& what) {
    const std::size_t size = size_of(type);
    const std::size_t count = bytes.size() / size;
    std::vector<std::int64_t> values(count);
    with_type(type, [&]<typename T>() {
        for (std::size_t i = 0; i < count; ++i) {
            const T value = load_number<T>(bytes.data() + i * size, big_endian);
            if constexpr (std::is_floating_point_v<T>) {
                values[i] = whole(static_cast<double>(value), i, where, what);
            } else if constexpr (std::is_same_v<T, std::uint64_t>) {
                if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
                    where.fail(what + ": value " + std::to_string(value) + " (item " +
                               std::to_string(i) + ") is too large");
                values[i] = static_cast<std::int64_t>(value);
            } else {
                values[i] = static_cast<std::int64_t>(value);
            }
        }
    });
    return values;
}

double parse_coordinate(std::string_view token, Scalar type, const Where& where,
                        const std::string& what) {
    // the text readers' number rules and messages (text.hpp, Cursor::to_double)
    static const std::string no_file;
    const Cursor numbers(std::string_view(), no_file, '\0');
    double value = 0;
    try {
        value = numbers.to_double(token, "a coordinate");
    } catch (const InputError& error) {
        where.fail(what + ": " + error.reason());
    }
    return type == Scalar::float32 ? static_cast<double>(static_cast<float>(value)) : value;
}

std::int64_t parse_integer(std::string_view token, Scalar type, std::size_t item,
                           const Where& where, const std::string& what) {
    if (is_float(type))
        return whole(parse_double(token, type, where, what), item, where, what);
    std::int64_t value = 0;
    const char* begin = token.data();
    if (token.size() > 1 && token[0] == '+')
        ++begin;  // istream, which VTK's ASCII readers use, takes a leading '+'
    const auto [end, error] = std::from_chars(begin, token.data() + token.size(), value);
    if (error == std::errc::result_out_of_range)
        where.fail(what + ": value " + quote(token) + " is too large");
    if (error != std::errc() || end != token.data() + token.size())
        where.fail(what + ": expected an integer, found " + quote(token));
    return value;
}

std::vector<double> ascii_coordinates(std::string_view text, std::size_t count, Scalar type,
                                      const Where& where, const std::string& what) {
    std::vector<double> values;
    values.reserve(plausible_count(static_cast<std::int64_t>(std::min<std::size_t>(
                                       count, std::numeric_limits<std::int64_t>::max())),
                                   text.size(), 2));
    for_tokens(text, count, where, what, [&](std::string_view token, std::size_t) {
        values.push_back(parse_coordinate(token, type, where, what));
    });
    return values;
}

void check_coordinates(std::span<const double> values, const Where& where,
                       const std::string& what) {
    for (double value : values)
        if (!std::isfinite(value))
            where.fail(what + ": coordinate is not finite");
}

std::vector<std::int64_t> ascii_integers(std::string_view text, std::size_t count, Scalar type,
                                         const Where& where, const std::string& what) {
    std::vector<std::int64_t> values;
    values.reserve(plausible_count(static_cast<std::int64_t>(std::min<std::size_t>(
                                       count, std::numeric_limits<std::int64_t>::max())),
                                   text.size(), 2));
    for_tokens(text, count, where, what, [&](std::string_view token, std::size_t i) {
        values.push_back(parse_integer(token, type, i, where, what));
    });
    return values;
}

// ---- binary blocks ----------------------------------------------------------------------------

void RawSource::read(std::size_t n, std::vector<unsigned char>& out) {
    if (n > most_left())
        m_where.fail(m_what + ": truncated data");
    out.insert(out.end(), m_bytes.begin() + static_cast<std::ptrdiff_t>(m_at),
               m_bytes.begin() + static_cast<std::ptrdiff_t>(m_at + n));
    m_at += n;
}

std::size_t Base64Source::most_left() const {
    return (m_text.size() - m_at + 3) / 4 * 3 + static_cast<std::size_t>(m_group_size - m_group_used);
}

namespace {

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '+')
        return 62;
    if (c == '/')
        return 63;
    return -1;
}

}  // namespace

bool Base64Source::decode_group() {
    char chars[4];
    int n = 0;
    while (n < 4) {
        while (m_at < m_text.size() && space(m_text[m_at]))
            ++m_at;
        if (m_at == m_text.size())
            break;
        chars[n++] = m_text[m_at++];
    }
    if (n == 0)
        return false;
    if (n < 4)
        m_where.fail(m_what + ": truncated base64 data");
    int values[4];
    int padding = 0;
    for (int j = 0; j < 4; ++j) {
        values[j] = base64_value(chars[j]);
        if (chars[j] == '=' && j >= 2 && (padding > 0 || j == 2 || chars[3] == '=')) {
            values[j] = 0;
            ++padding;
            continue;
        }
        if (values[j] < 0 || padding > 0) {
            std::string shown(1, chars[j]);
            if (static_cast<unsigned char>(chars[j]) < 0x20 || static_cast<unsigned char>(chars[j]) >= 0x7F) {
                static const char digits[] = "0123456789ABCDEF";
                const auto byte = static_cast<unsigned char>(chars[j]);
                shown = std::string("0x") + digits[byte >> 4] + digits[byte & 15];
            } else {
                shown = "'" + shown + "'";
            }
            m_where.fail(m_what + ": invalid base64 character " + shown);
        }
    }
    const std::uint32_t bits = static_cast<std::uint32_t>(values[0]) << 18 |
                               static_cast<std::uint32_t>(values[1]) << 12 |
                               static_cast<std::uint32_t>(values[2]) << 6 |
                               static_cast<std::uint32_t>(values[3]);
    m_group[0] = static_cast<unsigned char>(bits >> 16);
    m_group[1] = static_cast<unsigned char>(bits >> 8);
    m_group[2] = static_cast<unsigned char>(bits);
    m_group_size = 3 - padding;
    m_group_used = 0;
    return true;
}

void Base64Source::read(std::size_t n, std::vector<unsigned char>& out) {
    while (n > 0) {
        if (m_group_used == m_group_size && !decode_group())
            m_where.fail(m_what + ": truncated base64 data");
        while (n > 0 && m_group_used < m_group_size) {
            out.push_back(m_group[m_group_used++]);
            --n;
        }
    }
}

namespace {

std::uint64_t read_word(Source& source, std::size_t header_bytes, bool big_endian) {
    std::vector<unsigned char> bytes;
    source.read(header_bytes, bytes);
    return header_bytes == 4 ? load_number<std::uint32_t>(bytes.data(), big_endian)
                             : load_number<std::uint64_t>(bytes.data(), big_endian);
}

// deflate's largest expansion: 258 bytes from a 2-bit code at best (zlib's technical notes)
constexpr std::uint64_t deflate_ratio = 1032;

}  // namespace

std::vector<unsigned char> read_block(Source& source, std::size_t header_bytes,
                                      bool header_big_endian, bool compressed,
                                      std::uint64_t expected_bytes, const Where& where,
                                      const std::string& what) {
    std::vector<unsigned char> data;
    const auto word = [&] { return read_word(source, header_bytes, header_big_endian); };
    if (!compressed) {
        const std::uint64_t n = word();
        if (n != expected_bytes)
            where.fail(what + ": header declares " + std::to_string(n) + " bytes, " +
                       std::to_string(expected_bytes) + " expected");
        if (n > source.most_left())
            where.fail(what + ": header declares " + std::to_string(n) + " bytes but only " +
                       std::to_string(source.most_left()) + " remain");
        data.reserve(static_cast<std::size_t>(n));
        source.read(static_cast<std::size_t>(n), data);
        return data;
    }
    const std::uint64_t blocks = word();
    const std::uint64_t block_size = word();
    const std::uint64_t last_size = word();
    if (blocks > source.most_left() / header_bytes)
        where.fail(what + ": compression header declares " + std::to_string(blocks) +
                   " blocks but only " + std::to_string(source.most_left()) + " bytes remain");
    // the uncompressed total; no header can overflow it
    constexpr std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
    bool overflow = false;
    std::uint64_t total = 0;
    if (blocks > 0) {
        const std::uint64_t last = last_size != 0 ? last_size : block_size;
        overflow = blocks > 1 && block_size > (most - last) / (blocks - 1);
        if (!overflow)
            total = (blocks - 1) * block_size + last;
    }
    if (overflow || total != expected_bytes)
        where.fail(what + ": compression header declares " +
                   (overflow ? std::string("more than 2^64") : std::to_string(total)) +
                   " bytes, " + std::to_string(expected_bytes) + " expected");
    std::vector<std::uint64_t> sizes(static_cast<std::size_t>(blocks));
    std::uint64_t compressed_total = 0;  // saturates at 2^64 - 1
    for (std::uint64_t& size : sizes) {
        size = word();
        compressed_total = size > most - compressed_total ? most : compressed_total + size;
    }
    if (compressed_total > source.most_left())
        where.fail(what + ": compressed blocks declare " + std::to_string(compressed_total) +
                   " bytes but only " + std::to_string(source.most_left()) + " remain");
    const auto inflated_size = [&](std::size_t b) {
        return b + 1 == sizes.size() && last_size != 0 ? last_size : block_size;
    };
    // a zlib bomb is refused here, before anything is allocated for it
    for (std::size_t b = 0; b < sizes.size(); ++b)
        if (inflated_size(b) > sizes[b] * deflate_ratio)
            where.fail(what + ": block " + std::to_string(b + 1) + " declares " +
                       std::to_string(inflated_size(b)) + " bytes from " +
                       std::to_string(sizes[b]) + " compressed, more than zlib can expand");
    data.resize(static_cast<std::size_t>(expected_bytes));
    std::vector<unsigned char> packed;
    std::size_t at = 0;
    for (std::size_t b = 0; b < sizes.size(); ++b) {
        packed.clear();
        source.read(static_cast<std::size_t>(sizes[b]), packed);
        const std::uint64_t want = inflated_size(b);
        uLongf produced = static_cast<uLongf>(want);
        uLong consumed = static_cast<uLong>(packed.size());
        // uncompress2 writes at most `want` bytes: a block that inflates to more stops there
        const int status = uncompress2(data.data() + at, &produced, packed.data(), &consumed);
        const std::string block = "block " + std::to_string(b + 1) + " of " + std::to_string(blocks);
        if (status == Z_BUF_ERROR && produced == want)
            where.fail(what + ": " + block + " inflates to more than its declared " +
                       std::to_string(want) + " bytes");
        if (status != Z_OK)
            where.fail(what + ": " + block + " is not valid zlib data");
        if (produced != want)
            where.fail(what + ": " + block + " inflates to " + std::to_string(produced) +
                       " bytes, " + std::to_string(want) + " declared");
        at += static_cast<std::size_t>(want);
    }
    return data;
}

// ---- writing ----------------------------------------------------------------------------------

void append_base64(std::string& out, std::span<const unsigned char> bytes) {
    static constexpr char digits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const std::uint32_t bits = std::uint32_t{bytes[i]} << 16 | std::uint32_t{bytes[i + 1]} << 8 |
                                   std::uint32_t{bytes[i + 2]};
        out += digits[bits >> 18];
        out += digits[(bits >> 12) & 63];
        out += digits[(bits >> 6) & 63];
        out += digits[bits & 63];
    }
    if (i < bytes.size()) {
        const bool two = i + 2 == bytes.size();
        const std::uint32_t bits =
            std::uint32_t{bytes[i]} << 16 | (two ? std::uint32_t{bytes[i + 1]} << 8 : 0);
        out += digits[bits >> 18];
        out += digits[(bits >> 12) & 63];
        out += two ? digits[(bits >> 6) & 63] : '=';
        out += '=';
    }
}


void append_zlib_blocks(std::string& out, std::span<const unsigned char> data) {
    constexpr std::size_t block_size = 32768;
    const std::size_t blocks = (data.size() + block_size - 1) / block_size;
    const std::size_t header = out.size();
    append_number_bytes<std::uint64_t>(out, blocks, false);
    append_number_bytes<std::uint64_t>(out, block_size, false);
    append_number_bytes<std::uint64_t>(out, data.size() % block_size, false);
    out.append(8 * blocks, '\0');  // the compressed sizes, filled in below
    std::string packed(compressBound(block_size), '\0');
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::size_t begin = b * block_size;
        const std::size_t size = std::min(block_size, data.size() - begin);
        uLongf length = static_cast<uLongf>(packed.size());
        // level 1: on the arrays of a 235k-tetrahedron cylinder (18.1 MB, `sxk generate --shape
        // cylinder --rings 10 --layers 120`) level 5, VTK's, took 1.15x the time for 5% fewer
        // bytes (4.13 -> 3.92 MB), level 6 1.23x for the same
        if (compress2(reinterpret_cast<Bytef*>(packed.data()), &length, data.data() + begin,
                      static_cast<uLong>(size), 1) != Z_OK)
            throw OutputError("zlib could not compress a block");
        out.append(packed.data(), length);
        std::string size_bytes;
        append_number_bytes<std::uint64_t>(size_bytes, length, false);
        out.replace(header + 24 + 8 * b, 8, size_bytes);
    }
}

// ---- the grid the writers write ---------------------------------------------------------------

namespace {

// An element of which `face` is a face: the boundary map for boundary faces, else the star of
// its first vertex (faces are few: the labelled ones).
ElementId element_having(const Mesh& mesh, const Simplex& face) {
    for (const Simplex& side : {face, face.mate()})
        if (const FaceId f = mesh.find_boundary_face(side); f != invalid_id)
            return mesh.face_element(f);
    for (ElementId t : star(mesh, face.vertex(0))) {
        const Simplex& s = mesh.simplex(t);
        if (std::all_of(face.vertices().begin(), face.vertices().end(),
                        [&](VertexId v) { return s.contains(v); }))
            return t;
    }
    return invalid_id;
}

}  // namespace

Grid grid_of(const Mesh& mesh, const WriteOptions& options) {
    Grid grid;
    grid.points = chosen_positions(mesh, options);
    const int k = mesh.element_vertex_count();
    grid.element_type = k == 4 ? 10 : 5;
    grid.face_type = k == 4 ? 5 : 3;
    grid.element_count = mesh.element_count();
    const std::vector<std::pair<Simplex, int>> faces = sorted_face_labels(mesh);
    const std::size_t cells = grid.element_count + faces.size();
    grid.connectivity.reserve(grid.element_count * static_cast<std::size_t>(k) +
                              faces.size() * static_cast<std::size_t>(k - 1));
    grid.offsets.reserve(cells);
    grid.types.reserve(cells);
    grid.label.reserve(cells);
    grid.piece.reserve(cells);
    const Components components = connected_components(mesh);
    for (ElementId t : elements(mesh)) {
        const auto v = oriented_vertices(mesh.simplex(t));
        grid.connectivity.insert(grid.connectivity.end(), v.begin(), v.begin() + k);
        grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
        grid.types.push_back(static_cast<std::uint8_t>(grid.element_type));
        grid.label.push_back(mesh.label(t));
        grid.piece.push_back(static_cast<std::int32_t>(components.element_component[t]));
    }
    for (const auto& [face, label] : faces) {
        const auto v = oriented_vertices(face);
        grid.connectivity.insert(grid.connectivity.end(), v.begin(), v.begin() + k - 1);
        grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
        grid.types.push_back(static_cast<std::uint8_t>(grid.face_type));
        grid.label.push_back(label);
        const ElementId t = element_having(mesh, face);
        grid.piece.push_back(t == invalid_id
                                 ? -1
                                 : static_cast<std::int32_t>(components.element_component[t]));
    }
    grid.quality = options.quality_cell_data;
    if (grid.quality) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        grid.aspect_ratio.assign(cells, nan);
        grid.radius_ratio.assign(cells, nan);
        grid.min_angle_deg.assign(cells, nan);
        std::vector<Point> points(static_cast<std::size_t>(k));
        std::size_t i = 0;
        for (ElementId t : elements(mesh)) {
            const Simplex& s = mesh.simplex(t);
            for (int j = 0; j < k; ++j)
                points[static_cast<std::size_t>(j)] = grid.points[s.vertex(j)];
            grid.aspect_ratio[i] = aspect_ratio(points);
            grid.radius_ratio[i] = radius_ratio(points);
            double smallest = 0;
            if (k == 4) {
                const auto angles = dihedral_angles(points);
                smallest = *std::min_element(angles.begin(), angles.end());
            } else {
                const auto angles = triangle_angles(points);
                smallest = *std::min_element(angles.begin(), angles.end());
            }
            grid.min_angle_deg[i] = smallest * 180.0 / pi;
            ++i;
        }
    }
    const std::span<const Point> reference = mesh.reference_positions();
    const std::span<const Point> deformed = mesh.deformed_positions();
    if (!std::equal(reference.begin(), reference.end(), deformed.begin(), deformed.end())) {
        grid.displacement.resize(3 * reference.size());
        for (std::size_t v = 0; v < reference.size(); ++v)
            for (std::size_t c = 0; c < 3; ++c)
                grid.displacement[3 * v + c] = deformed[v][c] - reference[v][c];
    }
    // the array a viewer shows first: the pieces after a cut, else the labels if they say
    // anything, else the quality (issue 47: a constant colour shows nothing)
    const bool labels_differ =
        std::adjacent_find(grid.label.begin(), grid.label.end(), std::not_equal_to<>()) !=
        grid.label.end();
    grid.active_scalars = components.count >= 2 ? "piece"
                          : labels_differ       ? "label"
                          : grid.quality        ? "min_angle_deg"
                                                : "label";
    return grid;
}

// ---- reading ----------------------------------------------------------------------------------

std::string_view cell_type_name(std::int64_t type) {
    switch (type) {
        case 1:
            return "vertex";
        case 2:
            return "poly-vertex";
        case 3:
            return "line";
        case 4:
            return "poly-line";
        case 5:
            return "triangle";
        case 6:
            return "triangle strip";
        case 7:
            return "polygon";
        case 8:
            return "pixel";
        case 9:
            return "quad";
        case 10:
            return "tetrahedron";
        case 11:
            return "voxel";
        case 12:
            return "hexahedron";
        case 13:
            return "wedge";
        case 14:
            return "pyramid";
        case 15:
            return "pentagonal prism";
        case 16:
            return "hexagonal prism";
        case 21:
            return "quadratic edge";
        case 22:
            return "quadratic triangle";
        case 23:
            return "quadratic quad";
        case 24:
            return "quadratic tetrahedron";
        case 25:
            return "quadratic hexahedron";
        case 42:
            return "polyhedron";
        default:
            return "";
    }
}

void add_cells(RawMesh& raw, const Cells& cells, std::size_t point_count, const Where& where) {
    const Where at_types{where.file, cells.types_line};
    const Where at_connectivity{where.file, cells.connectivity_line};
    const std::size_t n = cells.types.size();
    std::size_t counts[5] = {};
    for (std::size_t i = 0; i < n; ++i) {
        const std::int64_t type = cells.types[i];
        const int size = type == 10 ? 4 : type == 5 ? 3 : type == 3 ? 2 : type == 1 ? 1 : 0;
        if (size == 0) {
            const std::string_view name = cell_type_name(type);
            at_types.fail("cell " + std::to_string(i) + " has VTK type " + std::to_string(type) +
                          (name.empty() ? std::string() : " (" + std::string(name) + ")") +
                          "; only simplexes (tetrahedra, triangles, lines, vertices) are read");
        }
        ++counts[size];
    }
    raw.tetrahedra.reserve(counts[4], true);
    raw.triangles.reserve(counts[3], true);
    raw.edges.reserve(counts[2], true);
    std::int64_t begin = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int64_t end = cells.offsets[i];
        if (end < begin || end > static_cast<std::int64_t>(cells.connectivity.size()))
            at_connectivity.fail("cell " + std::to_string(i) + " ends at offset " +
                                 std::to_string(end) + ", outside " + std::to_string(begin) +
                                 ".." + std::to_string(cells.connectivity.size()));
        const std::int64_t type = cells.types[i];
        const int size = type == 10 ? 4 : type == 5 ? 3 : type == 3 ? 2 : 1;
        if (end - begin != size)
            at_connectivity.fail("cell " + std::to_string(i) + " (" +
                                 std::string(cell_type_name(type)) + ") has " +
                                 std::to_string(end - begin) + " points, not " +
                                 std::to_string(size));
        CellList* list = size == 4 ? &raw.tetrahedra : size == 3 ? &raw.triangles
                                     : size == 2 ? &raw.edges : nullptr;
        for (std::int64_t j = begin; j < end; ++j) {
            const std::int64_t point = cells.connectivity[static_cast<std::size_t>(j)];
            if (point < 0 || point >= static_cast<std::int64_t>(point_count))
                at_connectivity.fail("cell " + std::to_string(i) + " refers to point " +
                                     std::to_string(point) + "; the file has " +
                                     std::to_string(point_count) + " points");
            if (list)
                list->vertices.push_back(static_cast<VertexId>(point));
        }
        begin = end;
        if (!list)
            continue;
        std::int64_t label = cells.labels.empty() ? 0 : cells.labels[i];
        if (label < std::numeric_limits<int>::min() || label > std::numeric_limits<int>::max())
            where.fail("label " + std::to_string(label) + " of cell " + std::to_string(i) +
                       " is out of range");
        list->labels.push_back(static_cast<int>(label));
        list->lines.push_back(cells.connectivity_line);
        list->numbers.push_back(static_cast<std::int64_t>(i));
    }
}

}  // namespace sxk::io::vtk
