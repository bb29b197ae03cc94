// sxk validate MESH [--strict]: 0 when the mesh satisfies the connectivity invariants (thesis
// 7.1-7.5 and face-connected vertex stars) and no element is inverted in either position set
// (exact orientation, Mesh::validate with ValidateOptions::orientation), 1 naming the first
// broken one, 2 unreadable. Flat elements (orientation exactly zero) are reported; --strict
// makes them invalid.
#include <memory>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/predicates.hpp"

namespace sxk::cli {
namespace {

struct ValidateArguments {
    std::string file;
    bool strict = false;
};

// The flat elements of a valid mesh (none where orientation is undefined: a surface in space).
std::vector<ElementId> flat_elements(const Mesh& mesh) {
    std::vector<ElementId> flat;
    if (mesh.topological_dimension() != mesh.ambient_dimension()) return flat;
    for (ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::reference) == Sign::zero ||
            element_orientation(mesh, t, Positions::deformed) == Sign::zero)
            flat.push_back(t);
    return flat;
}

int run_validate(Context& context, const ValidateArguments& arguments) {
    const std::string& file = arguments.file;
    // lenient: duplicate, non-manifold, pinched, inverted and inconsistently oriented elements
    // are built as they come, so that validate() names the invariant instead of the reader
    // refusing the file: the file is judged as it is
    ReadOptions options;
    options.lenient = true;
    std::optional<Mesh> mesh = load_mesh(context, file, options);
    if (!mesh) return exit_usage;
    ValidateOptions checks;
    checks.orientation = true;
    checks.flat_is_invalid = arguments.strict;
    Outcome<Done> valid = [&] {
        Progress progress("validating " + file);
        return mesh->validate(checks);
    }();
    if (!valid) {
        context.out << file << ": invalid: " << valid.reason() << '\n';
        return exit_refused;
    }
    context.out << file << ": valid (" << mesh->vertex_count() << " vertices, " << element_count_text(*mesh) << ")";
    if (const std::vector<ElementId> flat = flat_elements(*mesh); !flat.empty())
        context.out << "; " << flat.size() << " flat " << (flat.size() == 1 ? "element" : "elements") << ", first element "
                    << flat.front() << " (--strict: invalid)";
    context.out << '\n';
    return exit_success;
}

}  // namespace

void add_validate_command(CLI::App& app, Context& context) {
    auto arguments = std::make_shared<ValidateArguments>();
    CLI::App* command = app.add_subcommand(
        "validate",
        "Check the connectivity invariants and the exact orientation of every element: exit 0 valid, 1 invalid "
        "(names the invariant or the inverted element), 2 unreadable");
    command->add_option("MESH", arguments->file, "Mesh file")->required();
    command->add_flag("--strict", arguments->strict, "Flat elements (orientation exactly zero) make the mesh invalid");
    command->callback([&context, arguments] { context.exit_code = run_validate(context, *arguments); });
}

}  // namespace sxk::cli
