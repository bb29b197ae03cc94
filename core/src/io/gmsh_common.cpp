#include "gmsh_common.hpp"

#include <algorithm>
#include <charconv>
#include <set>

#include "sxk/mesh.hpp"

namespace sxk::io::gmsh {

int type_size(std::int64_t type) {
    switch (type) {
        case 15:
            return 1;  // point
        case 1:
            return 2;  // line
        case 2:
            return 3;  // triangle
        case 4:
            return 4;  // tetrahedron
        default:
            return 0;
    }
}

std::string unsupported_type(std::int64_t type) {
    return "element type " + std::to_string(type) +
           " is not supported (simplexes only: 15 point, 1 line, 2 triangle, 4 tetrahedron)";
}

std::optional<std::size_t> NodeMap::build(std::span<const std::int64_t> tags) {
    std::int64_t largest = 0;
    for (std::int64_t tag : tags)
        largest = std::max(largest, tag);
    m_dense = largest <= 2 * static_cast<std::int64_t>(tags.size()) + 1024;
    if (m_dense)
        m_vector.assign(static_cast<std::size_t>(largest) + 1, invalid_id);
    else
        m_map.reserve(tags.size());
    for (std::size_t i = 0; i < tags.size(); ++i) {
        bool fresh = true;
        if (m_dense) {
            VertexId& slot = m_vector[static_cast<std::size_t>(tags[i])];
            fresh = slot == invalid_id;
            slot = static_cast<VertexId>(i);
        } else {
            fresh = m_map.emplace(tags[i], static_cast<VertexId>(i)).second;
        }
        if (!fresh)
            return i;
    }
    return std::nullopt;
}

VertexId NodeMap::find(std::int64_t tag) const {
    if (m_dense)
        return tag > 0 && tag < static_cast<std::int64_t>(m_vector.size())
                   ? m_vector[static_cast<std::size_t>(tag)]
                   : invalid_id;
    const auto at = m_map.find(tag);
    return at == m_map.end() ? invalid_id : at->second;
}

std::optional<int> label_of_name(std::string_view name) {
    constexpr std::string_view prefix = "label ";
    if (name.substr(0, prefix.size()) != prefix)
        return std::nullopt;
    name.remove_prefix(prefix.size());
    int label = 0;
    const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), label);
    if (name.empty() || error != std::errc() || end != name.data() + name.size())
        return std::nullopt;
    return label;
}

void labels_from_groups(RawMesh& raw, std::span<const PhysicalName> names) {
    CellList* lists[] = {&raw.edges, &raw.triangles, &raw.tetrahedra};
    for (const PhysicalName& group : names) {
        const std::optional<int> label = label_of_name(group.name);
        if (!label || group.dimension < 1)
            continue;
        // a tag outside int's range labels no element (labels are int), so there is nothing to
        // rename
        if (group.tag < INT32_MIN || group.tag > INT32_MAX)
            continue;
        for (int& value : lists[group.dimension - 1]->labels)
            if (value == group.tag)
                value = *label;
    }
}

void keep_label_names(Mesh& mesh, std::span<const PhysicalName> names) {
    const int d = mesh.topological_dimension();
    for (const PhysicalName& group : names) {
        if (label_of_name(group.name) || group.tag < INT32_MIN || group.tag > INT32_MAX)
            continue;
        if (group.dimension == d)
            mesh.label_names().elements[static_cast<int>(group.tag)] = group.name;
        else if (group.dimension == d - 1)
            mesh.label_names().faces[static_cast<int>(group.tag)] = group.name;
    }
}

namespace {

// label -> tag for one dimension: positive labels are their own tag, the others take the
// smallest positive tags left over, in label order.
std::map<int, int> tags_of(const std::set<int>& labels) {
    std::map<int, int> tags;
    int next = 1;
    for (int label : labels)
        if (label <= 0) {
            while (labels.count(next))
                ++next;
            tags[label] = next++;
        } else {
            tags[label] = label;
        }
    return tags;
}

// Gmsh ends a name at its closing quote and a line at a newline: those characters cannot be
// written inside a name and are left out.
std::string writable(const std::string& name) {
    std::string out;
    for (char c : name)
        if (c != '"' && c != '\n' && c != '\r')
            out += c;
    return out;
}

}  // namespace

PhysicalGroups::PhysicalGroups(const Mesh& mesh) {
    std::set<int> elements, faces;
    for (ElementId t : sxk::elements(mesh))
        elements.insert(mesh.label(t));
    for (const auto& [face, label] : mesh.face_labels())
        faces.insert(label);
    m_elements = tags_of(elements);
    m_faces = tags_of(faces);
    const int d = mesh.topological_dimension();
    auto add_names = [&](int dimension, const std::map<int, int>& tags,
                         const std::map<int, std::string>& given) {
        for (const auto& [label, tag] : tags) {
            if (label <= 0) {
                m_names.push_back({dimension, tag, "label " + std::to_string(label)});
            } else if (const auto name = given.find(label); name != given.end()) {
                // a name that reads as another label's would turn this group into that label
                std::string text = writable(name->second);
                if (const auto named = label_of_name(text); !named || *named == label)
                    m_names.push_back({dimension, tag, std::move(text)});
            }
        }
    };
    add_names(d - 1, m_faces, mesh.label_names().faces);
    add_names(d, m_elements, mesh.label_names().elements);
    std::sort(m_names.begin(), m_names.end(), [](const PhysicalName& a, const PhysicalName& b) {
        return a.dimension != b.dimension ? a.dimension < b.dimension : a.tag < b.tag;
    });
}

}  // namespace sxk::io::gmsh
