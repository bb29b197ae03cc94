// Element attributes: named per-element fields (mesh.hpp) on the attribute table shared with
// the vertex attributes (attribute_table.hpp). replace_elements gives new elements their
// origin's values (replace_elements.cpp).
#include <algorithm>
#include <string>

#include "attribute_table.hpp"
#include "sxk/mesh.hpp"
#include "undo_log.hpp"

namespace sxk {

Outcome<AttributeId> Mesh::add_element_attribute(std::string name, int components,
                                                 std::span<const double> default_value) {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable, "add_element_attribute: not inside an EditJournal step"};
    auto added = detail::add_attribute(m_element_attributes, "add_element_attribute", std::move(name), components,
                                       default_value, m_elements.size());
    if (added) ++m_revision;  // a recorded step of the history would not restore the new column
    return added;
}

AttributeId Mesh::find_element_attribute(std::string_view name) const {
    return detail::find_attribute(m_element_attributes, name);
}

Outcome<Done> Mesh::remove_element_attribute(AttributeId attribute) {
    if (m_undo != nullptr)
        return Refusal{RefusalCode::not_applicable, "remove_element_attribute: not inside an EditJournal step"};
    auto removed = detail::remove_attribute(m_element_attributes, attribute, "remove_element_attribute",
                                            "an element attribute");
    if (removed) ++m_revision;
    return removed;
}

std::vector<AttributeId> Mesh::element_attributes() const { return detail::live_attributes(m_element_attributes); }

Outcome<Done> Mesh::set_element_attribute(AttributeId attribute, ElementId t, std::span<const double> value) {
    if (auto refused = detail::refuse_value(m_element_attributes, attribute, value, "set_element_attribute",
                                            "an element attribute"))
        return *refused;
    if (!is_element(t))
        return Refusal{RefusalCode::not_found,
                       "set_element_attribute: element " + std::to_string(t) + " does not exist"};
    if (m_undo != nullptr) m_undo->element_attribute(*this, attribute, t);
    ++m_revision;
    std::copy(value.begin(), value.end(), element_attribute(attribute, t).begin());
    return Done{};
}

void Mesh::grow_element_attributes() { detail::grow_rows(m_element_attributes, m_elements.size()); }

}  // namespace sxk
