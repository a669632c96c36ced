#pragma once
#include "debrisflow/core/vec3_k.hpp"
#include <functional>
#include <string>
#include <vector>

namespace debrisflow::scenario {

// Cartesian lattice points, spacing dp, at `origin + (i + 1/2) dp` per direction, covering
// [lo, hi]. In 2D the lattice lies in the x-z plane (y = 0). Throws InputError naming `what`
// when the lattice has more points than the memory budget allows (core/memory_budget.hpp).
std::vector<Vec3> lattice(Vec3 lo, Vec3 hi, Vec3 origin, Real dp, int dim,
                          const std::function<bool(Vec3)>& keep,
                          const std::string& what = "a particle lattice");

// Axis coordinates of an open tank or closed box wall: `layers` layers outside [lo, hi] on
// each side (the upper side of the last direction only when `closed_top`), interior at
// lo + (i + 1/2) dp.
std::vector<Vec3> tank_walls(Vec3 lo, Vec3 hi, Real dp, int dim, int layers, bool closed_top,
                             const std::string& what = "a tank wall");

// Removes points closer than `min_gap` to any point of `obstacles` (brute-force free: hashed).
std::vector<Vec3> remove_near(const std::vector<Vec3>& pts, const std::vector<Vec3>& obstacles,
                              Real min_gap);

} // namespace debrisflow::scenario
