#pragma once

// What `irid clip` does to colours, as one object: triples of a source space → the linear RGB
// of the destination space (through XYZ relative to the reference white, chromatically adapted
// where the whites differ, as irid/color/convert.h) → a clip method into [0, max]³ → encoded with
// the destination's transfer function when the destination is an encoded space ("srgb", not
// "srgb-linear"). The command line's CSV path, its image path and the Python module's clip() all
// run it.
//
// Two precisions:
// - double (clip(const Vec3&), clip(span<const double>, ...)): GamutClipper::clip per colour;
//   smits-xyz runs the thesis' XYZ form on XYZ relative to the destination's white. This is
//   exactly what `irid clip` prints for CSV.
// - float (clip(span<const float>, ...)): the conversion in double per colour, then clip_batch
//   (the SIMD kernels, within 1e-5 × max of the double methods, batch.h), then the encoding.
//   This is what `irid clip` does to images.

#include <irid/color/adaptation.h>
#include <irid/color/convert.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace irid {

/// The choices of a ClipPipeline beside its method and spaces.
struct ClipPipelineOptions {
    /// The destination gamut's peak: its cube is [0, max]³ (0 < max <= 1e6).
    double max = 1.0;
    /// The method's parameters and direction (clip.h).
    ClipSettings settings;
    /// The reference white of XYZ, CIELUV and CIELAB sources (D65).
    Xy white = d65_xy;
    /// The adaptation where a space's own white differs from the reference white.
    ChromaticAdaptation adaptation = ChromaticAdaptation::bradford;
};

class ClipPipeline {
public:
    /// Throws irid::Error when `to` is not an RGB space, for a peak out of range, and for
    /// settings that do not suit the method (GamutClipper's messages).
    ClipPipeline(ClipMethod method, const ColorSpace& from, const ColorSpace& to,
                 const ClipPipelineOptions& options = {});

    [[nodiscard]] const GamutClipper& clipper() const noexcept { return m_clipper; }
    [[nodiscard]] const ColorSpace& from() const noexcept { return m_from; }
    [[nodiscard]] const ColorSpace& to() const noexcept { return m_to; }
    [[nodiscard]] const RgbSpace& destination() const noexcept { return *m_to.rgb; }
    /// The reference white of XYZ, CIELUV and CIELAB sources.
    [[nodiscard]] const Xy& white() const noexcept { return m_convert.white(); }
    /// Source and destination are forms of the same RGB space: no conversion at all (in-gamut
    /// colours come back bit for bit).
    [[nodiscard]] bool same_space() const noexcept { return m_same_space; }
    /// Source and destination are the same encoded space: a colour the clip leaves where it is
    /// comes back as it came, bit for bit (not decoded and encoded again).
    [[nodiscard]] bool passes_through() const noexcept {
        return m_same_space && m_from.family == SpaceFamily::rgb_encoded &&
               m_to.family == SpaceFamily::rgb_encoded;
    }

    /// One source triple → the destination's linear RGB (encoded RGB decoded; non-finite values
    /// taken by clip.h's rule first). Throws irid::Error for xyY with y = 0 and Y ≠ 0.
    [[nodiscard]] Rgb to_linear(const Vec3& in) const;
    /// One source triple through the whole pipeline, in double.
    [[nodiscard]] Rgb clip(const Vec3& in) const;

    /// Whole triples in, the same number out (`in` may be `out`), in double, on up to `threads`
    /// threads (0: all). Throws irid::Error before writing anything for sizes that do not fit
    /// and for an xyY y = 0 with Y ≠ 0 (naming the colour's index).
    void clip(std::span<const double> in, std::span<double> out, int threads = 0) const;
    /// GamutClipper::branch_signature of each source triple in its destination linear RGB:
    /// where neighbouring colours' signatures differ, the method's definition may jump between
    /// them (clip.h). `out` holds one value per triple. Throws as clip does.
    void branch_signatures(std::span<const double> in, std::span<std::uint64_t> out,
                           int threads = 0) const;
    /// The float form (see the file comment); `options` as clip_batch's.
    void clip(std::span<const float> in, std::span<float> out, const BatchOptions& options = {}) const;

    /// The float pipeline's steps, for callers that stage pixels themselves (images): the
    /// conversion to the destination's linear RGB (checks as clip's), and the encoding with the
    /// destination's transfer function (whatever `to` says: an integer image file is encoded).
    void to_linear(std::span<const float> in, std::span<float> out, int threads = 0) const;
    void encode(std::span<float> rgb, int threads = 0) const;
    /// The index of the first triple the conversion refuses (an xyY y = 0 with Y ≠ 0), if any.
    [[nodiscard]] std::optional<std::size_t> find_unconvertible(std::span<const float> in) const noexcept;
    [[nodiscard]] std::optional<std::size_t> find_unconvertible(std::span<const double> in) const noexcept;

private:
    static void check(std::size_t in_size, std::size_t out_size, const void* in, const void* out,
                      std::size_t element_bytes);
    template <class T>
    [[nodiscard]] std::optional<std::size_t> first_unconvertible(std::span<const T> in) const noexcept;
    template <class T>
    void check_xyy(std::span<const T> in) const;

    ColorSpace m_from;
    ColorSpace m_to;
    Converter m_convert;  // from → the destination's linear RGB
    GamutClipper m_clipper;
    bool m_same_space;
    /// The source is XYZ or RGB: after decoding one matrix takes it to the destination.
    bool m_linear_source;
    Mat3 m_to_destination;
};

}  // namespace irid
