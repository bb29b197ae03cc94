// Drawings in the plane (Cairo): segments and dots in their own coordinates, fitted into the
// picture with the y axis up, one scale for both axes: a planar mesh's edges with a tool over them.
//
//     pictures::Drawing drawing{.title = "needle, step 12"};
//     drawing.segments.push_back({{0, 0}, {1, 0}, {0.6, 0.6, 0.6}, 1});
//     drawing.dots.push_back({{0.5, 0}, {0.1, 0.3, 0.9}, 3});
//     pictures::write_png("step.png", pictures::draw(drawing));
#pragma once

#include <array>
#include <string>
#include <vector>

#include "image.hpp"

namespace sxk::pictures {

using Colour = std::array<double, 3>;  // red, green, blue in [0, 1]

struct Drawing {
    struct Segment {
        std::array<double, 2> a, b;
        Colour colour{0, 0, 0};
        double width = 1;  // pixels
    };
    struct Dot {
        std::array<double, 2> at;
        Colour colour{0, 0, 0};
        double radius = 3;  // pixels
    };
    std::string title;
    int width = 800, height = 800;
    std::vector<Segment> segments;  // drawn in order, then the dots
    std::vector<Dot> dots;
    // the part of the plane shown: {x_low, y_low, x_high, y_high}; empty (low > high): everything
    std::array<double, 4> view{1, 1, 0, 0};
};

// The picture of `drawing`. Throws std::invalid_argument for a size below 100 x 100.
Image draw(const Drawing& drawing);

}  // namespace sxk::pictures
