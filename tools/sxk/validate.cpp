// sxk validate MESH: 0 when the mesh satisfies the connectivity invariants (thesis 7.1-7.5 and
// face-connected vertex stars, Mesh::validate), 1 naming the first broken one, 2 unreadable.
#include <memory>

#include "cli.hpp"
#include "progress.hpp"

namespace sxk::cli {
namespace {

int run_validate(Context& context, const std::string& file) {
    // lenient: duplicate, non-manifold and inconsistently oriented elements are built as they
    // come, so that validate() names the invariant instead of the reader refusing the file
    ReadOptions options;
    options.lenient = true;
    std::optional<Mesh> mesh = load_mesh(context, file, options);
    if (!mesh) return exit_usage;
    Outcome<Done> valid = [&] {
        Progress progress("validating " + file);
        return mesh->validate();
    }();
    if (!valid) {
        context.out << file << ": invalid: " << valid.reason() << '\n';
        return exit_refused;
    }
    context.out << file << ": valid (" << mesh->vertex_count() << " vertices, " << element_count_text(*mesh) << ")\n";
    return exit_success;
}

}  // namespace

void add_validate_command(CLI::App& app, Context& context) {
    auto file = std::make_shared<std::string>();
    CLI::App* command = app.add_subcommand(
        "validate", "Check the connectivity invariants: exit 0 valid, 1 invalid (names the invariant), 2 unreadable");
    command->add_option("MESH", *file, "Mesh file")->required();
    command->callback([&context, file] { context.exit_code = run_validate(context, *file); });
}

}  // namespace sxk::cli
