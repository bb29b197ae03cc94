// Cairo surfaces to images (cairo_image.hpp).
#include "cairo_image.hpp"

#include <cstdint>
#include <cstring>
#include <utility>

namespace sxk::pictures {

std::pair<Surface, Context> white_canvas(int width, int height) {
    Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
    Context context(cairo_create(surface.get()), cairo_destroy);
    cairo_set_source_rgb(context.get(), 1, 1, 1);
    cairo_paint(context.get());
    return {std::move(surface), std::move(context)};
}

Image image_of(cairo_surface_t* surface) {
    cairo_surface_flush(surface);
    const int width = cairo_image_surface_get_width(surface), height = cairo_image_surface_get_height(surface);
    Image image{width, height, std::vector<std::uint8_t>(3 * static_cast<std::size_t>(width * height))};
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            std::uint32_t word;
            std::memcpy(&word,
                        data + static_cast<std::size_t>(row) * static_cast<std::size_t>(stride) +
                            4 * static_cast<std::size_t>(column),
                        4);
            const std::size_t pixel =
                static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column);
            std::uint8_t* out = image.rgb.data() + 3 * pixel;
            out[0] = static_cast<std::uint8_t>(word >> 16);
            out[1] = static_cast<std::uint8_t>(word >> 8);
            out[2] = static_cast<std::uint8_t>(word);
        }
    return image;
}

}  // namespace sxk::pictures
