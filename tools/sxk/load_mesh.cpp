#include <new>

#include "cli.hpp"
#include "progress.hpp"

namespace sxk::cli {

std::optional<Mesh> load_mesh(Context& context, const std::string& file, const ReadOptions& options,
                              ReadReport* report) {
    try {
        ReadOptions chosen = options;
        if (context.strict) chosen.split_pinched = false;
        ReadReport own;
        if (!report) report = &own;
        std::optional<Mesh> mesh;
        {
            Progress progress("reading " + file);
            mesh = read_mesh(file, chosen, report);
        }
        // docs/cli.md "Reading meshes" (the same lines as plugins/command_line.hpp)
        if (report->pinched_vertices > 0) {
            const std::size_t n = report->pinched_vertices;
            context.err << "sxk: warning: " << file << ": split " << n << " pinched vert" << (n == 1 ? "ex" : "ices")
                        << " into " << n + report->vertex_copies.size() << " (--strict refuses them)\n";
        }
        if (report->label_conflicts > 0) {
            context.err << "sxk: warning: " << report->first_label_conflict << "; the first reference is kept";
            if (report->label_conflicts > 1) context.err << " (" << report->label_conflicts << " faces like this)";
            context.err << '\n';
        }
        return mesh;
    } catch (const InputError& error) {
        context.err << "sxk: " << error.what() << '\n';
    } catch (const std::bad_alloc&) {
        context.err << "sxk: " << file << ":0: out of memory while reading\n";
    } catch (const std::exception& error) {
        // readers promise InputError; anything else (filesystem errors) still names the file
        context.err << "sxk: " << file << ":0: " << error.what() << '\n';
    }
    context.exit_code = exit_usage;
    return std::nullopt;
}

bool save_mesh(Context& context, const Mesh& mesh, const std::string& file, const WriteOptions& options) {
    try {
        Progress progress("writing " + file);
        // a command's result must be a file every command accepts: refuse an empty or invalid
        // mesh (exit 1 from the caller, nothing written)
        WriteOptions checked = options;
        checked.refuse_invalid = true;
        write_mesh(mesh, file, checked);
        return true;
    } catch (const std::exception& error) {
        // the writers' messages read "cannot write FILE: why"; FILE is already in front
        std::string why = error.what();
        const std::string named = "cannot write " + file + ": ";
        if (why.rfind(named, 0) == 0) why = "cannot write: " + why.substr(named.size());
        context.err << "sxk: " << file << ":0: " << why << '\n';
        return false;
    }
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
