#pragma once
#include "debrisflow/io/vtk_writer.hpp"
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// Load map on one face of a structure, as a grid of flush-mounted load cells reads it. The face
// is the side of the wall's bounding box that `normal` (into the fluid) points out of (for a
// tank, whose box is the inside, the side the normal points into the tank from), tiled by
// n_u x n_v panels over the box in the two other axes (2D: n_u panels along the in-plane axis).
//  - Fluid: the wall's boundary particles that stand for this face (their wall normal is the
//    face's), each with its load -m_k a_k . n; a particle column owns the tile dp x dp (2D:
//    dp x 1 m) of the face around it. Load and tile are split between panels by overlap.
//  - Grains and bodies: each contact's force on the wall, -F . n, in the panel holding its
//    contact point (contacts on this face only).
// The fluid's particles come as rows of the wall's particles (FluidReader::rows), in the order
// of their ids, wherever the particles are stored.
// Panel pressure = panel load / panel area, the area being the particle tiles inside the panel
// (the face's real extent, so that panels narrower than dp or not a multiple of it read the
// same pressure), or the panel's geometric area where no particle tiles it (no fluid).
class PressureMapProbe : public Probe {
public:
    static constexpr std::string_view type_name = "pressure_map";
    static std::unique_ptr<Probe>
    from_config(const ProbeSetup& s); // keys: wall, axis, normal, panels
    // The face of wall `wall` (c.walls) normal to `axis`, tiled by nu x nv panels.
    PressureMapProbe(std::string name, Real every, int wall, int axis, Vec3 normal, int nu, int nv,
                     const io::CaseSpec& c);
    int contact_wall() const override { return wall_; }
    bool reads_particles() const override { return false; } // the wall's rows, ctx.fluid
    std::vector<std::string> columns() const override;
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    void open_extra(const std::string& dir) override;
    void after_sample(Real t, const std::vector<Real>& values) override;
    void extra_state(checkpoint::Archive& ar) override;
    // Area of each panel in the last sample [m2] (2D: per metre), column order.
    const std::vector<Real>& areas() const { return area_; }

private:
    // Adds load * overlap / tile to the panels that the tile [u0, u1] x [v0, v1] covers.
    void spread(Real u0, Real u1, Real v0, Real v1, Real load, Real tile_area,
                std::vector<Real>& force, std::vector<Real>& area) const;
    // The panel holding the face point (u, v), or -1 off the face.
    long panel_of(Real u, Real v) const;
    // The wall's particles' normals and depths, by id (geometry_), read once.
    void wall_geometry(const sph::SphSolver& solver);
    struct WallParticle {
        ParticleId id;
        Vec3 normal; // into the fluid
        Real depth;  // behind the wall's surface
    };
    std::vector<WallParticle> geometry_; // in the order of the ids
    bool geometry_read_ = false;
    std::unique_ptr<io::VtkSeries> vtk_;
    io::VtkSeries::Entries resume_frames_; // frames of a restored run, for open_extra
    int wall_, axis_, u_, v_, nu_, nv_;
    Vec3 normal_, lo_, hi_;
    Real face_, depth_; // the face's coordinate along axis; half the box's depth there
    Real du_, dv_;      // panel size along u and v
    Real reach_;        // side-face particles within this of the face load it: min(depth, 2h)
    Real dp_, grain_scale_;
    int dim_;
    std::vector<Real> force_, area_;
};

} // namespace debrisflow::probes
