// Placeholder while the reader is written (issue 47); replaced in this session.
#include "formats.hpp"

namespace sxk::io {

Mesh read_stl(std::string_view, const std::string& name, const ReadOptions&, ReadReport*) {
    throw InputError(name, 0, "this format cannot be read yet");
}

std::string write_stl(const Mesh&, const WriteOptions&) {
    throw OutputError("this format cannot be written yet");
}

}  // namespace sxk::io
