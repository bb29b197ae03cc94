// load_file, load_stream (load_file.hpp) and the public read_text_file / read_text_stream (sxk/io.hpp).
#include "load_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <memory>
#include <system_error>

#include "../fresh_array.hpp"
#include "sxk/io.hpp"
#include "text.hpp"

namespace sxk::io {

namespace {

[[noreturn]] void too_large(const std::string& name, std::size_t limit) {
    throw InputError(name, 0,
                     "larger than " + std::to_string(limit) + " bytes, the most one input is read to");
}

// Only files and FIFOs hold text to read; the others get a reason before anything is opened
// (opening a device can block or have effects of its own).
void refuse_non_file(std::filesystem::file_type type, const std::string& name) {
    using std::filesystem::file_type;
    switch (type) {
        case file_type::not_found:
            throw InputError(name, 0, "no such file");
        case file_type::directory:
            throw InputError(name, 0, "is a directory");
        case file_type::character:
            throw InputError(name, 0, "is a character device, not a file");
        case file_type::block:
            throw InputError(name, 0, "is a block device, not a file");
        case file_type::socket:
            throw InputError(name, 0, "is a socket, not a file");
        default:
            return;  // regular, FIFO, or unknown (no permission to look): fopen says why
    }
}

}  // namespace

detail::TextBuffer load_file(const std::filesystem::path& path, std::size_t limit) {
    const std::string name = path.string();
    std::error_code error;
    refuse_non_file(std::filesystem::status(path, error).type(), name);
    // stdio rather than ifstream: one fread into a buffer of the file's size, and errno for
    // the reason when it fails (permissions, I/O error).
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"),
                                                         &std::fclose);
    if (!file)
        throw InputError(name, 0, std::string("cannot open: ") + std::strerror(errno));
    detail::TextBuffer data;
    struct stat opened {};
    if (::fstat(::fileno(file.get()), &opened) == 0 && S_ISREG(opened.st_mode)) {
        if (static_cast<std::uintmax_t>(opened.st_size) > limit)
            too_large(name, limit);
        detail::reserve_fresh(data, static_cast<std::size_t>(opened.st_size));
        data.resize(static_cast<std::size_t>(opened.st_size));
        data.resize(std::fread(data.data(), 1, data.size(), file.get()));
    }
    // FIFOs and files that grew meanwhile: read whatever is left, up to the limit
    char chunk[65536];
    std::size_t got = 0;
    while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) {
        if (got > limit - data.size())
            too_large(name, limit);
        data.append(chunk, got);
    }
    if (std::ferror(file.get()))
        throw InputError(name, 0, std::string("cannot read: ") + std::strerror(errno));
    return data;
}

detail::TextBuffer load_stream(std::istream& in, const std::string& name, std::size_t limit) {
    detail::TextBuffer data;
    char chunk[65536];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        const auto got = static_cast<std::size_t>(in.gcount());
        if (got > limit - data.size())
            too_large(name, limit);
        data.append(chunk, got);
    }
    if (in.bad())
        throw InputError(name, 0, "cannot read the stream");
    return data;
}

}  // namespace sxk::io

namespace sxk {

namespace {

// The checked text without its byte order mark (check_text drops it from its view).
std::string checked_text(const detail::TextBuffer& data, const std::string& name) {
    return std::string(io::check_text(data, name));
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path, std::size_t limit) {
    return checked_text(io::load_file(path, limit), path.string());
}

std::string read_text_stream(std::istream& in, const std::string& name, std::size_t limit) {
    return checked_text(io::load_stream(in, name, limit), name);
}

}  // namespace sxk
