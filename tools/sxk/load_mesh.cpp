#include <new>

#include "cli.hpp"
#include "progress.hpp"

namespace sxk::cli {

std::optional<Mesh> load_mesh(Context& context, const std::string& file, const ReadOptions& options,
                              ReadReport* report) {
    ReadOptions chosen = options;
    if (context.strict) chosen.split_pinched = chosen.drop_stray_faces = false;
    ReadReport own;
    if (!report) report = &own;
    std::variant<Mesh, std::string> read = [&] {
        Progress progress("reading " + file);
        return try_read_mesh(file, chosen, *report);
    }();  // the progress line is gone before anything is printed
    if (std::string* error = std::get_if<std::string>(&read)) {
        context.err << "sxk: " << *error << '\n';
        context.exit_code = exit_usage;
        return std::nullopt;
    }
    print_read_warnings(context.err, file, *report);
    return std::move(std::get<Mesh>(read));
}

bool save_mesh(Context& context, const Mesh& mesh, const std::string& file, const WriteOptions& options) {
    const std::optional<std::string> error = [&] {
        Progress progress("writing " + file);
        return try_write_mesh(mesh, file, options);
    }();  // the progress line is gone before anything is printed
    if (error) context.err << "sxk: " << *error << '\n';
    return !error;
}

std::string element_count_text(const Mesh& mesh, std::size_t count) {
    const bool tetrahedra = mesh.topological_dimension() == 3;
    const char* noun = count == 1 ? (tetrahedra ? "tetrahedron" : "triangle") : (tetrahedra ? "tetrahedra" : "triangles");
    return std::to_string(count) + ' ' + noun;
}

std::string element_count_text(const Mesh& mesh) { return element_count_text(mesh, mesh.element_count()); }

const char* element_kind(const Mesh& mesh) {
    return mesh.topological_dimension() == 3 ? "tetrahedron" : "triangle";
}

}  // namespace sxk::cli
