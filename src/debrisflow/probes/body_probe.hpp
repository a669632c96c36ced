#pragma once
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// Track of one rigid body: centre of mass, the named point (track_point), velocity, angular
// velocity, orientation relative to the input frame (quaternion and Z-Y'-X'' roll, pitch,
// yaw), and the fluid and contact forces on it, separately.
class BodyProbe : public Probe {
public:
    static constexpr std::string_view type_name = "body";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: body
    BodyProbe(std::string name, Real every, std::string body)
        : Probe(std::move(name), every), body_(std::move(body)) {}
    const std::string& body() const { return body_; }
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // the body solver's state

private:
    std::string body_;
    int index_ = -1;
};

} // namespace debrisflow::probes
