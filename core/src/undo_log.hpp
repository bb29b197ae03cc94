// The record an EditJournal step keeps: what every store into the mesh overwrote, in order.
//
// The mesh calls note_* (mesh.hpp, private) before each store into its element and face pools,
// vertex anchors, boundary map, positions, labels and vertex and element attribute values while
// a step is open,
// and note_pools at the start of every edit (free lists, counts, pool sizes). Undoing is
// replaying the record backwards, each entry putting back what it saved. Because the storage is
// put back slot for slot, every id that was valid at the checkpoint names the same object
// afterwards and the free lists are as they were: the next edit allocates the same ids, and a
// written file is byte for byte the one written at the checkpoint.
//
// Replaying emits, into another record, what each entry overwrote in turn: the inverse, which
// replayed in its turn redoes the step. The undo/redo history of EditJournal is that.
//
// The mesh keeps an element or face once per stretch between checkpoints and rollbacks
// (Mesh::m_noted): a replay writes back the first state kept of each, so later ones would be
// overwritten anyway, and no replay can stop inside a stretch (it goes back to a checkpoint). The
// inverse a replay emits keeps each element and face it puts back, once per entry.
//
// Cost: at most one entry per store (an edit of k elements stores O(k) records), so a step costs
// what it touched, never the size of the mesh.
#pragma once

#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

#include "sxk/mesh.hpp"

namespace sxk::detail {

class UndoLog {
public:
    struct ElementWas {
        ElementId id;
        Mesh::ElementRecord record;
    };
    struct FaceWas {
        FaceId id;
        Mesh::FaceRecord record;
    };
    struct AnchorWas {
        VertexId vertex;
        ElementId anchor;
    };
    struct PoolsWere {
        ElementId free_element;
        FaceId free_face;
        std::size_t element_count;
        std::size_t elements;  // pool sizes (capacity in ids)
        std::size_t faces;
    };
    struct BoundaryInserted {
        Simplex key;
    };
    struct BoundaryErased {
        Simplex key;
        FaceId face;
    };
    struct PositionWas {
        VertexId vertex;
        Point reference;
        Point deformed;
    };
    struct FaceLabelWas {
        Simplex key;
        std::optional<int> label;
    };
    struct AttributeWas {  // the value is values()[offset, offset + components)
        AttributeId attribute;
        VertexId vertex;
        std::size_t offset;
    };
    struct ElementAttributeWas {  // the value is values()[offset, offset + components)
        AttributeId attribute;
        ElementId element;
        std::size_t offset;
    };
    struct VertexAdded {};
    struct VertexRemoved {  // the last vertex; its attribute values at values()[offset...)
        Point reference;
        Point deformed;
        ElementId anchor;
        std::size_t offset;
    };
    using Entry = std::variant<ElementWas, FaceWas, AnchorWas, PoolsWere, BoundaryInserted,
                               BoundaryErased, PositionWas, FaceLabelWas, AttributeWas,
                               ElementAttributeWas, VertexAdded, VertexRemoved>;

    std::size_t size() const { return m_entries.size(); }
    void reserve(std::size_t entries) { m_entries.reserve(entries); }
    bool empty() const { return m_entries.empty(); }
    void clear() {
        m_entries.clear();
        m_values.clear();
    }

    void element(const Mesh& mesh, ElementId t) { m_entries.emplace_back(ElementWas{t, mesh.m_elements[t]}); }
    void face(const Mesh& mesh, FaceId f) { m_entries.emplace_back(FaceWas{f, mesh.m_faces[f]}); }
    void anchor(const Mesh& mesh, VertexId v) { m_entries.emplace_back(AnchorWas{v, mesh.m_vertex_element[v]}); }
    void pools(const Mesh& mesh) {
        m_entries.emplace_back(PoolsWere{mesh.m_free_element, mesh.m_free_face, mesh.m_element_count,
                                         mesh.m_elements.size(), mesh.m_faces.size()});
    }
    void boundary_inserted(const Simplex& key) { m_entries.emplace_back(BoundaryInserted{key}); }
    void boundary_erased(const Simplex& key, FaceId f) { m_entries.emplace_back(BoundaryErased{key, f}); }
    void position(const Mesh& mesh, VertexId v) {
        m_entries.emplace_back(PositionWas{v, mesh.m_reference[v], mesh.m_deformed[v]});
    }
    void face_label(const Mesh& mesh, const Simplex& key);
    void attribute(const Mesh& mesh, AttributeId a, VertexId v);
    void element_attribute(const Mesh& mesh, AttributeId a, ElementId t);
    void vertex_added() { m_entries.emplace_back(VertexAdded{}); }
    void vertex_removed(const Mesh& mesh);  // call before the last vertex goes

    // Replays the entries from `first` on backwards into `mesh`, removing them; appends the
    // inverse to `inverse` when given. Tells the mesh's watchers the net change (watcher.hpp)
    // and advances the mesh's revision.
    void undo(Mesh& mesh, std::size_t first, UndoLog* inverse);

private:
    std::vector<Entry> m_entries;
    std::vector<double> m_values;
};

}  // namespace sxk::detail
