// The bezier plug-in: `sxk render INPUT OUT.png [--size WxH] [--camera eye,target,up]
// [--fov DEG] [--tessellate] [--segments N] [--flatness F] [--colour quality|label|plain]
// [--json]` (docs/cli.md "sxk render"), and the colours it paints meshes with.
//
//   INPUT .bpt   read_bpt -> to_triangular (two triangular patches per tensor patch) ->
//                Scene::from_patches (Bézier clipping in an Embree BVH, Roth ch. 6), or with
//                --tessellate Scene::from_triangles(tessellate(patches, segments))
//   INPUT mesh   any file read_mesh reads -> mesh_surface (boundary triangles; a triangle mesh:
//                its triangles) -> Scene::from_triangles, one colour per triangle
//
// then render() (Lambert + ambient, one light) and write_png(). One summary line on stdout:
//
//   teapot.bpt -> teapot.png: 640x480, 64 patches, 1920 leaves, 0.84 s
#pragma once

#include "render.hpp"
#include "sxk/plugin.hpp"

// The named entry point (the MODULE's sxk_plugin_entry forwards to it); programs that link
// sxk_plugin_bezier_static pass it to PluginHost::add_static.
extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_bezier();

namespace sxk::bezier {

// The colour ramp of `--colour quality` for a normalised quality q in [0, 1]
// (SurfaceTriangleKeys::quality: aspect ratio over that of the regular simplex), linear
// between these sRGB stops and clamped outside [0, 1]:
//
//   q    0     0.25    0.5     0.75    1
//        red   orange  yellow  green   blue        (bad -> good)
Colour quality_colour(double quality);

// `--colour label`: a palette of ten distinct sRGB colours, label l takes entry l mod 10
// (negative labels too); it has no magenta, which is the cut colour.
Colour label_colour(int label);

// Faces on a cut (SurfaceTriangleKeys::cut), whatever --colour says: magenta.
Colour cut_colour();

// The grey of `--colour plain` (and of patches by default).
Colour plain_colour();

}  // namespace sxk::bezier
