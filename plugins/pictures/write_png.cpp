// PNG output through libpng's simplified API (image.hpp): 8-bit RGB, no colour management beyond
// the sRGB bytes the image holds; encoded in memory and written atomically.
#include <png.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "image.hpp"
#include "sxk/atomic_write.hpp"

namespace sxk::pictures {

void write_png(const std::filesystem::path& path, const Image& image) {
    const std::string name = path.string();
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() !=
            static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
        throw std::invalid_argument("write_png: " + name + ": the image is " +
                                    std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " with " +
                                    std::to_string(image.rgb.size()) + " bytes, not 3 per pixel");
    // encoded in memory, then written atomically: a failed write (full disk) leaves no partial
    // picture and an existing file as it was
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    std::vector<unsigned char> encoded;
    // the first call measures, the second encodes
    int done = png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr);
    if (done != 0) {
        encoded.resize(size);
        done =
            png_image_write_to_memory(&png, encoded.data(), &size, 0, image.rgb.data(), 0, nullptr);
    }
    const std::string libpng_message = png.message;
    png_image_free(&png);
    if (done == 0)
        throw OutputError("cannot write " + name + ": libpng: " + libpng_message);
    write_file_atomically(path,
                          std::string_view(reinterpret_cast<const char*>(encoded.data()), size));
}

}  // namespace sxk::pictures
