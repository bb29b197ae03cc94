// sxk validate MESH [--flat-invalid] [--json]: 0 when the mesh satisfies the connectivity
// invariants (thesis 7.1-7.5 and face-connected vertex stars) and no element is inverted in
// either position set (exact orientation, Mesh::validate with ValidateOptions::orientation), 1
// naming the first broken one, 2 unreadable. Flat elements (orientation exactly zero) are
// reported; --flat-invalid makes them invalid. The file is judged as it is: nothing is repaired,
// so the readers' --strict has nothing to refuse here.
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/predicates.hpp"

namespace sxk::cli {
namespace {

struct ValidateArguments {
    std::string file;
    bool flat_invalid = false;
    bool json = false;
    bool strict = false;  // given: a usage error that says what to use instead
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
    if (arguments.strict) {
        // --strict once meant --flat-invalid here, and means "refuse what the readers repair"
        // everywhere else: one meaning per option name
        context.err << "sxk: validate: --strict: validate repairs nothing (the file is judged as it is); flat "
                       "elements are made invalid by --flat-invalid\nRun 'sxk validate --help' for more "
                       "information.\n";
        return exit_usage;
    }
    // lenient: duplicate, non-manifold, pinched, inverted and inconsistently oriented elements
    // are built as they come, so that validate() names the invariant instead of the reader
    // refusing the file: the file is judged as it is
    ReadOptions options;
    options.lenient = true;
    std::optional<Mesh> mesh = load_mesh(context, file, options);
    if (!mesh) return exit_usage;
    ValidateOptions checks;
    checks.orientation = true;
    checks.flat_is_invalid = arguments.flat_invalid;
    Outcome<Done> valid = [&] {
        Progress progress("validating " + file);
        return mesh->validate(checks);
    }();
    const std::vector<ElementId> flat = valid ? flat_elements(*mesh) : std::vector<ElementId>{};
    if (arguments.json) {
        nlohmann::ordered_json json;
        json["file"] = file;
        json["valid"] = valid.ok();
        json["vertices"] = mesh->vertex_count();
        json["elements"] = mesh->element_count();
        json["element_kind"] = element_kind(*mesh);
        if (valid) {
            json["flat"] = flat.size();
            json["first_flat"] = flat.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(flat.front());
        } else {
            json["refusal"] = {{"code", to_string(valid.code())}, {"reason", valid.reason()}};
        }
        context.out << json.dump(2) << '\n';
        return valid ? exit_success : exit_refused;
    }
    if (!valid) {
        context.out << file << ": invalid: " << valid.reason() << '\n';
        return exit_refused;
    }
    context.out << file << ": valid (" << mesh->vertex_count() << " vertices, " << element_count_text(*mesh) << ")";
    if (!flat.empty())
        context.out << "; " << flat.size() << " flat " << (flat.size() == 1 ? "element" : "elements") << ", first element "
                    << flat.front() << " (--flat-invalid: invalid)";
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
    command->add_flag("--flat-invalid", arguments->flat_invalid,
                      "Flat elements (orientation exactly zero) make the mesh invalid");
    command->add_flag("--json", arguments->json, "Print one JSON object instead of the verdict line");
    command->add_flag("--strict", arguments->strict, "Not for validate (it repairs nothing): see --flat-invalid")
        ->group("");  // hidden: a usage error saying so
    command->callback([&context, arguments] { context.exit_code = run_validate(context, *arguments); });
}

}  // namespace sxk::cli
