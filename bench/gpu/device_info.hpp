#pragma once
#include <stdexcept>
#include <string>

namespace debrisflow::gpu {

// Thrown when no CUDA device can be used (no GPU, or a driver older than the runtime).
struct NoDevice : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The name of the first CUDA device (made current); throws NoDevice when there is none.
std::string first_device();

} // namespace debrisflow::gpu
