// What the couplings keep between steps, for checkpoints: the boundary particles' rows in the
// elements (those exposed by erosion included) and on the bodies (those of bodies added during
// the run included), the surface facets and how much erosion each coupling has seen.
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/coupling/dem_body.hpp"
#include "debrisflow/coupling/dem_fem.hpp"
#include "debrisflow/coupling/sph_body.hpp"
#include "debrisflow/coupling/sph_dem.hpp"
#include "debrisflow/coupling/sph_fem.hpp"

namespace debrisflow::coupling {

void SphFemCoupling::state(checkpoint::Archive& ar) {
    ar.section("sph-fem");
    for (auto* rows : {&rows_, &hidden_})
        ar.columns(*rows, &Row::solid, &Row::element, &Row::n, &Row::facet, &Row::X);
    ar(surface_stale_, facets_, row_of_id_, eroded_seen_, last_force_);
    // The particles' indices follow from their ids at the next use; the carriers from the rows.
    if (ar.is_loading()) {
        layout_seen_ = ~std::uint64_t(0);
        carriers_.clear();
        for (const auto* rows : {&rows_, &hidden_})
            for (const Row& r : *rows)
                if (r.solid < 0 || std::size_t(r.solid) >= fem_.solids().size() || r.element < 0 ||
                    std::size_t(r.element) >= fem_.solids()[std::size_t(r.solid)].volume.size() ||
                    r.facet < -1 || r.facet >= std::int32_t(facets_.size()))
                    ar.fail("a boundary particle row outside the solids' elements or facets");
        for (const Row& r : rows_) carriers_.push_back(carrier_of(r));
        // (a resident backend takes them again when it takes the restored particles over)
    }
}

void DemFemCoupling::state(checkpoint::Archive& ar) {
    ar.section("dem-fem");
    ar(eroded_seen_, last_grain_force_);
}

void DemBodyCoupling::state(checkpoint::Archive& ar) {
    ar.section("obstacles");
    dem::ObstacleSet& o = obstacles_;
    ar(o.spheres, o.body_com, o.impulse, o.angular_impulse, o.time, o.version);
    ar(grain_force_, grain_torque_);
    if (grain_force_.size() != o.body_com.size() || grain_torque_.size() != o.body_com.size() ||
        o.impulse.size() != o.body_com.size() || o.angular_impulse.size() != o.body_com.size())
        ar.fail("grain loads that do not match its bodies");
}

void SphBodyCoupling::state(checkpoint::Archive& ar) {
    ar.section("sph-rigid");
    ar(rows_.owner, rows_.offset, rows_.normal, rows_.extra_rows);
    if (rows_.offset.size() != rows_.owner.size() || rows_.normal.size() != rows_.owner.size() ||
        rows_.owner.size() < initial_rows_)
        ar.fail("body particle rows of mismatched lengths");
    // The particles' indices follow from their ids at the next use.
    if (ar.is_loading()) layout_seen_ = ~std::uint64_t(0);
}

void SphDemCoupling::state(checkpoint::Archive& ar) {
    ar.section("sph-dem");
    dem::FluidLoad& l = load_;
    ar(l.force, l.u, l.beta, l.impulse, l.felt, l.handover, l.time, l.max_rate);
    ar(share_, reaction_, step_dt_);
}

} // namespace debrisflow::coupling
