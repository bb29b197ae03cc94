// The pictures' Cairo surfaces (private to plugins/pictures): a white RGB24 surface to draw on,
// and its pixels copied out as an Image.
#pragma once

#include <cairo.h>

#include <memory>

#include "image.hpp"

namespace sxk::pictures {

using Surface = std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)>;
using Context = std::unique_ptr<cairo_t, void (*)(cairo_t*)>;

// A width x height surface painted white, and a context on it.
std::pair<Surface, Context> white_canvas(int width, int height);

// The surface's pixels (RGB24: one native-endian 32-bit word per pixel, 0x00RRGGBB) as an Image.
Image image_of(cairo_surface_t* surface);

}  // namespace sxk::pictures
