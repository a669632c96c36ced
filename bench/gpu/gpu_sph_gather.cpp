// Runs one SPH force evaluation of a case both on the host (compute_forces_gather, OpenMP) and
// on a GPU (the same FluidInteraction functor compiled by nvcc), compares the results and
// reports both wall times. Exit status 1 when they differ by more than the tolerance, 77 when
// there is no GPU, 2 on any other error. Options: check_options.hpp.
#include "check_options.hpp"
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/io/case_spec.hpp"
#include "device_gather.hpp"
#include "scaled_difference.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <omp.h>
#include <stdexcept>
#include <string>
#include <vector>

using namespace debrisflow;
using gpu::scaled_difference;

namespace {

// The outputs of one force evaluation.
struct Forces {
    std::vector<Real> ax, ay, az, drho, tau;
    static Forces of(const particles::ParticleSet& s) {
        return {s.ax, s.ay, s.az, s.drho, s.sps_tau};
    }
};

} // namespace

int main(int argc, char** argv) try {
    const auto opt = gpu::CheckOptions::parse(argc, argv);
    gpu::first_device(); // before the host's work: no GPU, nothing to check
    const auto loaded = opt.load();
    app::Simulation& sim = *loaded;
    if (!sim.has_fluid()) throw std::runtime_error(opt.path + " has no SPH fluid");
    auto& solver = sim.solver();
    solver.update_neighbors(true);
    auto& set = sim.particles();
    const std::vector<Real> tau0 = set.sps_tau;

    std::vector<double> host_ms;
    for (int r = 0; r < std::max(opt.repeat, 1); ++r) {
        set.sps_tau = tau0;
        double seconds = 0;
        {
            ScopedTimer w(seconds);
            solver.compute_forces_gather();
        }
        host_ms.push_back(1e3 * seconds);
    }
    std::sort(host_ms.begin(), host_ms.end());
    const Forces host = Forces::of(set);

    const double visits = 2.0 * double(solver.pair_list().pairs());
    const double host_med = host_ms[host_ms.size() / 2];
    std::printf("case %s, advanced to t = %g s\n", opt.path.c_str(), double(opt.advance));
    std::printf("particles %d (fluid %d), pair visits %.4g\n", int(set.size()),
                int(set.count(particles::Kind::fluid)), visits);
    std::printf("host gather, %d threads: %.3f ms (%.3g pair-visits/s)\n", omp_get_max_threads(),
                host_med, visits / (1e-3 * host_med));
    std::fflush(stdout);

    set.sps_tau = tau0;
    for (auto* v : {&set.ax, &set.ay, &set.az, &set.drho}) std::fill(v->begin(), v->end(), 0);
    const gpu::DeviceTimes dev = gpu::gather_on_device(solver, opt.repeat);
    const Forces device = Forces::of(set);
    const double e_acc =
        std::max({scaled_difference(device.ax, host.ax), scaled_difference(device.ay, host.ay),
                  scaled_difference(device.az, host.az)});
    const double e_rho = scaled_difference(device.drho, host.drho);
    const double e_tau = scaled_difference(device.tau, host.tau);
    std::printf("device %s\n", dev.device.c_str());
    std::printf("device kernel: %.3f ms (%.3g pair-visits/s), %.1fx the host\n", dev.kernel_ms,
                visits / (1e-3 * dev.kernel_ms), host_med / dev.kernel_ms);
    std::printf("device copies: %.3f ms in, %.3f ms out\n", dev.upload_ms, dev.download_ms);
    std::printf("max |device - host| / max |host|: acceleration %.3g, drho/dt %.3g, SPS stress "
                "%.3g (tolerance %.3g)\n",
                e_acc, e_rho, host.tau.empty() ? 0.0 : e_tau, opt.tolerance);
    const bool ok = e_acc <= opt.tolerance && e_rho <= opt.tolerance &&
                    (host.tau.empty() || e_tau <= opt.tolerance);
    std::printf("%s\n", ok ? "AGREE" : "DIFFER");
    return ok ? 0 : 1;
} catch (const gpu::NoDevice& e) {
    std::fprintf(stderr, "gpu_sph_gather: no GPU to run on (%s)\n", e.what());
    return gpu::no_gpu_status;
} catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_sph_gather: %s\n", e.what());
    return 2;
}
