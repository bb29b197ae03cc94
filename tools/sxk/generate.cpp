// sxk generate OUT [--shape box] [--cells N|NX,NY,NZ] [--spacing S|SX,SY,SZ]: a box of Kuhn
// tetrahedra (make_kuhn_box, sxk/generators.hpp): the thesis' test cube (§3.3: --cells 8 gives
// its 729 nodes and 3072 tetrahedra) and its cantilever beams (Table 3.1).
// sxk generate OUT --shape cylinder [--rings R] [--layers L] [--spacing S]: the Delaunay
// tetrahedralisation of a cylindrical point cloud (make_delaunay of cylinder_cloud), the thesis'
// other test object (§3.3's pie-like cuts: 891 vertices, 4020 tetrahedra).
// sxk generate OUT --shape square [--cells N|NX,NY] [--spacing S|SX,SY]: a planar grid of right
// triangles (make_triangle_grid), the meshes of the thesis' 2D cuts (§5.4).
// sxk generate OUT --shape bell [--cells N|NX,NY] [--spacing S|SX,SY] [--height H] [--width W]: that
// grid lifted into a Gaussian bell (make_gaussian_bell), the surface of the thesis' 3D cuts (Fig. 5.19).
// For the experiments, the demos and anyone who wants a tetrahedral mesh without a mesher.
#include <algorithm>
#include <array>
#include <memory>
#include <variant>

#include "cli.hpp"
#include "sxk/generators.hpp"

