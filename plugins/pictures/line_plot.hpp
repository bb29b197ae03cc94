// Line plots as pictures (Cairo): convergence histories, force profiles. Axes with ticks and
// labels, one colour per series and a legend; a logarithmic y axis for residuals.
//
//     pictures::Plot plot{.title = "CG convergence", .x_label = "iteration", .y_label = "|r|",
//                         .log_y = true};
//     plot.series.push_back({"residual", iterations, residuals});
//     pictures::write_png("convergence.png", pictures::draw(plot));
#pragma once

#include <string>
#include <vector>

#include "image.hpp"

namespace sxk::pictures {

struct Series {
    std::string label;
    std::vector<double> x, y;  // the same length; points that are not finite (or, on a log
                               // axis, not positive) break the line
};

// A horizontal line across the plot, dashed: a threshold, a reference value.
struct Level {
    std::string label;
    double y = 0;
};

struct Plot {
    std::string title, x_label, y_label;
    bool log_y = false;
    int width = 800, height = 500;
    std::vector<Series> series;
    std::vector<Level> levels;
};

// The picture of `plot`. The axes span the data (and the levels); a plot without any point to
// draw gets empty axes from 0 to 1. Throws std::invalid_argument for a series whose x and y
// differ in length or a size below 200 x 150.
Image draw(const Plot& plot);

}  // namespace sxk::pictures
