// Numbers stored as bytes, for the readers and writers of binary formats (Gmsh, VTK, STL, PLY):
// loading a value of either byte order from a file's bytes, and appending one in either order to
// a writer's content (formats.hpp: binary content is bytes in the string). The one copy of
// this mechanism: the byte swaps compile to bswap instructions.
//
// Loading does not check bounds: a reader checks that the bytes are there (ByteCursor::has)
// before it loads, so that its message can say which record ran out.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace sxk::io {

// The scalar types binary formats declare by name (VTK's Int8 ... Float64, PLY's char ... double):
// one list, each format's reader mapping its own names onto it.
enum class Scalar : std::uint8_t {
    int8,
    uint8,
    int16,
    uint16,
    int32,
    uint32,
    int64,
    uint64,
    float32,
    float64
};

constexpr std::size_t size_of(Scalar type) {
    switch (type) {
        case Scalar::int8:
        case Scalar::uint8:
            return 1;
        case Scalar::int16:
        case Scalar::uint16:
            return 2;
        case Scalar::int32:
        case Scalar::uint32:
        case Scalar::float32:
            return 4;
        case Scalar::int64:
        case Scalar::uint64:
        case Scalar::float64:
            return 8;
    }
    return 1;
}

constexpr bool is_float(Scalar type) {
    return type == Scalar::float32 || type == Scalar::float64;
}

// The T stored at `bytes` in little-endian order, or big-endian when `big_endian`.
template <class T>
T load_number(const char* bytes, bool big_endian = false) {
    static_assert(std::is_arithmetic_v<T>);
    std::array<char, sizeof(T)> copy;
    std::memcpy(copy.data(), bytes, sizeof(T));
    if (big_endian != (std::endian::native == std::endian::big))
        std::reverse(copy.begin(), copy.end());
    T value;
    std::memcpy(&value, copy.data(), sizeof(T));
    return value;
}

template <class T>
T load_number(const unsigned char* bytes, bool big_endian = false) {
    return load_number<T>(reinterpret_cast<const char*>(bytes), big_endian);
}

// Appends `value` to `out` in little-endian order, or big-endian when `big_endian`.
template <class T>
void append_number_bytes(std::string& out, T value, bool big_endian) {
    static_assert(std::is_arithmetic_v<T>);
    std::array<char, sizeof(T)> copy;
    std::memcpy(copy.data(), &value, sizeof(T));
    if (big_endian != (std::endian::native == std::endian::big))
        std::reverse(copy.begin(), copy.end());
    out.append(copy.data(), sizeof(T));
}

template <class T>
void append_little_endian(std::string& out, T value) {
    append_number_bytes(out, value, false);
}

// A position in a file's bytes that knows how many are left.
class ByteCursor {
public:
    explicit ByteCursor(std::string_view bytes) : m_bytes(bytes) {}
    std::size_t offset() const { return m_offset; }
    std::size_t left() const { return m_bytes.size() - m_offset; }
    bool has(std::size_t n) const { return n <= left(); }
    // The next n bytes (the caller checked has(n)), consumed.
    const char* take(std::size_t n) {
        const char* at = m_bytes.data() + m_offset;
        m_offset += n;
        return at;
    }
    std::string_view rest() const { return m_bytes.substr(m_offset); }

private:
    std::string_view m_bytes;
    std::size_t m_offset = 0;
};

}  // namespace sxk::io
