// SVG pictures of planar cuts (svg_picture.hpp). Written as text: a few hundred lines of SVG need no
// library, and a browser or any vector editor shows them.
#include "svg_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"

namespace sxk::delaunaycut {

namespace {

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", x);
    return text;
}

std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

}  // namespace

std::string mesh_svg(const Mesh& mesh, std::span<const Point> path, int cut_label, const std::string& title) {
    double low_x = std::numeric_limits<double>::infinity(), low_y = low_x;
    double high_x = -low_x, high_y = -low_x;
    auto grow = [&](const Point& p) {
        low_x = std::min(low_x, p[0]);
        low_y = std::min(low_y, p[1]);
        high_x = std::max(high_x, p[0]);
        high_y = std::max(high_y, p[1]);
    };
    for (const ElementId t : elements(mesh))
        for (const VertexId v : mesh.simplex(t).vertices()) grow(mesh.deformed(v));
    for (const Point& p : path) grow(p);
    if (!(high_x >= low_x)) low_x = low_y = 0, high_x = high_y = 1;
    const double size = std::max({high_x - low_x, high_y - low_y, 1e-300});
    const double scale = 760 / size, margin = 20, top = 40;
    const double width = (high_x - low_x) * scale + 2 * margin, height = (high_y - low_y) * scale + margin + top;
    auto x_of = [&](const Point& p) { return number(margin + (p[0] - low_x) * scale); };
    auto y_of = [&](const Point& p) { return number(top + (high_y - p[1]) * scale); };  // y up
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" +
                      number(height) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + number(margin) + "\" y=\"24\" font-family=\"sans-serif\" font-size=\"15\">" + escaped(title) +
           "</text>\n<g fill=\"#f4f4f0\" stroke=\"#9a9a9a\" stroke-width=\"0.7\" stroke-linejoin=\"round\">\n";
    for (const ElementId t : elements(mesh)) {
        svg += "<polygon points=\"";
        for (const VertexId v : mesh.simplex(t).vertices())
            svg += x_of(mesh.deformed(v)) + "," + y_of(mesh.deformed(v)) + " ";
        svg += "\"/>\n";
    }
    svg += "</g>\n";
    std::string outline, cut;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex edge = mesh.face_simplex(f);
        const Point& a = mesh.deformed(edge.vertex(0));
        const Point& b = mesh.deformed(edge.vertex(1));
        const std::optional<int> label = mesh.face_label(edge);
        (label && *label == cut_label ? cut : outline) +=
            "M" + x_of(a) + "," + y_of(a) + "L" + x_of(b) + "," + y_of(b);
    });
    svg += "<path d=\"" + outline + "\" stroke=\"black\" stroke-width=\"1.6\" fill=\"none\"/>\n";
    svg += "<path d=\"" + cut + "\" stroke=\"#d01c1c\" stroke-width=\"2.2\" fill=\"none\"/>\n";
    if (!path.empty()) {
        svg += "<polyline fill=\"none\" stroke=\"#1f5fd0\" stroke-width=\"1.4\" stroke-dasharray=\"2,3\" points=\"";
        for (const Point& p : path) svg += x_of(p) + "," + y_of(p) + " ";
        svg += "\"/>\n";
    }
    return svg + "</svg>\n";
}

AngleCounts triangle_angle_degrees(const Mesh& mesh) {
    AngleCounts counts;
    for (const ElementId t : elements(mesh)) {
        const std::vector<Point> corners = element_points(mesh, t, Positions::deformed);
        const std::array<double, 3> angles = triangle_angles(corners);
        counts.smallest.push_back(*std::min_element(angles.begin(), angles.end()) * 180 / pi);
        counts.largest.push_back(*std::max_element(angles.begin(), angles.end()) * 180 / pi);
    }
    return counts;
}

std::string angle_histogram_svg(const std::string& title, std::span<const AngleSeries> series) {
    constexpr int bins = 36;
    static constexpr const char* colours[] = {"#d01c1c", "#1f5fd0", "#2a9d3a", "#9a6a00"};
    std::vector<std::array<std::size_t, bins>> counts(series.size());
    std::size_t most = 1;
    for (std::size_t s = 0; s < series.size(); ++s) {
        counts[s].fill(0);
        for (const double d : series[s].degrees) {
            const int bin = std::clamp(static_cast<int>(d / 5), 0, bins - 1);
            most = std::max(most, ++counts[s][static_cast<std::size_t>(bin)]);
        }
    }
    const double left = 50, bottom = 330, plot_width = 720, plot_height = 260;
    const double bin_width = plot_width / bins;
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"380\" "
                      "font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
                      "<text x=\"50\" y=\"28\" font-size=\"15\">" +
                      escaped(title) + "</text>\n";
    for (std::size_t s = 0; s < series.size(); ++s) {
        const double bar = bin_width / static_cast<double>(series.size() + 1);
        svg += "<g fill=\"" + std::string(colours[s % 4]) + "\">\n";
        for (int b = 0; b < bins; ++b) {
            const auto count = static_cast<double>(counts[s][static_cast<std::size_t>(b)]);
            const double h = plot_height * count / static_cast<double>(most);
            if (h == 0) continue;
            svg += "<rect x=\"" + number(left + b * bin_width + static_cast<double>(s) * bar + bar / 2) + "\" y=\"" +
                   number(bottom - h) + "\" width=\"" + number(bar) + "\" height=\"" + number(h) + "\"/>\n";
        }
        svg += "</g>\n<text x=\"" + number(left + 10) + "\" y=\"" + number(56 + 18 * static_cast<double>(s)) +
               "\" font-size=\"13\" fill=\"" + colours[s % 4] + "\">" + escaped(series[s].name) + "</text>\n";
    }
    svg += "<path d=\"M" + number(left) + "," + number(bottom) + "H" + number(left + plot_width) +
           "\" stroke=\"black\"/>\n<g font-size=\"11\" text-anchor=\"middle\">\n";
    for (int degrees = 0; degrees <= 180; degrees += 30)
        svg += "<text x=\"" + number(left + degrees / 5.0 * bin_width) + "\" y=\"" + number(bottom + 16) + "\">" +
               std::to_string(degrees) + "</text>\n";
    svg += "</g>\n<text x=\"" + number(left + plot_width / 2) + "\" y=\"" + number(bottom + 36) +
           "\" font-size=\"12\" text-anchor=\"middle\">degrees (bins of 5); bar height: triangles, the tallest " +
           std::to_string(most) + "</text>\n";
    return svg + "</svg>\n";
}

}  // namespace sxk::delaunaycut
