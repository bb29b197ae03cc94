// Raster pictures shared by the plug-ins: an 8-bit RGB image and its PNG file (libpng).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sxk::pictures {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // row-major from the top-left, 3 bytes per pixel
};

// Writes `image` as a PNG file, atomically (a failed write leaves what was there). Throws
// std::invalid_argument for an image whose size and bytes disagree, and sxk::OutputError naming
// the file when it cannot be written.
void write_png(const std::filesystem::path& path, const Image& image);

// Reads a PNG file as 8-bit RGB (grey, palette and alpha converted by libpng; alpha composed on
// black). Throws std::runtime_error("cannot read FILE: libpng: why").
Image read_png(const std::filesystem::path& path);

}  // namespace sxk::pictures
