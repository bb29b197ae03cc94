// A body from `sxk deform`'s options (body_setup.hpp).
#include "body_setup.hpp"

#include <cstdint>
#include <string_view>
#include <utility>

#include "command_line.hpp"
#include "load_shares.hpp"
#include "sxk/components.hpp"

namespace sxk::elasticity {

void add_body_options(CLI::App& app, BodySetup& setup) {
    app.add_option(
        "--fix", setup.fix,
        "Vertices held in place: a selector such as 'x<0.001', 'label=2&boundary' (repeatable)");
    app.add_option("--displace", setup.displace,
                   "Vertices moved by a prescribed displacement: 'EXPR:DX,DY,DZ' (repeatable)");
    app.add_option("--force", setup.force,
                   "A total force on the selected vertices, shared among them as --share says: "
                   "'EXPR:FX,FY,FZ' "
                   "(repeatable)");
    app.add_option("--share", setup.share,
                   "How a --force is shared: equal (the same part each) or area (by the boundary "
                   "area around each "
                   "vertex: a uniform traction on the selected boundary)")
        ->check(CLI::IsMember({"equal", "area"}))
        ->capture_default_str();
    app.add_option("--gravity", setup.gravity,
                   "An acceleration on every element's mass, 'GX,GY,GZ' (m/s^2, e.g. 0,-9.8,0): "
                   "each element's weight "
                   "shared equally by its corners");
    app.add_option("--density", setup.density, "Mass per volume for --gravity (kg/m^3)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--material", setup.material,
                   "Material model: linear (small strains) or neohookean (compressible "
                   "neo-Hookean, large strains, "
                   "nonlinear CG)")
        ->check(CLI::IsMember({"linear", "neohookean"}))
        ->capture_default_str();
    app.add_option("--thickness", setup.thickness,
                   "Slab thickness of a triangle mesh in plane stress, > 0 (default 1)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"));
    app.add_option("--E,--young", setup.young, "Young's modulus, > 0")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--nu,--poisson", setup.poisson, "Poisson's ratio, -1 < nu < 0.5")
        ->check(number_in(-1, false, 0.5, false, "(-1, 0.5)"))
        ->capture_default_str();
    app.add_option("--tol", setup.tolerance,
                   "Relative tolerance of the residual against the loads and reactions (thesis eq. "
                   "6.9), 0 < tol < 1")
        ->check(number_in(0, false, 1, false, "(0, 1)"))
        ->capture_default_str();
    app.add_option("--rounding", setup.rounding,
                   "epsilon_round of eq. 6.9: the part of the stop threshold that stands for rounding, "
                   "relative to E times the body's area (the thesis' needle runs: 1e-8), 0 <= x < 1")
        ->check(number_in(0, true, 1, false, "[0, 1)"))
        ->capture_default_str();
    app.add_option("--max-iterations", setup.max_iterations, "Most CG iterations before giving up")
        ->check(whole_number_in(1, 100000000))
        ->capture_default_str();
    app.add_option("--stop", setup.stop,
                   "What --tol is relative to: reactions (the loads and the reactions that hold the fixed "
                   "vertices, eq. 6.9) or external (the loads only, eq. 6.8: the thesis' chapters 3 and 4)")
        ->check(CLI::IsMember({"reactions", "external"}))
        ->capture_default_str();
}

