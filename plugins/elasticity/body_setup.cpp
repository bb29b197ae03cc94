// A body from `sxk deform`'s options (body_setup.hpp).
#include "body_setup.hpp"

#include <cstdint>
#include <optional>
#include <vector>
#include <string_view>
#include <utility>

#include "load_shares.hpp"
#include "sxk/components.hpp"
#include "vertex_selector.hpp"

namespace sxk::elasticity {

namespace {

// A selection as a load's or a fix's; the refusal names the option ("deform: --fix: selector
// 'x<<1': ...").
struct Selected {
    VertexSelector selector;
    Vector3 vector{0, 0, 0};
};

Outcome<std::vector<Selected>> selected(const std::string& option, const std::vector<Load>& loads) {
    std::vector<Selected> all;
    for (const Load& load : loads) {
        auto selector = parse_vertex_selector(load.where);
        if (!selector) return Refusal{RefusalCode::bad_argument, "deform: " + option + ": " + selector.reason()};
        all.push_back({std::move(*selector), load.value});
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

namespace {

// The selections of `options`: fixes, displacements, forces.
struct Selections {
    std::vector<Selected> fixes, displaces, forces;
};

Outcome<Selections> selections_of(const Options& options) {
    if (auto checked = options.check(); !checked) return checked.refusal();
    std::vector<Load> fixed;
    for (const std::string& where : options.fix) fixed.push_back({where, {0, 0, 0}});
    auto fixes = selected("--fix", fixed);
    if (!fixes) return fixes.refusal();
    auto displaces = selected("--displace", options.displace);
    if (!displaces) return displaces.refusal();
    auto forces = selected("--force", options.force);
    if (!forces) return forces.refusal();
    if (fixes->empty() && displaces->empty())
        return Refusal{RefusalCode::bad_argument,
                       "deform: nothing holds the body (no --fix or --displace), so it can move freely and the "
                       "problem is singular; fix at least three non-collinear vertices of every connected part"};
    return Selections{std::move(*fixes), std::move(*displaces), std::move(*forces)};
}

}  // namespace

Outcome<Done> check_body(const Options& options) {
    if (auto selections = selections_of(options); !selections) return selections.refusal();
    return Done{};
}

Outcome<BuiltBody> build_body(const Mesh& mesh, const std::string& file, const Options& options) {
    const Outcome<Selections> selections = selections_of(options);
    if (!selections) return selections.refusal();
    const auto& [fixes, displaces, forces] = *selections;
    const std::string name = file.empty() ? "the mesh" : file;
    const bool planar = mesh.topological_dimension() == 2 && mesh.ambient_dimension() == 2;
    if (options.thickness && !planar)
        return Refusal{RefusalCode::bad_argument,
                       "deform: --thickness is for triangle meshes in the plane (plane stress); " + name + " has " +
                           std::to_string(mesh.topological_dimension()) + "-dimensional elements in " +
                           std::to_string(mesh.ambient_dimension()) + "-dimensional space"};
    const Model model = options.model;
    auto body = ElasticBody::make(mesh, {.young = options.young, .poisson = options.poisson},
                                  {.model = model, .thickness = options.thickness.value_or(1.0)});
    if (!body) return body.refusal().prefixed(file.empty() ? "" : file + ":0: ");
    BuiltBody result;
    result.body = std::make_unique<ElasticBody>(std::move(*body));
    result.planar = planar;
    result.model = model;
    // selections: one that selects nothing is a mistake worth stopping for (a coordinate off by
    // a unit, a label the file does not have)
    auto select = [&](const std::string& option, const Selected& s) -> Outcome<std::vector<VertexId>> {
        std::vector<VertexId> vertices = select_vertices(mesh, s.selector);
        if (vertices.empty())
            return Refusal{RefusalCode::bad_argument,
                           "deform: " + option + " '" + s.selector.text + "' selects no vertex of " + name};
        return vertices;
    };
    for (const Selected& s : fixes) {
        const auto vertices = select("--fix", s);
        if (!vertices) return vertices.refusal();
        for (const VertexId v : *vertices) (void)result.body->fix(v);
    }
    for (const Selected& s : displaces) {
        const auto vertices = select("--displace", s);
        if (!vertices) return vertices.refusal();
        for (const VertexId v : *vertices) (void)result.body->fix(v, s.vector);
    }
    for (const Selected& s : forces) {
        const auto vertices = select("--force", s);
        if (!vertices) return vertices.refusal();
        const auto parts = load_shares(mesh, *vertices, options.share);
        if (!parts)
            return Refusal{parts.code(), "deform: --force '" + s.selector.text + "' --share area: " + parts.reason()};
        for (std::size_t i = 0; i < vertices->size(); ++i) {
            const double part = (*parts)[i];
            (void)result.body->add_force((*vertices)[i],
                                  {s.vector[0] * part, s.vector[1] * part, s.vector[2] * part});
        }
    }
    if (options.gravity) {
        const Vector3& g = *options.gravity;
        (void)result.body->add_body_force({options.density * g[0], options.density * g[1], options.density * g[2]});
    }
    for (VertexId v = 0; v < result.body->vertex_count(); ++v) {
        const Vector3 f = result.body->force(v);
        result.loaded += f[0] != 0 || f[1] != 0 || f[2] != 0;
    }
    if (const std::optional<FreePart> free = loaded_free_part(mesh, *result.body))
        return Refusal{RefusalCode::bad_argument,
                       "deform: component " + std::to_string(free->component) + " of " + name + " (" +
                           std::to_string(free->elements) + (free->elements == 1 ? " element" : " elements") +
                           ", as `sxk components` numbers them) is loaded and nothing holds it (no --fix or "
                           "--displace selects a vertex of it), so it can move freely and the problem is singular; "
                           "fix at least three non-collinear vertices of every connected part"};
    return result;
}

}  // namespace sxk::elasticity
