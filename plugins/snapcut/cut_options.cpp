// The snap cutter's options as words (cut_options.hpp).
#include "cut_options.hpp"

#include "command_line.hpp"

namespace sxk::snapcut {

void add_cut_options(CLI::App& app, Options& options) {
    // CLI11 flags write true; these name what is switched off
    app.add_flag_callback("--no-snap", [&options] { options.snap = false; },
                          "Dissect the selected faces where they are: no node snapping (jagged incisions)");
    app.add_flag_callback("--no-degeneracy-removal", [&options] { options.remove_degeneracies = false; },
                          "Leave the flat elements the snapping makes");
    app.add_option("--aspect", options.aspect_ratio,
                   "Aspect ratio threshold A, 0 < A < 1: below it an element is degenerate")
        ->check(number_in(0, false, 1, false, "(0, 1)"))
        ->capture_default_str();
    app.add_option("--angle", options.large_angle,
                   "Large dihedral angle threshold in radians, pi/2 < x < pi (default 0.99 pi)")
        ->check(number_in(pi / 2, false, pi, false, "(pi/2, pi)"));
    app.add_option("--snap-min-aspect", options.min_snap_aspect_ratio,
                   "Refuse a snap that leaves an element below this aspect ratio, 0 <= A < 1 (0: only "
                   "inverted and flat elements are refused)")
        ->check(number_in(0, true, 1, false, "[0, 1)"))
        ->capture_default_str();
    app.add_option("--split-beyond", options.split_beyond,
                   "Split a crossed edge where the sweep crosses it when its nearer end is farther than this "
                   "from where the blade has swept, in mean edge lengths, 0..1000 (0: never; only snapping moves "
                   "the incision)")
        ->check(number_in(0, true, 1000, true, "[0, 1000]"))
        ->capture_default_str();
    app.add_flag("--remove-loose", options.remove_loose_pieces, "Remove the pieces a step cuts loose");
    app.add_option("--largest-crumb", options.largest_crumb,
                   "Keep pieces of at most this many elements attached instead of cutting them loose, and cut "
                   "free (remove) a piece that comes loose with no more material than this many mean elements, "
                   "0..1000 (0: any piece may come loose, none is removed)")
        ->check(whole_number_in(0, 1000))
        ->capture_default_str();
    app.add_option("--relax-iterations", options.relax_iterations,
                   "With a simulation (--deform): CG iterations after each step, 1..10^8")
        ->check(whole_number_in(1, 100000000))
        ->capture_default_str();
    app.add_option("--local", options.local_vertices,
                   "With a simulation (--deform): relax only around what each step changed, at most this many "
                   "vertices (the edited elements' corners and the snapped nodes, then their neighbours ring by "
                   "ring), the rest of the body held: a step costs the same on any mesh size, the far field lags "
                   "(0: the whole body every step)")
        ->check(whole_number_in(0, 100000000))
        ->capture_default_str();
    app.add_option("--far", options.far_vertices,
                   "With --local: after each step's relaxation, one more block of at most this many vertices "
                   "where the far field is most out of balance (0: none)")
        ->check(whole_number_in(0, 100000000))
        ->capture_default_str();
    app.add_option("--cut-label", options.cut_label, "Face label of the cut surface")
        ->check(whole_number("LABEL"))
        ->capture_default_str();
}

}  // namespace sxk::snapcut