namespace {

// Three numbers "A,B,C" of option `option` given as `text`; nullopt with the message printed
// ("expected three numbers NAMES, found 2").
std::optional<Vector3> parse_vector(const std::string& option, const std::string& text,
                                    std::string_view numbers, const char* names,
                                    std::ostream& err) {
    const auto parsed = parse_number_list(numbers);
    if (const std::string* why = std::get_if<std::string>(&parsed)) {
        err << "sxk: deform: " << option << " '" << text << "': " << *why << '\n';
        return std::nullopt;
    }
    const auto& list = std::get<std::vector<double>>(parsed);
    if (list.size() != 3) {
        err << "sxk: deform: " << option << " '" << text << "': expected three numbers " << names
            << ", found " << list.size() << '\n';
        return std::nullopt;
    }
    return Vector3{list[0], list[1], list[2]};
}

// "EXPR" (with_vector false) or "EXPR:X,Y,Z"; nullopt with the message printed.
std::optional<Selected> parse_selected(const std::string& option, const std::string& text,
                                       bool with_vector, std::ostream& err) {
    Selected s;
    std::string expression = text;
    if (with_vector) {
        const std::size_t colon = text.rfind(':');
        if (colon == std::string::npos) {
            err << "sxk: deform: " << option << " '" << text << "': expected SELECTOR:X,Y,Z\n";
            return std::nullopt;
        }
        expression = text.substr(0, colon);
        const std::optional<Vector3> vector = parse_vector(
            option, text, std::string_view(text).substr(colon + 1), "X,Y,Z after ':'", err);
        if (!vector)
            return std::nullopt;
        s.vector = *vector;
    }
    auto selector = parse_vertex_selector(expression);
    if (!selector) {
        err << "sxk: deform: " << option << ": " << selector.reason() << '\n';
        return std::nullopt;
    }
    s.selector = std::move(*selector);
    return s;
}

// Every occurrence of one option; nullopt when one of them does not parse (message printed).
std::optional<std::vector<Selected>> parse_all(const std::string& option,
                                               const std::vector<std::string>& texts,
                                               bool with_vector, std::ostream& err) {
    std::vector<Selected> all;
    for (const std::string& text : texts) {
        std::optional<Selected> s = parse_selected(option, text, with_vector, err);
        if (!s)
            return std::nullopt;
        all.push_back(std::move(*s));
    }
    return all;
}

// A face-connected component (sxk/components.hpp) with a load on some vertex and no vertex held.
struct FreePart {
    std::size_t component = 0;  // numbered as connected_components numbers them
    std::size_t elements = 0;
};

// The first such component, if any. Such a part has no equilibrium: CG chases it off to infinity
// (issue 47 saw |r| = 2.3e18 on a free body among fixed ones) instead of naming it. O(n), once
// at set-up: the whole-mesh scan a static solve affords, and a tool's session pays before its
// first step (the snap cutter holds the pieces it cuts loose itself, thesis §3.3).
std::optional<FreePart> loaded_free_part(const Mesh& mesh, const ElasticBody& body) {
    const Components components = connected_components(mesh);
    if (components.count < 2) return std::nullopt;  // "nothing holds the body" is parse_body_setup's
    std::vector<char> held(components.count, 0), pushed(components.count, 0);
    std::vector<std::size_t> size(components.count, 0);
    for (const ElementId t : elements(mesh)) {
        const std::uint32_t c = components.element_component[t];
        ++size[c];
        for (const VertexId v : mesh.simplex(t).vertices()) {
            if (v >= body.vertex_count()) continue;
            held[c] |= body.freedom(v) != Freedom::free;
            const Vector3 f = body.force(v);
            pushed[c] |= f[0] != 0 || f[1] != 0 || f[2] != 0;
        }
    }
    for (std::size_t c = 0; c < components.count; ++c)
        if (pushed[c] && !held[c]) return FreePart{c, size[c]};
    return std::nullopt;
}

}  // namespace

std::optional<ParsedBody> parse_body_setup(const BodySetup& setup, std::ostream& err) {
    const auto fixes = parse_all("--fix", setup.fix, false, err);
    const auto displaces = parse_all("--displace", setup.displace, true, err);
    const auto forces = parse_all("--force", setup.force, true, err);
    if (!fixes || !displaces || !forces) return std::nullopt;
    ParsedBody parsed{*fixes, *displaces, *forces, {0, 0, 0}};
    if (!setup.gravity.empty()) {
        const std::optional<Vector3> vector = parse_vector("--gravity", setup.gravity, setup.gravity, "GX,GY,GZ", err);
        if (!vector) return std::nullopt;
        parsed.gravity = *vector;
    }
    if (parsed.fixes.empty() && parsed.displaces.empty()) {
        err << "sxk: deform: nothing holds the body (no --fix or --displace), so it can move "
               "freely and the problem "
               "is singular; fix at least three non-collinear vertices of every connected part\n";
        return std::nullopt;
    }
    return parsed;
}