namespace sxk::cli {
namespace {

struct GenerateOptions {
    std::string output;
    std::string shape = "box";
    std::string cells = "8";
    std::string spacing = "1";
    int rings = 4;
    int layers = 13;
    // bell: the height of its top and the standard deviation of its Gaussian, in fractions of the
    // grid's shorter side
    double height = 1.0 / 3;
    double width = 1.0 / 6;
};

// One number for all three axes, or three.
std::variant<std::array<double, 3>, std::string> three_numbers(const std::string& text) {
    auto parsed = parse_number_list(text);
    if (const auto* why = std::get_if<std::string>(&parsed)) return *why;
    const auto& numbers = std::get<std::vector<double>>(parsed);
    if (numbers.size() == 1) return std::array<double, 3>{numbers[0], numbers[0], numbers[0]};
    if (numbers.size() == 3) return std::array<double, 3>{numbers[0], numbers[1], numbers[2]};
    return "expected one number or three (X,Y,Z), found " + std::to_string(numbers.size()) + " in '" + text + "'";
}

// The generated mesh written to OUT with "OUT: V vertices, N elements", or the generator's refusal.
int write_generated(Context& context, const Outcome<Mesh>& mesh, const std::string& output) {
    if (!mesh) {
        context.err << "sxk: generate: " << mesh.reason() << '\n';
        return exit_usage;
    }
    if (!save_mesh(context, *mesh, output)) return exit_refused;
    context.report() << output << ": " << written_text(*mesh, written_of(*mesh, *format_of(context, output))) << '\n';
    return exit_success;
}

// --shape square: a planar grid of right triangles (make_triangle_grid), the thesis' 2D cuts' meshes;
// --shape bell: the same grid lifted into a Gaussian bell (make_gaussian_bell), their 3D cuts' surface.
int run_generate_square(Context& context, const GenerateOptions& options) {
    std::array<int, 2> counts{};
    std::array<double, 2> spacing{};
    for (const bool of_cells : {true, false}) {
        const std::string& text = of_cells ? options.cells : options.spacing;
        const char* name = of_cells ? "--cells" : "--spacing";
        auto parsed = parse_number_list(text);
        if (const auto* why = std::get_if<std::string>(&parsed)) {
            context.err << "sxk: generate: " << name << ": " << *why << '\n';
            return exit_usage;
        }
        const auto& numbers = std::get<std::vector<double>>(parsed);
        if (numbers.size() != 1 && numbers.size() != 2) {
            context.err << "sxk: generate: " << name << ": a square takes one number or two (X,Y), found "
                        << numbers.size() << " in '" << text << "'\n";
            return exit_usage;
        }
        for (std::size_t k = 0; k < 2; ++k) {
            const double n = numbers[numbers.size() == 1 ? 0 : k];
            if (!of_cells) {
                spacing[k] = n;
            } else if (n != static_cast<double>(static_cast<int>(n)) || n < 1 || n > 5000) {
                context.err << "sxk: generate: --cells: '" << text << "' is not a whole number in 1..5000 per axis\n";
                return exit_usage;
            } else {
                counts[k] = static_cast<int>(n);
            }
        }
    }
    if (options.shape == "bell") {
        const double side = std::min(counts[0] * spacing[0], counts[1] * spacing[1]);
        return write_generated(
            context, make_gaussian_bell(counts, spacing, options.height * side, options.width * side), options.output);
    }
    return write_generated(context, make_triangle_grid(counts, spacing), options.output);
}

int run_generate(Context& context, const GenerateOptions& options) {
    // one or two numbers each
    if (options.shape == "square" || options.shape == "bell") return run_generate_square(context, options);
    const auto cells = three_numbers(options.cells);
    const auto spacing = three_numbers(options.spacing);
    for (const auto* problem : {std::get_if<std::string>(&cells), std::get_if<std::string>(&spacing)})
        if (problem) {
            context.err << "sxk: generate: " << (problem == std::get_if<std::string>(&cells) ? "--cells" : "--spacing")
                        << ": " << *problem << '\n';
            return exit_usage;
        }
    if (options.shape == "cylinder") {
        const double spacing_value = std::get<std::array<double, 3>>(spacing)[0];
        return write_generated(context, make_delaunay(cylinder_cloud(options.rings, options.layers, spacing_value)),
                               options.output);
    }
    std::array<int, 3> counts{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double n = std::get<std::array<double, 3>>(cells)[i];
        if (n != static_cast<double>(static_cast<int>(n)) || n < 1 || n > 1000) {
            context.err << "sxk: generate: --cells: '" << options.cells << "' is not a whole number in 1..1000 per axis\n";
            return exit_usage;
        }
        counts[i] = static_cast<int>(n);
    }
    return write_generated(context, make_kuhn_box(counts, std::get<std::array<double, 3>>(spacing)), options.output);
}

}  // namespace

void add_generate_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<GenerateOptions>();
    CLI::App* command = app.add_subcommand(
        "generate",
        "A box of Kuhn tetrahedra (the thesis' test cube: --cells 8), a Delaunay cylinder (--shape cylinder) or a "
        "planar grid of triangles (--shape square: the thesis' 2D cuts, --cells 5 gives Fig. 5.16's 50 triangles), or "
        "that grid lifted into a Gaussian bell (--shape bell: the thesis' 3D cuts, --cells 14 gives Fig. 5.19's 392)");
    command->add_option("OUT", options->output, "Output mesh, format by extension (" + std::string(known_mesh_extensions()) + ")")
        ->required();
    command->add_option("--shape", options->shape,
                        "box: Kuhn tetrahedra, 6 per cell; cylinder: Delaunay; square: 2 triangles per cell; "
                        "bell: the square lifted into a Gaussian bell (a surface in space)")
        ->check(CLI::IsMember({"box", "cylinder", "square", "bell"}))
        ->capture_default_str();
    command->add_option("--cells", options->cells,
                        "box: cells per axis, N or NX,NY,NZ (each 1..1000); square, bell: N or NX,NY (each 1..5000)")
        ->capture_default_str();
    command->add_option("--spacing", options->spacing,
                        "box: cell size, S or SX,SY,SZ; square, bell: S or SX,SY; cylinder: ring and disc spacing "
                        "(positive)")
        ->capture_default_str();
    command->add_option("--rings", options->rings, "cylinder: rings around the axis")
        ->check(whole_number_in(1, 200))
        ->capture_default_str();
    command->add_option("--layers", options->layers, "cylinder: discs along the axis, minus one")
        ->check(whole_number_in(1, 2000))
        ->capture_default_str();
    command->add_option("--height", options->height, "bell: the height of its top, in fractions of the shorter side")
        ->check(CLI::Range(-1e6, 1e6))
        ->capture_default_str();
    command->add_option("--width", options->width,
                        "bell: the standard deviation of the Gaussian, in fractions of the shorter side (positive)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->callback([&context, options] { context.exit_code = run_generate(context, *options); });
}

}  // namespace sxk::cli
