#pragma once
#include "debrisflow/kernels/cubic_spline_k.hpp"
#include "debrisflow/kernels/wendland_c2_k.hpp"
#include "debrisflow/kernels/wendland_c4_k.hpp"
#include "debrisflow/models/registry.hpp"

namespace debrisflow::kernels {

// All smoothing kernels, selectable by name (`sph.kernel`).
using KernelRegistry = models::Registry<WendlandC2, CubicSpline, WendlandC4>;
using Kernel = KernelRegistry::Variant;

inline Kernel make_kernel(const std::string& name, Real h, int dim) {
    return KernelRegistry::visit_name(name, [&]<class K>() -> Kernel { return K(h, dim); });
}

} // namespace debrisflow::kernels