std::optional<BuiltBody> build_body(const Mesh& mesh, const std::string& file, const BodySetup& setup,
                                    const ParsedBody& parsed, std::ostream& err) {
    const std::string name = file.empty() ? "the mesh" : file;
    const bool planar = mesh.topological_dimension() == 2 && mesh.ambient_dimension() == 2;
    if (setup.thickness && !planar) {
        err << "sxk: deform: --thickness is for triangle meshes in the plane (plane stress); "
            << name << " has " << mesh.topological_dimension() << "-dimensional elements in "
            << mesh.ambient_dimension() << "-dimensional space\n";
        return std::nullopt;
    }
    const Model model = setup.material == "linear" ? Model::linear : Model::neohookean;
    auto body = ElasticBody::make(mesh, {.young = setup.young, .poisson = setup.poisson},
                                  {.model = model, .thickness = setup.thickness.value_or(1.0)});
    if (!body) {
        err << "sxk: " << (file.empty() ? "" : file + ":0: ") << body.reason() << '\n';
        return std::nullopt;
    }
    BuiltBody result;
    result.body = std::make_unique<ElasticBody>(std::move(*body));
    result.planar = planar;
    result.model = model;
    // selections: one that selects nothing is a mistake worth stopping for (a coordinate off by
    // a unit, a label the file does not have)
    auto select = [&](const std::string& option,
                      const Selected& s) -> std::optional<std::vector<VertexId>> {
        std::vector<VertexId> vertices = select_vertices(mesh, s.selector);
        if (vertices.empty()) {
            err << "sxk: deform: " << option << " '" << s.selector.text << "' selects no vertex of "
                << name << '\n';
            return std::nullopt;
        }
        return vertices;
    };
    for (const Selected& s : parsed.fixes) {
        const auto vertices = select("--fix", s);
        if (!vertices)
            return std::nullopt;
        for (const VertexId v : *vertices)
            (void)result.body->fix(v);
    }
    for (const Selected& s : parsed.displaces) {
        const auto vertices = select("--displace", s);
        if (!vertices)
            return std::nullopt;
        for (const VertexId v : *vertices)
            (void)result.body->fix(v, s.vector);
    }
    for (const Selected& s : parsed.forces) {
        const auto vertices = select("--force", s);
        if (!vertices)
            return std::nullopt;
        const auto parts =
            load_shares(mesh, *vertices, setup.share == "area" ? Share::area : Share::equal);
        if (!parts) {
            err << "sxk: deform: --force '" << s.selector.text
                << "' --share area: " << parts.reason() << '\n';
            return std::nullopt;
        }
        for (std::size_t i = 0; i < vertices->size(); ++i) {
            const double part = (*parts)[i];
            (void)result.body->add_force((*vertices)[i],
                                  {s.vector[0] * part, s.vector[1] * part, s.vector[2] * part});
        }
    }
    if (!setup.gravity.empty()) {
        (void)result.body->add_body_force(
            {setup.density * parsed.gravity[0], setup.density * parsed.gravity[1], setup.density * parsed.gravity[2]});
    }
    for (VertexId v = 0; v < result.body->vertex_count(); ++v) {
        const Vector3 f = result.body->force(v);
        result.loaded += f[0] != 0 || f[1] != 0 || f[2] != 0;
    }
    if (const std::optional<FreePart> free = loaded_free_part(mesh, *result.body)) {
        err << "sxk: deform: component " << free->component << " of " << name << " (" << free->elements
            << (free->elements == 1 ? " element" : " elements")
            << ", as `sxk components` numbers them) is loaded and nothing holds it (no --fix or --displace selects "
               "a vertex of it), so it can move freely and the problem is singular; fix at least three "
               "non-collinear vertices of every connected part\n";
        return std::nullopt;
    }
    return result;
}

}  // namespace sxk::elasticity
