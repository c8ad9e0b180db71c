#pragma once

// The renderer: a ray tracer sized to the thesis' scenes (irid/render/scene.h). Per pixel,
// stratified samples are traced (camera → surfaces → Fresnel-weighted reflection and
// transmission to a bounded depth → the environment and the sun), each sample gives XYZ, and a
// Gaussian reconstruction filter gathers the samples around each pixel. Then
//   XYZ (× exposure) → linear RGB of the destination space → the view transform (render.view:
//   the highlight roll-off on luminance, or nothing for "thesis") → the gamut clip → encoded
//   output.
//
// Determinism: every random number is a hash of (seed, pixel, sample, dimension), and every
// pixel is computed from its own samples in a fixed order, so the image is bit-identical for
// any thread count and tile order.

#include <irid/io/image.h>
#include <irid/render/scene.h>

#include <cstdint>
#include <functional>
#include <string>

namespace irid::render {

struct RenderOptions {
    /// Worker threads; 0 = all available. Must be >= 0.
    int threads = 0;
    /// Called from worker threads as tiles finish, with (tiles done, tiles in all); may be empty.
    std::function<void(int, int)> progress;
};

struct RenderStats {
    /// Camera rays, and all rays (camera, reflected, transmitted, shadow).
    std::uint64_t camera_rays = 0;
    std::uint64_t rays = 0;
    /// Pixels whose linear colour (RenderResult::linear) was outside the destination gamut.
    std::uint64_t out_of_gamut_pixels = 0;
    double seconds = 0;
    double table_seconds = 0;  // building the colour tables (included in seconds)
};

struct RenderResult {
    /// Linear RGB of the destination space, exposure applied, scene-referred: before the view
    /// transform and the clip ("R", "G", "B").
    io::Image linear;
    /// The displayed image: `linear` through the view transform (the roll-off, unless
    /// render.view = thesis) and the clip, or `xyz` through the ACES 2.0 chain (render.view =
    /// aces2), encoded with the destination space's transfer function, in [0, 1].
    io::Image display;
    /// CIE XYZ per pixel (relative, the D65 white at Y = 1, exposure applied), for comparisons.
    io::Image xyz;
    RenderStats stats;
};

/// Renders the scene. Throws irid::Error for a scene whose values are valid one by one but not
/// together (an unknown material, RGB space or clip method; a camera looking along `up`; an
/// unreadable environment image or mesh).
[[nodiscard]] RenderResult render(const Scene& scene, const RenderOptions& options = {});

/// Mean and 99th percentile of CIEDE2000 between two XYZ images of the same size (D65 white),
/// per pixel. Throws irid::Error when the sizes differ.
struct ImageDifference {
    double mean = 0;
    double p99 = 0;
    double max = 0;
};
[[nodiscard]] ImageDifference delta_e_2000_images(const io::Image& xyz_a, const io::Image& xyz_b);

}  // namespace irid::render
