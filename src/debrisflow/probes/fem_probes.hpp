#pragma once
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// probes/<name>.csv: displacement of a deformable solid at a node set (mean over its nodes,
// e.g. "dam.crest") or at the node nearest to `position` [m].
class FemDisplacementProbe : public Probe {
public:
    static constexpr std::string_view type_name = "fem_displacement";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: set or position
    // set: "<solid>.<set>" or "<solid>" ("": the node nearest to position).
    FemDisplacementProbe(std::string name, Real every, std::string set, Vec3 position, int dim)
        : Probe(std::move(name), every), set_(std::move(set)), position_(position), dim_(dim) {}
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // the FEM solids

private:
    std::string set_;
    Vec3 position_;
    int dim_;
    std::vector<std::int32_t> nodes_; // resolved at the first sample
};

// probes/<name>.csv: total interface load on the solids by source (fluid, grains, bodies) and
// their sum [N] (2D: N/m); the grains' load is their mean over the step (impulse / dt).
class FemForceProbe : public Probe {
public:
    static constexpr std::string_view type_name = "fem_force";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // no keys
    FemForceProbe(std::string name, Real every, int dim)
        : Probe(std::move(name), every), unit_(dim == 2 ? "N/m" : "N") {}
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // the FEM solids

private:
    std::string unit_;
};

// probes/<name>.csv: distribution of the coupling load (fluid + grains + bodies) over a face:
// the component along `normal` summed over the nodes of `set` in `bins` equal bands of their
// reference coordinate along `axis` (e.g. the upstream face of a dam by height) [N] (2D: N/m),
// and the total.
class FemFaceLoadProbe : public Probe {
public:
    static constexpr std::string_view type_name = "fem_face_load";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: set, normal, axis, bins
    FemFaceLoadProbe(std::string name, Real every, std::string set, Vec3 normal, int axis, int bins,
                     int dim)
        : Probe(std::move(name), every), set_(std::move(set)), unit_(dim == 2 ? "N/m" : "N"),
          normal_(normal), axis_(axis), bins_(bins) {}
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // the FEM solids

private:
    std::string set_, unit_;
    Vec3 normal_;
    int axis_, bins_;
    std::vector<Real> edges_;               // bin edges, resolved at the first sample
    std::vector<std::int32_t> nodes_, bin_; // set nodes and their bins
};

} // namespace debrisflow::probes
