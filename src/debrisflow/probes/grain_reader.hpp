#pragma once
// What the grain probes read of the grains, wherever they are (issue #34): the host's
// DemSolver (probes/host_grain_reader.cpp) or a resident DEM phase's memory
// (dem/resident_grain_reader.hpp). Sums and maxima over the grains (kinetic energy, a
// deposit's mass, run-up on a wall) are evaluated beside the grain arrays and only their few
// numbers come back; a flow section gets the rows of the grains in its window, never the
// arrays. The per-grain rules are grain_samples_k.hpp's, shared by both.
#include "debrisflow/probes/grain_samples_k.hpp"
#include <algorithm>
#include <vector>

namespace debrisflow::dem {
class DemSolver;
}

namespace debrisflow::probes {

class GrainReader {
public:
    virtual ~GrainReader() = default;
    // Kinetic energy (translational, rotational, count) of the free grains and clumps whose
    // centres are in the box, and the mass and solid volume of every grain whose centre is.
    virtual GrainSums sums(const GrainBox& box) const = 0;
    // The highest grain top above `bed` among the grains touching DEM wall `wall` (0 if none).
    virtual Real runup(int wall, Real bed) const = 0;
    // The grains whose centres are in the box, in the order of their ids: a probe's sums over
    // them come out the same on every backend, whatever order the grains are stored in.
    std::vector<GrainRow> rows(const GrainBox& box) const {
        std::vector<GrainRow> r = select(box);
        std::sort(r.begin(), r.end(),
                  [](const GrainRow& a, const GrainRow& b) { return a.id < b.id; });
        return r;
    }

    // Planes that grains cross (mass_flux, discharge, trapping), counted where the grains are:
    // each keeps every grain id's signed distance at its previous count. Returns the plane's
    // number.
    virtual int add_plane(const CrossingPlane& plane) = 0;
    // The net mass and solid volume (GrainSums' mass, volume) of the grains that crossed the
    // plane towards its normal since its previous count (grains seen for the first time count
    // from now).
    virtual GrainSums cross(int plane) = 0;
    // Each grain id's distance at the plane's last count (unseen_distance: not counted yet),
    // for a checkpoint, and its restoration.
    virtual std::vector<Real> distances(int plane) const = 0;
    virtual void restore(int plane, const std::vector<Real>& distances) = 0;

protected:
    // The grains in the box in storage order.
    virtual std::vector<GrainRow> select(const GrainBox& box) const = 0;
};

// The host DemSolver's grains, read in place (loops in index order, folds as the host space's).
class HostGrainReader final : public GrainReader {
public:
    explicit HostGrainReader(const dem::DemSolver& solver) : solver_(solver) {}
    GrainSums sums(const GrainBox& box) const override;
    Real runup(int wall, Real bed) const override;
    int add_plane(const CrossingPlane& plane) override;
    GrainSums cross(int plane) override;
    std::vector<Real> distances(int plane) const override { return last_[std::size_t(plane)]; }
    void restore(int plane, const std::vector<Real>& distances) override {
        last_[std::size_t(plane)] = distances;
    }

protected:
    std::vector<GrainRow> select(const GrainBox& box) const override;

private:
    const dem::DemSolver& solver_;
    std::vector<CrossingPlane> planes_;
    std::vector<std::vector<Real>> last_; // each plane's distances by grain id
};

} // namespace debrisflow::probes
