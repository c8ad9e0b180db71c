#include <irid/gamut/pipeline.h>

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/parallel.h>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace irid {
namespace {

GamutClipper make_clipper(ClipMethod method, const ColorSpace& to, const ClipPipelineOptions& o) {
    if (!to.is_rgb() || to.rgb == nullptr) {
        throw Error("clip: the destination " + color_space_name(to) +
                    " is not an RGB space; the gamut is an RGB space's cube, valid names: " +
                    [] {
                        std::string s;
                        for (const std::string& n : rgb_color_space_names()) s += (s.empty() ? "" : ", ") + n;
                        return s;
                    }());
    }
    return GamutClipper(method, Gamut(*to.rgb, o.max), o.settings);
}

/// parallel_ranges over colours, in pieces of at least 16384 (a piece is cheap work).
void for_colours(std::size_t n, int threads, const std::function<void(std::size_t, std::size_t)>& body) {
    parallel_ranges(n, threads, body, std::size_t{1} << 14);
}

}  // namespace

void parallel_ranges(std::size_t n, int threads, const std::function<void(std::size_t, std::size_t)>& body,
                     std::size_t grain) {
    const int hardware = tbb::info::default_concurrency();
    const int workers = threads <= 0 ? hardware : std::min(threads, hardware);
    if (workers <= 1 || n <= grain) {
        body(0, n);
        return;
    }
    tbb::task_arena arena(workers);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                          [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    });
}

ClipPipeline::ClipPipeline(ClipMethod method, const ColorSpace& from, const ColorSpace& to,
                           const ClipPipelineOptions& options)
    : m_from(from),
      m_to(to),
      m_convert(from, to.is_rgb() ? to.linear() : to, options.white, options.adaptation),
      m_clipper(make_clipper(method, to, options)),
      m_same_space(from.is_rgb() && from.rgb == to.rgb),
      m_linear_source(from.family == SpaceFamily::xyz || from.is_rgb()),
      m_to_destination(Mat3::identity()) {
    if (m_linear_source && !m_same_space) {
        const Converter linear(from.linear(), to.linear(), options.white, options.adaptation);
        m_to_destination = *linear.linear_matrix();
    }
}

Rgb ClipPipeline::to_linear(const Vec3& in) const {
    Vec3 v{finite_or_default(in[0]), finite_or_default(in[1]), finite_or_default(in[2])};
    if (m_from.family == SpaceFamily::rgb_encoded) {
        const Rgb d = m_from.rgb->decode({v[0], v[1], v[2]});
        v = {d.r, d.g, d.b};
    }
    if (m_same_space) return {v[0], v[1], v[2]};
    const Vec3 l = m_linear_source ? m_to_destination * v : m_convert.from_xyz(m_convert.to_xyz(v));
    return {l[0], l[1], l[2]};
}

Rgb ClipPipeline::clip(const Vec3& in) const {
    const Rgb linear = to_linear(in);
    Rgb c{};
    if (m_clipper.method() != ClipMethod::smits_xyz || m_clipper.gamut().contains(linear)) {
        c = m_clipper.clip(linear);  // in-gamut colours come back unchanged
    } else {
        // The thesis' XYZ form on XYZ relative to the destination's white.
        const RgbSpace& dest = destination();
        const Xyz xyz = m_same_space ? dest.to_xyz(linear)
                                     : m_convert.to_destination_white(m_convert.to_xyz(
                                           {finite_or_default(in[0]), finite_or_default(in[1]),
                                            finite_or_default(in[2])}));
        c = dest.from_xyz(m_clipper.clip_xyz(xyz));
        // The XYZ → RGB matrix's rounding (a few ulps) must not leave the cube.
        const double max = m_clipper.gamut().max();
        c = {std::clamp(c.r, 0.0, max), std::clamp(c.g, 0.0, max), std::clamp(c.b, 0.0, max)};
    }
    if (m_to.family == SpaceFamily::rgb_encoded) {
        // The same encoded space and a colour the clip did not move: the input itself, bit for
        // bit (decoding and encoding again would round).
        if (passes_through() && c.r == linear.r && c.g == linear.g && c.b == linear.b) {
            return {finite_or_default(in[0]), finite_or_default(in[1]), finite_or_default(in[2])};
        }
        c = destination().encode(c);
    }
    return c;
}

void ClipPipeline::check(std::size_t in_size, std::size_t out_size, const void* in,
                         const void* out, std::size_t element_bytes) {
    if (in_size % 3 != 0 || out_size != in_size) {
        throw Error("clip: " + std::to_string(in_size) + " values in, " +
                    std::to_string(out_size) + " out; both must be the same multiple of 3");
    }
    // The same memory, or none in common (std::less: a total order on unrelated pointers).
    const auto* a = static_cast<const unsigned char*>(in);
    const auto* b = static_cast<const unsigned char*>(out);
    const std::size_t bytes = in_size * element_bytes;
    const std::less<const unsigned char*> less;
    if (a != b && less(a, b + bytes) && less(b, a + bytes)) {
        throw Error("clip: input and output overlap; they must be the same array or disjoint");
    }
}

template <class T>
std::optional<std::size_t> ClipPipeline::first_unconvertible(std::span<const T> in) const noexcept {
    if (m_from.family != SpaceFamily::xyy) return std::nullopt;
    for (std::size_t i = 0; i + 2 < in.size(); i += 3) {
        const double y = finite_or_default(static_cast<double>(in[i + 1]));
        const double Y = finite_or_default(static_cast<double>(in[i + 2]));
        if (y == 0.0 && Y != 0.0) return i / 3;
    }
    return std::nullopt;
}

