// Marks drawn over a finished picture (Cairo): a rendered mesh gets its tool, its step and time,
// a legend and a colour bar, so that a frame says what it shows (issue 47, item 5).
//
//     pictures::Annotation marks{.title = "cut snap: step 3 of 20, t = 0.15"};
//     marks.lines.push_back({{{10, 10}, {200, 120}}, {0.1, 0.1, 0.1}, 4});
//     marks.legend.push_back({"cut faces", {0.93, 0.1, 0.93}});
//     pictures::annotate(image, marks);
//
// Coordinates are pixels, (0, 0) the top-left corner of the top-left pixel; colours sRGB in [0, 1].
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "image.hpp"
#include "planar_drawing.hpp"  // Colour

namespace sxk::pictures {

struct Annotation {
    // A polyline (closed: a polygon, filled when fill_alpha > 0), stroked with a light halo so it
    // stands out on dark and light surfaces alike.
    struct Line {
        std::vector<std::array<double, 2>> points;
        Colour colour{0, 0, 0};
        double width = 2;  // pixels
        bool closed = false;
        double fill_alpha = 0;
    };
    struct Dot {
        std::array<double, 2> at;
        Colour colour{0, 0, 0};
        double radius = 4;  // pixels
    };
    struct LegendEntry {
        std::string text;
        Colour colour;
    };
    // A vertical bar at the right edge: `stops` evenly spaced from `low` (bottom) to `high` (top).
    struct ColourBar {
        std::string caption, low, high;
        std::vector<Colour> stops;
    };
    std::string title;  // top-left
    std::vector<Line> lines;
    std::vector<Dot> dots;
    std::vector<LegendEntry> legend;  // bottom-left, a swatch and a text each
    std::optional<ColourBar> bar;
};

// Draws `marks` over `image` (text in DejaVu Sans, sized to the picture's height). Throws
// std::invalid_argument for an image whose size and bytes disagree.
void annotate(Image& image, const Annotation& marks);

}  // namespace sxk::pictures
