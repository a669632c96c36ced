#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/particles/particle_set.hpp"
#include <string>
#include <vector>

namespace debrisflow::fem {
class FemSolver;
}

namespace debrisflow::io {

// Writes particle frames as VTK XML UnstructuredGrid (.vtu, raw appended binary) and keeps a
// ParaView collection (.pvd) listing every frame with its time.
class VtkSeries {
public:
    explicit VtkSeries(std::string dir, std::string base = "particles");
    // Fields: velocity, acceleration, pressure, density, type (0 fluid, 1 boundary), group, id.
    void write(const particles::ParticleSet& set, Real t);
    // Grain fields: velocity, angular_velocity, force, radius, material, id.
    void write(const dem::GrainSet& grains, Real t);
    // Rigid-body surface points (contact samples, vertices): velocity, radius, body index.
    void write(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
               const std::vector<float>& radius, const std::vector<std::int32_t>& body, Real t);
    // Points with named scalar fields (e.g. panel centres of a pressure map).
    void write(const std::vector<Vec3>& x,
               const std::vector<std::pair<std::string, std::vector<float>>>& scalars, Real t);
    // Solid meshes (all FEM solids): current node positions; point data displacement and
    // velocity; cell data stress and strain (xx, yy, zz, xy, yz, zx), von_mises,
    // max_principal_strain, damage, eroded and solid index.
    void write(const fem::FemSolver& fem, Real t);
    int frames() const { return int(entries_.size()); }
    // The frames written so far (time, file); resume() continues a series from a checkpoint
    // with these frames (later files are overwritten as the run writes them again).
    using Entries = std::vector<std::pair<Real, std::string>>;
    const Entries& entries() const { return entries_; }
    void resume(Entries e) {
        entries_ = std::move(e);
        write_pvd();
    }

    struct Block {
        std::string name, type;
        int components;
        std::vector<char> bytes;
    };

private:
    void write_frame(std::size_t n, Block points, const std::vector<Block>& point_data,
                     const std::string& scalars, Real t);
    // Any unstructured grid: cells = connectivity, offsets, types blocks.
    void write_grid(std::size_t n, std::size_t cells_count, Block points,
                    const std::vector<Block>& point_data, const std::vector<Block>& cells,
                    const std::vector<Block>& cell_data, const std::string& scalars, Real t);
    void write_pvd() const;
    std::string dir_, base_;
    std::vector<std::pair<Real, std::string>> entries_;
};

} // namespace debrisflow::io