std::optional<std::size_t> ClipPipeline::find_unconvertible(std::span<const float> in) const noexcept {
    return first_unconvertible(in);
}

std::optional<std::size_t> ClipPipeline::find_unconvertible(std::span<const double> in) const noexcept {
    return first_unconvertible(in);
}

template <class T>
void ClipPipeline::check_xyy(std::span<const T> in) const {
    if (const std::optional<std::size_t> i = first_unconvertible(in)) {
        throw Error("colour " + std::to_string(*i) + ": chromaticity y = 0 with luminance Y = " +
                    format_shortest(finite_or_default(static_cast<double>(in[3 * *i + 2]))) +
                    " has no XYZ (only black may have y = 0)");
    }
}

void ClipPipeline::clip(std::span<const double> in, std::span<double> out, int threads) const {
    check(in.size(), out.size(), in.data(), out.data(), sizeof(double));
    check_xyy(in);
    for_colours(in.size() / 3, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Rgb c = clip({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
            out[3 * i] = c.r;
            out[3 * i + 1] = c.g;
            out[3 * i + 2] = c.b;
        }
    });
}

void ClipPipeline::branch_signatures(std::span<const double> in, std::span<std::uint64_t> out,
                                     int threads) const {
    if (in.size() % 3 != 0 || out.size() != in.size() / 3) {
        throw Error("branch_signatures: " + std::to_string(in.size()) + " values in and " +
                    std::to_string(out.size()) + " out; must be whole triples and one value per triple");
    }
    check_xyy(in);
    for_colours(in.size() / 3, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            out[i] = m_clipper.branch_signature(to_linear(Vec3{in[3 * i], in[3 * i + 1], in[3 * i + 2]}));
        }
    });
}

void ClipPipeline::to_linear(std::span<const float> in, std::span<float> out, int threads) const {
    check(in.size(), out.size(), in.data(), out.data(), sizeof(float));
    check_xyy(in);
    if (m_same_space && m_from.family == SpaceFamily::rgb_linear) {
        if (in.data() != out.data()) std::copy(in.begin(), in.end(), out.begin());
        return;
    }
    for_colours(in.size() / 3, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Rgb c = to_linear(Vec3{in[3 * i], in[3 * i + 1], in[3 * i + 2]});
            out[3 * i] = static_cast<float>(c.r);
            out[3 * i + 1] = static_cast<float>(c.g);
            out[3 * i + 2] = static_cast<float>(c.b);
        }
    });
}

void ClipPipeline::encode(std::span<float> rgb, int threads) const {
    if (rgb.size() % 3 != 0) {
        throw Error("encode: " + std::to_string(rgb.size()) + " values is not a multiple of 3");
    }
    const RgbSpace& dest = destination();
    for_colours(rgb.size() / 3, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Rgb c = dest.encode({rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
            rgb[3 * i] = static_cast<float>(c.r);
            rgb[3 * i + 1] = static_cast<float>(c.g);
            rgb[3 * i + 2] = static_cast<float>(c.b);
        }
    });
}

void ClipPipeline::clip(std::span<const float> in, std::span<float> out,
                        const BatchOptions& options) const {
    if (options.threads < 0) {
        throw Error("clip: threads " + std::to_string(options.threads) +
                    " must be >= 0 (0 = all hardware threads)");
    }
    if (m_to.family != SpaceFamily::rgb_encoded) {
        to_linear(in, out, options.threads);
        clip_batch(m_clipper, out, options);
        return;
    }
    // An encoded destination: chunk by chunk, so that a colour the clip did not move can be
    // given back as it came (passes_through) also when `in` is `out`.
    check(in.size(), out.size(), in.data(), out.data(), sizeof(float));
    check_xyy(in);
    const std::size_t colours = in.size() / 3;
    const std::size_t chunks = (colours + batch_chunk_colours - 1) / batch_chunk_colours;
    const RgbSpace& dest = destination();
    const bool keep = passes_through();
    parallel_ranges(chunks, options.threads, [&](std::size_t first, std::size_t last) {
        const std::size_t room = 3 * std::min(batch_chunk_colours, colours);
        std::vector<float> linear(room), clipped(room);
        for (std::size_t k = first; k < last; ++k) {
            const std::size_t begin = k * batch_chunk_colours;
            const std::size_t n = std::min(batch_chunk_colours, colours - begin);
            const std::span<const float> src = in.subspan(3 * begin, 3 * n);
            const std::span<float> lin(linear.data(), 3 * n), cl(clipped.data(), 3 * n);
            for (std::size_t i = 0; i < n; ++i) {
                const Rgb c = to_linear(Vec3{src[3 * i], src[3 * i + 1], src[3 * i + 2]});
                lin[3 * i] = static_cast<float>(c.r);
                lin[3 * i + 1] = static_cast<float>(c.g);
                lin[3 * i + 2] = static_cast<float>(c.b);
            }
            clip_batch(m_clipper, lin, cl, BatchOptions{.threads = 1, .simd = options.simd});
            for (std::size_t i = 0; i < n; ++i) {
                float* o = &out[3 * (begin + i)];
                if (keep && cl[3 * i] == lin[3 * i] && cl[3 * i + 1] == lin[3 * i + 1] &&
                    cl[3 * i + 2] == lin[3 * i + 2]) {
                    for (std::size_t j = 0; j < 3; ++j) {
                        o[j] = static_cast<float>(finite_or_default(src[3 * i + j]));
                    }
                    continue;
                }
                const Rgb e = dest.encode({cl[3 * i], cl[3 * i + 1], cl[3 * i + 2]});
                o[0] = static_cast<float>(e.r);
                o[1] = static_cast<float>(e.g);
                o[2] = static_cast<float>(e.b);
            }
        }
    });
}

}  // namespace irid
