// The one mechanism behind vertex and element attributes: a table of named columns of doubles
// (detail::AttributeColumn, mesh.hpp). The Mesh members of both kinds (vertex_attributes.cpp,
// element_attributes.cpp) are this with their own table, row count and names in the refusals.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::detail {

using AttributeTable = std::vector<AttributeColumn>;

// A new column of `rows` rows at the default value. `function` starts the refusals
// ("add_vertex_attribute: ..."): an empty or taken name, components < 1, a default value of
// another size than components (empty: zeros).
Outcome<AttributeId> add_attribute(AttributeTable& table, std::string_view function, std::string name,
                                   int components, std::span<const double> default_value, std::size_t rows);
// The live column called `name`, or invalid_id.
AttributeId find_attribute(const AttributeTable& table, std::string_view name);
// The live columns by increasing id.
std::vector<AttributeId> live_attributes(const AttributeTable& table);
// Empties the slot of a live column (other ids keep their meaning); refuses an unknown one
// ("FUNCTION: ID is not KIND", kind: "a vertex attribute").
Outcome<Done> remove_attribute(AttributeTable& table, AttributeId attribute, std::string_view function,
                               std::string_view kind);
// Why `value` cannot be stored in column `attribute`, or nothing: an unknown column, or a value
// of another size ("FUNCTION: \"NAME\" has N components, not M").
std::optional<Refusal> refuse_value(const AttributeTable& table, AttributeId attribute,
                                    std::span<const double> value, std::string_view function,
                                    std::string_view kind);
// Appends rows at the default value until every live column holds `rows` rows.
void grow_rows(AttributeTable& table, std::size_t rows);

}  // namespace sxk::detail
