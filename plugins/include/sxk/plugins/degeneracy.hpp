// The degeneracy plug-in (thesis §3.2.3): the removal of flat elements as a service, and the tool
// "degeneracies", a brush that removes them where it passes. Installed:
//
//     auto removal = host.service<sxk::degeneracy::DegeneracyService>();
//     sxk::degeneracy::Options options;            // the thesis' thresholds: 0.01 and 0.99 pi
//     auto report = (*removal)->remove(mesh, options);
//
//     sxk::degeneracy::BrushOptions brush;         // the tool
//     brush.radius = 0.05;
//     auto session = host.begin_tool(mesh, brush);
//     (*session)->step(pose);   // report->actions: "3 degenerate, 3 removed (...)"
//
// What the removal does, and why, is told in docs/plugins.md and the plug-in's
// remove_degeneracies.hpp; `sxk degeneracies` reads the same options from its words.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/ids.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"
#include "sxk/quality.hpp"

namespace sxk::degeneracy {

// How far a run is, told between two elements of a pass: `done` of the `listed` degenerates of
// pass `pass` (from 1) have been handled. A pass may make new degenerates, so the next pass's
// list may be longer; the passes end when it no longer shrinks (see the header comment).
struct Progress {
    std::size_t pass = 0;
    const char* stage = "";  // "collapse", "flip", "peel" or "cut free" (to_string of the kind)
    std::size_t done = 0, listed = 0;
};

struct Options {
    double aspect_ratio = 0.01;      // thesis aspect ratio below this: degenerate (0 < a < 1)
    double large_angle = 0.99 * pi;  // a dihedral (triangle) angle above this is large (pi/2 < x < pi)
    bool flips = true;               // try crack-free flips before cutting free
    bool peel = true;                // remove flat elements lying on the boundary (no crack)
    bool cut_free = true;            // cut free and remove what no collapse, flip or peel removed
    // A boundary face whose vertex a collapse moves may leave its plane (line) by at most this
    // times its longest edge (0: exactly in the plane, which the snapped positions of a cut
    // rarely allow). The default matches aspect_ratio: a collapse may move the boundary by no
    // more than the height of the flat element it removes.
    double boundary_tolerance = 0.01;
    std::size_t max_passes = 64;     // collapse passes in all (the list must also shrink)
    // Shapes are measured in these positions. Reference by default: the reference shape makes
    // the stiffness matrix (thesis §3.2.3: flat elements give unbounded condition numbers), and
    // a snap cut moves the reference positions (§3.2.2).
    Positions positions = Positions::reference;
    // Called on the caller's thread between elements (a command's progress line: the femur at
    // aspect ratio 0.2 lists 16,234 elements and takes minutes); nothing when empty. It must
    // not edit the mesh.
    std::function<void(const Progress&)> progress;

    // The ranges above, bad_argument ("remove_degeneracies: aspect_ratio 2 is not in (0, 1)").
    Outcome<Done> check() const {
        using namespace option_checks;
        constexpr std::string_view name = "remove_degeneracies";
        return first_refusal({
            in(name, "aspect_ratio", aspect_ratio, {0, 1, true, true}),
            in(name, "large_angle", large_angle, {pi / 2, pi, true, true}, "pi/2", "pi"),
            in(name, "boundary_tolerance", boundary_tolerance, {0, 1, false, true}),
            in(name, "max_passes", max_passes, 1, std::size_t(-1)),
        });
    }
};

// One pass over the list of degenerates.
struct PassReport {
    enum class Kind { collapse, flip, peel, cut_free };
    Kind kind = Kind::collapse;
    // degenerates on the list at the start of the pass, by DegenerateClass (index = enum value;
    // triangles use needle and cap)
    std::array<std::size_t, 5> found{};
    std::size_t collapses = 0;
    std::size_t splits = 0;       // kept splits (undone ones are not counted)
    std::size_t flips = 0;
    std::size_t peeled = 0;       // flat elements removed from the boundary (no crack)
    std::size_t cut_free = 0;     // elements cut free and removed (cracks)
    std::size_t elements_before = 0, elements_after = 0;
    std::size_t vertices_before = 0, vertices_after = 0;  // vertices in some element
    // over the whole mesh after the pass, in options.positions
    double min_aspect_ratio_after = 0;
    double min_angle_after = 0, max_angle_after = 0;  // dihedral angles (triangles: angles), radians
    std::size_t found_total() const {
        std::size_t total = 0;
        for (const std::size_t n : found) total += n;
        return total;
    }
};

inline const char* to_string(PassReport::Kind kind) {
    switch (kind) {
        case PassReport::Kind::collapse: return "collapse";
        case PassReport::Kind::flip: return "flip";
        case PassReport::Kind::peel: return "peel";
        case PassReport::Kind::cut_free: return "cut free";
    }
    return "?";
}

struct Report {
    std::vector<PassReport> passes;
    std::size_t found = 0;         // degenerates on the first list
    std::size_t remaining = 0;     // degenerates left at the end (0 unless cut_free is off)
    std::size_t cut_free = 0;      // cracks: elements cut free and removed
    std::size_t collapses = 0, splits = 0, flips = 0, peeled = 0;
    std::size_t elements_before = 0, elements_after = 0;
    std::size_t vertices_before = 0, vertices_after = 0;
    // The elements still degenerate at the end (when remaining > 0), and why their last
    // attempt was refused (one reason per element, same order): the refusal of each pass that
    // tried, and the code of the first of them (none for an element that was not tried).
    std::vector<ElementId> remaining_elements;
    std::vector<std::string> remaining_reasons;
    std::vector<std::optional<RefusalCode>> remaining_codes;
};

struct DegeneracyService {
    static constexpr std::string_view service_id = "sxk.degeneracy";
    // 1 was the untyped "sxk.degeneracy/1"; 2 had refusals without a code and no remaining_codes;
    // 3 had no Options::progress; 4 had no Options::check
    static constexpr std::uint32_t service_version = 5;

    // Every degenerate element of `mesh` removed; refuses options out of range (check()) and a
    // mesh that is not of triangles or tetrahedra (wrong_dimension), the mesh untouched.
    Outcome<Report> (*remove)(Mesh& mesh, const Options& options);
    // The same among `candidates` and what the removal makes (a local edit: the cost stays local).
    Outcome<Report> (*remove_among)(Mesh& mesh, std::span<const ElementId> candidates, const Options& options);
    // The class of element t (none when it is not degenerate).
    DegenerateClass (*classify)(const Mesh& mesh, ElementId t, const Options& options);
};

// The brush: at each step, the degenerate elements having a vertex within `radius` of the tool's
// position (the axis-aligned cube of half-side radius) are removed, as one undoable step.
struct BrushOptions {
    static constexpr std::string_view tool_name = "degeneracies";
    static constexpr std::uint32_t options_version = 1;

    double radius = 0;  // > 0: there is no default reach
    Options removal;    // positions: where the shapes are measured and the brush reaches

    Outcome<Done> check() const {
        if (auto refused = option_checks::in(tool_name, "radius", radius, {0, 1e300, true, false}))
            return *refused;
        return removal.check();
    }
};

}  // namespace sxk::degeneracy
