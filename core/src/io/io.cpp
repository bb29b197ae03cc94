// read_mesh / write_mesh: choose the format, load the text, hand it to the format's reader.
#include "sxk/io.hpp"

#include <algorithm>
#include <cctype>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

#include "formats.hpp"
#include "sxk/atomic_write.hpp"
#include "load_file.hpp"
#include "text.hpp"

namespace sxk {

InputError::InputError(std::string file, std::size_t line, std::string reason)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + reason),
      m_file(std::move(file)),
      m_line(line),
      m_reason(std::move(reason)) {}

std::string_view to_string(Format format) {
    switch (format) {
        case Format::medit:
            return "medit";
        case Format::gmsh:
            return "gmsh";
        case Format::tetgen:
            return "tetgen";
        case Format::off:
            return "off";
        case Format::obj:
            return "obj";
        case Format::vtu:
            return "vtu";
        case Format::vtk:
            return "vtk";
        case Format::stl:
            return "stl";
        case Format::ply:
            return "ply";
    }
    return "unknown";
}

std::string_view to_string(Encoding encoding) {
    switch (encoding) {
        case Encoding::standard:
            return "standard";
        case Encoding::ascii:
            return "ascii";
        case Encoding::binary:
            return "binary";
    }
    return "unknown";
}

std::optional<Encoding> encoding_from_string(std::string_view name) {
    for (const Encoding encoding : {Encoding::standard, Encoding::ascii, Encoding::binary})
        if (to_string(encoding) == name)
            return encoding;
    return std::nullopt;
}

namespace {

// Each extension and its format: the one list format_from_extension and known_mesh_extensions
// read.
constexpr std::pair<std::string_view, Format> extensions[] = {
    {".mesh", Format::medit}, {".msh", Format::gmsh}, {".node", Format::tetgen},
    {".ele", Format::tetgen}, {".off", Format::off},  {".obj", Format::obj},
    {".vtu", Format::vtu},    {".vtk", Format::vtk},  {".stl", Format::stl},
    {".ply", Format::ply}};

}  // namespace

std::string_view known_mesh_extensions() {
    static const std::string list = [] {
        std::string text;
        for (const auto& [extension, format] : extensions)
            text += (text.empty() ? "" : " ") + std::string(extension);
        return text;
    }();
    return list;
}

std::optional<Format> format_from_name(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const auto& [extension, format] : extensions)
        if (lower == to_string(format) || lower == extension || lower == extension.substr(1)) return format;
    return std::nullopt;
}

std::optional<Format> format_from_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const auto& [known, format] : extensions)
        if (extension == known)
            return format;
    return std::nullopt;
}

namespace {

bool blank(std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
    });
}

// Every text reader starts the same way: refuse binary data, then an empty file.
std::string_view checked(std::string_view data, const std::string& name) {
    const std::string_view text = io::check_text(data, name);
    if (blank(text))
        throw InputError(name, 0, "empty file");
    return text;
}

// The formats that may hold binary data get their bytes unchecked (formats.hpp); an empty file
// and a byte order mark are the same for all.
std::string_view bytes_of(std::string_view data, const std::string& name) {
    if (data.substr(0, 3) == "\xEF\xBB\xBF")
        data.remove_prefix(3);
    if (blank(data))
        throw InputError(name, 0, "empty file");
    return data;
}

Mesh read_data(std::string_view data, Format format, const std::string& name,
               const ReadOptions& options, ReadReport* report) {
    switch (format) {
        case Format::medit:
            return io::read_medit(checked(data, name), name, options, report);
        case Format::off:
            return io::read_off(checked(data, name), name, options, report);
        case Format::obj:
            return io::read_obj(checked(data, name), name, options, report);
        case Format::gmsh:
            return io::read_gmsh(bytes_of(data, name), name, options, report);
        case Format::vtu:
            return io::read_vtu(bytes_of(data, name), name, options, report);
        case Format::vtk:
            return io::read_vtk(bytes_of(data, name), name, options, report);
        case Format::stl:
            return io::read_stl(bytes_of(data, name), name, options, report);
        case Format::ply:
            return io::read_ply(bytes_of(data, name), name, options, report);
        case Format::tetgen:
            break;
    }
    throw InputError(name, 0, "TetGen meshes need a .node and an .ele stream (read_tetgen)");
}

}  // namespace

Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options, ReadReport* report) {
    const std::string name = path.string();
    const std::optional<Format> format = format_from_extension(path);
    if (!format)
        throw InputError(name, 0,
                         "unknown mesh file extension '" + path.extension().string() + "' (known: " +
                             std::string(known_mesh_extensions()) + ")");
    if (*format == Format::tetgen) {
        // X.node and X.ele belong together; X.face (tetrahedra) or X.edge (triangles) carries
        // the boundary markers when it exists
        std::filesystem::path node = path, ele = path, face = path, edge = path;
        node.replace_extension(".node");
        ele.replace_extension(".ele");
        face.replace_extension(".face");
        edge.replace_extension(".edge");
        io::RawMesh raw;
        {  // the texts go before the build (formats.hpp, parse_tetgen_text)
            const detail::TextBuffer node_data = io::load_file(node);
            const detail::TextBuffer ele_data = io::load_file(ele);
            io::TetgenText text;
            text.node_name = node.string();
            text.ele_name = ele.string();
            text.node = checked(node_data, text.node_name);
            text.ele = checked(ele_data, text.ele_name);
            // which of .face/.edge applies depends on the .ele file; the reader picks one
            detail::TextBuffer face_data;
            std::string_view face_text;
            const bool tetrahedra = io::tetgen_announces_tetrahedra(text.ele, text.ele_name);
            const std::filesystem::path& labels = tetrahedra ? face : edge;
            if (std::filesystem::exists(labels)) {
                text.face_name = labels.string();
                face_data = io::load_file(labels);
                face_text = checked(face_data, text.face_name);
                text.face = &face_text;
            }
            raw = io::parse_tetgen_text(text);
        }
        return io::build_mesh(raw, ele.string(), options, report);
    }
    const detail::TextBuffer data = io::load_file(path);
    return read_data(data, *format, name, options, report);
}

