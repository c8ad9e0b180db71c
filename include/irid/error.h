#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace irid {

/// The exception irid throws: invalid parameters found when an object is built or a file is
/// read. The message names the parameter (or file and line) and what is allowed.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// A name that is none of those of its kind (a colour space, a clip method, an illuminant, an
/// observer, a material, a parameter, ...). The message lists the valid names, which valid()
/// also gives. The Python module raises KeyError for it.
class UnknownNameError : public Error {
public:
    UnknownNameError(const std::string& message, std::vector<std::string> valid)
        : Error(message), m_valid(std::move(valid)) {}
    [[nodiscard]] const std::vector<std::string>& valid() const noexcept { return m_valid; }

private:
    std::vector<std::string> m_valid;
};

}  // namespace irid
