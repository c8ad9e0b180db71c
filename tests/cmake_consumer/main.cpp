// Prints the CIELAB of sRGB red; exits non-zero unless it is the published value.
#include <irid/color.h>

#include <cmath>
#include <cstdio>

int main() {
    const irid::Xyz xyz = irid::srgb().to_xyz({1.0, 0.0, 0.0});
    const irid::Lab lab = irid::xyz_to_lab(xyz, irid::srgb().white_xyz());
    std::printf("sRGB red: L* %.2f a* %.2f b* %.2f\n", lab.L, lab.a, lab.b);
    // sRGB red in CIELAB (D65 white) is L* 53.24, a* 80.09, b* 67.20 (to the 0.05 that the
    // published D65 whites, xy or ASTM E308 XYZ, differ by).
    const bool ok = std::abs(lab.L - 53.24) < 0.05 && std::abs(lab.a - 80.09) < 0.05 &&
                    std::abs(lab.b - 67.20) < 0.05;
    return ok ? 0 : 1;
}
