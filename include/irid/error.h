#pragma once

#include <stdexcept>
#include <string>

namespace irid {

/// The one exception type irid throws: invalid parameters found when an object is built or a
/// file is read. The message names the parameter (or file and line) and what is allowed.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace irid
