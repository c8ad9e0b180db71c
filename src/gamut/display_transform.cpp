#include <irid/error.h>
#include <irid/gamut/display_transform.h>
#include <irid/parallel.h>
#include <irid/text_input.h>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cmath>

namespace irid {
namespace {

bool display_side_ok(const ColorSpace& s) noexcept {
    return s.family == SpaceFamily::xyz || s.is_rgb();
}

ColorSpace space_of(const std::string& name, const char* option) {
    if (const std::optional<ColorSpace> s = find_color_space(name)) return *s;
    std::vector<std::string> names = color_space_names();
    const std::string message = fmt::format("{}: unknown space {}; known: {}", option,
                                            quote_untrusted(name), fmt::join(names, ", "));
    throw UnknownNameError(message, std::move(names));
}

}  // namespace

std::vector<std::string> display_views() {
    return {"aces2"};
}

std::string display_view(std::string_view name) {
    std::vector<std::string> views = display_views();
    const std::string lower = ascii_lower(name);
    for (const std::string& v : views) {
        if (v == lower) return v;
    }
    const std::string message =
        fmt::format("view: unknown view {}; known: {}", quote_untrusted(name), fmt::join(views, ", "));
    throw UnknownNameError(message, std::move(views));
}

DisplayTransform::DisplayTransform(const DisplayTransformOptions& options) : m_options(options) {
    m_options.view = display_view(options.view);
    m_output = std::make_shared<const Aces2Output>(aces2_display(options.display));
    const ColorSpace source = space_of(options.source, "source");
    const ColorSpace target = space_of(options.target, "target");
    // Names are found in any case; options() says the canonical ones.
    m_options.source = color_space_name(source);
    m_options.target = color_space_name(target);
    const ColorSpace aces = color_space("aces2065-1-linear");
    const ColorSpace xyz = color_space("xyz");
    const ColorSpace& display = options.inverse ? source : target;
    if (!display_side_ok(display))
        throw Error(fmt::format("{} is not a display space: the display's side of the transform (the {}) "
                                "takes xyz or an RGB space",
                                quote_untrusted(options.inverse ? options.source : options.target),
                                options.inverse ? "source, inverse" : "target"));
    // XYZ of the display is relative to D65 (the display's white), with Y = 1 at 100 cd/m².
    if (!options.inverse) {
        m_scene = std::make_unique<Converter>(source, aces, d65_xy);
        m_display = std::make_unique<Converter>(xyz, target, d65_xy);
    } else {
        m_display = std::make_unique<Converter>(source, xyz, d65_xy);
        m_scene = std::make_unique<Converter>(aces, target, d65_xy);
    }
    // Both sides linear: the float kernel, with the converters' matrices folded into its own.
    const std::optional<Mat3> scene = m_scene->linear_matrix(), shown = m_display->linear_matrix();
    if (scene && shown)
        m_kernel = options.inverse
                       ? std::make_unique<const Aces2Kernel>(*m_output, true, *shown, *scene)
                       : std::make_unique<const Aces2Kernel>(*m_output, false, *scene, *shown);
}

Vec3 DisplayTransform::operator()(const Vec3& in) const {
    const auto finite = [](Vec3 v) {
        for (double& x : v) x = aces2_finite_input(x);
        return v;
    };
    if (!m_options.inverse) {
        const Vec3 aces = finite((*m_scene)(finite(in)));
        const Xyz x = m_output->forward(aces);
        return finite((*m_display)({x.X, x.Y, x.Z}));
    }
    const Vec3 x = finite((*m_display)(finite(in)));
    return finite((*m_scene)(m_output->inverse({x[0], x[1], x[2]})));
}

std::string no_scene_value_note(const std::vector<std::size_t>& places, std::size_t colours,
                                std::string_view where) {
    const std::size_t shown = std::min<std::size_t>(places.size(), 8);
    const bool one = places.size() == 1;
    return fmt::format(
        "{} of {} display colour{} ({}{} {}{}) {} no scene value: the display never shows {} "
        "(docs/DISPLAY.md, \"The inverse\"); {} given the nearest scene value the chain reaches, "
        "which the display shows as another colour",
        places.size(), colours, colours == 1 ? "" : "s", where, one ? "" : "s",
        fmt::join(places.begin(), places.begin() + static_cast<std::ptrdiff_t>(shown), ", "),
        places.size() > shown ? ", ..." : "", one ? "has" : "have", one ? "it" : "them",
        one ? "it is" : "each is");
}

bool DisplayTransform::has_scene_value(const Vec3& display, double tolerance) const {
    if (!m_options.inverse)
        throw Error(
            "display transform: whether a scene value exists is asked of an inverse transform");
    Vec3 in = display;
    for (double& v : in) v = aces2_finite_input(v);
    const Vec3 x = (*m_display)(in);
    return m_output->has_scene_value({x[0], x[1], x[2]}, tolerance);
}

std::vector<unsigned char> DisplayTransform::scene_values_exist(std::span<const double> display,
                                                                int threads,
                                                                double tolerance) const {
    if (display.size() % 3 != 0)
        throw Error(fmt::format("display transform: {} values; give RGB triples", display.size()));
    if (!m_options.inverse)
        throw Error(
            "display transform: whether a scene value exists is asked of an inverse transform");
    std::vector<unsigned char> exists(display.size() / 3, 0);
    parallel_ranges(
        exists.size(), threads,
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i)
                exists[i] = has_scene_value(
                                {display[3 * i], display[3 * i + 1], display[3 * i + 2]}, tolerance)
                                ? 1
                                : 0;
        },
        256);
    return exists;
}

template <class T>
void DisplayTransform::apply_batch(std::span<const T> in, std::span<T> out, int threads) const {
    if (in.size() % 3 != 0 || out.size() != in.size())
        throw Error(fmt::format(
            "display transform: {} values in and {} out; give RGB triples, as many out as in",
            in.size(), out.size()));
    // In place is allowed: each triple is read before it is written.
    parallel_ranges(
        in.size() / 3, threads,
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Vec3 c =
                    (*this)({static_cast<double>(in[3 * i]), static_cast<double>(in[3 * i + 1]),
                             static_cast<double>(in[3 * i + 2])});
                for (int k = 0; k < 3; ++k)
                    out[3 * i + static_cast<std::size_t>(k)] =
                        static_cast<T>(c[static_cast<std::size_t>(k)]);
            }
        },
        256);
}

void DisplayTransform::apply(std::span<const double> in, std::span<double> out, int threads) const {
    apply_batch(in, out, threads);
}

void DisplayTransform::apply(std::span<const float> in, std::span<float> out, int threads) const {
    // apply_batch also reports sizes that do not fit.
    if (!m_kernel || in.size() % 3 != 0 || out.size() != in.size())
        return apply_batch(in, out, threads);
    parallel_ranges(
        in.size() / 3, threads,
        [&](std::size_t begin, std::size_t end) {
            (void)m_kernel->run(in.subspan(3 * begin, 3 * (end - begin)),
                                out.subspan(3 * begin, 3 * (end - begin)));
        },
        256);
}

}  // namespace irid
