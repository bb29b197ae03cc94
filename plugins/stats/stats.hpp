// The stats plug-in: `sxk stats MESH [--bins N] [--json]`, histograms of aspect ratio, radius
// ratio and dihedral angles (triangles: angles) — the distributions behind `sxk quality`'s
// min/mean/max (thesis §3.2.3).
#pragma once

#include <cstddef>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/plugin.hpp"

// The named entry point (the MODULE's sxk_plugin_entry forwards to it); programs that link
// sxk_plugin_stats_static pass it to PluginHost::add_static.
extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_stats();

namespace sxk::stats {

// Counts of values in `bins` equal bins over [low, high]; values outside are clamped into the
// first/last bin (an angle of pi - 1e-16 stays in the last bin); NaN values (elements too flat
// to have an angle) are counted in `undefined`.
struct Histogram {
    double low = 0;
    double high = 1;
    std::vector<std::size_t> counts;
    std::size_t undefined = 0;

    Histogram(double low, double high, std::size_t bins);
    void add(double value);
    std::size_t total() const;
};

struct QualityHistograms {
    Histogram aspect_ratio;
    Histogram radius_ratio;
    Histogram angles;  // dihedral angles for tetrahedra, angles for triangles; radians
    std::size_t elements = 0;
};

// bins >= 1. Uses deformed positions, as sxk quality does.
QualityHistograms quality_histograms(const Mesh& mesh, std::size_t bins);

}  // namespace sxk::stats
