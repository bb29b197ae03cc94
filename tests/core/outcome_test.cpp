// Refusal codes: every code has its stable snake_case name (JSON output carries it), and a
// refusal passed on by a caller keeps the code of the refusal it wraps.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sxk/outcome.hpp"

namespace sxk {
namespace {

TEST(RefusalCode, EveryCodeHasItsName) {
    const std::vector<std::pair<RefusalCode, std::string>> names{
        {RefusalCode::bad_argument, "bad_argument"},
        {RefusalCode::not_found, "not_found"},
        {RefusalCode::wrong_dimension, "wrong_dimension"},
        {RefusalCode::would_invert, "would_invert"},
        {RefusalCode::would_flatten, "would_flatten"},
        {RefusalCode::link_condition, "link_condition"},
        {RefusalCode::moves_boundary, "moves_boundary"},
        {RefusalCode::not_manifold, "not_manifold"},
        {RefusalCode::pinched_star, "pinched_star"},
        {RefusalCode::label_conflict, "label_conflict"},
        {RefusalCode::not_applicable, "not_applicable"},
        {RefusalCode::bad_marking, "bad_marking"},
        {RefusalCode::stale, "stale"},
        {RefusalCode::invalid_mesh, "invalid_mesh"},
        {RefusalCode::too_large, "too_large"},
        {RefusalCode::internal_error, "internal_error"},
    };
    for (const auto& [code, name] : names) EXPECT_EQ(to_string(code), name);
    // the table is complete: the codes are numbered 0.. in declaration order, internal_error last
    ASSERT_EQ(names.size(), static_cast<std::size_t>(RefusalCode::internal_error) + 1);
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_EQ(static_cast<std::size_t>(names[i].first), i) << names[i].second;
    std::set<std::string> distinct;
    for (const auto& [code, name] : names) distinct.insert(name);
    EXPECT_EQ(distinct.size(), names.size());
}

TEST(RefusalCode, AnOutcomeReportsTheCodeReasonAndItem) {
    const Outcome<int> refused = Refusal(RefusalCode::not_found, "7 is not a vertex", 2);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.code(), RefusalCode::not_found);
    EXPECT_EQ(refused.reason(), "7 is not a vertex");
    EXPECT_EQ(refused.refusal().item, 2u);
    const Refusal plain(RefusalCode::bad_argument, "no item");
    EXPECT_EQ(plain.item, Refusal::npos);
}

TEST(RefusalCode, APrefixedRefusalKeepsItsCodeAndDropsTheInnerItem) {
    const Refusal inner(RefusalCode::pinched_star, "star connectivity: vertex 4 would be pinched",
                        3);
    const Refusal outer = inner.prefixed("flip_edge: ");
    EXPECT_EQ(outer.code, RefusalCode::pinched_star);
    EXPECT_EQ(outer.reason, "flip_edge: star connectivity: vertex 4 would be pinched");
    EXPECT_EQ(outer.item, Refusal::npos);
}

}  // namespace
}  // namespace sxk
