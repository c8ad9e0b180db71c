#pragma once

// A small OpenColorIO 2 config that offers irid's clip methods as looks, for a chosen source
// and display space: what `irid ocio-config -o DIR` writes.
//
// DIR/config.ocio and, beside it, DIR/luts/irid-<method>.clf. The reference space (and the
// scene_linear role) is the source's linear form; an encoded source is a colour space decoded
// from it. The display's colour space is one matrix from the reference (irid's, with the chosen
// adaptation) and the display's transfer function as an OCIO transform (sRGB:
// ExponentWithLinear γ 2.4, offset 0.055; BT.709 and BT.2020: γ 1/0.45, offset 0.099 and
// 0.0993 (OCIO puts the break where the two pieces meet smoothly, within 3e-4 of the
// standards' 0.018 / 4.5); a pure power: Exponent).
//
// Each look runs in the display's linear space, where the gamut is the cube [0, 1]³: its LUT
// takes a colour to the method's result. The LUT's nodes (ocio_look_domain) include 0 and 1 on
// every axis and its shaper is linear between nodes, so a colour inside the gamut interpolates
// between nodes inside the gamut only: a method that leaves such colours alone (every hard one)
// leaves them alone through the LUT too, to float rounding. One view per method and an
// "unclipped" view (what the display does without a look) are offered on one display.
//
// ACES 2.0 views: for each chosen ACES 2.0 display (by default every built-in one whose default
// encoding is the config's display space), a colour space "aces2-<display>" whose transform from
// the reference is the display transform baked as a .clf (display_lut.h: a matrix to AP1 and
// the log2 shaper over [0, the forward limit]) in DIR/luts/aces2-<display>.clf, and a view
// "ACES 2.0 <display>" on the display. OpenColorIO 2.1, which has no ACES 2.0, shows it through
// the LUT. A display brighter than the display space holds (an HDR one on sRGB) is refused.

#include <irid/color/adaptation.h>
#include <irid/color/convert.h>
#include <irid/exchange/lut.h>
#include <irid/gamut/clip.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace irid {

struct OcioConfigOptions {
    /// The scene's space: an RGB space, linear or encoded; its linear form is the reference.
    ColorSpace source = color_space("acescg-linear");
    /// The display: an encoded or linear RGB space whose cube is the gamut.
    ColorSpace display = color_space("srgb");
    /// The methods offered, in order (default: every method).
    std::vector<ClipMethod> methods;
    /// The LUTs' nodes per axis (at least ocio_look_min_size).
    int size = 33;
    /// The source values the looks cover on each channel: every source colour in [min, max]³
    /// lies inside the LUTs' domain (beyond it, inputs clamp). Default: [-1, 16] for a linear
    /// source (scene-linear: 4 stops above diffuse white, and the negatives of colours beyond
    /// the source's own gamut), [0, 1] for an encoded one (its code values).
    std::optional<std::pair<double, double>> source_range;
    ChromaticAdaptation adaptation = ChromaticAdaptation::bradford;
    /// The built-in ACES 2.0 displays (aces2_display.h) offered as views; unset: every one whose
    /// default encoding is `display`; empty: none.
    std::optional<std::vector<std::string>> aces2_displays;
    int threads = 0;
};

/// The smallest LUT size ocio_look_domain lays out (a node below 0, at 0, at 1, above 1).
inline constexpr int ocio_look_min_size = 5;

/// The source range of the options, or its default (OcioConfigOptions::source_range).
[[nodiscard]] std::pair<double, double> ocio_source_range(const OcioConfigOptions& options);

/// The nodes of the looks' LUTs, in the display's linear space, the same on every axis: from the
/// lowest to the highest value a source colour of the source range takes there (0 and 1 at
/// least), with nodes at 0 and 1. The size − 1 cells are shared by [0, 1] (at least 3/8 of
/// them, spaced as 0.5 − 0.5 cos: denser near 0 and 1, where soft methods bend), the range
/// below 0 (spaced evenly in log2(1 + |x| / w), w the first cell of [0, 1]) and above 1 (evenly
/// in log2 x), in proportion to 1, log2(1 + |min|) and log2(max). Nodes lie on whole steps of a
/// power of two (at most 1/64, at most 2^18 steps) small enough to keep them apart. Throws
/// irid::Error for a size below ocio_look_min_size or above lut_max_size, a source range that is
/// not finite with -1e5 <= min < max <= 1e5 and max > 0, or one that reaches more than 4096
/// wide in the display's linear space.
[[nodiscard]] LutDomain ocio_look_domain(const OcioConfigOptions& options);

struct OcioConfig {
    /// The text of config.ocio.
    std::string config;
    /// The looks' LUTs: file names relative to the folder ("luts/irid-smits.clf") and the LUTs,
    /// whose outputs are in the source space.
    std::vector<std::pair<std::string, Lut3D>> luts;
    /// The ACES 2.0 views' LUTs ("luts/aces2-sdr-100nit-rec709.clf"), from the reference space
    /// to the display space.
    std::vector<std::pair<std::string, Lut3D>> display_luts;
};

/// The ACES 2.0 displays the config offers as views: the options' list, or its default. Throws
/// irid::UnknownNameError for an unknown display, and irid::Error for a custom one (a config
/// names its views and LUT files by built-in names) and for one brighter than the config's
/// display space holds at its code value 1 (an HDR display, above 100 cd/m², on an SDR curve:
/// sRGB, γ 2.4, ...; PQ holds 10000 cd/m², a linear space any value), naming the display's own
/// encoding.
[[nodiscard]] std::vector<std::string> ocio_aces2_displays(const OcioConfigOptions& options);

/// Builds the config and bakes its LUTs. Throws irid::Error for a source or display that is not
/// an RGB space, a display transfer OCIO cannot express, bad LUT settings, or ACES 2.0 displays
/// ocio_aces2_displays refuses.
[[nodiscard]] OcioConfig make_ocio_config(const OcioConfigOptions& options);

/// Writes make_ocio_config's files into `dir` (created if missing) as a set (io::write_output_files:
/// a failure leaves the old config and LUTs, or all the new ones, never a mix). The LUTs an
/// earlier config left in DIR/luts under irid's names (irid-*.clf, aces2-*.clf) that this one
/// does not write are then removed, so that the folder holds this config alone; other files
/// stay. Returns the paths removed. Throws irid::Error naming the folder when it cannot be made
/// (a symbolic link to a folder that does not exist is named as one).
std::vector<std::filesystem::path> write_ocio_config(const std::filesystem::path& dir, const OcioConfig& config);

}  // namespace irid
