#pragma once
// FEM solids in a resident backend's fluid (issues #33, #34): the carried boundary particles of
// the SPH-FEM coupling (coupling/sph_fem.hpp) where the particles are. Each move uploads the
// nodes' positions and velocities and the facets' normals (a solid's few thousand nodes, not
// the particles) and the particles take their elements' motion there; each FEM load brings
// back only the carried particles' rows and loads (compacted in index order), which the host
// hands to the nodes in that order, as its own pass does; erosion removes the eroded rows'
// particles and appends the exposed surface's by the backend's compaction and append. The
// rows, the id -> row map and the FEM stay on the host. The rules are coupling/sph_fem_k.hpp's,
// shared with the host coupling.
#include "debrisflow/coupling/sph_fem.hpp"
#include "debrisflow/coupling/sph_fem_k.hpp"
#include <vector>

namespace debrisflow::sph {

template <class Space> class ResidentSph;

template <class Space> class ResidentFem final : public coupling::FemParticles {
    template <class T> using Buffer = typename Space::template Buffer<T>;

public:
    ResidentFem(ResidentSph<Space>& sph, coupling::SphFemCoupling& coupling)
        : sph_(sph), coupling_(coupling) {}

    // The row of each particle of the host's set (by persistent id), or -1.
    std::vector<std::int32_t> rows_of(const std::vector<ParticleId>& ids) const {
        std::vector<std::int32_t> r(ids.size());
        for (std::size_t k = 0; k < ids.size(); ++k) r[k] = coupling_.row_of(ids[k]);
        return r;
    }

    void carriers_changed() override { upload(carrier_, coupling_.carriers()); }

    void move(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
              const std::vector<Vec3>& facet_normal, Real ahead) override {
        sph_.upload_once();
        upload(x_, x);
        upload(v_, v);
        upload(normal_, facet_normal);
        Space::for_each(sph_.n_, coupling::FollowElements{sph_.view(), rows(), x_.data(), v_.data(),
                                                          normal_.data(), ahead,
                                                          sph_.host_.params().dim == 2});
        Space::synchronize();
    }

    std::vector<coupling::CarriedLoad> loads() override {
        sph_.upload_once();
        const Index n = sph_.n_;
        flag_.resize(n);
        at_.resize(n);
        Space::for_each(n, coupling::CarriedFlags{sph_.fem_row_.data(), flag_.data()});
        const Index m = Space::exclusive_scan(n, flag_.data(), at_.data());
        picked_.resize(m);
        Space::for_each(n, coupling::GatherCarriedLoads{sph_.view(), sph_.fem_row_.data(),
                                                        flag_.data(), at_.data(), picked_.data()});
        std::vector<coupling::CarriedLoad> out(static_cast<std::size_t>(m));
        picked_.download(out.data());
        return out;
    }

    void remove_rows(const std::vector<std::uint8_t>& dead) override {
        upload(dead_, dead);
        sph_.remove_where(
            coupling::KeepOffErodedElements{sph_.fem_row_.data(), dead_.data(), nullptr});
    }

    void resurface(const std::vector<Vec3>& facet_normal, const std::vector<Real>& depth) override {
        sph_.upload_once();
        upload(normal_, facet_normal);
        upload(depth_, depth);
        Space::for_each(
            sph_.n_, coupling::CarriedSurface{sph_.view(), rows(), normal_.data(), depth_.data()});
        Space::synchronize();
    }

    ParticleId append(const std::vector<particles::NewParticle>& fresh,
                      const std::vector<rigid::ShellPoint>& walls,
                      const std::vector<std::int32_t>& rows) override {
        return sph_.append_particles(fresh, walls, {}, rows);
    }

    std::size_t bytes() const {
        return carrier_.bytes() + x_.bytes() + v_.bytes() + normal_.bytes() + flag_.bytes() +
               at_.bytes() + picked_.bytes() + dead_.bytes() + depth_.bytes();
    }

private:
    template <class T> static void upload(Buffer<T>& b, const std::vector<T>& v) {
        b.upload(v.data(), Index(v.size()));
    }
    coupling::FemRows rows() const { return {sph_.fem_row_.data(), carrier_.data()}; }

    ResidentSph<Space>& sph_;
    coupling::SphFemCoupling& coupling_; // on the host: the rows and the id -> row map
    Buffer<coupling::FemCarrier> carrier_;
    Buffer<Vec3> x_, v_, normal_;
    Buffer<Index> flag_, at_;
    Buffer<coupling::CarriedLoad> picked_;
    Buffer<std::uint8_t> dead_;
    Buffer<Real> depth_;
};

} // namespace debrisflow::sph
