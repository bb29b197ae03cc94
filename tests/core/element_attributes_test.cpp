// Element attributes: registration and refusals, what replace_elements gives new elements (their
// origin's values), how the operations pass them on (split children, flips, collapses, dissection,
// 2D and 3D bisection with and without a bisection state), and the EditJournal putting them
// back. The random edit sequences of tests/ops/edit_journal_random_test.cpp and
// random_ops_test.cpp check them as well (the "box" attribute of fuzz/ops_driver.hpp).
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

double value_of(const Mesh& mesh, AttributeId a, ElementId t) { return mesh.element_attribute(a, t)[0]; }

// "stiffness" (one component, default 1) set to 10 + t on every element t.
AttributeId add_stiffness(Mesh& mesh) {
    const std::array<double, 1> one{1.0};
    const auto added = mesh.add_element_attribute("stiffness", 1, one);
    EXPECT_TRUE(added.ok()) << added.reason();
    for (const ElementId t : elements(mesh)) {
        const std::array<double, 1> v{10.0 + t};
        EXPECT_TRUE(mesh.set_element_attribute(*added, t, v).ok());
    }
    return *added;
}

TEST(ElementAttributes, RegisterFindListAndDefaults) {
    Mesh mesh = test::unit_square();
    const std::array<double, 2> lame{1e4, 0.3};
    const auto material = mesh.add_element_attribute("lame", 2, lame);
    ASSERT_TRUE(material.ok()) << material.reason();
    const auto rest = mesh.add_element_attribute("rest_volume", 1);
    ASSERT_TRUE(rest.ok());
    EXPECT_EQ(mesh.find_element_attribute("lame"), *material);
    EXPECT_EQ(mesh.find_element_attribute("rest_volume"), *rest);
    EXPECT_EQ(mesh.find_element_attribute("pressure"), invalid_id);
    EXPECT_EQ(mesh.find_vertex_attribute("lame"), invalid_id);  // the two kinds are separate
    EXPECT_EQ(mesh.element_attributes(), (std::vector<AttributeId>{*material, *rest}));
    EXPECT_EQ(mesh.element_attribute_name(*material), "lame");
    EXPECT_EQ(mesh.element_attribute_components(*material), 2);
    EXPECT_EQ(mesh.element_attribute_default(*material)[1], 0.3);
    for (const ElementId t : elements(mesh)) {
        EXPECT_EQ(mesh.element_attribute(*material, t)[0], 1e4);
        EXPECT_EQ(mesh.element_attribute(*rest, t)[0], 0.0);
    }
    // a vertex attribute of the same name is another attribute
    ASSERT_TRUE(mesh.add_vertex_attribute("lame", 1).ok());
    ASSERT_TRUE(mesh.remove_element_attribute(*material).ok());
    EXPECT_FALSE(mesh.is_element_attribute(*material));
    EXPECT_EQ(mesh.element_attributes(), std::vector<AttributeId>{*rest});
    EXPECT_NE(mesh.find_vertex_attribute("lame"), invalid_id);
    // the slot is not reused
    const auto again = mesh.add_element_attribute("lame", 2);
    ASSERT_TRUE(again.ok());
    EXPECT_NE(*again, *material);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ElementAttributes, RefusalsSayWhy) {
    Mesh mesh = test::unit_square();
    const AttributeId stiffness = add_stiffness(mesh);
    const std::array<double, 2> two{1, 2};
    const std::array<double, 1> one{5};
    const Mesh before = mesh;
    EXPECT_EQ(mesh.add_element_attribute("", 1).reason(), "add_element_attribute: the name is empty");
    EXPECT_EQ(mesh.add_element_attribute("stiffness", 1).reason(),
              "add_element_attribute: an attribute called \"stiffness\" exists");
    EXPECT_EQ(mesh.add_element_attribute("stiffness", 1).code(), RefusalCode::not_applicable);
    EXPECT_EQ(mesh.add_element_attribute("flags", 0).reason(),
              "add_element_attribute: \"flags\" needs at least one component, not 0");
    EXPECT_EQ(mesh.add_element_attribute("flags", 1, two).reason(),
              "add_element_attribute: \"flags\" has 1 components but a default value of 2");
    EXPECT_EQ(mesh.remove_element_attribute(7).reason(), "remove_element_attribute: 7 is not an element attribute");
    EXPECT_EQ(mesh.remove_element_attribute(7).code(), RefusalCode::not_found);
    EXPECT_EQ(mesh.set_element_attribute(7, 0, one).reason(), "set_element_attribute: 7 is not an element attribute");
    EXPECT_EQ(mesh.set_element_attribute(stiffness, 0, two).reason(),
              "set_element_attribute: \"stiffness\" has 1 components, not 2");
    EXPECT_EQ(mesh.set_element_attribute(stiffness, 0, two).code(), RefusalCode::bad_argument);
    EXPECT_EQ(mesh.set_element_attribute(stiffness, 9, one).reason(), "set_element_attribute: element 9 does not exist");
    EXPECT_EQ(mesh.set_element_attribute(stiffness, 9, one).code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ElementAttributes, ReplaceElementsGivesEachNewElementItsOriginsValuesAndLabel) {
    Mesh mesh = test::unit_square();
    const AttributeId stiffness = add_stiffness(mesh);  // element 0: 10, element 1: 11
    mesh.set_label(0, 5);
    mesh.set_label(1, 7);
    const VertexId c = mesh.add_vertex({0.5, 0.5, 0});
    const std::array<ElementId, 2> old{0, 1};
    const std::array<Simplex, 4> fan{Simplex(+1, {0, 1, c}), Simplex(+1, {1, 2, c}), Simplex(+1, {2, 3, c}),
                                     Simplex(+1, {3, 0, c})};
    const Mesh before = mesh;
    // refusals first: the mesh stays as it was
    const std::array<std::uint32_t, 3> short_origins{0, 0, 1};
    EXPECT_EQ(mesh.replace_elements(old, fan, {}, short_origins).reason(), "got 3 origins for 4 new elements");
    const std::array<std::uint32_t, 4> far_origin{0, 2, 1, 1};
    const auto far = mesh.replace_elements(old, fan, {}, far_origin);
    EXPECT_EQ(far.reason(), "origin 2 of new element 1 is not an index into the 2 old elements");
    EXPECT_EQ(far.code(), RefusalCode::bad_argument);
    EXPECT_EQ(far.refusal().item, 1u);
    expect_same_state(mesh, before);

    // (0,1,c) and (1,2,c) come from element 0, the others from element 1; new ids reuse 1 and 0
    const std::array<std::uint32_t, 4> origins{0, 0, 1, 1};
    const auto made = mesh.replace_elements(old, fan, {}, origins);
    ASSERT_TRUE(made.ok()) << made.reason();
    const std::vector<ElementId>& t = *made;
    EXPECT_EQ(value_of(mesh, stiffness, t[0]), 10);
    EXPECT_EQ(value_of(mesh, stiffness, t[1]), 10);
    EXPECT_EQ(value_of(mesh, stiffness, t[2]), 11);
    EXPECT_EQ(value_of(mesh, stiffness, t[3]), 11);
    EXPECT_EQ(mesh.label(t[0]), 5);
    EXPECT_EQ(mesh.label(t[3]), 7);
    ASSERT_TRUE(mesh.validate().ok());

    // explicit labels win over the origins' labels; the values still come from the origins
    mesh.set_element_attribute(stiffness, t[1], std::array<double, 1>{42}).value();
    const std::array<Simplex, 2> halves{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})};
    const std::array<int, 2> labels{9, 9};
    const std::array<std::uint32_t, 2> picked{1, 2};
    const auto merged = mesh.replace_elements(t, halves, labels, picked);
    ASSERT_TRUE(merged.ok()) << merged.reason();
    EXPECT_EQ(mesh.label((*merged)[0]), 9);
    EXPECT_EQ(mesh.label((*merged)[1]), 9);
    EXPECT_EQ(value_of(mesh, stiffness, (*merged)[0]), 42);
    EXPECT_EQ(value_of(mesh, stiffness, (*merged)[1]), 11);

    // without origins every new element is old_elements[0]'s; without old elements, defaults
    const auto fanned = mesh.replace_elements(*merged, fan);
    ASSERT_TRUE(fanned.ok()) << fanned.reason();
    for (const ElementId u : *fanned) {
        EXPECT_EQ(value_of(mesh, stiffness, u), 42);
        EXPECT_EQ(mesh.label(u), 9);
    }
    const VertexId far_vertex = mesh.add_vertex({2, 0, 0});
    const std::array<Simplex, 1> extra{Simplex(+1, {1, far_vertex, 2})};
    const auto added = mesh.replace_elements({}, extra);
    ASSERT_TRUE(added.ok()) << added.reason();
    EXPECT_EQ(value_of(mesh, stiffness, (*added)[0]), 1.0);
    EXPECT_EQ(mesh.label((*added)[0]), 0);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(ElementAttributes, SplitChildrenFlipsAndCollapsesPassThemOn) {
    Mesh mesh = test::planar_grid(3);  // 18 triangles
    const AttributeId stiffness = add_stiffness(mesh);
    // split the diagonal of cell (1,1): its two triangles 8 and 9, values 18 and 19
    const VertexId a = 5, b = 10;
    const auto split = split_edge(mesh, a, b);
    ASSERT_TRUE(split.ok()) << split.reason();
    for (const ElementId child : split->elements) {
        const Simplex& s = mesh.simplex(child);
        const bool in_lower = s.contains(6);  // triangle 8 is (5, 6, 10)
        EXPECT_EQ(value_of(mesh, stiffness, child), in_lower ? 18 : 19) << to_text(s);
    }
    // a flip's new elements take the first old element's values
    const FaceId edge = mesh.face(2, 1);  // triangle 2 = (1, 2, 6): slot 1 is edge 1-6, inside
    ASSERT_NE(mesh.mate(edge), invalid_id);
    const double first = value_of(mesh, stiffness, 2);
    const auto flipped = flip_edge(mesh, edge);
    ASSERT_TRUE(flipped.ok()) << flipped.reason();
    for (const ElementId t : *flipped) EXPECT_EQ(value_of(mesh, stiffness, t), first);
    // a collapse keeps each surviving element's own values
    std::vector<std::pair<Simplex, double>> kept;
    for (const ElementId t : star(mesh, split->vertex))
        if (!mesh.simplex(t).contains(a)) kept.emplace_back(mesh.simplex(t), value_of(mesh, stiffness, t));
    ASSERT_TRUE(collapse_edge(mesh, split->vertex, a).ok());
    for (const auto& [simplex, value] : kept) {
        const Simplex moved = simplex.substituted(split->vertex, a);
        bool found = false;
        for (const ElementId t : star(mesh, a))
            if (mesh.simplex(t).same_vertices(moved)) {
                EXPECT_EQ(value_of(mesh, stiffness, t), value);
                found = true;
            }
        EXPECT_TRUE(found) << to_text(moved);
    }
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(ElementAttributes, DissectionKeepsThemWithTheElements) {
    Mesh mesh = test::planar_grid(2);
    const AttributeId stiffness = add_stiffness(mesh);
    // the vertical line x = 1 through vertices 1, 4, 7
    const std::array<Simplex, 2> cut{Simplex(+1, {1, 4}), Simplex(+1, {4, 7})};
    const auto done = dissect(mesh, cut);
    ASSERT_TRUE(done.ok()) << done.reason();
    EXPECT_FALSE(done->new_vertices.empty());
    for (const ElementId t : elements(mesh)) EXPECT_EQ(value_of(mesh, stiffness, t), 10.0 + t);
    ASSERT_TRUE(mesh.validate().ok());
}

// Every element of `mesh` lies in the reference bounding box `boxes[value]` of the element
// whose value it carries (children lie in their parents).
void expect_inside_origin(const Mesh& mesh, AttributeId stiffness, const std::vector<std::array<double, 6>>& boxes) {
    for (const ElementId t : elements(mesh)) {
        const auto index = static_cast<std::size_t>(value_of(mesh, stiffness, t) - 10);
        ASSERT_LT(index, boxes.size());
        const Simplex& s = mesh.simplex(t);
        for (const VertexId v : s.vertices())
            for (std::size_t k = 0; k < 3; ++k) {
                EXPECT_GE(mesh.reference(v)[k], boxes[index][k] - 1e-12) << "element " << t;
                EXPECT_LE(mesh.reference(v)[k], boxes[index][k + 3] + 1e-12) << "element " << t;
            }
    }
}

std::vector<std::array<double, 6>> boxes_of(const Mesh& mesh) {
    std::vector<std::array<double, 6>> boxes(mesh.element_capacity());
    for (const ElementId t : elements(mesh)) {
        std::array<double, 6>& box = boxes[t];
        box = {1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
        for (const VertexId v : mesh.simplex(t).vertices())
            for (std::size_t k = 0; k < 3; ++k) {
                box[k] = std::min(box[k], mesh.reference(v)[k]);
                box[k + 3] = std::max(box[k + 3], mesh.reference(v)[k]);
            }
    }
    return boxes;
}

// Refines `mesh` with `refine` and checks that it added elements, each inside its origin.
template <class Refine>
void expect_refined_inside_origins(Mesh mesh, Refine&& refine) {
    const std::size_t before = mesh.element_count();
    const AttributeId stiffness = add_stiffness(mesh);
    const auto boxes = boxes_of(mesh);
    const auto refined = refine(mesh);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    EXPECT_GT(mesh.element_count(), before);
    expect_inside_origin(mesh, stiffness, boxes);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(ElementAttributes, BisectionLeavesCarryTheirRootsValuesIn2DAnd3D) {
    expect_refined_inside_origins(test::planar_grid(4), [](Mesh& m) { return refine_around(m, {1.3, 2.2, 0}, 0.05); });
    // longest edge: split_edge
    expect_refined_inside_origins(test::kuhn_cube(2),
                                  [](Mesh& m) { return refine_around_tetrahedra(m, {0.7, 1.1, 0.4}, 0.2); });
    // Arnold-Mukherjee-Pouly: one replace_elements of every leaf
    expect_refined_inside_origins(test::kuhn_cube(2), [](Mesh& m) -> Outcome<std::size_t> {
        auto state = TetBisection::with_amp_marking(m);
        if (!state.ok()) return state.refusal();
        return refine_around_tetrahedra(*state, {0.7, 1.1, 0.4}, 0.2);
    });
}

TEST(ElementAttributes, RollbackUndoAndRedoPutThemBack) {
    Mesh mesh = test::planar_grid(3);
    const AttributeId stiffness = add_stiffness(mesh);
    EditJournal journal(mesh);
    const Mesh at_start = mesh;
    journal.checkpoint();
    EXPECT_EQ(mesh.add_element_attribute("heat", 1).reason(), "add_element_attribute: not inside an EditJournal step");
    EXPECT_EQ(mesh.remove_element_attribute(stiffness).reason(),
              "remove_element_attribute: not inside an EditJournal step");
    ASSERT_TRUE(mesh.set_element_attribute(stiffness, 3, std::array<double, 1>{-1}).ok());
    ASSERT_TRUE(split_edge(mesh, 5, 10).ok());  // children reuse ids 8, 9 and take fresh ones
    ASSERT_TRUE(flip_edge(mesh, mesh.face(2, 1)).ok());
    ASSERT_TRUE(journal.rollback().ok());
    expect_same_state(mesh, at_start);

    journal.checkpoint();
    ASSERT_TRUE(split_edge(mesh, 5, 10).ok());
    ASSERT_TRUE(mesh.set_element_attribute(stiffness, 0, std::array<double, 1>{7}).ok());
    ASSERT_TRUE(journal.commit().ok());
    const Mesh after = mesh;
    ASSERT_TRUE(journal.undo().ok());
    expect_same_state(mesh, at_start);
    ASSERT_TRUE(journal.redo().ok());
    expect_same_state(mesh, after);
    // adding an attribute is a change outside the history: undoing over it is refused
    ASSERT_TRUE(mesh.add_element_attribute("heat", 1).ok());
    EXPECT_EQ(journal.undo().code(), RefusalCode::stale);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(ElementAttributes, CopiesAndAssignElementsStartAtDefaults) {
    Mesh mesh = test::unit_square();
    const AttributeId stiffness = add_stiffness(mesh);
    const std::size_t bytes = test::unit_square().memory_bytes();
    EXPECT_GT(mesh.memory_bytes(), bytes);
    const Mesh copy = mesh;
    EXPECT_EQ(value_of(copy, stiffness, 1), 11);
    Mesh rebuilt(2, 2);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) rebuilt.add_vertex(mesh.reference(v));
    ASSERT_TRUE(rebuilt.add_element_attribute("stiffness", 1, std::array<double, 1>{3}).ok());
    const std::array<Simplex, 2> triangles{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})};
    ASSERT_TRUE(rebuilt.assign_elements(triangles).ok());
    EXPECT_EQ(value_of(rebuilt, 0, 0), 3);
    EXPECT_EQ(value_of(rebuilt, 0, 1), 3);
    ASSERT_TRUE(rebuilt.validate().ok());
}

}  // namespace
}  // namespace sxk
