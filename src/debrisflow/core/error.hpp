#pragma once
#include <stdexcept>
#include <string>

namespace debrisflow {

// A problem in the user's input (case file, --set override, mesh file). Exit code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A run that stopped before its end time; the output written so far is kept.
class RunStopped : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A run that went unstable (NaN, particles leaving the domain, dt collapse). Exit code 3.
class InstabilityError : public RunStopped {
public:
    using RunStopped::RunStopped;
};

// A run stopped on request (SIGINT / SIGTERM, app/stop_request.hpp). Exit code 130.
class InterruptedError : public RunStopped {
public:
    using RunStopped::RunStopped;
};

// A run that needs more memory than the budget allows (core/memory_budget.hpp), found before
// the allocation that would exceed it. Exit code 2, as an allocation failure.
class OutOfMemoryError : public RunStopped {
public:
    using RunStopped::RunStopped;
};

} // namespace debrisflow
