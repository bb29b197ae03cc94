#include "text.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <iterator>
#include <memory>
#include <system_error>

namespace sxk::io {

namespace {

// One table lookup per byte instead of five comparisons: the cursor's loops run over every
// byte of the file (docs/performance.md, "io").
enum : std::uint8_t { other = 0, blank = 1, newline = 2 };
constexpr std::array<std::uint8_t, 256> byte_classes = [] {
    std::array<std::uint8_t, 256> classes{};
    for (const char c : {' ', '\t', '\r', '\v', '\f'})
        classes[static_cast<unsigned char>(c)] = blank;
    classes[static_cast<unsigned char>('\n')] = newline;
    return classes;
}();
std::uint8_t byte_class(char c) {
    return byte_classes[static_cast<unsigned char>(c)];
}
bool is_blank(char c) {
    return byte_class(c) == blank;
}
bool is_space(char c) {
    return byte_class(c) != other;
}

std::string hex_byte(unsigned char c) {
    static constexpr char digits[] = "0123456789ABCDEF";
    return std::string("0x") + digits[c >> 4] + digits[c & 15];
}

}  // namespace

std::string_view check_text(std::string_view text, const std::string& name) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t size = text.size();
    std::size_t i = 0;
    std::size_t careful_until = 0;  // bytes before this go through the byte loop
    auto fail = [&](std::size_t at) {
        const std::size_t line =
            1 + static_cast<std::size_t>(
                    std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
        throw InputError(name, line, "binary data (byte " + hex_byte(bytes[at]) + ")");
    };
    while (i < size) {
        // Fast path, 8 bytes at a time while they are all printable ASCII (0x20..0x7E) or
        // newlines: the byte loop alone measured ~5% of read_mesh on the femur-1226k
        // (docs/performance.md, "io"). A word holding anything else (a tab, UTF-8, a bad byte)
        // goes through the byte loop, which names the first bad byte as before.
        if (i >= careful_until) {
            constexpr std::uint64_t ones = 0x0101010101010101ULL;
            constexpr std::uint64_t lows = 0x7f * ones, highs = 0x80 * ones;
            // high bit of each byte of x that is zero; per byte exact (no carries between bytes)
            auto zero_bytes = [](std::uint64_t x) { return ~(((x & lows) + lows) | x) & highs; };
            while (size - i >= 8) {
                std::uint64_t word;
                std::memcpy(&word, bytes + i, 8);
                const std::uint64_t below_space = ~(((word & lows) + (0x80 - 0x20) * ones) | word);
                const std::uint64_t newline = zero_bytes(word ^ ('\n' * ones));
                const std::uint64_t del = zero_bytes(word ^ (0x7f * ones));
                if (((word | (below_space & ~newline) | del) & highs) != 0)
                    break;
                i += 8;
            }
            careful_until = i + 8;
            if (i == size)
                break;
        }
        const unsigned char c = bytes[i];
        if (c >= 0x20 && c < 0x7f) {
            ++i;
            continue;
        }
        if (c < 0x80) {
            if (c != '\n' && c != '\t' && c != '\r' && c != '\v' && c != '\f')
                fail(i);
            ++i;
            continue;
        }
        // UTF-8: a lead byte announcing 1..3 continuation bytes 10xxxxxx (0xC0/0xC1 and
        // 0xF5.. can only start overlong or out-of-range sequences)
        const int more = (c >= 0xC2 && c <= 0xDF)   ? 1
                         : (c >= 0xE0 && c <= 0xEF) ? 2
                         : (c >= 0xF0 && c <= 0xF4) ? 3
                                                    : -1;
        if (more < 0)
            fail(i);
        for (int k = 1; k <= more; ++k)
            if (i + static_cast<std::size_t>(k) >= size ||
                (bytes[i + static_cast<std::size_t>(k)] & 0xC0) != 0x80)
                fail(i);
        i += static_cast<std::size_t>(more) + 1;
    }
    return text;
}

Cursor::Cursor(std::string_view text, const std::string& name, char comment)
    : m_p(text.data()), m_end(text.data() + text.size()), m_name(name), m_comment(comment) {}

void Cursor::skip(bool cross_lines) {
    while (m_p < m_end) {
        const char c = *m_p;
        if (is_blank(c)) {
            ++m_p;
        } else if (c == '\n') {
            if (!cross_lines)
                return;
            ++m_line;
            ++m_p;
        } else if (c == m_comment && m_comment != '\0') {
            const void* newline = std::memchr(m_p, '\n', static_cast<std::size_t>(m_end - m_p));
            m_p = newline ? static_cast<const char*>(newline) : m_end;
        } else {
            return;
        }
    }
}

std::string_view Cursor::take_token() {
    const char* start = m_p;
    while (m_p < m_end && !is_space(*m_p))
        ++m_p;
    m_token_line = m_line;
    m_in_line = true;
    return {start, static_cast<std::size_t>(m_p - start)};
}

bool Cursor::at_end() {
    skip(true);
    return m_p == m_end;
}

std::string_view Cursor::next() {
    skip(true);
    if (m_p == m_end)
        return {};
    return take_token();
}

std::string_view Cursor::peek() {
    skip(true);
    const char* start = m_p;
    while (start < m_end && !is_space(*start))
        ++start;
    return {m_p, static_cast<std::size_t>(start - m_p)};
}

std::string_view Cursor::need(const char* what) {
    const std::string_view token = next();
    if (token.empty())
        fail(std::string("truncated file: expected ") + what);
    return token;
}

bool Cursor::next_line() {
    // leave the current line; whatever is left on it is the caller's business (it asks
    // line_done() where trailing data matters)
    if (m_in_line) {
        const void* newline = std::memchr(m_p, '\n', static_cast<std::size_t>(m_end - m_p));
        if (!newline) {
            m_p = m_end;
            return false;
        }
        m_p = static_cast<const char*>(newline) + 1;
        ++m_line;
    }
    skip(true);
    if (m_p == m_end)
        return false;
    m_in_line = true;
    m_token_line = m_line;
    return true;
}

std::string_view Cursor::next_in_line() {
    skip(false);
    if (m_p == m_end || *m_p == '\n')
        return {};
    return take_token();
}

std::string_view Cursor::need_in_line(const char* what) {
    const std::string_view token = next_in_line();
    if (token.empty())
        fail(std::string("missing ") + what);
    return token;
}

bool Cursor::line_done() {
    skip(false);
    return m_p == m_end || *m_p == '\n';
}

namespace {

// Decides whether a decimal number that from_chars found out of range overflows (true) or
// underflows: compares the position of its leading significant digit plus its exponent with 0.
// Only called for tokens from_chars accepted as a number, so the syntax is known to be valid.
bool overflows(std::string_view token) {
    std::size_t i = 0;
    if (i < token.size() && (token[i] == '-' || token[i] == '+'))
        ++i;
    std::int64_t digits_before_point = 0;  // significant digits before '.'
    std::int64_t zeros_after_point = 0;    // zeros between '.' and the first significant digit
    bool significant = false, point = false;
    for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
        const char c = token[i];
        if (c == '.') {
            point = true;
        } else if (c != '0' || significant) {
            significant = true;
            if (!point)
                ++digits_before_point;
        } else if (point) {
            ++zeros_after_point;
        }
    }
    std::int64_t exponent = 0;
    if (i < token.size()) {
        ++i;
        bool negative = false;
        if (i < token.size() && (token[i] == '-' || token[i] == '+'))
            negative = token[i++] == '-';
        for (; i < token.size(); ++i)
            exponent = std::min<std::int64_t>(exponent * 10 + (token[i] - '0'), 1'000'000'000);
        if (negative)
            exponent = -exponent;
    }
    const std::int64_t magnitude =
        (digits_before_point > 0 ? digits_before_point : -zeros_after_point) + exponent;
    return magnitude > 0;
}

}  // namespace

double Cursor::to_double(std::string_view token, const char* what) const {
    std::string_view digits = token;
    // from_chars takes no '+' (C++ follows strtol's grammar minus the plus); files have them
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-')
        digits.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || error == std::errc::invalid_argument)
        fail(std::string("expected ") + what + ", found " + quote(token));
    if (error == std::errc::result_out_of_range) {
        if (overflows(digits))
            fail("coordinate is not finite");
        return digits[0] == '-' ? -0.0 : 0.0;
    }
    if (!std::isfinite(value))
        fail("coordinate is not finite");
    return value;
}

