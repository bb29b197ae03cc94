// draw(Drawing): segments and dots in the plane, drawn with Cairo (planar_drawing.hpp).
#include "planar_drawing.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cairo_image.hpp"

namespace sxk::pictures {

Image draw(const Drawing& drawing) {
    if (drawing.width < 100 || drawing.height < 100)
        throw std::invalid_argument("pictures: a drawing needs at least 100 x 100 pixels");
    std::array<double, 4> view = drawing.view;
    if (!(view[0] <= view[2] && view[1] <= view[3])) {
        const double inf = std::numeric_limits<double>::infinity();
        view = {inf, inf, -inf, -inf};
        auto take = [&](const std::array<double, 2>& p) {
            if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return;
            view = {std::min(view[0], p[0]), std::min(view[1], p[1]), std::max(view[2], p[0]), std::max(view[3], p[1])};
        };
        for (const auto& s : drawing.segments) {
            take(s.a);
            take(s.b);
        }
        for (const auto& d : drawing.dots) take(d.at);
        if (!(view[0] <= view[2])) view = {0, 0, 1, 1};
    }
    const double margin = 30, top = drawing.title.empty() ? margin : margin + 20;
    const double span = std::max({view[2] - view[0], view[3] - view[1], 1e-300});
    const double scale = std::min((drawing.width - 2 * margin) / std::max(view[2] - view[0], span * 1e-9),
                                  (drawing.height - top - margin) / std::max(view[3] - view[1], span * 1e-9));
    auto px = [&](const std::array<double, 2>& p) { return margin + (p[0] - view[0]) * scale; };
    auto py = [&](const std::array<double, 2>& p) { return drawing.height - margin - (p[1] - view[1]) * scale; };

    const auto [surface, context] = white_canvas(drawing.width, drawing.height);
    cairo_t* cr = context.get();
    cairo_rectangle(cr, 0, top - 5, drawing.width, drawing.height - top + 5);
    cairo_clip(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (const auto& s : drawing.segments) {
        cairo_set_source_rgb(cr, s.colour[0], s.colour[1], s.colour[2]);
        cairo_set_line_width(cr, s.width);
        cairo_move_to(cr, px(s.a), py(s.a));
        cairo_line_to(cr, px(s.b), py(s.b));
        cairo_stroke(cr);
    }
    for (const auto& d : drawing.dots) {
        cairo_set_source_rgb(cr, d.colour[0], d.colour[1], d.colour[2]);
        cairo_arc(cr, px(d.at), py(d.at), d.radius, 0, 2 * M_PI);
        cairo_fill(cr);
    }
    cairo_reset_clip(cr);
    if (!drawing.title.empty()) {
        cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr, 14);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, margin, margin);
        cairo_show_text(cr, drawing.title.c_str());
    }
    return image_of(surface.get());
}

}  // namespace sxk::pictures
