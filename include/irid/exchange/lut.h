#pragma once

// 3D LUTs of any clip pipeline (irid/gamut/pipeline.h), for the tools that load LUTs rather than
// run irid: OpenColorIO, DaVinci Resolve, Nuke, ffmpeg.
//
// A LUT samples the pipeline (source triple → clipped, and encoded when the destination is an
// encoded space) at size³ nodes and the client interpolates between them. Where its nodes lie is
// the LUT's domain:
// - uniform over [min, max] on every channel: every format. .spi3d can only say [0, 1]; .cube
//   says another range with LUT_3D_INPUT_RANGE (DaVinci Resolve's form, read by OCIO; ffmpeg
//   2.x-7.x does not know it and takes [0, 1], so it is written only for another range, ahead of
//   LUT_3D_SIZE where ffmpeg skips it); .clf with a Range node.
// - a log2 shaper (.clf only: a Range node that clamps, then a Log node, ahead of the cube):
//   s(x) = (log2(x − min + e) − log2(e)) / (log2(max − min + e) − log2(e)), e = (max − min) ·
//   2^−stops, which spends the nodes evenly over `stops` stops below max and still puts the first
//   node at min. Linear and HDR sources need it: a uniform cube spends its nodes on highlights.
// - nodes at given positions (.clf only: a Range node that clamps, then a LUT1D that carries each
//   input to its place between the nodes, ahead of the cube): a rectilinear grid, the same on
//   every axis. Between two nodes the shaper is linear, so a function that is affine on every
//   cell (the identity on the nodes of a gamut's cube) is reproduced exactly. The LUT1D samples
//   the shaper every `step`, on which every node lies.
// Inputs beyond the domain clamp to it (every client does).
//
// A domain may also carry a matrix (.clf only: a Matrix node ahead of everything else): the
// inputs go through it first, and the cube's axes are then those of the matrix's output space.
// A display LUT over a linear source takes it to AP1, where ACES 2.0 clamps its input
// (display_lut.h), so that the domain's faces are the transform's own clamp.
//
// The nodes are written in each format's order: .cube red fastest, .clf blue fastest (CLF 3,
// the LUT3D Array), .spi3d with explicit indices. The text names irid's version, the method, its
// parameters and both spaces: .cube in '#' comments ahead of the data (OCIO 2.1's Resolve reader
// refuses TITLE), .clf in Description and the Input/OutputDescriptor, .spi3d in a '#' line after
// the last entry (the only place OCIO's reader ignores).

#include <irid/color/matrix.h>
#include <irid/gamut/pipeline.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

enum class LutFormat { cube, clf, spi3d };

/// The format of a LUT file by its extension (.cube, .clf, .spi3d, any case); throws
/// UnknownNameError listing them.
[[nodiscard]] LutFormat lut_format_for(const std::filesystem::path& path);
[[nodiscard]] std::string_view lut_format_name(LutFormat format) noexcept;

enum class LutShaper { none, log2, nodes };

struct LutDomain {
    LutShaper shaper = LutShaper::none;
    /// The inputs covered on every channel: finite, -1e6 <= min < max <= 1e6.
    double min = 0.0;
    double max = 1.0;
    /// The log2 shaper's stops below max (1..40).
    int stops = 14;
    /// LutShaper::nodes: the node positions, increasing, from min to max, one per node of the
    /// LUT, each a whole multiple of `step` (2^-20 to 1; (max − min) / step at most 2^20).
    std::vector<double> nodes{};
    double step = 0.0;
    /// The matrix (rows: out = matrix · in) that takes an input to the cube's space before the
    /// shaper, and that space's name (color_space_name); none: the cube is in the input space.
    /// Finite and invertible; .clf only.
    std::optional<Mat3> matrix{};
    std::string matrix_space{};
};