std::int64_t Cursor::to_integer(std::string_view token, const char* what) const {
    // The common case, up to 18 plain digits (no sign, cannot overflow), without from_chars'
    // generality; anything else takes the general path and its messages.
    if (!token.empty() && token.size() <= 18) {
        std::int64_t value = 0;
        std::size_t i = 0;
        for (; i < token.size(); ++i) {
            const unsigned digit = static_cast<unsigned char>(token[i]) - unsigned{'0'};
            if (digit > 9)
                break;
            value = value * 10 + static_cast<std::int64_t>(digit);
        }
        if (i == token.size())
            return value;
    }
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-')
        digits.remove_prefix(1);
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || error == std::errc::invalid_argument)
        fail(std::string("expected ") + what + ", found " + quote(token));
    if (error == std::errc::result_out_of_range)
        fail(std::string(what) + " is too large: " + quote(token));
    return value;
}

std::int64_t Cursor::to_integer(std::string_view token, const char* what, std::int64_t minimum,
                                std::int64_t maximum) const {
    const std::int64_t value = to_integer(token, what);
    if (value < minimum || value > maximum)
        fail(std::string(what) + " out of range: " + quote(token));
    return value;
}

void Cursor::fail(const std::string& reason) const {
    fail_at(m_token_line, reason);
}

void Cursor::fail_at(std::size_t line, const std::string& reason) const {
    throw InputError(m_name, line, reason);
}

std::string quote(std::string_view token) {
    constexpr std::size_t limit = 24;
    // appended piece by piece: g++ 12 reports a spurious -Wrestrict for "'" + std::string(...)
    std::string quoted(1, '\'');
    if (token.size() <= limit) {
        quoted.append(token);
    } else {
        // cut at a UTF-8 character boundary so the message stays valid text
        std::size_t cut = limit;
        while (cut > 0 && (static_cast<unsigned char>(token[cut]) & 0xC0) == 0x80)
            --cut;
        quoted.append(token.substr(0, cut));
        quoted.append("...");
    }
    quoted.push_back('\'');
    return quoted;
}

void append_number(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

void append_number(std::string& out, std::int64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

}  // namespace sxk::io
