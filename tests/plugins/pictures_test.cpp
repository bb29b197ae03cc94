// The plug-ins' shared pictures: line plots drawn with Cairo (line_plot.hpp) into RGB images.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "line_plot.hpp"

namespace sxk::pictures {
namespace {

std::array<int, 3> pixel(const Image& image, int x, int y) {
    const std::size_t at =
        3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
             static_cast<std::size_t>(x));
    return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

// Pixels of the first series' colour (blue: more blue than red and green by far).
int blue_pixels(const Image& image, int x0, int x1) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const auto p = pixel(image, x, y);
            count += p[2] > 120 && p[0] < 100 && p[2] - p[1] > 40;
        }
    return count;
}

TEST(PicturesLinePlot, DrawsTheSeriesOnAWhitePicture) {
    Plot plot;
    plot.title = "residual";
    plot.log_y = true;
    Series s;
    s.label = "|r|";
    for (int i = 0; i <= 100; ++i) {
        s.x.push_back(i);
        s.y.push_back(std::pow(10.0, -i / 10.0));
    }
    plot.series.push_back(s);
    const Image image = draw(plot);
    ASSERT_EQ(image.width, 800);
    ASSERT_EQ(image.height, 500);
    ASSERT_EQ(image.rgb.size(), 800u * 500u * 3u);
    EXPECT_EQ(pixel(image, 2, 2), (std::array<int, 3>{255, 255, 255}));
    // the line runs through the whole width of the frame (left 80, right 780): blue pixels in
    // its left, middle and right thirds
    EXPECT_GT(blue_pixels(image, 90, 300), 50);
    EXPECT_GT(blue_pixels(image, 300, 560), 50);
    EXPECT_GT(blue_pixels(image, 560, 770), 50);
    // points a log axis cannot show break the line instead of failing
    plot.series[0].y[50] = 0;
    plot.series[0].y[51] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NO_THROW(draw(plot));
}

TEST(PicturesLinePlot, RefusesWhatItCannotDraw) {
    Plot plot;
    Series s;
    s.label = "bad";
    s.x = {0, 1};
    s.y = {1};
    plot.series.push_back(s);
    try {
        draw(plot);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "draw: series 'bad' has 2 x values and 1 y values");
    }
    plot.series.clear();
    plot.width = 100;
    try {
        draw(plot);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "draw: a plot of 100x500 is smaller than 200x150");
    }
    // nothing to draw: empty axes
    plot.width = 300;
    EXPECT_EQ(draw(plot).rgb.size(), 300u * 500u * 3u);
}

}  // namespace
}  // namespace sxk::pictures
