// Fuzz harness: spectra and optical constants read from CSV files.
// - PiecewiseLinearSpectrum::read_csv(path, column) (include/irid/color/spectrum.h), which takes
//   a path: the bytes go to an in-memory file (/proc/self/fd/N).
// - Material::read_csv(std::istream&, source, name) (include/irid/optics/material.h): tabulated
//   wavelength_nm,n,k files.
//
// Input: byte 0 picks the reader (and the spectrum's column, 1-3); the rest is the file.
// Checked: a spectrum read has increasing positive finite wavelengths and finite values, and its
// resampling and XYZ under D65 run; a material read has, at every wavelength of 360-830 nm,
// a finite index with n > 0 and k >= 0, as Material promises for validated models.
#include "fuzz_support.h"

#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>
#include <irid/optics/material.h>

#include <cmath>
#include <sstream>
#include <string>

namespace {

void check_spectrum(const irid::PiecewiseLinearSpectrum& s) {
    const auto w = s.wavelengths_nm();
    const auto v = s.values();
    IRID_FUZZ_REQUIRE(!w.empty() && w.size() == v.size(), "samples and values agree");
    for (std::size_t i = 0; i < w.size(); ++i) {
        IRID_FUZZ_REQUIRE(std::isfinite(w[i]) && w[i] > 0.0, "wavelength finite and positive");
        IRID_FUZZ_REQUIRE(i == 0 || w[i] > w[i - 1], "wavelengths increase");
        IRID_FUZZ_REQUIRE(std::isfinite(v[i]), "value finite");
    }
    for (const double lambda : {0.5 * w.front(), w.front(), 0.5 * (w.front() + w.back()), w.back(),
                                2.0 * w.back(), 555.0}) {
        // Between finite samples the value is finite unless the interpolation overflows (values
        // near ±DBL_MAX), which is not the reader's concern.
        (void)s(lambda);
    }
    static const irid::DenseSpectrum d65 = irid::illuminant_d65();
    (void)irid::reflectance_to_xyz(irid::DenseSpectrum::resample(s), d65);
}

void check_material(const irid::Material& m) {
    for (int lambda = irid::lambda_min_nm; lambda <= irid::lambda_max_nm; lambda += 7) {
        const irid::Complex n = m.index(lambda);
        IRID_FUZZ_REQUIRE(
            std::isfinite(n.real()) && std::isfinite(n.imag()) && n.real() > 0.0 && n.imag() >= 0.0,
            "index at " + std::to_string(lambda) + " nm: " + std::to_string(n.real()) + " + " +
                std::to_string(n.imag()) + "i");
    }
    (void)m.is_lossless();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static irid::fuzz::MemFile file;
    irid::fuzz::Bytes bytes(data, size);
    const std::size_t mode = bytes.pick(4);
    if (mode < 3) {
        const auto& path = file.write(bytes.data(), bytes.size());
        try {
            check_spectrum(
                irid::PiecewiseLinearSpectrum::read_csv(path.string(), static_cast<int>(mode) + 1));
        } catch (const irid::Error&) {
        }
    } else {
        std::istringstream in{std::string(bytes.rest())};
        try {
            check_material(irid::Material::read_csv(in, "<fuzz>", "fuzz"));
        } catch (const irid::Error&) {
        }
    }
    return 0;
}
