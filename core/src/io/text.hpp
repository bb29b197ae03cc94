// The strict text layer every reader stands on: loading a file into memory, refusing binary
// data, and a cursor that hands out whitespace-separated tokens while counting 1-based lines.
//
// Why not iostreams: `in >> x` per token costs a virtual call, a locale lookup and a sentry per
// number; the femur (213k tets, ~10 MB of text) must read in well under a second. Here the whole
// file is one buffer, tokens are string_views into it, and numbers go through std::from_chars
// (locale-independent, so a German LC_NUMERIC cannot turn "0.5" into 0).
//
// Two ways to walk the text, because the formats differ:
//   token mode  next()/need(): whitespace-separated, newlines are just whitespace
//               (Medit, Gmsh, where a record may wrap)
//   line mode   next_line() then next_in_line()/need_in_line(): one record per line
//               (TetGen, OFF, OBJ, where a line may carry optional trailing values)
// Both skip comments that start with the cursor's comment character at the start of a token.
#pragma once

#include <array>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "sxk/io.hpp"

namespace sxk::io {

// Loading a file's bytes: load_file / load_stream in load_file.hpp.

// Throws InputError(name, line, "binary data (byte 0xNN)") at the first byte that cannot be
// text: a control character other than \t \n \v \f \r, DEL, or a malformed UTF-8 sequence
// (UTF-8 is allowed because comments and names may carry it). Returns `text` without a UTF-8
// byte order mark.
std::string_view check_text(std::string_view text, const std::string& name);

class Cursor {
public:
    // `text` must outlive the cursor (it is not copied). comment == '\0': no comments.
    Cursor(std::string_view text, const std::string& name, char comment);

    const std::string& name() const { return m_name; }
    // The line of the token last returned (1-based); before the first token, 1.
    std::size_t line() const { return m_token_line; }

    // True when no token is left (comments and whitespace only).
    bool at_end();

    // ---- token mode --------------------------------------------------------------------------
    // The next token, or an empty view at the end of the text.
    std::string_view next();
    // The next token without consuming it (empty at the end).
    std::string_view peek();
    // The next token, or InputError "truncated file: expected WHAT".
    std::string_view need(const char* what);

    // ---- line mode ---------------------------------------------------------------------------
    // Moves to the next line holding a token, past whatever is left of the current one.
    // False at the end of the text.
    bool next_line();
    // The next token on the current line, or an empty view when the line is done.
    std::string_view next_in_line();
    // The next token on the current line, or InputError "missing WHAT".
    std::string_view need_in_line(const char* what);
    // True when the current line holds no more tokens.
    bool line_done();

    // ---- numbers -----------------------------------------------------------------------------
    // A finite double; "coordinate is not finite" for nan/inf and overflow, "expected WHAT,
    // found 'TOKEN'" for anything that is not a number. Underflow gives (signed) zero.
    double to_double(std::string_view token, const char* what) const;
    // An integer; "expected WHAT, found 'TOKEN'" or "WHAT is too large: 'TOKEN'".
    std::int64_t to_integer(std::string_view token, const char* what) const;
    // to_integer, and within [minimum, maximum] ("WHAT out of range: 'TOKEN'").
    std::int64_t to_integer(std::string_view token, const char* what, std::int64_t minimum,
                            std::int64_t maximum) const;
    double need_double(const char* what) { return to_double(need(what), what); }
    std::int64_t need_integer(const char* what) { return to_integer(need(what), what); }

    // Throws InputError(name, line(), reason).
    [[noreturn]] void fail(const std::string& reason) const;
    [[noreturn]] void fail_at(std::size_t line, const std::string& reason) const;

private:
    // Skips blanks and comments; stops at a token, at '\n' (when !cross_lines) or at the end.
    void skip(bool cross_lines);
    std::string_view take_token();

    const char* m_p;
    const char* m_end;
    std::string m_name;
    char m_comment;
    std::size_t m_line = 1;        // line of m_p
    std::size_t m_token_line = 1;  // line of the last token returned
    bool m_in_line = false;        // a token of the current line was handed out
};

// A token for an error message: at most 24 characters, so a megabyte of garbage on one line does
// not become a megabyte of message.
std::string quote(std::string_view token);

// Shortest text that reads back to exactly the same double (std::to_chars); appends to out.
void append_number(std::string& out, double value);
void append_number(std::string& out, std::int64_t value);
inline void append_number(std::string& out, int value) {
    append_number(out, static_cast<std::int64_t>(value));
}
inline void append_number(std::string& out, std::size_t value) {
    append_number(out, static_cast<std::int64_t>(value));
}
inline void append_number(std::string& out, std::uint32_t value) {
    append_number(out, static_cast<std::int64_t>(value));
}
// "x y z" of a point, each coordinate in shortest round-trip form.
inline void append_xyz(std::string& out, const std::array<double, 3>& p) {
    append_number(out, p[0]);
    out += ' ';
    append_number(out, p[1]);
    out += ' ';
    append_number(out, p[2]);
}

}  // namespace sxk::io