Mesh read_mesh(std::istream& in, Format format, const std::string& name, const ReadOptions& options,
               ReadReport* report) {
    const detail::TextBuffer data = io::load_stream(in, name);
    return read_data(data, format, name, options, report);
}

Mesh read_tetgen(std::istream& node, const std::string& node_name, std::istream& ele,
                 const std::string& ele_name, const ReadOptions& options, ReadReport* report) {
    io::RawMesh raw;
    {  // the texts go before the build (formats.hpp, parse_tetgen_text)
        const detail::TextBuffer node_data = io::load_stream(node, node_name);
        const detail::TextBuffer ele_data = io::load_stream(ele, ele_name);
        io::TetgenText text;
        text.node_name = node_name;
        text.ele_name = ele_name;
        text.node = checked(node_data, node_name);
        text.ele = checked(ele_data, ele_name);
        raw = io::parse_tetgen_text(text);
    }
    return io::build_mesh(raw, ele_name, options, report);
}

namespace {

// A one-file format's content (TetGen writes a set: write_mesh does it).
std::string content_of(const Mesh& mesh, Format format, const WriteOptions& options) {
    switch (format) {
        case Format::medit:
            return io::write_medit(mesh, options);
        case Format::gmsh:
            return io::write_gmsh(mesh, options);
        case Format::off:
            return io::write_off(mesh, options);
        case Format::obj:
            return io::write_obj(mesh, options);
        case Format::vtu:
            return io::write_vtu(mesh, options);
        case Format::vtk:
            return io::write_vtk(mesh, options);
        case Format::stl:
            return io::write_stl(mesh, options);
        case Format::ply:
            return io::write_ply(mesh, options);
        case Format::tetgen:
            break;
    }
    throw std::logic_error("content_of: a TetGen mesh is a set of files");
}

}  // namespace

namespace {

// The checks every writer makes first (OutputError "cannot write NAME: ..."), and the mesh to
// write: `mesh`, or its copy with the vertices in no element dropped, kept in `compact`.
const Mesh& writable(const Mesh& mesh, const std::string& name, const WriteOptions& options,
                     std::optional<Mesh>& compact) {
    if (mesh.element_count() == 0) throw OutputError("cannot write " + name + ": the mesh has no elements");
    if (options.refuse_invalid) {
        ValidateOptions checks;
        checks.orientation = true;
        if (const Outcome<Done> valid = mesh.validate(checks); !valid)
            throw OutputError("cannot write " + name + ": the mesh is invalid: " + valid.reason());
    }
    if (options.drop_unused_vertices)
        for (VertexId v = 0; v < mesh.vertex_count(); ++v)
            if (mesh.vertex_element(v) == invalid_id) {
                compact = mesh;
                (void)compact->compact_vertices();  // a copy has no journal: cannot refuse
                return *compact;
            }
    return mesh;
}

}  // namespace

void write_mesh(const Mesh& mesh, std::ostream& out, Format format, const std::string& name,
                const WriteOptions& options) {
    if (format == Format::tetgen)
        throw OutputError("cannot write " + name + ": a TetGen mesh is a set of files (.node, .ele, .face); write it "
                                                   "to a file");
    std::optional<Mesh> compact;
    const std::string content = content_of(writable(mesh, name, options, compact), format, options);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw OutputError("cannot write " + name + ": the stream took no more data");
}

void write_mesh(const Mesh& original, const std::filesystem::path& path, const WriteOptions& options) {
    const std::optional<Format> format = format_from_extension(path);
    if (!format)
        throw OutputError("cannot write " + path.string() + ": unknown mesh file extension '" +
                          path.extension().string() + "' (known: " + std::string(known_mesh_extensions()) + ")");
    std::optional<Mesh> compact;
    const Mesh& mesh = writable(original, path.string(), options, compact);
    switch (*format) {
        case Format::medit:
        case Format::gmsh:
        case Format::off:
        case Format::obj:
        case Format::vtu:
        case Format::vtk:
        case Format::stl:
        case Format::ply:
            write_file_atomically(path, content_of(mesh, *format, options));
            return;
        case Format::tetgen: {
            const io::TetgenFiles files = io::write_tetgen(mesh, options);
            std::filesystem::path node = path, ele = path, face = path;
            node.replace_extension(".node");
            ele.replace_extension(".ele");
            face.replace_extension(mesh.topological_dimension() == 3 ? ".face" : ".edge");
            // all three or none: a set with a new .node and an old .ele is no mesh
            const FileContent set[] = {{node, files.node}, {ele, files.ele}, {face, files.face}};
            write_files_atomically(set);
            return;
        }
    }
}

}  // namespace sxk
