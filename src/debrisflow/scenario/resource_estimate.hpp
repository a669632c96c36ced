#pragma once
#include "debrisflow/io/case_spec.hpp"
#include <string>
#include <vector>

namespace debrisflow::scenario {

// What a case will allocate, estimated from the spec alone before anything is built: fluid,
// boundary and body particles, grains (also those a feed releases by the end time), cells of
// the neighbour grid, FEM nodes; each with the key that drives it.
struct ResourceItem {
    std::string what;  // "fluid 'column'"
    std::string where; // "case.toml:12:1: key 'fluid.0.max'"
    double count = 0;  // particles, grains, cells or nodes
    double bytes = 0;  // with the pair lists, contact slots and integrator copies they need
};

struct ResourceEstimate {
    std::vector<ResourceItem> items;
    double total_bytes() const;
};

ResourceEstimate estimate_resources(const io::CaseSpec& c);

// Throws InputError naming the largest items when the estimate exceeds the memory budget
// (core/memory_budget.hpp), before anything is allocated.
void require_within_budget(const ResourceEstimate& e);

// Bytes of one SPH particle (fields, reorder and integrator copies, grid, half pair list) and
// of one grain (state and about 12 contact slots with history, and with the device contact
// layout their results); Simulation::memory_bytes uses
// the same figures.
// With `density_gradient` (a diffusion model that reads renormalised density gradients) also
// their 3 reals per particle and the wider scatter buffers of their pair pass.
double sph_bytes_per_particle(int dim, double support_over_dp, bool density_gradient = false);
double bytes_per_grain(const io::CaseSpec& c);

// Guard of every lattice built from input sizes: throws InputError naming `what` when the
// lattice of spacing dp over [lo, hi] has more points than the budget allows.
void require_lattice_within_budget(Vec3 lo, Vec3 hi, Real dp, int dim, const std::string& what);

} // namespace debrisflow::scenario
