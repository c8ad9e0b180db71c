#include <irid/color/numeric_table.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace irid {

double DenseSpectrum::operator()(double lambda_nm) const noexcept {
    const double t = lambda_nm - lambda_min_nm;
    if (!(t >= 0.0) || t > dense_sample_count - 1) return 0.0;
    const int i = std::min(static_cast<int>(t), dense_sample_count - 2);
    const double f = t - i;
    return m_values[i] + f * (m_values[i + 1] - m_values[i]);
}

DenseSpectrum DenseSpectrum::resample(const PiecewiseLinearSpectrum& s) {
    return from_function([&](double lambda) { return s(lambda); });
}

double DenseSpectrum::sum() const noexcept {
    return std::accumulate(m_values.begin(), m_values.end(), 0.0);
}

double DenseSpectrum::dot(const DenseSpectrum& other) const noexcept {
    return std::inner_product(m_values.begin(), m_values.end(), other.m_values.begin(), 0.0);
}

double DenseSpectrum::max_value() const noexcept {
    return *std::max_element(m_values.begin(), m_values.end());
}

DenseSpectrum& DenseSpectrum::operator*=(const DenseSpectrum& o) noexcept {
    for (int i = 0; i < dense_sample_count; ++i) m_values[i] *= o.m_values[i];
    return *this;
}

DenseSpectrum& DenseSpectrum::operator+=(const DenseSpectrum& o) noexcept {
    for (int i = 0; i < dense_sample_count; ++i) m_values[i] += o.m_values[i];
    return *this;
}

DenseSpectrum& DenseSpectrum::operator*=(double k) noexcept {
    for (double& v : m_values) v *= k;
    return *this;
}

PiecewiseLinearSpectrum::PiecewiseLinearSpectrum(std::vector<double> wavelengths_nm,
                                                 std::vector<double> values,
                                                 Extrapolation extrapolation)
    : m_wavelengths(std::move(wavelengths_nm)),
      m_values(std::move(values)),
      m_extrapolation(extrapolation) {
    if (m_wavelengths.empty()) throw Error("spectrum: at least one sample is required");
    if (m_wavelengths.size() != m_values.size()) {
        throw Error("spectrum: " + std::to_string(m_wavelengths.size()) + " wavelengths but " +
                    std::to_string(m_values.size()) + " values; the counts must match");
    }
    for (std::size_t i = 0; i < m_wavelengths.size(); ++i) {
        const double l = m_wavelengths[i];
        if (!std::isfinite(l) || l <= 0.0) {
            throw Error("spectrum: wavelength " + format_shortest(l) + " nm at sample " +
                        std::to_string(i + 1) + " must be finite and positive");
        }
        if (i > 0 && !(l > m_wavelengths[i - 1])) {
            throw Error("spectrum: wavelengths must increase strictly; " + format_shortest(l) +
                        " nm at sample " + std::to_string(i + 1) + " follows " +
                        format_shortest(m_wavelengths[i - 1]) + " nm");
        }
        if (!std::isfinite(m_values[i])) {
            throw Error("spectrum: the value at " + format_shortest(l) + " nm is not finite");
        }
    }
}

PiecewiseLinearSpectrum PiecewiseLinearSpectrum::from_dense(const DenseSpectrum& s) {
    std::vector<double> lambda(dense_sample_count);
    std::vector<double> value(dense_sample_count);
    for (int i = 0; i < dense_sample_count; ++i) {
        lambda[i] = DenseSpectrum::wavelength_nm(i);
        value[i] = s[i];
    }
    return {std::move(lambda), std::move(value), Extrapolation::zero};
}

PiecewiseLinearSpectrum PiecewiseLinearSpectrum::read_csv(const std::string& path, int column) {
    if (column < 1) {
        throw Error(path + ": spectrum column " + std::to_string(column) +
                    " must be >= 1 (column 0 holds the wavelengths)");
    }
    const NumericTable table =
        read_numeric_table(read_text_file(path, "spectrum CSV file", StreamInput::accept), path, 0,
                           column + 1);
    if (table.empty()) throw Error(path + ": no data rows");
    std::vector<double> lambda;
    std::vector<double> value;
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const double l = table.row(r)[0];
        if (!lambda.empty() && !(l > lambda.back())) {
            throw Error(path + ":" + std::to_string(table.line_numbers[r]) + ": wavelength " +
                        format_shortest(l) + " nm does not increase (previous " +
                        format_shortest(lambda.back()) + " nm)");
        }
        if (!(l > 0.0)) {
            throw Error(path + ":" + std::to_string(table.line_numbers[r]) +
                        ": wavelength must be positive, found " + format_shortest(l));
        }
        lambda.push_back(l);
        value.push_back(table.row(r)[static_cast<std::size_t>(column)]);
    }
    return {std::move(lambda), std::move(value)};
}

double PiecewiseLinearSpectrum::operator()(double lambda_nm) const noexcept {
    if (lambda_nm <= m_wavelengths.front()) {
        if (lambda_nm == m_wavelengths.front() || m_extrapolation == Extrapolation::hold_ends) {
            return m_values.front();
        }
        return 0.0;
    }
    if (lambda_nm >= m_wavelengths.back()) {
        if (lambda_nm == m_wavelengths.back() || m_extrapolation == Extrapolation::hold_ends) {
            return m_values.back();
        }
        return 0.0;
    }
    if (std::isnan(lambda_nm)) return 0.0;
    const auto upper = std::upper_bound(m_wavelengths.begin(), m_wavelengths.end(), lambda_nm);
    const auto i = static_cast<std::size_t>(upper - m_wavelengths.begin());
    const double l0 = m_wavelengths[i - 1];
    const double l1 = m_wavelengths[i];
    const double f = (lambda_nm - l0) / (l1 - l0);
    return m_values[i - 1] + f * (m_values[i] - m_values[i - 1]);
}

}  // namespace irid
