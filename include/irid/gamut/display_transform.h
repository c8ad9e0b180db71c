#pragma once

// A display transform from a scene space to a display (and back), as `irid display`,
// `irid.display_transform` and the renderer use it. The one view so far is "aces2", the ACES 2.0
// Output Transform through one of OpenColorIO's built-in displays (aces2_display.h).
//
// Forward: scene colours in `source` (any space of irid/color/convert.h; aces2065-1 by default)
// are converted to ACES2065-1 (Bradford adaptation where the whites differ), rendered to CIE XYZ
// of the D65 display with 1.0 = 100 cd/m², and written in `target`: "xyz", or an RGB space,
// linear or encoded (the RGB of that space with 1.0 = 100 cd/m²).
// Inverse: display colours in `source` ("xyz" or an RGB space) back to scene colours in
// `target` (aces2065-1 by default).

#include <irid/color/convert.h>
#include <irid/gamut/aces2_display.h>
#include <irid/gamut/aces2_kernel.h>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

struct DisplayTransformOptions {
    std::string view = "aces2";
    std::string display;
    std::string source = "aces2065-1";
    std::string target = "xyz";
    bool inverse = false;
};

/// The note for display colours without a scene value (DisplayTransform::has_scene_value): how
/// many of `colours`, where (`where` followed by the first eight of `places`, e.g. "stdin line"
/// and line numbers), and what the inverse gave them. One sentence, without a final stop.
[[nodiscard]] std::string no_scene_value_note(const std::vector<std::size_t>& places,
                                              std::size_t colours, std::string_view where);

/// The views a display transform knows.
[[nodiscard]] std::vector<std::string> display_views();
/// The view of a name, in any case, by its name in display_views(). Throws
/// irid::UnknownNameError listing them for another name.
[[nodiscard]] std::string display_view(std::string_view name);

class DisplayTransform {
public:
    /// Throws irid::UnknownNameError for an unknown view, display or space, and irid::Error
    /// for a display side that is not XYZ or RGB (the display side is `target` forward,
    /// `source` inverse).
    explicit DisplayTransform(const DisplayTransformOptions& options);

    /// One colour; finite for any input (a non-finite value is taken as aces2_finite_input
    /// does: +Inf as 65504, -Inf and NaN as 0, before any conversion). Throws irid::Error
    /// for an input that has no XYZ (an xyY chromaticity y = 0 with Y ≠ 0).
    [[nodiscard]] Vec3 operator()(const Vec3& in) const;

    /// Interleaved RGB triples, `in` to `out` (the same size; they may be the same array), on up
    /// to `threads` threads (0: all); a colour's result is the same for any number of threads.
    /// Doubles are computed in double; floats by the float SIMD kernel (aces2_kernel.h, within
    /// 1e-5 × max(|result|, 1) of the double path) when both sides are linear, else in double.
    /// Throws irid::Error for sizes that are not triples.
    void apply(std::span<const double> in, std::span<double> out, int threads = 0) const;
    void apply(std::span<const float> in, std::span<float> out, int threads = 0) const;

    /// For an inverse transform: whether a display colour (in `source`) has a scene value the
    /// forward shows as it, to `tolerance` of the peak (Aces2Output::has_scene_value, docs/
    /// DISPLAY.md "The inverse"): where it has none, operator() gives the nearest source the
    /// chain reaches, and showing it misses the colour. Throws irid::Error for a forward
    /// transform.
    [[nodiscard]] bool has_scene_value(const Vec3& display, double tolerance = 1e-5) const;
    /// The same for interleaved triples, on up to `threads` threads: one flag per triple.
    [[nodiscard]] std::vector<unsigned char> scene_values_exist(std::span<const double> display,
                                                                int threads = 0,
                                                                double tolerance = 1e-5) const;

    [[nodiscard]] const DisplayTransformOptions& options() const noexcept { return m_options; }
    [[nodiscard]] const Aces2Output& output() const noexcept { return *m_output; }
    /// The float kernel's error bound relative to a result's largest channel
    /// (Aces2Kernel::error_of_largest), when apply() on floats runs it (both sides linear).
    [[nodiscard]] std::optional<double> kernel_error_of_largest() const noexcept {
        return m_kernel ? std::optional(m_kernel->error_of_largest()) : std::nullopt;
    }

private:
    template <class T>
    void apply_batch(std::span<const T> in, std::span<T> out, int threads) const;

    DisplayTransformOptions m_options;
    std::shared_ptr<const Aces2Output> m_output;
    std::unique_ptr<Converter> m_scene;  // source → aces2065-1-linear (forward) or aces → target
    std::unique_ptr<Converter> m_display;  // xyz → target (forward) or source → xyz (inverse)
    std::unique_ptr<const Aces2Kernel> m_kernel;  // floats, when both converters are linear
};

}  // namespace irid
