#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/sph/sph_solver.hpp"

namespace debrisflow::sph {

void SphSolver::state(checkpoint::Archive& ar) {
    set_.state(ar);
    ar.section("sph");
    std::uint8_t valid = list_valid_;
    ar(xref_, yref_, zref_, valid, list_builds_);
    if (!ar.is_loading()) return;
    list_valid_ = valid != 0;
    if (!list_valid_) return;
    const std::size_t n = std::size_t(set_.size());
    if (xref_.size() != n || yref_.size() != n || zref_.size() != n) {
        list_valid_ = false; // built before particles were added: the next step rebuilds it
        return;
    }
    if (params_.gathers()) return; // the gather loop has no list; its grid is built every step
    // The list as the saved run built it: the same particle order at the same positions.
    grid_.build(xref_.data(), yref_.data(), zref_.data(), set_.size());
    auto at_build = set_.view();
    at_build.x = xref_.data(), at_build.y = yref_.data(), at_build.z = zref_.data();
    list_.build(grid_.view(), at_build);
    grid_.build(set_.x.data(), set_.y.data(), set_.z.data(), set_.size());
}

} // namespace debrisflow::sph
