// PNG output through libpng's simplified API (render.hpp): 8-bit RGB, no colour management
// beyond the sRGB bytes render() produces.
#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "render.hpp"

namespace sxk::bezier {

void write_png(const std::filesystem::path& path, const Image& image) {
    const std::string name = path.string();
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() !=
            static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
        throw std::invalid_argument("write_png: " + name + ": the image is " +
                                    std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " with " +
                                    std::to_string(image.rgb.size()) + " bytes, not 3 per pixel");
    // opened here, not by libpng, so that the reason (errno) reaches the message
    std::FILE* file = std::fopen(name.c_str(), "wb");
    if (file == nullptr)
        throw std::runtime_error("cannot write " + name + ": " + std::strerror(errno));
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGB;
    const int written = png_image_write_to_stdio(&png, file, 0, image.rgb.data(), 0, nullptr);
    const std::string libpng_message = png.message;
    png_image_free(&png);
    const bool stream_failed = std::ferror(file) != 0;
    int failure = errno;
    // fclose flushes: a full disk shows here
    const bool closed = std::fclose(file) == 0;
    if (!closed)
        failure = errno;
    if (written == 0)
        throw std::runtime_error("cannot write " + name + ": libpng: " + libpng_message);
    if (stream_failed || !closed)
        throw std::runtime_error("cannot write " + name + ": " + std::strerror(failure));
}

}  // namespace sxk::bezier
