// Vertex attributes (named per-vertex fields that follow the edits) and the vertex primitives
// the operations build on: interpolated vertices for the splits, removal of the last vertex to
// roll back an edit refused after adding it.
#include <algorithm>
#include <string>

#include "attribute_table.hpp"
#include "sxk/mesh.hpp"
#include "undo_log.hpp"

namespace sxk {

std::pair<Point, Point> Mesh::interpolated_positions(std::span<const VertexId> vertices,
                                                     std::span<const double> weights) const {
    Point reference{0, 0, 0}, deformed{0, 0, 0};
    for (std::size_t i = 0; i < vertices.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            // the first term is assigned, not added to 0, so that -0.0 survives a copy
            const double r = weights[i] * m_reference[vertices[i]][k];
            const double d = weights[i] * m_deformed[vertices[i]][k];
            reference[k] = i == 0 ? r : reference[k] + r;
            deformed[k] = i == 0 ? d : deformed[k] + d;
        }
    return {reference, deformed};
}

Outcome<VertexId> Mesh::add_interpolated_vertex(std::span<const VertexId> parents,
                                                std::span<const double> weights) {
    if (parents.empty() || parents.size() != weights.size())
        return Refusal{RefusalCode::bad_argument,
                       "add_interpolated_vertex: " + std::to_string(parents.size()) +
                       " parents but " + std::to_string(weights.size()) + " weights"};
    for (std::size_t i = 0; i < parents.size(); ++i)
        if (parents[i] >= vertex_count())
            return Refusal{RefusalCode::not_found,
                           "add_interpolated_vertex: parent " + std::to_string(parents[i]) +
                               " is not a vertex",
                           i};
    const auto [reference, deformed] = interpolated_positions(parents, weights);
    if (m_undo != nullptr) m_undo->vertex_added();
    ++m_revision;
    m_reference.push_back(reference);
    m_deformed.push_back(deformed);
    m_vertex_element.push_back(invalid_id);
    for (detail::AttributeColumn& a : m_attributes) {
        if (a.components == 0) continue;
        const auto n = static_cast<std::size_t>(a.components);
        // values of the new vertex are computed before appending (the vector may move)
        std::vector<double> value(n, 0.0);
        for (std::size_t i = 0; i < parents.size(); ++i)
            for (std::size_t c = 0; c < n; ++c) {
                const double term = weights[i] * a.values[parents[i] * n + c];
                value[c] = i == 0 ? term : value[c] + term;
            }
        a.values.insert(a.values.end(), value.begin(), value.end());
    }
    return static_cast<VertexId>(m_reference.size() - 1);
}

Outcome<Done> Mesh::remove_last_vertex() {
    if (m_reference.empty())
        return Refusal{RefusalCode::not_found, "remove_last_vertex: the mesh has no vertex"};
    const auto last = static_cast<VertexId>(m_reference.size() - 1);
    if (m_vertex_element[last] != invalid_id)
        return Refusal{RefusalCode::not_applicable,
                       "remove_last_vertex: vertex " + std::to_string(last) + " is in element " +
                       std::to_string(m_vertex_element[last])};
    if (m_undo != nullptr) m_undo->vertex_removed(*this);
    ++m_revision;
    m_reference.pop_back();
    m_deformed.pop_back();
    m_vertex_element.pop_back();
    for (detail::AttributeColumn& a : m_attributes)
        a.values.resize(a.values.size() - static_cast<std::size_t>(a.components));
    return Done{};
}

Outcome<AttributeId> Mesh::add_vertex_attribute(std::string name, int components,
                                                std::span<const double> default_value) {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable,
                       "add_vertex_attribute: not inside an EditJournal step"};
    auto added = detail::add_attribute(m_attributes, "add_vertex_attribute", std::move(name), components,
                                       default_value, vertex_count());
    if (added) ++m_revision;  // a recorded vertex removal would not restore the new column
    return added;
}

AttributeId Mesh::find_vertex_attribute(std::string_view name) const {
    return detail::find_attribute(m_attributes, name);
}

Outcome<Done> Mesh::remove_vertex_attribute(AttributeId attribute) {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable,
                       "remove_vertex_attribute: not inside an EditJournal step"};
    auto removed = detail::remove_attribute(m_attributes, attribute, "remove_vertex_attribute", "a vertex attribute");
    if (removed) ++m_revision;
    return removed;
}

Outcome<Done> Mesh::set_vertex_attribute(AttributeId attribute, VertexId v, std::span<const double> value) {
    if (auto refused = detail::refuse_value(m_attributes, attribute, value, "set_vertex_attribute",
                                            "a vertex attribute"))
        return *refused;
    if (v >= vertex_count())
        return Refusal{RefusalCode::not_found,
                       "set_vertex_attribute: vertex " + std::to_string(v) + " does not exist"};
    if (m_undo != nullptr) m_undo->attribute(*this, attribute, v);
    ++m_revision;
    std::copy(value.begin(), value.end(), vertex_attribute(attribute, v).begin());
    return Done{};
}

std::vector<AttributeId> Mesh::vertex_attributes() const { return detail::live_attributes(m_attributes); }

}  // namespace sxk
