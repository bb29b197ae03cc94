// sxk quality MESH [--json] [--aspect A] [--angle RADIANS]: element quality (thesis §3.2.3)
// from summarize_quality: aspect ratio, radius ratio, (dihedral) angles, inverted and flat
// elements, and degenerate elements by class (needle, spindle, sliver, cap; Fig. 3.8).
#include <algorithm>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/quality.hpp"

namespace sxk::cli {
namespace {

struct QualityOptions {
    std::string mesh;
    bool json = false;
    DegeneracyThresholds thresholds;
};

constexpr DegenerateClass degenerate_classes[] = {DegenerateClass::needle, DegenerateClass::spindle,
                                                  DegenerateClass::sliver, DegenerateClass::cap};

std::string fixed(double value, int digits = 4) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

double degrees(double radians) { return radians * 180.0 / pi; }

void print_json(Context& context, const QualityOptions& options, const Mesh& mesh, const QualitySummary& summary) {
    const bool tetrahedra = mesh.topological_dimension() == 3;
    nlohmann::ordered_json json;
    json["file"] = options.mesh;
    json["element_kind"] = element_kind(mesh);
    json["elements"] = summary.elements;
    json["min_aspect_ratio"] = summary.min_aspect_ratio;
    json["mean_aspect_ratio"] = summary.mean_aspect_ratio;
    json["max_aspect_ratio"] = summary.max_aspect_ratio;
    json["min_radius_ratio"] = summary.min_radius_ratio;
    json["mean_radius_ratio"] = summary.mean_radius_ratio;
    json["angle_kind"] = tetrahedra ? "dihedral" : "triangle";
    json["min_angle"] = summary.min_angle;  // radians
    json["max_angle"] = summary.max_angle;
    json["inverted"] = summary.inverted;
    json["flat"] = summary.flat;
    json["degenerate"] = summary.degenerate;
    nlohmann::ordered_json by_class = nlohmann::ordered_json::object();
    if (tetrahedra)
        for (DegenerateClass c : degenerate_classes)
            by_class[std::string(to_string(c))] = summary.by_class[static_cast<std::size_t>(c)];
    json["degenerate_by_class"] = by_class;
    json["aspect_histogram"] = summary.aspect_histogram;
    json["thresholds"] = {{"aspect_ratio", options.thresholds.aspect_ratio},
                          {"large_angle", options.thresholds.large_angle}};
    context.out << json.dump(2) << '\n';
}

void print_text(Context& context, const QualityOptions& options, const Mesh& mesh, const QualitySummary& summary) {
    const bool tetrahedra = mesh.topological_dimension() == 3;
    std::ostream& out = context.out;
    out << "file: " << options.mesh << '\n'
        << "elements: " << element_count_text(mesh, summary.elements) << '\n'
        << "aspect ratio: min " << fixed(summary.min_aspect_ratio) << "  mean " << fixed(summary.mean_aspect_ratio)
        << "  max " << fixed(summary.max_aspect_ratio) << '\n'
        << "radius ratio: min " << fixed(summary.min_radius_ratio) << "  mean " << fixed(summary.mean_radius_ratio)
        << '\n'
        << (tetrahedra ? "dihedral angles" : "angles") << ": min " << fixed(degrees(summary.min_angle), 2)
        << " deg  max " << fixed(degrees(summary.max_angle), 2) << " deg\n"
        << "inverted: " << summary.inverted << '\n'
        << "flat: " << summary.flat << '\n'
        << "degenerate (aspect ratio < " << options.thresholds.aspect_ratio << "): " << summary.degenerate << '\n';
    if (tetrahedra) {
        out << " ";
        for (DegenerateClass c : degenerate_classes)
            out << ' ' << to_string(c) << ' ' << summary.by_class[static_cast<std::size_t>(c)];
        out << "  (large dihedral angle > " << fixed(degrees(options.thresholds.large_angle), 2) << " deg)\n";
    }
    out << "aspect ratio histogram:\n";
    std::size_t largest = 1;
    for (std::size_t count : summary.aspect_histogram) largest = std::max(largest, count);
    for (std::size_t bin = 0; bin < summary.aspect_histogram.size(); ++bin) {
        const std::size_t count = summary.aspect_histogram[bin];
        out << "  [" << fixed(bin / 10.0, 1) << ", " << fixed((bin + 1) / 10.0, 1) << (bin == 9 ? "] " : ") ");
        char number[32];
        std::snprintf(number, sizeof number, "%10zu ", count);
        out << number << std::string((count * 40 + largest - 1) / largest, '#') << '\n';
    }
}

int run_quality(Context& context, const QualityOptions& options) {
    std::optional<Mesh> mesh = load_mesh(context, options.mesh);
    if (!mesh) return exit_usage;
    QualitySummary summary;
    {
        Progress progress("quality of " + options.mesh);
        summary = summarize_quality(*mesh, options.thresholds);
    }
    if (options.json)
        print_json(context, options, *mesh, summary);
    else
        print_text(context, options, *mesh, summary);
    return exit_success;
}

}  // namespace

void add_quality_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<QualityOptions>();
    CLI::App* command = app.add_subcommand(
        "quality", "Angles, aspect ratios, radius ratios, inverted/flat elements, degenerate elements by class");
    command->add_option("MESH", options->mesh, "Mesh file")->required();
    command->add_flag("--json", options->json, "Print one JSON object instead of text");
    command->add_option("--aspect", options->thresholds.aspect_ratio,
                        "Aspect ratio below which an element is degenerate")
        ->check(number_in(0, true, 1, true, "[0, 1]"))
        ->capture_default_str();
    command->add_option("--angle", options->thresholds.large_angle,
                        "Dihedral angle (radians) above which an angle counts as large when classifying")
        ->check(number_in(0, true, pi, true, "[0, pi]"))
        ->capture_default_str();
    command->callback([&context, options] { context.exit_code = run_quality(context, *options); });
}

}  // namespace sxk::cli
