#pragma once
#include <stdexcept>
#include <string>

namespace debrisflow {

// A problem in the user's input (case file, --set override, mesh file). Exit code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A run that went unstable (NaN, particles leaving the domain, dt collapse). Exit code 3.
class InstabilityError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace debrisflow
