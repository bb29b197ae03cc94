// PNG input through libpng's simplified API (image.hpp): any PNG as 8-bit RGB, for the tests
// that look at the pictures the commands draw.
#include <png.h>

#include <stdexcept>
#include <string>

#include "image.hpp"

namespace sxk::pictures {

Image read_png(const std::filesystem::path& path) {
    const std::string name = path.string();
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (png_image_begin_read_from_file(&png, name.c_str()) == 0) {
        const std::string message = png.message;
        png_image_free(&png);
        throw std::runtime_error("cannot read " + name + ": libpng: " + message);
    }
    png.format = PNG_FORMAT_RGB;
    Image image;
    image.width = static_cast<int>(png.width);
    image.height = static_cast<int>(png.height);
    image.rgb.resize(PNG_IMAGE_SIZE(png));
    if (png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr) == 0) {
        const std::string message = png.message;
        png_image_free(&png);
        throw std::runtime_error("cannot read " + name + ": libpng: " + message);
    }
    return image;
}

}  // namespace sxk::pictures
