#include "render_plugin.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <new>
#include <optional>
#include <sstream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <variant>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "annotation.hpp"
#include "command_line.hpp"
#include "flat_subdivision.hpp"
#include "mesh_surface.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "sxk/plugins/render.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/dissect.hpp"
#include "triangular_patch.hpp"
#include "vector3.hpp"

namespace sxk::bezier {

namespace {

double linear_from_srgb(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Colour linear(const Colour& srgb) {
    return {linear_from_srgb(srgb[0]), linear_from_srgb(srgb[1]), linear_from_srgb(srgb[2])};
}

}  // namespace

Colour quality_colour(double quality) {
    // red, orange, yellow, green, blue at 0, 1/4, 1/2, 3/4, 1 (sRGB); interpolated in sRGB so
    // that the steps look even
    constexpr std::array<Colour, 5> stops{{{0.84, 0.09, 0.11},
                                           {0.97, 0.55, 0.13},
                                           {0.95, 0.88, 0.25},
                                           {0.30, 0.72, 0.30},
                                           {0.20, 0.45, 0.85}}};
    const double position = std::clamp(std::isnan(quality) ? 0.0 : quality, 0.0, 1.0) * 4.0;
    const std::size_t lower = std::min<std::size_t>(3, static_cast<std::size_t>(position));
    const double w = position - static_cast<double>(lower);
    Colour srgb{};
    for (std::size_t c = 0; c < 3; ++c)
        srgb[c] = (1 - w) * stops[lower][c] + w * stops[lower + 1][c];
    return linear(srgb);
}

Colour label_colour(int label) {
    // Tableau 10 with its pink and purple replaced (too close to the magenta of cuts) and its
    // grey darkened (too close to the plain grey), sRGB
    constexpr std::array<Colour, 10> palette{{{0.31, 0.47, 0.65},
                                              {0.95, 0.56, 0.17},
                                              {0.88, 0.34, 0.35},
                                              {0.46, 0.72, 0.70},
                                              {0.35, 0.63, 0.31},
                                              {0.93, 0.79, 0.28},
                                              {0.61, 0.46, 0.37},
                                              {0.63, 0.63, 0.19},
                                              {0.17, 0.24, 0.55},
                                              {0.45, 0.42, 0.40}}};
    const int size = static_cast<int>(palette.size());
    return linear(palette[static_cast<std::size_t>((label % size + size) % size)]);
}

Colour cut_colour() {
    return linear({0.93, 0.10, 0.93});
}

Colour plain_colour() {
    return linear({0.75, 0.75, 0.75});
}

namespace {

constexpr int max_image_side = 16384;
constexpr int max_segments = 512;
// Bounds on what a small input can ask for (issue 12): a picture of 2^26 pixels (8192x8192) is
// 201 MB of RGB and about 20 s of the teapot's primary rays on two cores; 2^24 tessellation
// triangles (the teapot at 512 segments) about 2.3 GB with Embree's BVH (docs/performance.md:
// 4.6 GB for 2^25).
constexpr long long max_pixels = 1LL << 26;
constexpr long long max_tessellation_triangles = 1LL << 24;
// and 2^31 de Casteljau point steps to evaluate a tessellation's vertices, about 4 s of CPU:
// the teapot at 512 segments takes 4.7e8, 400 degree-40 patches allow 29 segments. The default
// count's search measures several tessellations with 2.5 segments^2 more points each, so it
// searches only counts whose tessellation takes a sixteenth of that.
constexpr long long max_tessellation_steps = 1LL << 31;

// Default views: patch files and 3D meshes from the front-left and above (z up, as the teapot
// is), planar meshes from +z with y up.
constexpr Point default_view{1, -2, 1.2};
constexpr Point default_up{0, 0, 1};
constexpr Point planar_view{0, 0, 1};
constexpr Point planar_up{0, 1, 0};

struct CommandOptions {
    std::string input;
    std::string output;
    ReadOptions reading;  // --strict (meshes)
    std::array<int, 2> size{640, 480};
    std::optional<Camera> camera;  // none: frame() the scene's box
    double fov = 40;
    bool tessellate = false;
    int segments = 0;  // when not given: default_segments
    double flatness = PatchSceneOptions{}.flatness;
    std::string colour;  // empty: quality for meshes, plain for patches
    std::optional<int> cut_label;
    std::vector<Point> tool;  // --tool: a point, a segment or a triangle drawn over the picture
    std::string title;        // --title
    double explode = 0;       // --explode
    bool json = false;
    // which of the above were given (the patch-only options refuse meshes)
    bool segments_given = false, flatness_given = false;
};

// "WxH" as two whole numbers in [1, max_image_side]; nullopt otherwise.
std::optional<std::array<int, 2>> parse_size(std::string_view text) {
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos)
        return std::nullopt;
    std::array<int, 2> size{};
    const std::array<std::string_view, 2> parts{text.substr(0, x), text.substr(x + 1)};
    for (std::size_t i = 0; i < 2; ++i) {
        const std::string_view part = parts[i];
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), size[i]);
        if (part.empty() || error != std::errc() || end != part.data() + part.size() ||
            size[i] < 1 || size[i] > max_image_side)
            return std::nullopt;
    }
    return size;
}


