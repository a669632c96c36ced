#pragma once
#include <chrono>

namespace debrisflow {

// Adds the seconds between construction and destruction to a counter.
class ScopedTimer {
public:
    explicit ScopedTimer(double& acc) : acc_(acc), t0_(std::chrono::steady_clock::now()) {}
    ~ScopedTimer() {
        acc_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    }
    ScopedTimer(const ScopedTimer&) = delete;
    ScopedTimer& operator=(const ScopedTimer&) = delete;

private:
    double& acc_;
    std::chrono::steady_clock::time_point t0_;
};

} // namespace debrisflow
