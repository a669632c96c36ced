#pragma once
// The probes' view of a resident DEM phase's grains (probes/grain_reader.hpp): evaluated where
// the grains are, with grain_samples_k.hpp's rules; only the few numbers, or the selected
// grains' rows, come back (issue #34), so that kinetic-energy, deposit, run-up and flow-section
// probes copy no grain arrays to the host. Before the phase has taken the grains over they are
// read where they still are, on the host.
#include "debrisflow/dem/resident_dem_k.hpp"
#include "debrisflow/probes/grain_reader.hpp"
#include <memory>
#include <vector>

namespace debrisflow::dem {

template <class Space> class ResidentDem;

template <class Space> class ResidentGrainReader final : public probes::GrainReader {
    template <class T> using Buffer = typename Space::template Buffer<T>;

public:
    explicit ResidentGrainReader(const ResidentDem<Space>& dem) : dem_(dem), host_(dem.host_) {}

    probes::GrainSums sums(const probes::GrainBox& box) const override {
        if (!dem_.resident_) return host_.sums(box);
        const probes::GrainsRead g = grains();
        probes::GrainSums s = Space::template fold<probes::GrainSums>(
            dem_.clumps_, probes::ClumpEnergy{clumps(), box});
        probes::GrainSums::combine(s, Space::template fold<probes::GrainSums>(
                                          g.n, probes::GrainSumsIn{g, densities(), box}));
        return s;
    }

    Real runup(int wall, Real bed) const override {
        if (!dem_.resident_) return host_.runup(wall, bed);
        std::vector<WallPrimitive> faces;
        for (const auto& w : dem_.host_.walls().primitives())
            if (w.wall == wall) faces.push_back(w);
        faces_.upload(faces.data(), Index(faces.size()));
        const probes::GrainsRead g = grains();
        return Space::max_from(g.n, probes::GrainTopOnWall{g, faces_.data(), faces_.size(), bed, 0},
                               0);
    }

    // A plane's distances live where the grains are counted: on the host before the take-over
    // (and after a checkpoint's restoration), then here; each move copies them once.
    int add_plane(const probes::CrossingPlane& plane) override {
        planes_.push_back(plane);
        last_.push_back(std::make_unique<Buffer<Real>>());
        on_host_.push_back(1);
        return host_.add_plane(plane);
    }

    probes::GrainSums cross(int plane) override {
        const std::size_t k = std::size_t(plane);
        Buffer<Real>& last = *last_[k];
        if (!dem_.resident_) {
            if (!on_host_[k]) host_.restore(plane, downloaded(last));
            on_host_[k] = 1;
            return host_.cross(plane);
        }
        if (on_host_[k]) {
            const std::vector<Real> d = host_.distances(plane);
            last.upload(d.data(), Index(d.size()));
            on_host_[k] = 0;
        }
        const probes::GrainsRead g = grains();
        const Index ids = Index(Space::max_from(g.n, probes::GrainIdOf{g.id}, -1)) + 1;
        if (last.size() < ids) {
            const Index had = last.size();
            last.resize(ids);
            Space::for_each(ids - had, FillWith<Real>{last.data() + had, probes::unseen_distance});
        }
        return Space::template fold<probes::GrainSums>(
            g.n, probes::GrainCrossing{g, densities(), planes_[k], last.data()});
    }

    std::vector<Real> distances(int plane) const override {
        const std::size_t k = std::size_t(plane);
        return on_host_[k] ? host_.distances(plane) : downloaded(*last_[k]);
    }

    void restore(int plane, const std::vector<Real>& distances) override {
        host_.restore(plane, distances);
        on_host_[std::size_t(plane)] = 1;
    }

    std::size_t bytes() const {
        std::size_t planes = 0;
        for (const auto& b : last_) planes += b->bytes();
        return density_.bytes() + faces_.bytes() + flag_.bytes() + at_.bytes() + rows_.bytes() +
               planes;
    }

protected:
    // Stream compaction of the selected grains' rows (flags, their exclusive scan, a gather).
    std::vector<probes::GrainRow> select(const probes::GrainBox& box) const override {
        if (!dem_.resident_) return host_.rows(box); // sorted again by rows(): cheap
        const probes::GrainsRead g = grains();
        flag_.resize(g.n);
        at_.resize(g.n);
        Space::for_each(g.n, probes::FlagGrainsIn{g, box, flag_.data()});
        const Index m = Space::exclusive_scan(g.n, flag_.data(), at_.data());
        rows_.resize(m);
        Space::for_each(
            g.n, probes::GatherGrainRows{g, densities(), flag_.data(), at_.data(), rows_.data()});
        std::vector<probes::GrainRow> rows(static_cast<std::size_t>(m));
        if (m > 0) rows_.download(rows.data());
        return rows;
    }

private:
    static std::vector<Real> downloaded(const Buffer<Real>& b) {
        std::vector<Real> out(static_cast<std::size_t>(b.size()));
        if (!out.empty()) b.download(out.data());
        return out;
    }

    probes::GrainsRead grains() const {
        const auto& d = dem_;
        return {d.pos_.data(),
                d.vel_.data(),
                d.spin_.data(),
                d.radius_.data(),
                d.mass_.data(),
                d.inv_inertia_.data(),
                d.material_.data(),
                d.id_.data(),
                d.clumps_ > 0 ? d.clump_of_.data() : nullptr,
                d.n_};
    }

    probes::ClumpsRead clumps() const {
        const auto& d = dem_;
        return {d.cl_pos_.data(),
                d.cl_vel_.data(),
                d.cl_ang_mom_.data(),
                d.cl_inv_inertia_.data(),
                d.cl_orient_.data(),
                d.cl_mass_.data(),
                d.clumps_};
    }

    // Each material's density, uploaded at the first use (the materials do not change).
    const Real* densities() const {
        if (density_.size() == 0) {
            std::vector<Real> rho;
            for (const auto& m : dem_.host_.materials()) rho.push_back(m.density);
            density_.upload(rho.data(), Index(rho.size()));
        }
        return density_.data();
    }

    const ResidentDem<Space>& dem_;
    probes::HostGrainReader host_; // the grains before the take-over
    mutable Buffer<Real> density_;
    mutable Buffer<WallPrimitive> faces_;
    mutable Buffer<Index> flag_, at_;
    mutable Buffer<probes::GrainRow> rows_;
    // crossing planes: each one's distances by grain id, and whether the host's are current
    std::vector<probes::CrossingPlane> planes_;
    std::vector<std::unique_ptr<Buffer<Real>>> last_;
    std::vector<std::uint8_t> on_host_;
};

} // namespace debrisflow::dem
