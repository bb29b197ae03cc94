// Bringing an input's bytes into memory, for the mesh readers and for the side inputs of the
// commands (read_text_file in sxk/io.hpp): one guarded way in, so that no input is read until
// memory runs out (docs/formats.md "Reading files").
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>

#include "sxk/detail/large_array.hpp"  // TextBuffer
#include "sxk/io.hpp"                  // max_input_bytes

namespace sxk::io {

// The file's bytes (in huge pages when large: sxk/detail/large_array.hpp). Regular files and FIFOs (a shell's <(...)) are read, at most `limit` bytes;
// a directory, a character or block device (/dev/zero), a socket, a file that cannot be opened
// or read, and one larger than `limit` throw InputError(path, 0, reason).
detail::TextBuffer load_file(const std::filesystem::path& path, std::size_t limit = max_input_bytes);
// The stream's bytes, at most `limit`; InputError(name, 0, reason) otherwise.
detail::TextBuffer load_stream(std::istream& in, const std::string& name,
                        std::size_t limit = max_input_bytes);

}  // namespace sxk::io
