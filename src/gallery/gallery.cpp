// The gallery page: the scenes, the figures and tables, the colour paths compared, thin-film
// anti-aliasing and the clip report, assembled into one HTML page (irid/gallery/gallery.h).
#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/figures/clip_sets.h>
#include <irid/figures/figures.h>
#include <irid/gallery/gallery.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/report.h>
#include <irid/io/image.h>
#include <irid/io/output_file.h>
#include <irid/render/render.h>
#include <irid/render/scene.h>

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace irid::gallery {

// The page is made of the figures: their names unqualified here.
using namespace irid::figures;

namespace {

struct SceneInfo {
    const char* name;
    const char* thesis_figure;
    const char* title;
    const char* what;
    /// The image's file name (without .png) and overrides of the scene, for a second view.
    const char* file = nullptr;
    std::vector<std::string> overrides = {};
};

const SceneInfo scene_infos[] = {
    {"oil-slick", "Figure 7", "An oil slick on wet pavement",
     "Mineral oil floating on a water film over asphalt; the thickness is Smits' eq. 28, "
     "t = t<sub>max</sub> e<sup>−k₁(x² + y² + k₂ turb(x, y))</sup>, and the pavement is bump-mapped "
     "through dnoise. Expect concentric, irregular rings whose colours change with the view angle."},
    {"soap-bubbles", "Figure 8", "Soap bubbles",
     "Soap films (water) in air whose thickness grows downwards as the film drains, with turbulence; "
     "reflection and transmission through each film are both coloured by interference. Expect "
     "black films at the tops, where they are thinnest, and horizontal bands below."},
    {"morpho", "Figure 9", "A Morpho butterfly",
     "Wings coloured by the exact multilayer of a Morpho scale's ridges (eight chitin lamellae of "
     "55 nm, n = 1.56, between air gaps blended over 100–140 nm, by the transfer matrix), indexed "
     "by the viewing angle, over a melanin base, with dark margins and veins, on slightly bumpy "
     "wings. Seen from above: the saturated structural blue of real wings."},
    {"morpho", "Figure 9", "The Morpho from a low camera",
     "The same butterfly from a low camera: the wings now reflect at larger angles and their blue "
     "shifts towards violet, and at grazing angles to a pale lilac, as the multilayer's "
     "reflectance peak moves to shorter wavelengths.",
     "morpho-oblique", {"camera.eye=[3.0,2.3,2.4]", "camera.look_at=[0,0,0.1]"}},
};

class Page {
public:
    void add(const std::string& html) { m_html += html; }
    [[nodiscard]] const std::string& html() const { return m_html; }

    void image(const std::string& file, int w, int h, const std::string& alt, const std::string& thesis,
               const std::string& title, const std::string& caption,
               const std::vector<std::pair<std::string, std::string>>& measurements) {
        m_html += "<figure>\n";
        m_html += fmt::format(
            "<a href=\"{0}\"><img src=\"{0}\" width=\"{1}\" height=\"{2}\" alt=\"{3}\"></a>\n",
            html_escape(file), w, h, html_escape(alt));
        m_html += "<figcaption><p class=\"title\">";
        if (!thesis.empty())
            m_html += fmt::format("<span class=\"thesis\">Thesis {}</span> ", html_escape(thesis));
        m_html += html_escape(title) + "</p>\n<p>" + caption + "</p>\n";
        if (!measurements.empty()) {
            m_html += "<table class=\"numbers\">\n";
            for (const auto& [k, v] : measurements)
                m_html += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", html_escape(k), html_escape(v));
            m_html += "</table>\n";
        }
        m_html += "</figcaption>\n</figure>\n";
    }

private:
    std::string m_html;
};

constexpr const char* style = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 2em auto; max-width: 1100px;
       color: #1b1b1b; background: #fafafa; line-height: 1.45; padding: 0 1em; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; } h2 { margin-top: 2em; border-bottom: 1px solid #ccc; }
figure { margin: 1.5em 0; } img { max-width: 100%; height: auto; border: 1px solid #ddd; background: #fff; }
figcaption { font-size: 0.92em; } .title { font-weight: bold; margin-bottom: 0.2em; }
.thesis { background: #2a4d8f; color: #fff; padding: 0.05em 0.45em; border-radius: 3px; font-weight: normal; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: left; }
table.numbers th { font-weight: normal; color: #555; }
.pair { display: flex; gap: 1em; flex-wrap: wrap; } .pair figure { flex: 1 1 300px; margin: 0.5em 0; }
code { background: #eee; padding: 0 0.2em; }
)css";

/// The body of an HTML file written by a table figure (its <body> contents, or all of it).
std::string html_fragment(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string s = ss.str();
    const auto b = s.find("<body");
    if (b != std::string::npos) {
        const auto start = s.find('>', b);
        const auto end = s.find("</body>");
        if (start != std::string::npos && end != std::string::npos) return s.substr(start + 1, end - start - 1);
    }
    return s;
}

/// --set values for the image's size.
std::vector<std::string> size_overrides(int width, int height, int spp) {
    return {fmt::format("image.width={}", width), fmt::format("image.height={}", height),
            fmt::format("image.spp={}", spp)};
}

/// The image enlarged k times by repeating pixels, so that single pixels can be seen.
io::Image magnify(const io::Image& in, int k) {
    io::Image out = io::Image::blank(in.width * k, in.height * k, in.channels);
    out.color_space = in.color_space;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < in.channels; ++c) out.at(x, y, c) = in.at(x / k, y / k, c);
    return out;
}

/// The w × h pixels of `in` from (x0, y0), moved inside the image where they would leave it.
io::Image crop(const io::Image& in, int x0, int y0, int w, int h) {
    w = std::min(w, in.width), h = std::min(h, in.height);
    x0 = std::clamp(x0, 0, in.width - w), y0 = std::clamp(y0, 0, in.height - h);
    io::Image out = io::Image::blank(w, h, in.channels);
    out.color_space = in.color_space;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < in.channels; ++c) out.at(x, y, c) = in.at(x0 + x, y0 + y, c);
    return out;
}

std::string format_number(double v, int digits = 2) { return fmt::format("{:.{}f}", v, digits); }

void check_options(const GalleryOptions& o) {
    const auto in = [](const char* what, int v, int lo, int hi) {
        if (v < lo || v > hi) throw Error(fmt::format("gallery: {} {} must be in {}..{}", what, v, lo, hi));
    };
    if (o.dir.empty()) throw Error("gallery: an empty folder name; give the folder to write into");
    in("width", o.width, 32, 4096);
    in("height", o.height, 24, 4096);
    in("spp", o.spp, 1, 256);
    in("figure width", o.figure_width, 320, 4096);
    in("threads", o.threads, 0, 1024);
    for (const LinkedPage& p : o.pages) {
        const std::filesystem::path file = p.file.lexically_normal();
        if (p.file.empty() || file.is_absolute() || file.has_root_name() || *file.begin() == "..")
            throw Error(fmt::format("gallery: the linked page '{}' must be a file inside the folder, "
                                    "given relative to it", p.file.string()));
        if (p.title.empty())
            throw Error(fmt::format("gallery: the linked page '{}' has an empty title", p.file.string()));
        if (!std::filesystem::is_regular_file(o.dir / file))
            throw Error(fmt::format("gallery: the linked page '{}' is not in '{}' (write it first)",
                                    p.file.string(), o.dir.string()));
    }
}

}  // namespace

GalleryResult make_gallery(const GalleryOptions& o) {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    check_options(o);
    const fs::path& dir = o.dir;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw Error(fmt::format("cannot create the folder '{}': {}", o.dir.string(),
                                ec ? ec.message() : "it is not a folder"));
    auto say = [&](const std::string& what) {
        if (o.progress) o.progress(what);
    };

    Page page;
    page.add(
        "<h1>irid — the gallery</h1>\n"
        "<p>What irid computes, figure by figure, beside Brian Smits' 1990 thesis "
        "<i>Interference Phenomena and an Efficient Solution to the Out of Gamut Colors "
        "Problem</i>. Every image on this page was made by this run of <code>irid gallery</code>; "
        "the numbers were measured while making them. Badges give the thesis' figure number "
        "where the thesis has one.</p>\n");

    if (!o.pages.empty()) {
        page.add("<h2>Live pages</h2>\n<ul>\n");
        for (const LinkedPage& p : o.pages)
            page.add(fmt::format("<li><a href=\"{}\">{}</a></li>\n",
                                 html_escape(p.file.lexically_normal().generic_string()),
                                 html_escape(p.title)));
        page.add("</ul>\n");
    }

    // --- The scenes ------------------------------------------------------------------------
    page.add("<h2>The thesis' scenes</h2>\n");
    render::RenderOptions ropt;
    ropt.threads = o.threads;
    std::vector<std::pair<std::string, std::string>> speed_rows;
    for (const SceneInfo& info : scene_infos) {
        std::vector<std::string> overrides = size_overrides(o.width, o.height, o.spp);
        overrides.insert(overrides.end(), info.overrides.begin(), info.overrides.end());
        const render::Scene scene = render::load_scene(info.name, overrides);
        const std::string stem = info.file ? info.file : info.name;
        say(fmt::format("rendering {} ({}×{}, {} spp)", stem, o.width, o.height, o.spp));
        const render::RenderResult r = render::render(scene, ropt);
        const std::string file = stem + ".png";
        io::write_image(dir / file, r.display);
        const auto& s = r.stats;
        std::string sets;
        for (const std::string& set : info.overrides) sets += fmt::format(" --set '{}'", set);
        page.image(file, o.width, o.height, info.title, info.thesis_figure, info.title,
                   std::string(info.what) +
                       fmt::format(" Rendered with <code>irid render {} --width {} --height {} "
                                   "--spp {}{}</code>: {} optics, table path, clip "
                                   "<code>{}</code> to {}.",
                                   info.name, o.width, o.height, o.spp, html_escape(sets),
                                   scene.render.optics == render::OpticsModel::exact ? "exact" : "thesis",
                                   html_escape(std::string(clip_method_name(scene.render.clip))), html_escape(scene.render.space)),
                   {{"time", format_number(s.seconds) + " s"},
                    {"rays per second", format_number(static_cast<double>(s.rays) / s.seconds * 1e-6) + " M"},
                    {"pixels out of gamut before the clip",
                     format_number(100.0 * static_cast<double>(s.out_of_gamut_pixels) /
                                       (static_cast<double>(o.width) * o.height), 1) + " %"}});
    }

    // --- Table and Fourier paths against the spectral path ----------------------------------
    const int cw = std::max(32, o.width / 4), ch = std::max(24, o.height / 4);
    page.add(fmt::format(
        "<h2>The thesis' table path and the Fourier path against per-pixel spectra</h2>\n<p>Each "
        "scene at {}×{}, {} samples per pixel, rendered three times: with the thesis' colour "
        "tables (RGB products), with the film's exact colour per hit by the Fourier series "
        "(<code>render.path = fourier</code>: RGB products, no table; the Morpho keeps its wing "
        "table), and with a spectrum per ray (1 nm, products per wavelength); the CIEDE2000 "
        "against the spectral image per pixel.</p>\n<table>\n<tr><th>scene</th><th>spectral "
        "path</th><th>table path</th><th>mean / p99 ΔE2000</th><th>Fourier path</th>"
        "<th>mean / p99 ΔE2000</th></tr>\n",
        cw, ch, o.spp));
    for (const SceneInfo& info : scene_infos) {
        if (info.file) continue;  // a second view of a scene already compared
        std::vector<std::string> set = size_overrides(cw, ch, o.spp);
        say(fmt::format("comparing the colour paths on {}", info.name));
        const auto with_path = [&](const char* path) {
            std::vector<std::string> s = set;
            s.push_back(std::string("render.path=") + path);
            return render::render(render::load_scene(info.name, s), ropt);
        };
        const render::RenderResult spectral = with_path("spectral");
        const render::RenderResult table = with_path("table");
        const render::RenderResult fourier = with_path("fourier");
        const render::ImageDifference dt = render::delta_e_2000_images(table.xyz, spectral.xyz);
        const render::ImageDifference df = render::delta_e_2000_images(fourier.xyz, spectral.xyz);
        page.add(fmt::format("<tr><td>{}</td><td>{:.3f} s</td><td>{:.3f} s ({:.1f}× faster)</td>"
                             "<td>{:.3f} / {:.3f}</td><td>{:.3f} s ({:.1f}× faster)</td>"
                             "<td>{:.3f} / {:.3f}</td></tr>\n",
                             info.name, spectral.stats.seconds, table.stats.seconds,
                             spectral.stats.seconds / table.stats.seconds, dt.mean, dt.p99,
                             fourier.stats.seconds, spectral.stats.seconds / fourier.stats.seconds,
                             df.mean, df.p99));
    }
    page.add("</table>\n");

    // --- The view transform -----------------------------------------------------------------
    {
        say("comparing the view transforms");
        const int vw = std::max(32, o.width / 2), vh = std::max(24, o.height / 2);
        page.add(fmt::format(
            "<h2>From scene light to a display</h2>\n<p>The oil slick at {}×{}, {} samples per "
            "pixel, under the Preetham–Shirley–Smits daylight sky: with the thesis' path "
            "(<code>render.view = thesis</code>: the gamut clip alone, so every luminance above "
            "the display's white becomes white); with the default view, which first rolls "
            "the highlights off on luminance (the identity up to the knee, Reinhard et al. 2002's "
            "L/(1 + L) above it) and then clips the chroma that is left outside the gamut; and "
            "through the ACES 2.0 Output Transform for an SDR Rec.709 display "
            "(<code>render.view = aces2</code>, <code>sdr-100nit-rec709</code>), whose tonescale "
            "shows 18 % grey at 10 cd/m² where the others show it at 18, and whose highlights "
            "desaturate toward white. The same exposure for all three. The "
            "numbers are the share of pixels stored as 255 in all three channels and the brightest "
            "scene luminance (white = 1); below the images, the brightest glint of each at 4× "
            "(nearest neighbour).</p>\n<div class=\"pair\">\n",
            vw, vh, o.spp));
        constexpr int zoom = 4;
        const int gw = std::max(8, vw / 4), gh = std::max(6, vh / 4);
        int glint_x = 0, glint_y = 0;
        struct Glint {
            io::Image part;
            std::string file, title;
        };
        std::vector<Glint> glints;
        for (const char* view : {"thesis", "rolloff", "aces2"}) {
            std::vector<std::string> set = size_overrides(vw, vh, o.spp);
            set.push_back(fmt::format("render.view={}", view));
            const render::RenderResult r = render::render(render::load_scene("oil-slick", set), ropt);
            std::size_t white = 0;
            float brightest = 0;
            for (std::size_t i = 0; i < r.display.pixel_count(); ++i) {
                bool all = true;
                for (int c = 0; c < 3; ++c) all = all && r.display.pixels[3 * i + c] >= 254.5f / 255.0f;
                white += all ? 1 : 0;
                if (r.xyz.pixels[3 * i + 1] > brightest) {
                    brightest = r.xyz.pixels[3 * i + 1];
                    glint_x = static_cast<int>(i % static_cast<std::size_t>(vw));
                    glint_y = static_cast<int>(i / static_cast<std::size_t>(vw));
                }
            }
            const std::string file = fmt::format("oil-slick-view-{}.png", view);
            io::write_image(dir / file, r.display);
            const std::string title = std::string(view) == "thesis"    ? "render.view = thesis (clip only)"
                                      : std::string(view) == "rolloff" ? "render.view = rolloff (the default)"
                                                                       : "render.view = aces2 (ACES 2.0, SDR Rec.709)";
            page.image(file, vw, vh, title, "", title,
                       fmt::format("<code>irid render oil-slick --set render.view={}</code>", view),
                       {{"clipped white", format_number(100.0 * static_cast<double>(white) /
                                                            static_cast<double>(r.display.pixel_count()),
                                                        3) + " %"},
                        {"brightest scene Y", format_number(brightest, 3)}});
            glints.push_back({crop(r.display, glint_x - gw / 2, glint_y - gh / 2, gw, gh),
                              fmt::format("oil-slick-view-{}-glint.png", view), title});
        }
        // The glints in a row of their own, each below its view.
        page.add("</div>\n<div class=\"pair\">\n");
        for (const Glint& g : glints) {
            io::write_image(dir / g.file, magnify(g.part, zoom));
            page.image(g.file, g.part.width * zoom, g.part.height * zoom, g.title + ", the glint", "",
                       g.title + ", the glint", "The brightest glint of the image above, 4×.", {});
        }
        page.add("</div>\n");
    }

    // --- Thin-film aliasing ----------------------------------------------------------------
    {
        say("showing the thin-film anti-aliasing");
        const int aw = std::max(32, o.width / 8), ah = std::max(24, o.height / 8);
        constexpr int zoom = 4;
        // A thicker slick than the scene's, so that its bands crowd below the pixel size, on a
        // flat pavement, so that what differs between the images is the film.
        const std::vector<std::string> slick = {"oil.max_thickness_nm=6000", "pavement.bump_height=0",
                                                "pavement.fine_height=0",
                                                "pavement.albedo_variation=0"};
        auto render_slick = [&](int spp, const char* mode) {
            std::vector<std::string> set = size_overrides(aw, ah, spp);
            set.insert(set.end(), slick.begin(), slick.end());
            set.push_back(fmt::format("render.antialias={}", mode));
            return render::render(render::load_scene("oil-slick", set), ropt);
        };
        const render::RenderResult reference = render_slick(64, "none");
        page.add(fmt::format(
            "<h2>Thin-film aliasing</h2>\n<p>Where a film's thickness changes faster than the "
            "pixel grid, point samples of its colour alias into false bands and speckle. irid "
            "averages the colour over the thickness range each sample covers (running integrals "
            "of the colour table). The oil slick with a 6 µm maximum thickness on a flat, uniform "
            "pavement, {}×{} pixels "
            "shown at {}× (nearest neighbour): 1 sample per pixel without and with the "
            "footprint filter, and 64 point samples per pixel as the reference. ΔE2000 is the "
            "mean difference to the reference.</p>\n<div class=\"pair\">\n",
            aw, ah, zoom));
        struct Variant {
            const char* file;
            const char* title;
            const render::RenderResult* result;
        };
        const render::RenderResult none = render_slick(1, "none");
        const render::RenderResult footprint = render_slick(1, "footprint");
        for (const Variant& v :
             {Variant{"oil-slick-antialias-none.png", "1 sample per pixel, no filtering", &none},
              Variant{"oil-slick-antialias-footprint.png", "1 sample per pixel, footprint filter",
                      &footprint},
              Variant{"oil-slick-antialias-reference.png", "64 samples per pixel (reference)",
                      &reference}}) {
            io::write_image(dir / v.file, magnify(v.result->display, zoom));
            const double de = render::delta_e_2000_images(v.result->xyz, reference.xyz).mean;
            page.image(v.file, aw * zoom, ah * zoom, v.title, "", v.title,
                       "oil.max_thickness_nm = 6000, pavement bumps and albedo variation 0; the rest as "
                       "the oil-slick scene.",
                       {{"mean ΔE2000 to the reference", format_number(de, 3)}});
        }
        page.add("</div>\n");
    }

    // --- Figures and tables ----------------------------------------------------------------
    page.add("<h2>Figures</h2>\n");
    const int fw = o.figure_width, fh = o.figure_width * 5 / 8;
    std::vector<std::string> tables;
    for (const FigureInfo& info : figure_catalog()) {
        const bool is_table = std::find(info.extensions.begin(), info.extensions.end(), ".html") !=
                              info.extensions.end();
        say(fmt::format("drawing {}", info.name));
        FigureRequest req;
        req.name = info.name;
        req.width_px = fw;
        req.height_px = fh;
        req.output = dir / (info.name + (is_table ? ".html" : ".png"));
        const FigureResult fr = draw_figure(req);
        if (is_table) {
            tables.push_back(fmt::format(
                "<section>\n<p class=\"title\">{}{}</p>\n{}\n<p>{}</p>\n</section>\n",
                info.thesis_figure.empty()
                    ? ""
                    : fmt::format("<span class=\"thesis\">Thesis {}</span> ", html_escape(info.thesis_figure)),
                html_escape(info.title), html_fragment(req.output), html_escape(fr.caption)));
            continue;
        }
        page.image(info.name + ".png", fr.width_px, fr.height_px, info.title, info.thesis_figure,
                   info.title, html_escape(fr.caption), fr.measurements);
    }
    page.add("<h2>Tables</h2>\n");
    for (const std::string& t : tables) page.add(t);

    // --- The clip report ---------------------------------------------------------------------
    say("measuring the clip report");
    page.add("<h2>Gamut clipping: the clip report</h2>\n");
        for (const ClipReportSet set : {ClipReportSet::spectrum, ClipReportSet::interference}) {
        const ClipReport rep = measure_clip_report(clip_report_color_set(set, srgb()),
                                                   Gamut(srgb(), 1.0), ClipReportOptions{0.05});
        page.add(fmt::format("<p>{} — {} colours, {} outside {} — {}</p>\n<table>\n"
                             "<tr><th>method</th><th>ΔE2000 mean</th><th>ΔE2000 p95</th>"
                             "<th>ΔE2000 max</th><th>Oklab hue change mean [°]</th>"
                             "<th>CIELUV hue change mean [°]</th><th>ΔY mean</th>"
                             "<th>colours per second</th></tr>\n",
                             html_escape(rep.set_name), rep.size, rep.out_of_gamut,
                             html_escape(rep.destination), html_escape(rep.set_description)));
        for (const MethodClipReport& m : rep.methods) {
            page.add(fmt::format("<tr><td>{}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.2f}</td>"
                                 "<td>{:.2f}</td><td>{:.2f}</td><td>{:.4f}</td><td>{:.3g}</td></tr>\n",
                                 clip_method_name(m.method), m.delta_e2000.mean, m.delta_e2000.p95,
                                 m.delta_e2000.max, m.hue_oklab.mean, m.hue_luv.mean,
                                 m.delta_y.mean, m.colors_per_second));
        }
        page.add("</table>\n");
    }
    {
        // The ramps: what each method does to gradients (speeds are not shown: a single pass).
        const ClipReport rep = measure_clip_report(clip_report_color_set(ClipReportSet::ramps, srgb()),
                                                   Gamut(srgb(), 1.0), ClipReportOptions{0.0});
        page.add(fmt::format(
            "<p>{} — {} colours in {} ramps, {} outside {} — {}. Banding: per ramp the largest "
            "ΔE2000 between neighbouring outputs over their mean (1 = even; the input ramps "
            "themselves: mean {:.2f}); collapse: the share of a ramp's out-of-gamut steps whose "
            "output is within ΔE2000 0.5 of the next step's (½ step: within half the ramp's mean "
            "input step); the figure <i>ramps</i> above shows them.</p>\n<table>\n"
            "<tr><th>method</th><th>in-gamut ΔE2000 mean / max</th><th>banding mean / max</th>"
            "<th>collapse</th><th>collapse ½ step</th></tr>\n",
            html_escape(rep.set_name), rep.size, rep.ramps, rep.out_of_gamut,
            html_escape(rep.destination), html_escape(rep.set_description),
            rep.input_banding.mean));
        for (const MethodClipReport& m : rep.methods) {
            page.add(fmt::format("<tr><td>{}</td><td>{:.2f} / {:.2f}</td><td>{:.2f} / {:.2f}</td>"
                                 "<td>{:.3f}</td><td>{:.3f}</td></tr>\n",
                                 clip_method_name(m.method), m.in_gamut_moved.mean, m.in_gamut_moved.max,
                                 m.banding.mean, m.banding.max, m.collapse.mean, m.collapse_relative.mean));
        }
        page.add("</table>\n");
    }

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    page.add(fmt::format("<p><small>Made by irid 0.1.0 in {:.1f} s.</small></p>\n", seconds));
    const std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                             "<title>irid — gallery</title>\n<style>" +
                             std::string(style) + "</style>\n</head>\n<body>\n" + page.html() +
                             "</body>\n</html>\n";
    const fs::path index = dir / "index.html";
    io::write_output_file(index, html);
    return {index, seconds};
}

}  // namespace irid::gallery
