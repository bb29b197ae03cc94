// What the Gmsh readers (ASCII gmsh.cpp, binary gmsh_binary.cpp) and the writer share: element
// types, node tags, and how labels become physical groups and back (docs/formats.md "Gmsh").
//
// Physical groups. Gmsh keeps an element only when it is in a physical group: a file with any
// physical group and elements outside them loses those elements when Gmsh saves it again, and
// meshio refuses a file whose element blocks have physical tags for some blocks only. So every
// element and labelled face is written in a physical group, whose tag is its label when the label
// is positive. Labels Gmsh cannot hold as a physical tag (0, the kernel's "no label", and negative
// ones) get the smallest positive tags no label of their dimension uses, and the group's name
// `label N` carries the label: reading a group named `label N` gives label N, whatever its tag.
// Other names (`$PhysicalNames`) are the mesh's label names (Mesh::label_names) and are written
// back.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "raw_mesh.hpp"
#include "sxk/mesh.hpp"
#include "text.hpp"

namespace sxk::io::gmsh {

// Sections that carry nothing a mesh keeps ($NodeData, ...): read past.
inline constexpr std::array<std::string_view, 10> skipped_sections{"$Comments",
                                                                   "$NodeData",
                                                                   "$ElementData",
                                                                   "$ElementNodeData",
                                                                   "$Periodic",
                                                                   "$GhostElements",
                                                                   "$Parametrizations",
                                                                   "$InterpolationScheme",
                                                                   "$PartitionedEntities",
                                                                   "$NodeGroups"};

// 4.1's entities, (dimension, tag), and the label their first physical tag gives.
struct EntityHash {
    std::size_t operator()(const std::pair<int, std::int64_t>& key) const {
        // unsigned: entity tags may be anything, and signed overflow is undefined
        return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(key.second) * 4 +
                                          static_cast<std::uint64_t>(key.first));
    }
};
using EntityLabels = std::unordered_map<std::pair<int, std::int64_t>, int, EntityHash>;

// Vertices per element for the types a simplicial mesh can hold; 0 for the others.
int type_size(std::int64_t type);
// "element type 5 is not supported (simplexes only: ...)".
std::string unsupported_type(std::int64_t type);

// Node tags -> vertex ids. Tags are usually 1..N, so a vector does; sparse tags go to a map.
class NodeMap {
public:
    // The index of the first tag that repeats an earlier one, or nullopt when all are distinct.
    std::optional<std::size_t> build(std::span<const std::int64_t> tags);
    VertexId find(std::int64_t tag) const;

private:
    bool m_dense = true;
    std::vector<VertexId> m_vector;
    std::unordered_map<std::int64_t, VertexId> m_map;
};

// One entry of $PhysicalNames.
struct PhysicalName {
    int dimension = 0;
    std::int64_t tag = 0;
    std::string name;
};

// Reads "$PhysicalNames" from the count line on, through "$EndPhysicalNames" (gmsh.cpp); the
// section is text in ASCII and binary files alike.
std::vector<PhysicalName> read_physical_names(Cursor& in);

// The label a group named `name` stands for when the name is `label N`.
std::optional<int> label_of_name(std::string_view name);

// Turns the physical tags in `raw`'s cell lists (edges: dimension 1, triangles 2, tetrahedra 3)
// into labels: a tag whose group is named `label N` becomes N, others stay.
void labels_from_groups(RawMesh& raw, std::span<const PhysicalName> names);
// The other names, of the mesh's dimension and the one below, as the mesh's label names.
void keep_label_names(Mesh& mesh, std::span<const PhysicalName> names);

// Whether the file's header says file type 1 (binary); then read_binary reads it (gmsh_binary.cpp).
bool announces_binary(std::string_view bytes);
Mesh read_binary(std::string_view bytes, const std::string& name, const ReadOptions& options,
                 ReadReport* report);

// The physical group of each label a writer writes, per dimension (elements: the mesh's,
// faces: one below).
class PhysicalGroups {
public:
    explicit PhysicalGroups(const Mesh& mesh);
    int element_tag(int label) const { return m_elements.at(label); }
    int face_tag(int label) const { return m_faces.at(label); }
    // The $PhysicalNames entries, by dimension then tag; empty when no group has a name.
    const std::vector<PhysicalName>& names() const { return m_names; }

private:
    std::map<int, int> m_elements, m_faces;  // label -> tag
    std::vector<PhysicalName> m_names;
};

}  // namespace sxk::io::gmsh
