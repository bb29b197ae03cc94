// sxk locate MESH --points FILE [--deformed] [--json]: the element containing each query point
// and the point's barycentric coordinates, by a SpatialIndex (sxk/locate.hpp).
//
// FILE holds one point per line as whitespace-separated coordinates, `x y` or `x y z` for a
// planar mesh (z is ignored) and `x y z` otherwise; '#' starts a comment, blank lines are
// skipped. FILE is read as mesh files are (read_text_file). A bad line gives
// "sxk: FILE:LINE: reason" and exit code 2, like any other input error.
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/locate.hpp"

namespace sxk::cli {
namespace {

struct LocateOptions {
    std::string mesh;
    std::string points;
    bool deformed = false;
    bool json = false;
};

struct Query {
    Point point{};
    std::string text;  // the coordinates as read, for the text output
};

// Reads the query points; on an unreadable file or a bad line prints the error and returns nullopt.
std::optional<std::vector<Query>> read_points(Context& context, const std::string& file, const Mesh& mesh) {
    const bool planar = mesh.ambient_dimension() == 2;
    std::vector<Query> queries;
    const bool read = read_word_lines(context, file, [&](std::size_t, const std::vector<std::string>& words) {
        Query query;
        for (std::size_t k = 0; k < words.size(); ++k) {
            const std::optional<double> value = parse_finite_number(words[k]);
            if (!value) return not_a_finite_number(words[k]);
            if (k < 3) query.point[k] = *value;
            query.text += (k == 0 ? "" : " ") + words[k];
        }
        if (planar && (words.size() < 2 || words.size() > 3))
            return "expected 2 or 3 coordinates (x y [z]), found " + std::to_string(words.size());
        if (!planar && words.size() != 3)
            return "expected 3 coordinates (x y z), found " + std::to_string(words.size());
        if (planar) query.point[2] = 0;
        queries.push_back(query);
        return std::string();
    });
    if (!read) return std::nullopt;
    return queries;
}

int run_locate(Context& context, const LocateOptions& options) {
    std::optional<Mesh> mesh = load_mesh(context, options.mesh);
    if (!mesh) return exit_usage;
    std::optional<std::vector<Query>> queries = read_points(context, options.points, *mesh);
    if (!queries) return exit_usage;

    std::vector<Location> found;
    {
        Progress progress("locating in " + options.mesh);
        const SpatialIndex index(*mesh, options.deformed ? Positions::deformed : Positions::reference);
        ElementId hint = invalid_id;  // files list points along paths often: walk from the last one
        for (const Query& query : *queries) {
            found.push_back(index.locate(query.point, hint));
            if (found.back().found()) hint = found.back().element;
        }
    }
    if (options.json) {
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (const Location& location : found) {
            nlohmann::ordered_json entry;
            if (!location.found()) {
                entry["element"] = nullptr;
            } else {
                const Simplex& s = mesh->simplex(location.element);
                entry["element"] = location.element;
                entry["vertices"] = std::vector<VertexId>(s.vertices().begin(), s.vertices().end());
                entry["barycentric"] = std::vector<double>(location.barycentric.begin(),
                                                           location.barycentric.begin() + s.count());
            }
            points.push_back(entry);
        }
        nlohmann::ordered_json json;
        json["points"] = points;
        context.out << json.dump(2) << '\n';
        return exit_success;
    }
    for (std::size_t i = 0; i < found.size(); ++i) {
        context.out << (*queries)[i].text << ": ";
        if (!found[i].found()) {
            context.out << "outside\n";
            continue;
        }
        const Simplex& s = mesh->simplex(found[i].element);
        context.out << element_kind(*mesh) << ' ' << found[i].element << ", vertices";
        for (const VertexId v : s.vertices()) context.out << ' ' << v;
        context.out << ", barycentric";
        for (int j = 0; j < s.count(); ++j) context.out << ' ' << found[i].barycentric[static_cast<std::size_t>(j)];
        context.out << '\n';
    }
    return exit_success;
}

}  // namespace

void add_locate_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<LocateOptions>();
    CLI::App* command = app.add_subcommand(
        "locate", "The element containing each point of a file, with its barycentric coordinates");
    command->add_option("MESH", options->mesh, "Mesh file")->required();
    command->add_option("--points", options->points,
                        "Text file: one point 'x y [z]' per line (z ignored for planar meshes), '#' comments")
        ->required();
    command->add_flag("--deformed", options->deformed, "Locate in the deformed positions (default: reference)");
    command->add_flag("--json", options->json, "Print one JSON object instead of text");
    command->callback([&context, options] { context.exit_code = run_locate(context, *options); });
}

}  // namespace sxk::cli
