#pragma once

// A small OpenColorIO 2 config that offers irid's clip methods as looks, for a chosen source
// and display space: what `irid ocio-config -o DIR` writes.
//
// DIR/config.ocio and, beside it, DIR/luts/irid-<method>.clf. The reference space is the source;
// the display's colour space is defined from it by one matrix (irid's, with the chosen
// adaptation) and the display's transfer function as an OCIO transform (sRGB:
// ExponentWithLinear γ 2.4, offset 0.055; BT.709 and BT.2020: γ 1/0.45, offset 0.099 and
// 0.0993 (OCIO puts the break where the two pieces meet smoothly, within 3e-4 of the
// standards' 0.018 / 4.5); a pure power: Exponent). Each look runs in the source space: its
// LUT takes a source colour to the method's result in the display's gamut, expressed again in
// the source space, so that the display's view only has to encode it. One view per method and
// an "unclipped" view (what the display does without a look) are offered on one display.

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
    /// The scene's space (the config's reference): an RGB space, linear or encoded.
    ColorSpace source = color_space("acescg-linear");
    /// The display: an encoded or linear RGB space whose cube is the gamut.
    ColorSpace display = color_space("srgb");
    /// The methods offered, in order (default: every method).
    std::vector<ClipMethod> methods;
    /// The LUTs' size and domain (default: log2 over [0, 16], 14 stops, for a linear source;
    /// uniform over [0, 1] for an encoded one: ocio_config_default_domain).
    int size = 33;
    std::optional<LutDomain> domain;
    ChromaticAdaptation adaptation = ChromaticAdaptation::bradford;
    int threads = 0;
};

[[nodiscard]] LutDomain ocio_config_default_domain(const ColorSpace& source) noexcept;

struct OcioConfig {
    /// The text of config.ocio.
    std::string config;
    /// The looks' LUTs: file names relative to the folder ("luts/irid-smits.clf") and the LUTs,
    /// whose outputs are in the source space.
    std::vector<std::pair<std::string, Lut3D>> luts;
};

/// Builds the config and bakes its LUTs. Throws irid::Error for a source or display that is not
/// an RGB space, a display transfer OCIO cannot express, or bad LUT settings.
[[nodiscard]] OcioConfig make_ocio_config(const OcioConfigOptions& options);

/// Writes make_ocio_config's files into `dir` (created if missing; an existing config.ocio and
/// LUTs of the same names are replaced, each file whole or not at all).
void write_ocio_config(const std::filesystem::path& dir, const OcioConfig& config);

}  // namespace irid
