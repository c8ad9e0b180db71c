#include <irid/color/numeric_table.h>
#include <irid/color/primaries.h>
#include <irid/error.h>

#include <string>

namespace irid {

PrimaryMatchingFunctions monochromatic_primary_matching_functions(double red_nm, double green_nm,
                                                                  double blue_nm, Observer observer) {
    for (const double lambda : {red_nm, green_nm, blue_nm}) {
        if (!(lambda >= lambda_min_nm && lambda <= lambda_max_nm)) {
            throw Error("primary wavelength " + format_shortest(lambda) +
                        " nm is outside 360-830 nm");
        }
    }
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    const auto column = [&](double lambda) {
        const Xyz c = monochromatic_xyz(lambda, observer);
        return Vec3{c.X, c.Y, c.Z};
    };
    const Mat3 p = Mat3::from_columns(column(red_nm), column(green_nm), column(blue_nm));
    if (std::abs(p.determinant()) < 1e-12) {
        throw Error("primaries at " + format_shortest(red_nm) + ", " + format_shortest(green_nm) +
                    " and " + format_shortest(blue_nm) +
                    " nm are not independent; choose three distinct, well separated wavelengths");
    }
    const Mat3 p_inverse = inverse(p, "primary matrix");
    // Amounts matching the equal-energy stimulus: p⁻¹ (Σx̄, Σȳ, Σz̄). Scale each primary so all
    // three amounts equal Σȳ.
    const double sum_y = cmf.y.sum();
    const Vec3 equal_energy = p_inverse * Vec3{cmf.x.sum(), sum_y, cmf.z.sum()};
    Vec3 scale{};
    for (int i = 0; i < 3; ++i) {
        if (!(std::abs(equal_energy[i]) > 1e-12)) {
            throw Error("primaries: the equal-energy white needs none of primary " +
                        std::to_string(i + 1) + "; the normalisation is undefined");
        }
        scale[i] = sum_y / equal_energy[i];
    }
    PrimaryMatchingFunctions out;
    out.red_nm = red_nm;
    out.green_nm = green_nm;
    out.blue_nm = blue_nm;
    out.xyz_to_rgb = Mat3::diagonal(scale) * p_inverse;
    for (int i = 0; i < dense_sample_count; ++i) {
        const Vec3 rgb = out.xyz_to_rgb * Vec3{cmf.x[i], cmf.y[i], cmf.z[i]};
        out.r[i] = rgb[0];
        out.g[i] = rgb[1];
        out.b[i] = rgb[2];
    }
    return out;
}

}  // namespace irid
