// The elasticity plug-in's options as words (body_words.hpp).
#include "body_words.hpp"

#include <variant>

#include "command_line.hpp"

namespace sxk::cli {

void add_body_options(CLI::App& app, BodyWords& words) {
    app.add_option("--fix", words.fix,
                   "Vertices held in place: a selector such as 'x<0.001', 'label=2&boundary' (repeatable)");
    app.add_option("--displace", words.displace,
                   "Vertices moved by a prescribed displacement: 'EXPR:DX,DY,DZ' (repeatable)");
    app.add_option("--force", words.force,
                   "A total force on the selected vertices, shared among them as --share says: 'EXPR:FX,FY,FZ' "
                   "(repeatable)");
    app.add_option("--share", words.share,
                   "How a --force is shared: equal (the same part each) or area (by the boundary area around each "
                   "vertex: a uniform traction on the selected boundary)")
        ->check(CLI::IsMember({"equal", "area"}))
        ->capture_default_str();
    app.add_option("--gravity", words.gravity,
                   "An acceleration on every element's mass, 'GX,GY,GZ' (m/s^2, e.g. 0,-9.8,0): each element's "
                   "weight shared equally by its corners");
    app.add_option("--density", words.density, "Mass per volume for --gravity (kg/m^3)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--material", words.material,
                   "Material model: linear (small strains) or neohookean (compressible neo-Hookean, large strains, "
                   "nonlinear CG)")
        ->check(CLI::IsMember({"linear", "neohookean"}))
        ->capture_default_str();
    app.add_option("--thickness", words.thickness, "Slab thickness of a triangle mesh in plane stress, > 0 (default 1)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"));
    app.add_option("--E,--young", words.young, "Young's modulus, > 0")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--nu,--poisson", words.poisson, "Poisson's ratio, -1 < nu < 0.5")
        ->check(number_in(-1, false, 0.5, false, "(-1, 0.5)"))
        ->capture_default_str();
    app.add_option("--tol", words.tolerance,
                   "Relative tolerance of the residual against the loads and reactions (thesis eq. 6.9), 0 < tol < 1")
        ->check(number_in(0, false, 1, false, "(0, 1)"))
        ->capture_default_str();
    app.add_option("--rounding", words.rounding,
                   "epsilon_round of eq. 6.9: the part of the stop threshold that stands for rounding, relative to E "
                   "times the body's area (the thesis' needle runs: 1e-8), 0 <= x < 1")
        ->check(number_in(0, true, 1, false, "[0, 1)"))
        ->capture_default_str();
    app.add_option("--max-iterations", words.max_iterations, "Most CG iterations before giving up")
        ->check(whole_number_in(1, 100000000))
        ->capture_default_str();
    app.add_option("--stop", words.stop,
                   "What --tol is relative to: reactions (the loads and the reactions that hold the fixed vertices, "
                   "eq. 6.9) or external (the loads only, eq. 6.8: the thesis' chapters 3 and 4)")
        ->check(CLI::IsMember({"reactions", "external"}))
        ->capture_default_str();
}

namespace {

// Three numbers "A,B,C" of option `option` given as `text`, or the refusal ("expected three
// numbers NAMES, found 2").
Outcome<Vector3> vector_of(std::string_view command, const std::string& option, const std::string& text,
                           std::string_view numbers, const char* names) {
    const auto parsed = parse_number_list(numbers);
    const std::string prefix = std::string(command) + ": " + option + " '" + text + "': ";
    if (const std::string* why = std::get_if<std::string>(&parsed))
        return Refusal{RefusalCode::bad_argument, prefix + *why};
    const auto& list = std::get<std::vector<double>>(parsed);
    if (list.size() != 3)
        return Refusal{RefusalCode::bad_argument, prefix + "expected three numbers " + names + ", found " +
                                                      std::to_string(list.size())};
    return Vector3{list[0], list[1], list[2]};
}

// "EXPR:X,Y,Z" of every occurrence of `option`.
Outcome<std::vector<elasticity::Load>> loads_of(std::string_view command, const std::string& option,
                                               const std::vector<std::string>& texts) {
    std::vector<elasticity::Load> loads;
    for (const std::string& text : texts) {
        const std::size_t colon = text.rfind(':');
        if (colon == std::string::npos)
            return Refusal{RefusalCode::bad_argument,
                           std::string(command) + ": " + option + " '" + text + "': expected SELECTOR:X,Y,Z"};
        auto vector = vector_of(command, option, text, std::string_view(text).substr(colon + 1), "X,Y,Z after ':'");
        if (!vector) return vector.refusal();
        loads.push_back({text.substr(0, colon), *vector});
    }
    return loads;
}

}  // namespace

Outcome<elasticity::Options> body_options(const BodyWords& words, std::string_view command) {
    elasticity::Options options;
    options.fix = words.fix;
    auto displace = loads_of(command, "--displace", words.displace);
    if (!displace) return displace.refusal();
    options.displace = std::move(*displace);
    auto force = loads_of(command, "--force", words.force);
    if (!force) return force.refusal();
    options.force = std::move(*force);
    options.share = words.share == "area" ? elasticity::Share::area : elasticity::Share::equal;
    if (!words.gravity.empty()) {
        auto gravity = vector_of(command, "--gravity", words.gravity, words.gravity, "GX,GY,GZ");
        if (!gravity) return gravity.refusal();
        options.gravity = *gravity;
    }
    options.density = words.density;
    options.model = words.material == "neohookean" ? elasticity::Model::neohookean : elasticity::Model::linear;
    options.young = words.young;
    options.poisson = words.poisson;
    options.thickness = words.thickness;
    options.tolerance = words.tolerance;
    options.rounding = words.rounding;
    options.max_iterations = words.max_iterations;
    options.stop = words.stop == "external" ? elasticity::Stop::external : elasticity::Stop::reactions;
    return options;
}

Outcome<elasticity::Options> body_options(std::span<const std::string> words) {
    BodyWords parsed;
    CLI::App app("elasticity simulation", "deform");
    add_body_options(app, parsed);
    if (auto refused = parse_words(app, words, "deform")) return *refused;
    return body_options(parsed);
}

Outcome<std::unique_ptr<Simulation>> simulation_from_words(const Services* host, Mesh& mesh,
                                                           const std::string& words) {
    auto elasticity = host ? host->service<elasticity::ElasticityService>()
                           : Outcome<elasticity::ElasticityService*>(
                                 Refusal{RefusalCode::not_found, "no plug-in host"});
    if (!elasticity) return Refusal{elasticity.code(), elasticity.reason() + " (the elasticity plug-in)"};
    const Outcome<elasticity::Options> body = body_options(words_of(words));
    if (!body) return body.refusal();
    return (*elasticity)->simulate(mesh, *body);
}

}  // namespace sxk::cli
