// annotate(): marks over a picture with Cairo (annotation.hpp).
#include "annotation.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "cairo_image.hpp"

namespace sxk::pictures {

namespace {

// The image's pixels on a Cairo surface (RGB24, 0x00RRGGBB words), to draw over.
Surface surface_of(const Image& image) {
    Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height), cairo_surface_destroy);
    cairo_surface_flush(surface.get());
    unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    for (int row = 0; row < image.height; ++row)
        for (int column = 0; column < image.width; ++column) {
            const std::uint8_t* in =
                image.rgb.data() + 3 * (static_cast<std::size_t>(row) * static_cast<std::size_t>(image.width) +
                                        static_cast<std::size_t>(column));
            const std::uint32_t word = (std::uint32_t{in[0]} << 16) | (std::uint32_t{in[1]} << 8) | in[2];
            std::memcpy(data + static_cast<std::size_t>(row) * static_cast<std::size_t>(stride) +
                            4 * static_cast<std::size_t>(column),
                        &word, 4);
        }
    cairo_surface_mark_dirty(surface.get());
    return surface;
}

// Text on a translucent white box, so that it reads over any surface; returns the box's height.
double label(cairo_t* cr, const std::string& text, double x, double baseline) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_font_extents_t font;
    cairo_font_extents(cr, &font);
    const double pad = font.ascent * 0.25;
    cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
    cairo_rectangle(cr, x - pad, baseline - font.ascent - pad, extents.x_advance + 2 * pad,
                    font.ascent + font.descent + 2 * pad);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
    cairo_move_to(cr, x, baseline);
    cairo_show_text(cr, text.c_str());
    return font.ascent + font.descent + 2 * pad;
}

void path_of(cairo_t* cr, const Annotation::Line& line) {
    cairo_new_path(cr);
    for (std::size_t i = 0; i < line.points.size(); ++i) {
        if (i == 0)
            cairo_move_to(cr, line.points[i][0], line.points[i][1]);
        else
            cairo_line_to(cr, line.points[i][0], line.points[i][1]);
    }
    if (line.closed) cairo_close_path(cr);
}

}  // namespace

void annotate(Image& image, const Annotation& marks) {
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
        throw std::invalid_argument("annotate: the image is " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " with " + std::to_string(image.rgb.size()) +
                                    " bytes, not 3 per pixel");
    Surface surface = surface_of(image);
    Context context(cairo_create(surface.get()), cairo_destroy);
    cairo_t* cr = context.get();
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (const Annotation::Line& line : marks.lines) {
        if (line.points.empty()) continue;
        if (line.closed && line.fill_alpha > 0) {
            path_of(cr, line);
            cairo_set_source_rgba(cr, line.colour[0], line.colour[1], line.colour[2], line.fill_alpha);
            cairo_fill(cr);
        }
        // the halo first, then the line: visible on the dark and the light parts of a picture
        path_of(cr, line);
        cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
        cairo_set_line_width(cr, line.width + 3);
        cairo_stroke(cr);
        path_of(cr, line);
        cairo_set_source_rgb(cr, line.colour[0], line.colour[1], line.colour[2]);
        cairo_set_line_width(cr, line.width);
        cairo_stroke(cr);
    }
    for (const Annotation::Dot& dot : marks.dots) {
        cairo_new_path(cr);
        cairo_arc(cr, dot.at[0], dot.at[1], dot.radius + 1.5, 0, 2 * M_PI);
        cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
        cairo_fill(cr);
        cairo_arc(cr, dot.at[0], dot.at[1], dot.radius, 0, 2 * M_PI);
        cairo_set_source_rgb(cr, dot.colour[0], dot.colour[1], dot.colour[2]);
        cairo_fill(cr);
    }

    // text sized to the picture: 15 px at 640 x 480, smaller in a narrow one, at least 10
    const double size = std::max(10.0, std::round(std::min(image.height, image.width * 3 / 4) / 32.0));
    const double margin = size * 0.8;
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    if (!marks.title.empty()) label(cr, marks.title, margin, margin + size);

    if (!marks.legend.empty()) {
        const double row = size * 1.5;
        double baseline = image.height - margin - row * static_cast<double>(marks.legend.size() - 1);
        for (const Annotation::LegendEntry& entry : marks.legend) {
            cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
            cairo_rectangle(cr, margin - 1, baseline - size - 1, size + 2, size + 2);
            cairo_fill(cr);
            cairo_set_source_rgb(cr, entry.colour[0], entry.colour[1], entry.colour[2]);
            cairo_rectangle(cr, margin, baseline - size, size, size);
            cairo_fill(cr);
            label(cr, entry.text, margin + size * 1.6, baseline);
            baseline += row;
        }
    }

    if (marks.bar && marks.bar->stops.size() >= 2) {
        const Annotation::ColourBar& bar = *marks.bar;
        const double width = size, height = std::min(image.height * 0.45, size * 12.0);
        // the bar left of its longer end label, both inside the picture
        cairo_text_extents_t low, high;
        cairo_text_extents(cr, bar.low.c_str(), &low);
        cairo_text_extents(cr, bar.high.c_str(), &high);
        const double labels = std::max(low.x_advance, high.x_advance) + size * 0.8;
        const double x = image.width - margin - width - labels, top = margin * 2 + size * 2;
        cairo_pattern_t* ramp = cairo_pattern_create_linear(0, top + height, 0, top);
        for (std::size_t i = 0; i < bar.stops.size(); ++i)
            cairo_pattern_add_color_stop_rgb(ramp, static_cast<double>(i) / static_cast<double>(bar.stops.size() - 1),
                                             bar.stops[i][0], bar.stops[i][1], bar.stops[i][2]);
        cairo_set_source(cr, ramp);
        cairo_rectangle(cr, x, top, width, height);
        cairo_fill(cr);
        cairo_pattern_destroy(ramp);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_set_line_width(cr, 1);
        cairo_rectangle(cr, x, top, width, height);
        cairo_stroke(cr);
        label(cr, bar.high, x + width + size * 0.4, top + size * 0.4);
        label(cr, bar.low, x + width + size * 0.4, top + height + size * 0.3);
        cairo_text_extents_t extents;
        cairo_text_extents(cr, bar.caption.c_str(), &extents);
        label(cr, bar.caption, std::max(margin, image.width - margin - extents.x_advance), top - size * 0.8);
    }
    image = image_of(surface.get());
}

}  // namespace sxk::pictures
