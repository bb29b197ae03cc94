// The planar cutter's options as words (cut_options.hpp).
#include "cut_options.hpp"

#include <string>

#include "command_line.hpp"

namespace sxk::delaunaycut {

void add_cut_options(CLI::App& app, Options& options) {
    app.add_option_function<std::string>(
           "--method",
           [&options](const std::string& method) {
               options.method = method == "subdivision" ? Method::subdivision : Method::delaunay;
           },
           "delaunay: drag a node, flip, remove and split (thesis 5.2, 5.3); subdivision: split every crossed "
           "edge where it is crossed (the baseline of 5.4; planar meshes only)")
        ->check(CLI::IsMember({"delaunay", "subdivision"}))
        ->default_str("delaunay");
    app.add_option("--eps-edge", options.eps_edge,
                   "Remove an interior node nearer the active node than this many mean edge lengths, 0 < F <= 10")
        ->check(number_in(0, false, 10, true, "(0, 10]"))
        ->capture_default_str();
    app.add_option("--short-angle", options.short_angle,
                   "Instead of --eps-edge, remove an interior node when every angle opposite its edge to the "
                   "active node is below this many degrees (thesis 5.5's scale-independent criterion), 0 <= D < 90 "
                   "(0: off)")
        ->check(number_in(0, true, 90, false, "[0, 90)"))
        ->capture_default_str();
    app.add_option("--eps-entry", options.eps_entry,
                   "Begin the incision once the active node is this far from the entry, in mean edge lengths, "
                   "0 < F <= 10")
        ->check(number_in(0, false, 10, true, "(0, 10]"))
        ->capture_default_str();
    app.add_option("--eps-exit", options.eps_exit,
                   "Finish the cut when the extrapolated movement meets the boundary this near, in mean edge "
                   "lengths, 0 < F <= 10")
        ->check(number_in(0, false, 10, true, "(0, 10]"))
        ->capture_default_str();
    app.add_option("--dilation", options.dilation,
                   "Move the nodes of an incision split this fraction of the way from the path towards the nodes "
                   "opposite them, 0 <= F < 0.5")
        ->check(number_in(0, true, 0.5, false, "[0, 0.5)"))
        ->capture_default_str();
    app.add_option("--cut-label", options.cut_label, "Face label of the cut")
        ->check(whole_number("LABEL"))
        ->capture_default_str();
}

}  // namespace sxk::delaunaycut