bool is_zero(const Point& a) {
    return a[0] == 0 && a[1] == 0 && a[2] == 0;
}

// Why the camera cannot see, or nothing: eye and target coincide, up lies along the view, or
// what the renderer's frame of the camera refuses beyond that (a view direction whose length
// overflows, an up vector parallel to it after rounding): a bad argument too, refused before the
// input is read rather than by the render (exit 1).
std::optional<std::string> camera_problem(const Camera& camera) {
    if (camera.eye == camera.target) return "eye and target coincide";
    if (is_zero(cross(minus(camera.target, camera.eye), camera.up)))
        return "up is zero or parallel to the view direction";
    try {
        primary_ray(camera, 1, 1, 0, 0);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return std::nullopt;
}

// "ex,ey,ez,tx,ty,tz,ux,uy,uz" as a camera (fov left at its default); the reason otherwise.
std::variant<Camera, std::string> parse_camera(const std::string& text) {
    const auto list = parse_number_list(text);
    if (const std::string* error = std::get_if<std::string>(&list))
        return *error + " (eye,target,up: nine numbers ex,ey,ez,tx,ty,tz,ux,uy,uz)";
    const std::vector<double>& numbers = std::get<std::vector<double>>(list);
    if (numbers.size() != 9)
        return "'" + text + "' is not eye,target,up (nine numbers ex,ey,ez,tx,ty,tz,ux,uy,uz)";
    Camera camera;
    camera.eye = {numbers[0], numbers[1], numbers[2]};
    camera.target = {numbers[3], numbers[4], numbers[5]};
    camera.up = {numbers[6], numbers[7], numbers[8]};
    if (const auto problem = camera_problem(camera)) return "'" + text + "': " + *problem;
    return camera;
}

// "x,y,z[,x,y,z[,x,y,z]]" as one to three points; the reason otherwise.
std::variant<std::vector<Point>, std::string> parse_tool(const std::string& text) {
    const auto list = parse_number_list(text);
    if (const std::string* error = std::get_if<std::string>(&list))
        return *error + " (a point, a segment or a triangle: 3, 6 or 9 numbers)";
    const std::vector<double>& numbers = std::get<std::vector<double>>(list);
    if (numbers.empty() || numbers.size() > 9 || numbers.size() % 3 != 0)
        return "'" + text + "' is not a point, a segment or a triangle (3, 6 or 9 numbers x,y,z,...)";
    std::vector<Point> points;
    for (std::size_t i = 0; i < numbers.size(); i += 3) points.push_back({numbers[i], numbers[i + 1], numbers[i + 2]});
    return points;
}

// Parses the command's arguments (without INPUT when `with_input` is false: run_on_mesh);
// nullopt with `code` set when the command is done already (--help: 0; usage error: 2).
std::optional<CommandOptions> parse(std::span<const std::string> args, bool with_input,
                                    std::ostream& out, std::ostream& err, int& code) {
    CommandOptions options;
    std::string size = "640x480", camera;
    CLI::App app(
        "Renders triangular Bézier patches (.bpt, Roth's thesis ch. 6: Bézier clipping in an "
        "Embree BVH) or the boundary of a mesh, coloured by element quality or label, to a "
        "PNG picture",
        "sxk render");
    if (with_input)
        app.add_option("INPUT", options.input,
                       "Patch file (.bpt) or mesh file (" + std::string(known_mesh_extensions()) + ")")
            ->required();
    app.add_option("OUT", options.output, "Output picture (.png)")->required();
    app.add_option("--size", size,
                   "Picture size WxH in pixels, each 1.." + std::to_string(max_image_side))
        ->check(CLI::Validator(
            [](std::string& text) {
                return parse_size(text) ? std::string()
                                        : "'" + text + "' is not WxH (two whole numbers 1.." +
                                              std::to_string(max_image_side) + ", e.g. 640x480)";
            },
            "WxH"))
        ->capture_default_str();
    app.add_option("--camera", camera,
                   "Camera eye,target,up as nine numbers ex,ey,ez,tx,ty,tz,ux,uy,uz (default: the "
                   "whole scene framed from direction (1,-2,1.2), z up; planar meshes from +z)")
        ->check(CLI::Validator(
            [](std::string& text) {
                const auto camera = parse_camera(text);
                return std::holds_alternative<std::string>(camera) ? std::get<std::string>(camera)
                                                                   : std::string();
            },
            "EYE,TARGET,UP"));
    app.add_option("--fov", options.fov, "Vertical field of view in degrees, 0 < DEG < 180")
        ->check(number_in(0, false, 180, false, "(0, 180)"))
        ->capture_default_str();
    app.add_flag("--tessellate", options.tessellate,
                 "Patches only: render a uniform tessellation as Embree triangles instead of "
                 "clipping the patches");
    app.add_option("--segments", options.segments,
                   "Patches with --tessellate: each patch's domain edge cut into N (N^2 triangles "
                   "per patch); default: the smallest N whose tessellation deviates at most "
                   "1e-4 x the box diagonal from the patches")
        ->check(whole_number_in(1, max_segments));
    app.add_option("--flatness", options.flatness,
                   "Patches: split into sub-patches until flatter than F x the box diagonal "
                   "(Roth's height criterion), 0 < F <= 1")
        ->check(number_in(0, false, 1, true, "(0, 1]"))
        ->capture_default_str();
    app.add_option("--colour", options.colour,
                   "quality (meshes' default: element aspect ratio, red bad -> blue good, with a colour "
                   "bar), label (a palette by element label; patches: by .bpt patch), piece (meshes: a "
                   "palette by connected component) or plain (grey; patches' default); faces on a cut "
                   "are magenta, seen through the body where it hides them")
        ->check(CLI::IsMember({"quality", "label", "piece", "plain"}));
    int cut_label = 0;
    app.add_option("--cut-label", cut_label,
                   "Meshes: boundary faces with this face label are drawn as cut faces too (default: "
                   "9999, the label dissection gives the faces it opens; cut faces are also found as "
                   "boundary faces that coincide)")
        ->check(whole_number("LABEL"));
    std::string tool;
    app.add_option("--tool", tool,
                   "Meshes: draw a tool over the picture: a point, a segment (a blade, a needle) or a "
                   "triangle (a swept blade) as 3, 6 or 9 numbers x,y,z,...")
        ->check(CLI::Validator(
            [](std::string& text) {
                const auto points = parse_tool(text);
                return std::holds_alternative<std::string>(points) ? std::get<std::string>(points) : std::string();
            },
            "X,Y,Z,..."));
    app.add_option("--title", options.title, "A line of text at the picture's top-left (a frame's step and time)");
    app.add_option("--explode", options.explode,
                   "Meshes: move each piece (connected component) away from the middle by F times its "
                   "centre's distance from it, to show the pieces of a cut apart, 0 <= F <= 10")
        ->check(number_in(0, true, 10, true, "[0, 10]"));
    app.add_flag("--json", options.json, "Print one JSON object instead of the summary line");
    if (with_input)
        add_read_options(app, options.reading);
    if (const std::optional<int> done = parse_command_line(app, args, "render", out, err)) {
        code = *done;
        return std::nullopt;
    }
    options.size = *parse_size(size);
    if (!camera.empty()) options.camera = std::get<Camera>(parse_camera(camera));
    if (app.count("--cut-label") > 0)
        options.cut_label = cut_label;
    if (!tool.empty()) options.tool = std::get<std::vector<Point>>(parse_tool(tool));
    options.segments_given = app.count("--segments") > 0;
    options.flatness_given = app.count("--flatness") > 0;
    return options;
}

std::string lowercase_extension(const std::string& file) {
    std::string extension = std::filesystem::path(file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// The output is checked before anything is read or rendered: a wrong name is a usage error
// (exit 2), not a failure after a long render. Only write_png failing later is exit 1.
bool check_output(const std::string& output, std::ostream& err) {
    if (lowercase_extension(output) != ".png") {
        err << "sxk: " << output << ":0: unknown output format (known: .png)\n";
        return false;
    }
    std::filesystem::path folder = std::filesystem::path(output).parent_path();
    if (folder.empty())
        folder = ".";
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) {
        err << "sxk: " << output << ":0: cannot write: no such folder " << folder.string() << '\n';
        return false;
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        err << "sxk: " << output << ":0: cannot write: folder " << folder.string()
            << " is not writable\n";
        return false;
    }
    return true;
}

// What a render draws, with the colour of a hit and the summary's words.
struct Drawing {
    Scene scene;
    std::string scheme;  // the --colour in effect
    std::function<Colour(const SceneHit&)> colour;
    nlohmann::ordered_json facts;  // kind-specific JSON keys
    std::string summary;           // e.g. "64 patches"
    // meshes: the cut faces again, drawn through the body where it hides them (Shading::overlay)
    std::optional<Scene> cuts;
    std::vector<Point> fit_points;  // meshes: what the default camera fits (empty: frame() the scene)
    std::uint32_t pieces = 0;       // meshes: connected components
    std::size_t cut_triangles = 0;
};

using Seconds = std::chrono::duration<double>;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return Seconds(std::chrono::steady_clock::now() - start).count();
}

std::string plural(std::size_t count, const char* one, const char* many) {
    return std::to_string(count) + ' ' + (count == 1 ? one : many);
}

// The default --segments: the smallest count whose tessellation deviates at most
// default_tessellation_error x the box diagonal from the patches. Not the tolerance the clipped
// hits are checked to (1e-7 x the diagonal, tests/plugins/bezier_mask_test.cpp): the teapot would
// need about 1600 segments there, 64 x 1600^2 triangles, and segments_for_error minutes to
// measure them. 1e-4 of the diagonal is a tenth of a pixel in a picture 1000 pixels across that
// shows the whole scene.
constexpr double default_tessellation_error = 1e-4;

int default_segments(const std::vector<TriangularPatch>& patches, int largest) {
    const double error = default_tessellation_error * box_of(patches).diagonal();
    if (!(error > 0))
        return 1;  // all control points coincide
    return segments_for_error(patches, error, largest);
}

// A usage error found once the patches are read: the message, the hint, nullopt (exit 2).
std::nullopt_t refuse(const std::string& why, std::ostream& err) {
    err << "sxk: render: " << why << "\nRun 'sxk render --help' for more information.\n";
    return std::nullopt;
}

std::string number_text(double value, const char* format = "%g") {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// The smallest --flatness the patches' scene accepts (smallest_flatness) rounded up to three
// digits, as text and as the number that text reads back to (which is what is compared, so the
// value the message names is accepted).
std::pair<std::string, double> smallest_accepted_flatness(const Box& box) {
    const double smallest = smallest_flatness(box);
    std::string text = number_text(smallest, "%.2e");
    if (std::stod(text) < smallest)
        text = number_text(smallest * 1.005, "%.2e");
    return {text, std::stod(text)};
}

// The patch file's scene; nullopt when it cannot be read or the options ask for more than it
// can do (the message is printed).
std::optional<Drawing> patch_drawing(const CommandOptions& options, std::ostream& err) {
    std::vector<TensorPatch> tensors;
    try {
        tensors = read_bpt(options.input);
    } catch (const InputError& error) {
        err << "sxk: " << error.what() << '\n';
        return std::nullopt;
    }
    std::vector<TriangularPatch> patches = to_triangular(tensors);

    PatchSceneOptions scene_options;
    scene_options.flatness = options.flatness;
    const bool by_label = options.colour == "label";
    nlohmann::ordered_json facts;
    facts["kind"] = options.tessellate ? "tessellated patches" : "patches";
    facts["patches"] = patches.size();
    facts["bpt_patches"] = tensors.size();
    if (!options.tessellate) {
        facts["flatness"] = options.flatness;
        const std::string flatness = "--flatness " + number_text(options.flatness) +
                                     (options.flatness_given ? "" : " (the default)");
        const auto [smallest_text, smallest] = smallest_accepted_flatness(box_of(patches));
        if (options.flatness < smallest)
            return refuse(flatness + " is below what double rounding resolves in " + options.input +
                              "; the smallest accepted is " + smallest_text,
                          err);
        std::optional<Scene> built;
        try {
            built = Scene::from_patches(patches, scene_options);
        } catch (const SubdivisionTooLarge& too_large) {
            return refuse(flatness + " splits the patches of " + options.input +
                              " into more sub-patches than fit in " +
                              std::to_string(too_large.max_bytes() >> 20) + " MiB (" +
                              std::to_string(too_large.pieces()) +
                              " made when it stopped); use a larger --flatness",
                          err);
        }
        Scene scene = std::move(*built);
        // primitives are the triangular patches, two per .bpt patch (to_triangular)
        auto colour = [by_label](const SceneHit& hit) {
            return by_label ? label_colour(static_cast<int>(hit.primitive / 2)) : plain_colour();
        };
        return Drawing{std::move(scene), options.colour.empty() ? "plain" : options.colour, colour,
                       facts, plural(patches.size(), "patch", "patches"), std::nullopt, {}, 0, 0};
    }
    // the largest count within max_tessellation_triangles, and within max_tessellation_steps:
    // a vertex costs one de Casteljau evaluation at the highest degree, n(n+1)(n+2)/6 steps
    const auto count = static_cast<long long>(patches.size());
    const auto fitting = static_cast<int>(
        std::sqrt(static_cast<double>(max_tessellation_triangles) / static_cast<double>(count)));
    int degree = 0;
    for (const TriangularPatch& patch : patches)
        degree = std::max(degree, patch.degree());
    const long long steps = static_cast<long long>(degree) * (degree + 1) * (degree + 2) / 6;
    const auto work = [&](int n) { return count * (n + 1) * (n + 2) / 2 * steps; };
    int affordable = max_segments;
    while (affordable > 1 && work(affordable) > max_tessellation_steps)
        --affordable;
    if (options.segments_given && options.segments > fitting) {
        const long long triangles = count * options.segments * options.segments;
        return refuse("--segments " + std::to_string(options.segments) + " gives " +
                          std::to_string(count) + " patches x " + std::to_string(options.segments) +
                          "^2 = " + std::to_string(triangles) + " triangles, more than the " +
                          std::to_string(max_tessellation_triangles) + " allowed; use --segments " +
                          std::to_string(fitting) + " or fewer",
                      err);
    }
    if (options.segments_given && options.segments > affordable) {
        const int n = options.segments;
        return refuse("--segments " + std::to_string(n) + " evaluates " + std::to_string(count) +
                          " patches x " + std::to_string((n + 1) * (n + 2) / 2) + " points x " +
                          std::to_string(steps) + " de Casteljau steps (degree " +
                          std::to_string(degree) + ") = " + std::to_string(work(n)) +
                          ", more than the " + std::to_string(max_tessellation_steps) +
                          " allowed; use --segments " + std::to_string(affordable) + " or fewer",
                      err);
    }
    int searched = std::min(fitting, affordable);
    while (searched > 1 && 16 * work(searched) > max_tessellation_steps)
        --searched;
    const int segments =
        options.segments_given ? options.segments : default_segments(patches, searched);
    facts["segments"] = segments;
    TriangleSoup soup = tessellate(patches, segments);
    facts["triangles"] = soup.triangles.size();
    const std::size_t per_patch =
        static_cast<std::size_t>(segments) * static_cast<std::size_t>(segments);
    Scene scene = Scene::from_triangles(std::move(soup));
    auto colour = [by_label, per_patch](const SceneHit& hit) {
        return by_label ? label_colour(static_cast<int>(hit.primitive / per_patch / 2))
                        : plain_colour();
    };
    return Drawing{std::move(scene), options.colour.empty() ? "plain" : options.colour, colour,
                   facts,
                   plural(patches.size(), "patch", "patches") + " tessellated (" +
                       std::to_string(segments) + " segments)",
                   std::nullopt, {}, 0, 0};
}

// --explode F: each piece's vertices moved by F x (the piece's centre - the middle of all), the
// centres those of the pieces' surface vertices. A vertex is in one piece only (the kernel holds
// no vertex whose elements do not connect through faces: sxk/io.hpp, pinched vertices).
void explode(MeshSurface& surface, double factor) {
    std::vector<std::uint32_t> piece_of(surface.soup.vertices.size(), 0);
    for (std::size_t i = 0; i < surface.keys.size(); ++i)
        for (const std::uint32_t v : surface.soup.triangles[i]) piece_of[v] = surface.keys[i].piece;
    std::vector<Point> centre(surface.pieces, Point{0, 0, 0});
    std::vector<double> count(surface.pieces, 0);
    for (std::size_t v = 0; v < piece_of.size(); ++v) {
        for (std::size_t q = 0; q < 3; ++q) centre[piece_of[v]][q] += surface.soup.vertices[v][q];
        count[piece_of[v]] += 1;
    }
    Point middle{0, 0, 0};
    double pieces = 0;
    for (std::size_t p = 0; p < centre.size(); ++p)
        if (count[p] > 0) {
            centre[p] = scaled(1 / count[p], centre[p]);
            for (std::size_t q = 0; q < 3; ++q) middle[q] += centre[p][q];
            pieces += 1;
        }
    if (pieces < 2) return;
    middle = scaled(1 / pieces, middle);
    for (std::size_t v = 0; v < piece_of.size(); ++v)
        for (std::size_t q = 0; q < 3; ++q)
            surface.soup.vertices[v][q] += factor * (centre[piece_of[v]][q] - middle[q]);
}

Drawing mesh_drawing(const Mesh& mesh, const CommandOptions& options) {
    MeshSurfaceOptions surface_options;
    // without --cut-label the label dissect gives the faces it opens (sxk/ops/dissect.hpp)
    surface_options.cut_label = options.cut_label.value_or(default_cut_label);
    MeshSurface surface = mesh_surface(mesh, surface_options);
    nlohmann::ordered_json facts;
    facts["kind"] = "mesh";
    facts["element_kind"] = mesh.topological_dimension() == 3 ? "tetrahedron" : "triangle";
    facts["elements"] = mesh.element_count();
    facts["triangles"] = surface.soup.triangles.size();
    facts["cut_triangles"] = surface.cut_count();
    std::string summary =
        plural(surface.soup.triangles.size(),
               mesh.topological_dimension() == 3 ? "boundary triangle" : "triangle",
               mesh.topological_dimension() == 3 ? "boundary triangles" : "triangles") +
        " (" + std::to_string(surface.cut_count()) + " on cuts)";
    const std::string scheme = options.colour.empty() ? "quality" : options.colour;
    facts["pieces"] = surface.pieces;
    if (options.explode > 0) explode(surface, options.explode);
    // the cut faces again, alone: where the body hides them they are drawn through it
    std::optional<Scene> cuts;
    if (surface.cut_count() > 0) {
        TriangleSoup cut_soup;
        cut_soup.vertices = surface.soup.vertices;
        for (std::size_t i = 0; i < surface.keys.size(); ++i)
            if (surface.keys[i].cut) cut_soup.triangles.push_back(surface.soup.triangles[i]);
        cuts = Scene::from_triangles(std::move(cut_soup));
    }
    std::vector<Point> fit_points = surface.soup.vertices;
    const std::uint32_t pieces = surface.pieces;
    const std::size_t cut_triangles = surface.cut_count();
    std::vector<SurfaceTriangleKeys> keys = std::move(surface.keys);
    Scene scene = Scene::from_triangles(std::move(surface.soup));
    auto colour = [scheme, keys = std::move(keys)](const SceneHit& hit) {
        const SurfaceTriangleKeys& key = keys[hit.primitive];
        if (key.cut)
            return cut_colour();
        if (scheme == "quality")
            return quality_colour(key.quality);
        if (scheme == "label")
            return label_colour(key.label);
        if (scheme == "piece")
            return label_colour(static_cast<int>(key.piece % 1000));
        return plain_colour();
    };
    return Drawing{std::move(scene), scheme, colour, facts, summary, std::move(cuts), std::move(fit_points),
                   pieces, cut_triangles};
}

nlohmann::ordered_json point_json(const Point& p) {
    return {p[0], p[1], p[2]};
}

// The 8-bit sRGB colour of a linear one, for the marks drawn over a picture.
pictures::Colour srgb(const Colour& linear) {
    pictures::Colour encoded{};
    for (std::size_t c = 0; c < 3; ++c) {
        const double v = std::clamp(linear[c], 0.0, 1.0);
        encoded[c] = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    }
    return encoded;
}

// Pictures smaller than this get no legend or colour bar: the text would cover them.
constexpr int smallest_annotated_width = 200, smallest_annotated_height = 150;
// The tool's colour: near black, which no surface colour is (the darkest shade of the palette's
// darkest entry is lighter), so a blade reads against the body and the background.
constexpr pictures::Colour tool_colour{0.08, 0.08, 0.12};

// What is drawn over a picture: the title, the tool, the legend of what the colours mean, and
// the colour bar of a scalar colouring.
pictures::Annotation marks_of(const CommandOptions& options, const Drawing& drawing, const Camera& camera,
                              const std::array<int, 2>& size) {
    pictures::Annotation marks;
    marks.title = options.title;
    std::vector<std::array<double, 2>> tool;
    for (const Point& p : options.tool)
        if (const auto at = project(camera, size[0], size[1], p)) tool.push_back(*at);
    const double width = std::max(3.0, size[1] / 120.0);
    if (tool.size() == 1)
        marks.dots.push_back({tool[0], tool_colour, width * 1.5});
    else if (tool.size() > 1)
        marks.lines.push_back({tool, tool_colour, width, tool.size() == 3, tool.size() == 3 ? 0.25 : 0.0});
    if (size[0] < smallest_annotated_width || size[1] < smallest_annotated_height || drawing.fit_points.empty())
        return marks;
    if (drawing.scheme == "piece" && drawing.pieces > 1) {
        const std::uint32_t listed = std::min<std::uint32_t>(drawing.pieces, 6);
        for (std::uint32_t p = 0; p < listed; ++p)
            marks.legend.push_back({"piece " + std::to_string(p + 1), srgb(label_colour(static_cast<int>(p)))});
        if (drawing.pieces > listed)
            marks.legend.back().text += " ... " + std::to_string(drawing.pieces) + " pieces";
    }
    if (drawing.cut_triangles > 0 || !options.tool.empty())
        marks.legend.push_back({"cut faces", srgb(cut_colour())});
    if (!options.tool.empty()) marks.legend.push_back({"tool", tool_colour});
    if (drawing.scheme == "quality") {
        pictures::Annotation::ColourBar bar{"aspect ratio / regular", "0 flat", "1 regular", {}};
        for (const double q : {0.0, 0.25, 0.5, 0.75, 1.0}) bar.stops.push_back(srgb(quality_colour(q)));
        marks.bar = std::move(bar);
    }
    return marks;
}

// Renders, writes and reports; the drawing is made. Returns the exit code.
int draw(const CommandOptions& options, Drawing& drawing, bool planar,
         double read_and_build_seconds, std::ostream& out, std::ostream& err) {
    const std::array<int, 2> size = options.size;
    Camera camera;
    if (!options.camera && !drawing.fit_points.empty()) {
        camera = fit(drawing.fit_points, planar ? planar_view : default_view, planar ? planar_up : default_up,
                     options.fov, static_cast<double>(size[0]) / size[1]);
    } else if (!options.camera) {
        camera = frame(drawing.scene.bounds(), planar ? planar_view : default_view,
                       planar ? planar_up : default_up, options.fov);
    } else {
        camera = *options.camera;
    }
    camera.fov_degrees = options.fov;

    Shading shading;
    shading.colour = drawing.colour;
    if (drawing.cuts) {
        shading.overlay = &*drawing.cuts;
        shading.overlay_colour = [](const SceneHit&) { return cut_colour(); };
    }
    const auto start = std::chrono::steady_clock::now();
    Image image = render(drawing.scene, camera, size[0], size[1], shading);
    annotate(image, marks_of(options, drawing, camera, size));
    const double render_seconds = seconds_since(start);
    try {
        write_png(options.output, image);
    } catch (const std::exception& error) {
        err << "sxk: " << write_error_line(options.output, error) << '\n';
        return cli::exit_refused;
    }

    const double total = read_and_build_seconds + render_seconds;
    if (options.json) {
        nlohmann::ordered_json json;
        json["input"] = options.input;
        json["output"] = options.output;
        json["width"] = size[0];
        json["height"] = size[1];
        for (const auto& [key, value] : drawing.facts.items())
            json[key] = value;
        json["primitives"] = drawing.scene.primitive_count();
        json["leaves"] = drawing.scene.leaf_count();
        json["colour"] = drawing.scheme;
        nlohmann::ordered_json camera_json;
        camera_json["eye"] = point_json(camera.eye);
        camera_json["target"] = point_json(camera.target);
        camera_json["up"] = point_json(camera.up);
        camera_json["fov"] = camera.fov_degrees;
        json["camera"] = camera_json;
        nlohmann::ordered_json seconds;
        seconds["read_and_build"] = read_and_build_seconds;
        seconds["render"] = render_seconds;
        seconds["total"] = total;
        json["seconds"] = seconds;
        out << json.dump(2) << '\n';
        return cli::exit_success;
    }
    char time[32];
    std::snprintf(time, sizeof time, "%.2f s", total);
    out << options.input << " -> " << options.output << ": " << size[0] << 'x' << size[1] << ", "
        << drawing.summary << ", " << plural(drawing.scene.leaf_count(), "leaf", "leaves") << ", "
        << time << '\n';
    return cli::exit_success;
}

// Options that do not fit the input's kind, or a picture beyond max_pixels: a usage error, found
// before anything is read.
bool refuse_options_for(const CommandOptions& options, bool patches, std::ostream& err) {
    std::string why;
    const std::array<int, 2> size = options.size;
    if (static_cast<long long>(size[0]) * size[1] > max_pixels) {
        why = "--size " + std::to_string(size[0]) + "x" + std::to_string(size[1]) + " has " +
              std::to_string(static_cast<long long>(size[0]) * size[1]) +
              " pixels, more than the " + std::to_string(max_pixels) + " allowed (8192x8192)";
    } else if (patches && options.colour == "quality") {
        why = "--colour quality needs a mesh; " + options.input + " holds patches";
    } else if (patches && options.cut_label) {
        why = "--cut-label needs a mesh; " + options.input + " holds patches";
    } else if (patches && (options.colour == "piece" || !options.tool.empty() || options.explode > 0)) {
        why = std::string(options.colour == "piece" ? "--colour piece" : !options.tool.empty() ? "--tool" : "--explode") +
              " needs a mesh; " + options.input + " holds patches";
    } else if (!patches) {
        const char* given = options.tessellate       ? "--tessellate"
                            : options.segments_given ? "--segments"
                            : options.flatness_given ? "--flatness"
                                                     : nullptr;
        if (given)
            why = std::string(given) + " applies to patch files (.bpt); " + options.input +
                  " is a mesh";
    }
    if (why.empty())
        return false;
    err << "sxk: render: " << why << "\nRun 'sxk render --help' for more information.\n";
    return true;
}

int render_mesh(const Mesh& mesh, const CommandOptions& options,
                std::chrono::steady_clock::time_point start, std::ostream& out, std::ostream& err) {
    if (mesh.element_count() == 0) {
        err << "sxk: " << options.input << ": the mesh has no elements to draw\n";
        return cli::exit_refused;
    }
    Drawing drawing = mesh_drawing(mesh, options);
    return draw(options, drawing, mesh.ambient_dimension() == 2, seconds_since(start), out, err);
}

class RenderCommand final : public PluginCommand {
public:
    std::string_view name() const override { return "render"; }
    std::string_view summary() const override {
        return "ray-trace Bézier patches (.bpt) or a mesh's boundary to a PNG picture";
    }

    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override {
        int code = 0;
        const std::optional<CommandOptions> options = parse(args, true, out, err, code);
        if (!options)
            return code;
        const bool patches = lowercase_extension(options->input) == ".bpt";
        if (!patches && !format_from_extension(options->input)) {
            err << "sxk: " << options->input << ":0: unknown input format (known: .bpt "
                << known_mesh_extensions() << ")\n";
            return cli::exit_usage;
        }
        if (refuse_options_for(*options, patches, err) || !check_output(options->output, err))
            return cli::exit_usage;
        const auto start = std::chrono::steady_clock::now();
        try {
            if (patches) {
                std::optional<Drawing> drawing = patch_drawing(*options, err);
                if (!drawing)
                    return cli::exit_usage;
                return draw(*options, *drawing, false, seconds_since(start), out, err);
            }
            const std::optional<Mesh> mesh = load_mesh_for_command(options->input, err, options->reading);
            if (!mesh)
                return cli::exit_usage;
            return render_mesh(*mesh, *options, start, out, err);
        } catch (const std::bad_alloc&) {
            err << "sxk: " << options->input << ": out of memory while rendering\n";
        } catch (const std::exception& error) {
            err << "sxk: " << options->input << ": " << error.what() << '\n';
        }
        return cli::exit_refused;
    }

    bool accepts_mesh() const override { return true; }
    int run_on_mesh(const Mesh& mesh, std::string_view mesh_name, std::span<const std::string> args,
                    std::ostream& out, std::ostream& err) override {
        int code = 0;
        std::optional<CommandOptions> options = parse(args, false, out, err, code);
        if (!options)
            return code;
        options->input = mesh_name;
        if (refuse_options_for(*options, false, err) || !check_output(options->output, err))
            return cli::exit_usage;
        try {
            return render_mesh(mesh, *options, std::chrono::steady_clock::now(), out, err);
        } catch (const std::exception& error) {
            err << "sxk: " << options->input << ": " << error.what() << '\n';
        }
        return cli::exit_refused;
    }
};

// The command's last message line without its "sxk: " (and CLI11's "Run ... --help" line).
std::string message_of(const std::string& err) {
    std::string text = err.substr(0, err.find('\n'));
    if (text.starts_with("sxk: ")) text = text.substr(5);
    return text.empty() ? "render: no picture" : text;
}

// RenderService::draw_mesh: the command's own path for a mesh in memory (run_on_mesh), with the
// picture's typed options.
Outcome<Done> draw_mesh(const Mesh& mesh, const std::filesystem::path& output, const MeshPicture& picture) {
    if (Outcome<Done> checked = picture.check(); !checked) return checked.refusal();
    CommandOptions options;
    options.input = "mesh";
    options.output = output.string();
    options.size = {picture.width, picture.height};
    if (picture.camera) {
        Camera camera;
        camera.eye = picture.camera->eye;
        camera.target = picture.camera->target;
        camera.up = picture.camera->up;
        if (const auto problem = camera_problem(camera))
            return Refusal{RefusalCode::bad_argument, "render: camera: " + *problem};
        options.camera = camera;
    }
    options.fov = picture.fov;
    constexpr std::array<const char*, 4> colourings{"quality", "label", "piece", "plain"};
    options.colour = colourings[static_cast<std::size_t>(picture.colour)];
    options.cut_label = picture.cut_label;
    options.tool = picture.tool;
    options.title = picture.title;
    options.explode = picture.explode;
    std::ostringstream out, err;
    if (!check_output(options.output, err)) return Refusal{RefusalCode::bad_argument, message_of(err.str())};
    try {
        if (render_mesh(mesh, options, std::chrono::steady_clock::now(), out, err) != 0)
            return Refusal{RefusalCode::not_applicable, message_of(err.str())};
    } catch (const std::exception& error) {
        return Refusal{RefusalCode::not_applicable, std::string("render: ") + error.what()};
    }
    return Done{};
}

// RenderService::default_camera: frame() from the default view, as draw() frames a mesh.
// The deformed positions of the vertices in elements: what a picture of the mesh shows.
std::vector<Point> shown_points(const Mesh& mesh) {
    std::vector<Point> points;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.vertex_element(v) != invalid_id) points.push_back(mesh.deformed(v));
    return points;
}

View view_of(const Camera& camera) { return View{camera.eye, camera.target, camera.up}; }

View default_camera(const Mesh& mesh) {
    const std::vector<Point> points = shown_points(mesh);
    const bool planar = mesh.ambient_dimension() == 2;
    return view_of(frame(box_of(points), planar ? planar_view : default_view, planar ? planar_up : default_up,
                         CommandOptions{}.fov));
}

// RenderService::frame_view: one view for every picture of a run, fitted to the mesh as it is
// (its deformed positions, the vertices in elements) with room for what moves (a margin of 8 %),
// the picture shaped to the body (width / height within [0.4, 2.5]) with about `pixels` pixels.
MeshPicture frame_view(const Mesh& mesh, long long pixels) {
    const std::vector<Point> points = shown_points(mesh);
    const bool planar = mesh.ambient_dimension() == 2;
    const Point& from = planar ? planar_view : default_view;
    const Point& up = planar ? planar_up : default_up;
    const double aspect = std::clamp(extent_aspect(points, from, up), 0.4, 2.5);
    const double area = static_cast<double>(std::clamp(pixels, 40000LL, max_pixels));
    // even sides: the video encoders of --animation (ffmpeg's yuv420p) need them
    const auto even = [](double side) { return std::max(2, 2 * static_cast<int>(std::lround(side / 2))); };
    const int width = even(std::sqrt(area * aspect)), height = even(area / std::sqrt(area * aspect));
    const Camera camera = fit(points, from, up, CommandOptions{}.fov, static_cast<double>(width) / height, 0.08);
    MeshPicture picture;
    picture.width = width;
    picture.height = height;
    picture.camera = view_of(camera);
    return picture;
}

class BezierPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == RenderService::service_id) return offer_of(&m_service);
        return {};
    }

private:
    RenderService m_service{&draw_mesh, &default_camera, &frame_view};
    RenderCommand m_render;
    PluginCommand* m_commands[1] = {&m_render};
};

}  // namespace
}  // namespace sxk::bezier

SXK_PLUGIN(bezier, sxk::bezier::BezierPlugin, "0.1.0",
           "ray tracing of triangular Bézier patches (Roth ch. 6) and meshes; sxk render");
