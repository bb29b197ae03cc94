#include "stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "sxk/io.hpp"
#include "sxk/quality.hpp"

namespace sxk::stats {

Histogram::Histogram(double low_value, double high_value, std::size_t bins)
    : low(low_value), high(high_value), counts(bins, 0) {}

void Histogram::add(double value) {
    if (std::isnan(value)) {
        ++undefined;
        return;
    }
    const double position = (value - low) / (high - low) * static_cast<double>(counts.size());
    const double last = static_cast<double>(counts.size() - 1);
    counts[static_cast<std::size_t>(std::clamp(std::floor(position), 0.0, last))] += 1;
}

std::size_t Histogram::total() const {
    return std::accumulate(counts.begin(), counts.end(), std::size_t{0}) + undefined;
}

QualityHistograms quality_histograms(const Mesh& mesh, std::size_t bins) {
    QualityHistograms result{Histogram(0, 1, bins), Histogram(0, 1, bins), Histogram(0, pi, bins), 0};
    const bool tetrahedra = mesh.topological_dimension() == 3;
    for (ElementId t : elements(mesh)) {
        const std::vector<Point> points = element_points(mesh, t);
        result.aspect_ratio.add(aspect_ratio(points));
        result.radius_ratio.add(radius_ratio(points));
        if (tetrahedra) {
            for (double angle : dihedral_angles(points)) result.angles.add(angle);
        } else {
            for (double angle : triangle_angles(points)) result.angles.add(angle);
        }
        ++result.elements;
    }
    return result;
}

namespace {

constexpr std::size_t default_bins = 10;
constexpr std::size_t bar_width = 40;

struct Options {
    std::string mesh;
    ReadOptions reading;  // --strict
    std::size_t bins = default_bins;
    bool json = false;
};

std::string fixed(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

nlohmann::ordered_json to_json(const Histogram& histogram) {
    nlohmann::ordered_json json;
    json["low"] = histogram.low;
    json["high"] = histogram.high;
    json["counts"] = histogram.counts;
    json["undefined"] = histogram.undefined;
    return json;
}

// One line per bin: range, count, a bar scaled to the fullest bin. `scale` converts the range
// for display (radians to degrees).
void print_histogram(std::ostream& out, const std::string& title, const Histogram& histogram, double scale,
                     int digits) {
    out << title << " (" << histogram.total() << " values)\n";
    const std::size_t largest = std::max<std::size_t>(1, *std::max_element(histogram.counts.begin(), histogram.counts.end()));
    const std::size_t bins = histogram.counts.size();
    const double width = (histogram.high - histogram.low) / static_cast<double>(bins);
    std::vector<std::string> ranges;
    std::size_t range_width = 0;
    for (std::size_t bin = 0; bin < bins; ++bin) {
        const double from = (histogram.low + width * static_cast<double>(bin)) * scale;
        const double to = (histogram.low + width * static_cast<double>(bin + 1)) * scale;
        // the last bin is closed: it holds the maximum (an aspect ratio of exactly 1)
        ranges.push_back("[" + fixed(from, digits) + ", " + fixed(to, digits) + (bin + 1 == bins ? "]" : ")"));
        range_width = std::max(range_width, ranges.back().size());
    }
    for (std::size_t bin = 0; bin < bins; ++bin) {
        char count[32];
        std::snprintf(count, sizeof count, " %10zu ", histogram.counts[bin]);
        const std::size_t bar = (histogram.counts[bin] * bar_width + largest - 1) / largest;
        ranges[bin].resize(range_width, ' ');
        out << "  " << ranges[bin] << count << std::string(bar, '#') << '\n';
    }
    if (histogram.undefined) out << "  undefined  " << histogram.undefined << '\n';
}

void print(std::ostream& out, const Options& options, const Mesh& mesh, const QualityHistograms& histograms) {
    const bool tetrahedra = mesh.topological_dimension() == 3;
    if (options.json) {
        nlohmann::ordered_json json;
        json["file"] = options.mesh;
        json["element_kind"] = tetrahedra ? "tetrahedron" : "triangle";
        json["elements"] = histograms.elements;
        json["bins"] = options.bins;
        json["aspect_ratio"] = to_json(histograms.aspect_ratio);
        json["radius_ratio"] = to_json(histograms.radius_ratio);
        nlohmann::ordered_json angles = to_json(histograms.angles);
        angles["unit"] = "radian";
        json[tetrahedra ? "dihedral_angles" : "angles"] = angles;
        out << json.dump(2) << '\n';
        return;
    }
    out << "file: " << options.mesh << " (" << histograms.elements << (tetrahedra ? " tetrahedra" : " triangles")
        << ")\n";
    print_histogram(out, "aspect ratio", histograms.aspect_ratio, 1.0, 3);
    print_histogram(out, "radius ratio", histograms.radius_ratio, 1.0, 3);
    print_histogram(out, tetrahedra ? "dihedral angles, degrees" : "angles, degrees", histograms.angles, 180.0 / pi, 1);
}

// Parses the command's arguments; nullopt with `code` set when the command is done already
// (--help printed: 0; usage error reported: 2).
std::optional<Options> parse(std::span<const std::string> args, bool with_mesh, std::ostream& out,
                             std::ostream& err, int& code) {
    Options options;
    CLI::App app("Histograms of aspect ratio, radius ratio and dihedral angles (triangles: angles)", "sxk stats");
    if (with_mesh) app.add_option("MESH", options.mesh, "Mesh file")->required();
    app.add_option("--bins", options.bins, "Number of histogram bins")
        ->check(whole_number_in(1, 1000))
        ->capture_default_str();
    app.add_flag("--json", options.json, "Print one JSON object instead of text bars");
    if (with_mesh) add_read_options(app, options.reading);
    if (const std::optional<int> done = parse_command_line(app, args, "stats", out, err)) {
        code = *done;
        return std::nullopt;
    }
    return options;
}

class StatsCommand final : public PluginCommand {
public:
    std::string_view name() const override { return "stats"; }
    std::string_view summary() const override {
        return "histograms of aspect ratio, radius ratio and dihedral angles";
    }

    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override {
        int code = 0;
        const std::optional<Options> options = parse(args, true, out, err, code);
        if (!options) return code;
        const std::optional<Mesh> mesh = load_mesh_for_command(options->mesh, err, options->reading);
        if (!mesh) return cli::exit_usage;
        print(out, *options, *mesh, quality_histograms(*mesh, options->bins));
        return cli::exit_success;
    }

    bool accepts_mesh() const override { return true; }
    int run_on_mesh(const Mesh& mesh, std::string_view mesh_name, std::span<const std::string> args,
                    std::ostream& out, std::ostream& err) override {
        int code = 0;
        std::optional<Options> options = parse(args, false, out, err, code);
        if (!options) return code;
        options->mesh = mesh_name;
        print(out, *options, mesh, quality_histograms(mesh, options->bins));
        return cli::exit_success;
    }
};

class StatsPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }

private:
    StatsCommand m_stats;
    PluginCommand* m_commands[1] = {&m_stats};
};

}  // namespace
}  // namespace sxk::stats

SXK_PLUGIN(stats, sxk::stats::StatsPlugin, "0.1.0", "histograms of element quality");
