#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace irid {

/// The visible range irid integrates over, as CIE 015:2018 §7.1 recommends [nm].
inline constexpr int lambda_min_nm = 360;
inline constexpr int lambda_max_nm = 830;
/// Number of 1 nm samples from lambda_min_nm to lambda_max_nm inclusive.
inline constexpr int dense_sample_count = lambda_max_nm - lambda_min_nm + 1;

class PiecewiseLinearSpectrum;
template <int N>
class SampledWavelengths;
template <int N>
class SampledSpectrum;

/// A spectrum sampled every 1 nm from 360 to 830 nm: the grid of the CIE tables and of every
/// colorimetric integral in irid. Values between samples are linear.
class DenseSpectrum {
public:
    /// Zero everywhere.
    constexpr DenseSpectrum() = default;
    /// The same value at every wavelength.
    explicit constexpr DenseSpectrum(double constant) noexcept { m_values.fill(constant); }
    explicit constexpr DenseSpectrum(const std::array<double, dense_sample_count>& values) noexcept
        : m_values(values) {}

    /// Samples f(lambda_nm) at 360, 361, ..., 830 nm.
    template <class F>
    [[nodiscard]] static DenseSpectrum from_function(F&& f) {
        DenseSpectrum s;
        for (int i = 0; i < dense_sample_count; ++i) s.m_values[i] = f(wavelength_nm(i));
        return s;
    }
    /// Resamples a piecewise-linear spectrum at every whole nanometre.
    [[nodiscard]] static DenseSpectrum resample(const PiecewiseLinearSpectrum& s);

    /// Wavelength of sample i [nm].
    [[nodiscard]] static constexpr double wavelength_nm(int i) noexcept {
        return static_cast<double>(lambda_min_nm + i);
    }

    [[nodiscard]] constexpr double operator[](int i) const noexcept { return m_values[i]; }
    [[nodiscard]] constexpr double& operator[](int i) noexcept { return m_values[i]; }
    /// Value at any wavelength by linear interpolation; 0 outside 360-830 nm.
    [[nodiscard]] double operator()(double lambda_nm) const noexcept;

    [[nodiscard]] std::span<const double, dense_sample_count> values() const noexcept {
        return m_values;
    }
    /// Sum of the samples: the 1 nm Riemann sum of the spectrum (CIE 015:2018 §7.2).
    [[nodiscard]] double sum() const noexcept;
    /// Sum of the products with another spectrum, sample by sample.
    [[nodiscard]] double dot(const DenseSpectrum& other) const noexcept;
    [[nodiscard]] double max_value() const noexcept;

    template <int N>
    [[nodiscard]] SampledSpectrum<N> sample(const SampledWavelengths<N>& wavelengths) const noexcept;

    DenseSpectrum& operator*=(const DenseSpectrum& o) noexcept;
    DenseSpectrum& operator+=(const DenseSpectrum& o) noexcept;
    DenseSpectrum& operator*=(double k) noexcept;
    friend DenseSpectrum operator*(DenseSpectrum a, const DenseSpectrum& b) noexcept { return a *= b; }
    friend DenseSpectrum operator+(DenseSpectrum a, const DenseSpectrum& b) noexcept { return a += b; }
    friend DenseSpectrum operator*(DenseSpectrum a, double k) noexcept { return a *= k; }
    friend DenseSpectrum operator*(double k, DenseSpectrum a) noexcept { return a *= k; }

private:
    std::array<double, dense_sample_count> m_values{};
};

/// What a piecewise-linear spectrum is outside its first and last wavelength.
enum class Extrapolation {
    /// Hold the first and last values: CIE 015:2018 §7.2.2's rule for measured data when
    /// nothing better is known.
    hold_ends,
    /// Zero outside the measured range.
    zero,
};

/// A spectrum given by samples at any strictly increasing wavelengths (measured data), linear
/// between them.
class PiecewiseLinearSpectrum {
public:
    /// Throws irid::Error unless there is at least one sample, the sizes agree, wavelengths are
    /// finite, positive and strictly increasing, and values are finite.
    PiecewiseLinearSpectrum(std::vector<double> wavelengths_nm, std::vector<double> values,
                            Extrapolation extrapolation = Extrapolation::hold_ends);

