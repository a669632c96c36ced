// Evaluates every grain-grain contact of a DEM case (dem::grain_pair_force with the live
// contact history) both on the host and on a GPU, compares the forces, torques and updated
// histories and reports both times. Exit status 1 when they differ by more than the
// tolerance, 77 when there is no GPU, 2 on any other error. Options: check_options.hpp.
#include "check_options.hpp"
#include "device_contacts.hpp"
#include "device_info.hpp"
#include <algorithm>
#include <cstdio>
#include <stdexcept>

using namespace debrisflow;

int main(int argc, char** argv) try {
    const auto opt = gpu::CheckOptions::parse(argc, argv);
    const std::string device = gpu::first_device();
    const auto sim = opt.load();
    if (!sim->has_grains()) throw std::runtime_error(opt.path + " has no DEM grains");
    auto& dem = sim->grains();
    auto in = dem.grain_contact_inputs();
    if (in.h <= 0) in.h = dem.dt(); // no step taken yet: the case's DEM step
    const auto c = gpu::compare_grain_contacts(in, opt.repeat);
    std::printf("case %s, advanced to t = %g s\n", opt.path.c_str(), double(opt.advance));
    std::printf("grains %d, contact slots %ld, candidates %ld, touching %ld, step %.3g s\n",
                int(in.n), c.slots, c.candidates, c.touching, double(in.h));
    std::printf("device %s\n", device.c_str());
    std::printf("host, 1 thread: %.3f ms (%.3g contacts/s)\n", c.host_ms,
                double(c.touching) / (1e-3 * c.host_ms));
    std::printf("device kernel: %.3f ms (%.3g contacts/s), %.1fx the host\n", c.kernel_ms,
                double(c.touching) / (1e-3 * c.kernel_ms), c.host_ms / c.kernel_ms);
    std::printf("max |device - host| / max |host|: force %.3g, torque %.3g, history %.3g "
                "(tolerance %.3g)\n",
                c.force, c.torque, c.history, opt.tolerance);
    const bool ok = c.touching > 0 && c.force <= opt.tolerance && c.torque <= opt.tolerance &&
                    c.history <= opt.tolerance;
    std::printf("%s\n", ok ? "AGREE" : c.touching == 0 ? "NO CONTACTS" : "DIFFER");
    return ok ? 0 : 1;
} catch (const gpu::NoDevice& e) {
    std::fprintf(stderr, "gpu_dem_contacts: no GPU to run on (%s)\n", e.what());
    return gpu::no_gpu_status;
} catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_dem_contacts: %s\n", e.what());
    return 2;
}
