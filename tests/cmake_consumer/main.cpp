// Uses an installed irid as a user's project would: the colour core (CIELAB of sRGB red, a
// published value), the figures' catalog (links Cairo through the package) and a tiny render
// (links the renderer, the noise, oneTBB and the scene reader). Exits non-zero on any mismatch.
#include <irid/color.h>
#include <irid/figures/figures.h>
#include <irid/render/render.h>

#include <cmath>
#include <cstdio>

int main() {
    const irid::Xyz xyz = irid::srgb().to_xyz({1.0, 0.0, 0.0});
    const irid::Lab lab = irid::xyz_to_lab(xyz, irid::srgb().white_xyz());
    std::printf("sRGB red: L* %.2f a* %.2f b* %.2f\n", lab.L, lab.a, lab.b);
    // sRGB red in CIELAB (D65 white) is L* 53.24, a* 80.09, b* 67.20 (to the 0.05 that the
    // published D65 whites, xy or ASTM E308 XYZ, differ by).
    const bool lab_ok = std::abs(lab.L - 53.24) < 0.05 && std::abs(lab.a - 80.09) < 0.05 &&
                        std::abs(lab.b - 67.20) < 0.05;

    const bool figures_ok = irid::figures::find_figure("table1") != nullptr;

    const irid::render::Scene scene =
        irid::render::load_scene("morpho", {"image.width=8", "image.height=6", "image.spp=1"});
    const irid::render::RenderResult r = irid::render::render(scene);
    const bool render_ok = r.display.width == 8 && r.display.height == 6 &&
                           r.stats.camera_rays == 48;
    std::printf("figures: %s, render: %s\n", figures_ok ? "ok" : "FAILED",
                render_ok ? "ok" : "FAILED");
    return lab_ok && figures_ok && render_ok ? 0 : 1;
}