    /// Samples a dense spectrum at its 1 nm grid (exact: both are linear between samples).
    [[nodiscard]] static PiecewiseLinearSpectrum from_dense(const DenseSpectrum& s);

    /// Loads column `column` (1 = the first after the wavelength) of a CSV file whose first
    /// column is the wavelength in nm. A non-numeric first line is a header. Throws irid::Error
    /// naming the file and line.
    [[nodiscard]] static PiecewiseLinearSpectrum read_csv(const std::string& path, int column = 1);

    [[nodiscard]] double operator()(double lambda_nm) const noexcept;
    [[nodiscard]] std::span<const double> wavelengths_nm() const noexcept { return m_wavelengths; }
    [[nodiscard]] std::span<const double> values() const noexcept { return m_values; }
    [[nodiscard]] Extrapolation extrapolation() const noexcept { return m_extrapolation; }

private:
    std::vector<double> m_wavelengths;
    std::vector<double> m_values;
    Extrapolation m_extrapolation;
};

/// N wavelengths for one spectral rendering sample, chosen by hero-wavelength sampling (Wilkie
/// et al. 2014, "Hero Wavelength Spectral Sampling", EGSR): one uniformly sampled hero and N-1
/// companions at equal offsets, rotated into [min, max). Each has the uniform pdf 1/(max - min).
template <int N>
class SampledWavelengths {
    static_assert(N >= 1);

public:
    /// u in [0, 1) picks the hero wavelength.
    [[nodiscard]] static SampledWavelengths hero(double u, double min_nm = lambda_min_nm,
                                                 double max_nm = lambda_max_nm) noexcept {
        SampledWavelengths w;
        const double range = max_nm - min_nm;
        const double hero_nm = min_nm + u * range;
        for (int i = 0; i < N; ++i) {
            double l = hero_nm + i * range / N;
            if (l >= max_nm) l -= range;
            w.m_lambda[i] = l;
            w.m_pdf[i] = 1.0 / range;
        }
        return w;
    }
    [[nodiscard]] constexpr double operator[](int i) const noexcept { return m_lambda[i]; }
    [[nodiscard]] constexpr double pdf(int i) const noexcept { return m_pdf[i]; }
    [[nodiscard]] static constexpr int size() noexcept { return N; }

private:
    std::array<double, N> m_lambda{};
    std::array<double, N> m_pdf{};
};

/// Spectral values at the N wavelengths of a SampledWavelengths.
template <int N>
class SampledSpectrum {
public:
    constexpr SampledSpectrum() = default;
    explicit constexpr SampledSpectrum(double c) noexcept { m_values.fill(c); }
    [[nodiscard]] constexpr double operator[](int i) const noexcept { return m_values[i]; }
    [[nodiscard]] constexpr double& operator[](int i) noexcept { return m_values[i]; }
    [[nodiscard]] static constexpr int size() noexcept { return N; }

    constexpr SampledSpectrum& operator*=(const SampledSpectrum& o) noexcept {
        for (int i = 0; i < N; ++i) m_values[i] *= o.m_values[i];
        return *this;
    }
    friend constexpr SampledSpectrum operator*(SampledSpectrum a, const SampledSpectrum& b) noexcept {
        return a *= b;
    }

private:
    std::array<double, N> m_values{};
};

template <int N>
SampledSpectrum<N> DenseSpectrum::sample(const SampledWavelengths<N>& wavelengths) const noexcept {
    SampledSpectrum<N> s;
    for (int i = 0; i < N; ++i) s[i] = (*this)(wavelengths[i]);
    return s;
}

/// Resamples a spectrum evaluated at sampled wavelengths: the piecewise-linear spectrum through
/// the N points (sorted by wavelength), held beyond its ends.
template <int N>
[[nodiscard]] PiecewiseLinearSpectrum to_piecewise_linear(const SampledSpectrum<N>& s,
                                                          const SampledWavelengths<N>& w) {
    std::array<int, N> order{};
    for (int i = 0; i < N; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return w[a] < w[b]; });
    std::vector<double> lambda(N), value(N);
    for (int i = 0; i < N; ++i) {
        lambda[i] = w[order[i]];
        value[i] = s[order[i]];
    }
    return PiecewiseLinearSpectrum(std::move(lambda), std::move(value), Extrapolation::hold_ends);
}

}  // namespace irid
