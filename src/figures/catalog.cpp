// The catalog of irid_figures: one entry per figure, {FigureInfo, draw function}, in thesis
// order first, then irid's own figures. Each figure lives in src/figures/fig_<name>.cpp.

#include "figure_support.h"

namespace irid::figures::detail {

// The draw functions (src/figures/fig_*.cpp).
FigureResult draw_cmf_primaries(const FigureRequest& request);
FigureResult draw_cmf_xyz(const FigureRequest& request);
FigureResult draw_chromaticity(const FigureRequest& request);
FigureResult draw_clip_geometry(const FigureRequest& request);
FigureResult draw_spectrum_clip(const FigureRequest& request);
FigureResult draw_film_spectra(const FigureRequest& request);
FigureResult draw_table1(const FigureRequest& request);
// figures-B's (fig_hue_shift.cpp, fig_clip_claims.cpp, fig_film_error.cpp, fig_newton.cpp,
// fig_morpho_angle.cpp).
FigureResult draw_hue_shift(const FigureRequest& request);
FigureResult draw_clip_claims(const FigureRequest& request);
FigureResult draw_film_error(const FigureRequest& request);
FigureResult draw_newton(const FigureRequest& request);
FigureResult draw_morpho_angle(const FigureRequest& request);
// films' (fig_renderer_films.cpp).
FigureResult draw_renderer_films(const FigureRequest& request);
// gamut-report's (fig_ramps.cpp).
FigureResult draw_ramps(const FigureRequest& request);

namespace {

const std::vector<std::string> image_extensions{".svg", ".png"};
const std::vector<std::string> table_extensions{".md", ".html"};

}  // namespace

std::span<const CatalogEntry> catalog_entries() {
    static const std::vector<CatalogEntry> entries{
        {{"cmf-primaries", "Figure 2", "Colour-matching functions of monochromatic primaries",
          image_extensions,
          "primaries=L1,L2,L3 (three wavelengths in nm, 360-830, default 444,526,645); "
          "observer=cie1931|cie1964 (default cie1931)"},
         draw_cmf_primaries},
        {{"cmf-xyz", "Figure 3", "CIE colour-matching functions x̄, ȳ, z̄", image_extensions,
          "observer=cie1931|cie1964|both (default cie1931)"},
         draw_cmf_xyz},
        {{"chromaticity", "Figure 4", "CIE chromaticity diagram with RGB gamut triangles",
          image_extensions,
          "spaces=LIST of srgb, display-p3, rec2020, adobe-rgb, smpte-c, ntsc1953 (default "
          "srgb,display-p3,rec2020); diagram=xy|uv (default xy); fill=colors|none (default "
          "colors)"},
         draw_chromaticity},
        {{"clip-geometry", "Figure 10",
          "A constant-luminance slice of the RGB gamut and where the clip methods land",
          image_extensions,
          "method=NAME|all (clamp, smits, smits-xyz, luv-lightness-hue, luv-hue, css, oklab, "
          "css-raytrace, oklab-adaptive, oklab-cusp, smits-soft, aces-rgc "
          "(clipped); default smits); color=x,y,Y (default: 520 nm at Y = 0.25); "
          "space=NAME (default srgb)"},
         draw_clip_geometry},
        {{"spectrum-clip", "Figure 11", "The spectrum at equal luminance, clipped by each method",
          image_extensions,
          "methods=LIST of clip methods (default clamp,smits,luv-hue, then all others); "
          "luminance=Y in [0.01, 0.99] (default 0.2)"},
         draw_spectrum_clip},
        {{"table1", "Table 1", "Operations per colour of the RGB clip, ours beside the thesis'",
          table_extensions, "html=page|fragment (for .html; default page)"},
         draw_table1},
        {{"film-spectra", "", "Reflectance spectra of single thin films, exact and thesis",
          image_extensions,
          "films=LIST of thickness_nm[@material] (default 100,300,500,1000); film=MATERIAL "
          "(default soap-film); substrate=MATERIAL (default air); ambient=MATERIAL (default "
          "air); angle=degrees 0-89 (default 0); model=exact|thesis|both (default exact)"},
         draw_film_spectra},
        {{"newton", "", "Newton's colour scale: film colour against thickness, thesis and exact",
          image_extensions,
          "brightness=strip|off|each (default strip); reference=NM, the wavelength of the order "
          "boundaries, 380-780 (default 550); k=matched|1 (default matched)"},
         draw_newton},
        {{"morpho-angle", "", "Morpho wing colour and reflectance peak against viewing angle",
          image_extensions, "brightness=strip|off|each (default strip)"},
         draw_morpho_angle},
        {{"film-error", "", "ΔE2000 of the thesis' single-film model against the exact film",
          image_extensions, "film=soap|oil (default soap); k=matched|1 (default matched)"},
         draw_film_error},
        {{"renderer-films", "",
          "ΔE2000 of the renderers' thin-film models (glTF, Belcour–Barla, Cycles) and the thesis' "
          "against the exact film",
          image_extensions, "metal=gold|silver|none, the second row's base (default gold)"},
         draw_renderer_films},
        {{"hue-shift", "", "Hue change of the clipped spectrum against wavelength, per clip method",
          image_extensions,
          "hue=oklab|luv|lab (default oklab); methods=LIST of clip methods or all (default: all "
          "but smits-xyz and luv-lightness-hue, which draw smits' curve); "
          "luminance=Y, 0.01-0.99 (default 0.3)"},
         draw_hue_shift},
        {{"clip-claims", "", "The thesis' §4.3.4 claims for its clip, measured per method",
          table_extensions,
          "set=spectrum|interference|rec2020|ramps|all (default spectrum); hue=oklab|lab|luv, the "
          "hue of the face-angle table and verdict 4 (default oklab)"},
         draw_clip_claims},
        {{"ramps", "", "Gradients from a grey out of the gamut, clipped by each method",
          image_extensions,
          "luminance=Y, 0.01-0.99 (default 0.3); end=locus|rec2020 (default locus); "
          "methods=LIST of clip methods or all (default all); boundary=on|off, marks where each "
          "ramp leaves sRGB (default on)"},
         draw_ramps},
    };
    return entries;
}

}  // namespace irid::figures::detail