/// Throws irid::Error unless the domain is valid.
void check_lut_domain(const LutDomain& domain);
/// The same, and for LutShaper::nodes one node per node of a LUT of `size`.
void check_lut_domain(const LutDomain& domain, int size);
/// The domain in words, as LUT titles name it ("log2 shaper over [0, 16], 14 stops"; with a
/// matrix, "... in acescg-linear").
[[nodiscard]] std::string describe_lut_domain(const LutDomain& domain);
/// The shaper s: [min, max] → [0, 1] (clamping) and its inverse ((x − min) / (max − min) for no
/// shaper).
[[nodiscard]] double lut_shape(const LutDomain& domain, double x) noexcept;
[[nodiscard]] double lut_unshape(const LutDomain& domain, double s) noexcept;

struct Lut3D {
    int size = 0;
    LutDomain domain;
    /// size³ output triples, red index fastest: node (r, g, b) at 3 (r + size (g + size b)).
    std::vector<float> values;
    /// One line naming irid's version, the method, its parameters and both spaces.
    std::string title;
    /// The spaces of the LUT's input and output (color_space_name).
    std::string source, destination;

    /// The value of node i along any axis (in the matrix's space when the domain has one).
    [[nodiscard]] double node(int i) const noexcept {
        return lut_unshape(domain, static_cast<double>(i) / (size - 1));
    }
};

/// The smallest and largest sizes bake_lut accepts (17, 33 and 65 are the usual ones).
inline constexpr int lut_min_size = 2;
inline constexpr int lut_max_size = 129;

/// A LUT of `size` over the domain whose values are the inputs of its nodes (the identity; with a
/// matrix, each node taken back through the matrix's inverse), ready to be run through a
/// transform in place; bake_lut and bake_display_lut (display_lut.h) start from it.
/// Throws irid::Error for a size outside [lut_min_size, lut_max_size] or a bad domain.
[[nodiscard]] Lut3D lut_grid(int size, const LutDomain& domain);

/// Bakes the pipeline at every node with its float path (the batch kernels) on up to `threads`
/// threads (0: all). Throws irid::Error for a size outside [lut_min_size, lut_max_size], a bad
/// domain, a source that is not an RGB space or XYZ (a cube's axes are one range), or a node the
/// pipeline cannot take. The title names irid's version, the method, its parameters and both spaces.
[[nodiscard]] Lut3D bake_lut(const ClipPipeline& pipeline, int size, const LutDomain& domain = {},
                             int threads = 0);

/// irid's version ("0.1.0"), as the LUTs and images it writes name it.
[[nodiscard]] std::string_view irid_version() noexcept;

/// Throws irid::Error when `format` cannot carry the domain (.spi3d: [0, 1] without a shaper or
/// matrix; .cube: no shaper or matrix; .clf: any), saying which format can.
void check_lut_format(LutFormat format, const LutDomain& domain);

/// The LUT as a file of `format`; throws irid::Error as check_lut_format.
[[nodiscard]] std::string lut_text(const Lut3D& lut, LutFormat format);
/// lut_text in the format of the path's extension, written whole or not at all
/// (io::write_output_file: never replaces what is not a regular file).
void write_lut(const std::filesystem::path& path, const Lut3D& lut);

/// How a client interpolates between nodes: trilinear (OCIO's default for .cube and .spi3d,
/// Resolve's default) or tetrahedral (ffmpeg's default; irid's .clf asks for it).
enum class LutInterpolation { trilinear, tetrahedral };
[[nodiscard]] std::string_view lut_interpolation_name(LutInterpolation interpolation) noexcept;
/// Throws UnknownNameError listing them.
[[nodiscard]] LutInterpolation parse_lut_interpolation(std::string_view name);
/// The interpolation a format's reader applies to irid's file of it (OCIO's: trilinear for .cube
/// and .spi3d, what the .clf names for .clf).
[[nodiscard]] LutInterpolation lut_format_interpolation(LutFormat format) noexcept;

/// The LUT at an input, the input taken through the domain's matrix, clamped to the domain and
/// shaped, then interpolated between the nodes as a client does; for measuring a LUT against the
/// method it stands for. A NaN channel (after the matrix) is taken as `min`.
[[nodiscard]] Rgb apply_lut(const Lut3D& lut, const Vec3& in,
                            LutInterpolation interpolation = LutInterpolation::trilinear) noexcept;

}  // namespace irid
