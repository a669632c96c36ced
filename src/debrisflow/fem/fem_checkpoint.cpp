// The FEM phase's state for checkpoints: node positions, velocities, accelerations and forces,
// element damage and erosion, the interface loads and the sub-cycle's clock.
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/fem/fem_solver.hpp"

namespace debrisflow::fem {

void FemSolver::state(checkpoint::Archive& ar) {
    ar.section("fem");
    const std::size_t n = x_.size();
    ar(x_, v_, a_, f_int_, f_ext_, f_step_, mass_, critical_dt_, t_, substeps_, initialized_);
    if (x_.size() != n || v_.size() != n || mass_.size() != n)
        ar.fail("its FEM node count differs from this case's");
    for (auto& s : solids_) {
        ar.section("solid " + s.name);
        const std::size_t e = s.volume.size();
        ar(s.kappa, s.damage, s.eroded, s.force);
        if (s.eroded.size() != e || s.damage.size() != s.kappa.size())
            ar.fail("solid '" + s.name + "' has another element count");
    }
    std::vector<std::string> names;
    std::vector<Vec3> forces;
    for (const auto& [k, f] : interface_) names.push_back(k), forces.push_back(f);
    ar(names, forces);
    if (!ar.is_loading()) return;
    if (names.size() != forces.size()) ar.fail("interface loads of mismatched lengths");
    interface_.clear();
    for (std::size_t i = 0; i < names.size(); ++i) interface_[names[i]] = forces[i];
}

} // namespace debrisflow::fem
