// draw(Plot): line plots drawn with Cairo into an image (line_plot.hpp).
#include "line_plot.hpp"

#include <cairo.h>

#include "cairo_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace sxk::pictures {
namespace {

using Colour = std::array<double, 3>;
// distinguishable on white and in grey print (the first four of Tableau's palette)
constexpr std::array<Colour, 4> palette{Colour{0.12, 0.47, 0.71}, Colour{1.0, 0.50, 0.05},
                                        Colour{0.17, 0.63, 0.17}, Colour{0.84, 0.15, 0.16}};

struct Range {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    void take(double v) {
        low = std::min(low, v);
        high = std::max(high, v);
    }
    bool empty() const { return !(low <= high); }
};

// Tick values for [low, high]: steps of 1, 2 or 5 times a power of ten, about five of them.
std::vector<double> linear_ticks(double low, double high) {
    const double raw = (high - low) / 5;
    const double power = std::pow(10, std::floor(std::log10(raw)));
    double step = power;
    for (const double m : {2.0, 5.0, 10.0})
        if (raw > step)
            step = m * power;
    std::vector<double> ticks;
    for (double t = std::ceil(low / step) * step; t <= high + step * 1e-9; t += step)
        ticks.push_back(std::abs(t) < step * 1e-9 ? 0 : t);
    return ticks;
}

std::string tick_text(double value, bool power_of_ten) {
    char buffer[32];
    if (power_of_ten)
        std::snprintf(buffer, sizeof buffer, "1e%d",
                      static_cast<int>(std::lround(std::log10(value))));
    else
        std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

}  // namespace

Image draw(const Plot& plot) {
    if (plot.width < 200 || plot.height < 150)
        throw std::invalid_argument("draw: a plot of " + std::to_string(plot.width) + "x" +
                                    std::to_string(plot.height) + " is smaller than 200x150");
    for (const Series& s : plot.series)
        if (s.x.size() != s.y.size())
            throw std::invalid_argument("draw: series '" + s.label + "' has " +
                                        std::to_string(s.x.size()) + " x values and " +
                                        std::to_string(s.y.size()) + " y values");
    auto usable = [&](double x, double y) {
        return std::isfinite(x) && std::isfinite(y) && (!plot.log_y || y > 0);
    };
    // the data's extent, y in log10 on a log axis
    Range xs, ys;
    for (const Series& s : plot.series)
        for (std::size_t i = 0; i < s.x.size(); ++i)
            if (usable(s.x[i], s.y[i])) {
                xs.take(s.x[i]);
                ys.take(plot.log_y ? std::log10(s.y[i]) : s.y[i]);
            }
    for (const Level& l : plot.levels)
        if (std::isfinite(l.y) && (!plot.log_y || l.y > 0))
            ys.take(plot.log_y ? std::log10(l.y) : l.y);
    if (xs.empty())
        xs = {0, 1};
    if (ys.empty())
        ys = {0, 1};
    if (xs.high == xs.low)
        xs = {xs.low - 0.5, xs.high + 0.5};
    if (plot.log_y)
        ys = {std::floor(ys.low), std::max(std::ceil(ys.high), std::floor(ys.low) + 1)};
    else if (ys.high == ys.low)
        ys = {ys.low - 0.5, ys.high + 0.5};
    else {  // a margin of 5% so that lines do not run along the frame
        const double margin = 0.05 * (ys.high - ys.low);
        ys = {ys.low - margin, ys.high + margin};
    }

    const auto [surface, context] = white_canvas(plot.width, plot.height);
    cairo_t* cr = context.get();
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

    const double left = 80, right = plot.width - 20.0, top = 40, bottom = plot.height - 55.0;
    auto px = [&](double x) { return left + (x - xs.low) / (xs.high - xs.low) * (right - left); };
    auto py = [&](double y) {
        const double v = plot.log_y ? std::log10(y) : y;
        return bottom - (v - ys.low) / (ys.high - ys.low) * (bottom - top);
    };
    auto text = [&](const std::string& s, double x, double y, double size, double align_x,
                    double align_y, bool vertical = false) {
        cairo_set_font_size(cr, size);
        cairo_text_extents_t e;
        cairo_text_extents(cr, s.c_str(), &e);
        cairo_save(cr);
        cairo_translate(cr, x, y);
        if (vertical)
            cairo_rotate(cr, -M_PI / 2);
        // align 0: the text's left (top) edge at x (y), 1: its right (bottom) edge, 0.5: centred
        cairo_move_to(cr, -align_x * e.width - e.x_bearing, -align_y * e.height - e.y_bearing);
        cairo_show_text(cr, s.c_str());
        cairo_restore(cr);
    };

    // grid and ticks
    cairo_set_line_width(cr, 1);
    std::vector<double> y_ticks;
    if (plot.log_y) {
        const int decades = static_cast<int>(ys.high - ys.low);
        const int every = std::max(1, decades / 8);
        for (int e = static_cast<int>(ys.low); e <= static_cast<int>(ys.high); e += every)
            y_ticks.push_back(std::pow(10.0, e));
    } else {
        y_ticks = linear_ticks(ys.low, ys.high);
    }
    for (const double t : y_ticks) {
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_move_to(cr, left, std::round(py(t)) + 0.5);
        cairo_line_to(cr, right, std::round(py(t)) + 0.5);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text(tick_text(t, plot.log_y), left - 6, py(t), 11, 1, 0.5);
    }
    for (const double t : linear_ticks(xs.low, xs.high)) {
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_move_to(cr, std::round(px(t)) + 0.5, top);
        cairo_line_to(cr, std::round(px(t)) + 0.5, bottom);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text(tick_text(t, false), px(t), bottom + 6, 11, 0.5, 0);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_rectangle(cr, left + 0.5, top + 0.5, right - left, bottom - top);
    cairo_stroke(cr);
    text(plot.title, (left + right) / 2, 12, 15, 0.5, 0);
    text(plot.x_label, (left + right) / 2, plot.height - 22.0, 12, 0.5, 0);
    text(plot.y_label, 16, (top + bottom) / 2, 12, 0.5, 0, true);

    // the data, clipped to the frame
    cairo_save(cr);
    cairo_rectangle(cr, left, top, right - left, bottom - top);
    cairo_clip(cr);
    cairo_set_line_width(cr, 1.5);
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
        const Series& s = plot.series[k];
        const Colour& c = palette[k % palette.size()];
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        bool drawing = false;
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (!usable(s.x[i], s.y[i])) {
                drawing = false;
                continue;
            }
            if (drawing)
                cairo_line_to(cr, px(s.x[i]), py(s.y[i]));
            else
                cairo_move_to(cr, px(s.x[i]), py(s.y[i]));
            drawing = true;
        }
        if (s.x.size() == 1 && usable(s.x[0], s.y[0]))
            cairo_arc(cr, px(s.x[0]), py(s.y[0]), 2, 0, 2 * M_PI);
        cairo_stroke(cr);
    }
    const double dash[] = {6, 4};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
    for (const Level& l : plot.levels) {
        if (!std::isfinite(l.y) || (plot.log_y && !(l.y > 0)))
            continue;
        cairo_move_to(cr, left, py(l.y));
        cairo_line_to(cr, right, py(l.y));
        cairo_stroke(cr);
        text(l.label, right - 6, py(l.y) - 4, 11, 1, 1);
    }
    cairo_restore(cr);

    // the legend, top right
    double y = top + 10;
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
        if (plot.series[k].label.empty())
            continue;
        const Colour& c = palette[k % palette.size()];
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_set_line_width(cr, 2);
        cairo_move_to(cr, right - 150, y);
        cairo_line_to(cr, right - 125, y);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text(plot.series[k].label, right - 118, y, 11, 0, 0.5);
        y += 16;
    }

    return image_of(surface.get());
}

}  // namespace sxk::pictures
