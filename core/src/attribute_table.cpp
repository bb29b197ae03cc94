// Attribute tables (attribute_table.hpp): registration, lookup and checks shared by the vertex
// and the element attributes.
#include "attribute_table.hpp"

#include <algorithm>

namespace sxk::detail {

Outcome<AttributeId> add_attribute(AttributeTable& table, std::string_view function, std::string name,
                                   int components, std::span<const double> default_value, std::size_t rows) {
    const std::string prefix = std::string(function) + ": ";
    if (name.empty()) return Refusal{RefusalCode::bad_argument, prefix + "the name is empty"};
    if (find_attribute(table, name) != invalid_id)
        return Refusal{RefusalCode::not_applicable, prefix + "an attribute called \"" + name + "\" exists"};
    if (components < 1)
        return Refusal{RefusalCode::bad_argument, prefix + "\"" + name +
                                                      "\" needs at least one component, not " +
                                                      std::to_string(components)};
    const auto n = static_cast<std::size_t>(components);
    if (!default_value.empty() && default_value.size() != n)
        return Refusal{RefusalCode::bad_argument, prefix + "\"" + name + "\" has " + std::to_string(n) +
                                                      " components but a default value of " +
                                                      std::to_string(default_value.size())};
    AttributeColumn column;
    column.name = std::move(name);
    column.components = components;
    column.default_value.assign(n, 0.0);
    std::copy(default_value.begin(), default_value.end(), column.default_value.begin());
    table.push_back(std::move(column));
    grow_rows(table, rows);
    return static_cast<AttributeId>(table.size() - 1);
}

AttributeId find_attribute(const AttributeTable& table, std::string_view name) {
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].components > 0 && table[i].name == name) return static_cast<AttributeId>(i);
    return invalid_id;
}

std::vector<AttributeId> live_attributes(const AttributeTable& table) {
    std::vector<AttributeId> live;
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].components > 0) live.push_back(static_cast<AttributeId>(i));
    return live;
}

namespace {

// The refusal of an id that names no live column ("FUNCTION: ID is not KIND"), or nothing.
std::optional<Refusal> refuse_unknown(const AttributeTable& table, AttributeId attribute, std::string_view function,
                                      std::string_view kind) {
    if (attribute < table.size() && table[attribute].components > 0) return std::nullopt;
    return Refusal{RefusalCode::not_found,
                   std::string(function) + ": " + std::to_string(attribute) + " is not " + std::string(kind)};
}

}  // namespace

Outcome<Done> remove_attribute(AttributeTable& table, AttributeId attribute, std::string_view function,
                               std::string_view kind) {
    if (auto refused = refuse_unknown(table, attribute, function, kind)) return *refused;
    table[attribute] = AttributeColumn{};
    return Done{};
}

std::optional<Refusal> refuse_value(const AttributeTable& table, AttributeId attribute,
                                    std::span<const double> value, std::string_view function,
                                    std::string_view kind) {
    if (auto refused = refuse_unknown(table, attribute, function, kind)) return refused;
    const auto n = static_cast<std::size_t>(table[attribute].components);
    if (value.size() != n)
        return Refusal{RefusalCode::bad_argument, std::string(function) + ": \"" + table[attribute].name +
                                                      "\" has " + std::to_string(n) + " components, not " +
                                                      std::to_string(value.size())};
    return std::nullopt;
}

void grow_rows(AttributeTable& table, std::size_t rows) {
    for (AttributeColumn& column : table) {
        if (column.components == 0) continue;
        const auto n = static_cast<std::size_t>(column.components);
        // no exact reserve: the element pool grows one row at a time, and inserting grows the
        // capacity geometrically (an exact reserve would copy the column every time)
        while (column.values.size() < rows * n)
            column.values.insert(column.values.end(), column.default_value.begin(), column.default_value.end());
    }
}

}  // namespace sxk::detail
