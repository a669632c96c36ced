#include "debrisflow/io/vtk_writer.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/fem/fem_solver.hpp"
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace debrisflow::io {

namespace {

using Block = VtkSeries::Block;

template <class T>
Block make_block(std::string name, std::string type, int comps, const std::vector<T>& data) {
    Block b{std::move(name), std::move(type), comps, {}};
    b.bytes.resize(data.size() * sizeof(T));
    std::memcpy(b.bytes.data(), data.data(), b.bytes.size());
    return b;
}

} // namespace

VtkSeries::VtkSeries(std::string dir, std::string base)
    : dir_(std::move(dir)), base_(std::move(base)) {
    std::filesystem::create_directories(dir_);
}

void VtkSeries::write(const particles::ParticleSet& s, Real t) {
    const std::size_t n = std::size_t(s.size());
    std::vector<float> pos(3 * n), vel(3 * n), acc(3 * n), p(n), rho(n), mu(n);
    std::vector<std::int32_t> group(n);
    std::vector<std::uint8_t> kind(s.kind);
    std::vector<std::uint64_t> id(s.id);
    for (std::size_t i = 0; i < n; ++i) {
        pos[3 * i] = float(s.x[i]);
        pos[3 * i + 1] = float(s.y[i]);
        pos[3 * i + 2] = float(s.z[i]);
        vel[3 * i] = float(s.vx[i]);
        vel[3 * i + 1] = float(s.vy[i]);
        vel[3 * i + 2] = float(s.vz[i]);
        acc[3 * i] = float(s.ax[i]);
        acc[3 * i + 1] = float(s.ay[i]);
        acc[3 * i + 2] = float(s.az[i]);
        p[i] = float(s.p[i]);
        rho[i] = float(s.rho[i]);
        mu[i] = float(s.mu[i]);
        group[i] = s.group[i];
    }
    std::vector<Block> point_data;
    point_data.push_back(make_block("velocity", "Float32", 3, vel));
    point_data.push_back(make_block("acceleration", "Float32", 3, acc));
    point_data.push_back(make_block("pressure", "Float32", 1, p));
    point_data.push_back(make_block("density", "Float32", 1, rho));
    point_data.push_back(make_block("apparent_viscosity", "Float32", 1, mu)); // [Pa s]
    point_data.push_back(make_block("type", "UInt8", 1, kind));
    point_data.push_back(make_block("group", "Int32", 1, group));
    point_data.push_back(make_block("id", "UInt64", 1, id));
    write_frame(n, make_block("points", "Float32", 3, pos), point_data, "pressure", t);
}

void VtkSeries::write(const dem::GrainSet& g, Real t) {
    const std::size_t n = std::size_t(g.size());
    std::vector<float> pos(3 * n), vel(3 * n), spin(3 * n), force(3 * n), radius(n);
    std::vector<std::uint8_t> mat(g.material);
    std::vector<std::uint32_t> id(g.id);
    for (std::size_t i = 0; i < n; ++i) {
        const float p[3] = {float(g.pos[i].x), float(g.pos[i].y), float(g.pos[i].z)};
        const float v[3] = {float(g.vel[i].x), float(g.vel[i].y), float(g.vel[i].z)};
        const float w[3] = {float(g.spin[i].x), float(g.spin[i].y), float(g.spin[i].z)};
        const float f[3] = {float(g.force[i].x), float(g.force[i].y), float(g.force[i].z)};
        for (int d = 0; d < 3; ++d) {
            pos[3 * i + std::size_t(d)] = p[d];
            vel[3 * i + std::size_t(d)] = v[d];
            spin[3 * i + std::size_t(d)] = w[d];
            force[3 * i + std::size_t(d)] = f[d];
        }
        radius[i] = float(g.radius[i]);
    }
    std::vector<Block> point_data;
    point_data.push_back(make_block("velocity", "Float32", 3, vel));
    point_data.push_back(make_block("angular_velocity", "Float32", 3, spin));
    point_data.push_back(make_block("force", "Float32", 3, force));
    point_data.push_back(make_block("radius", "Float32", 1, radius));
    point_data.push_back(make_block("material", "UInt8", 1, mat));
    point_data.push_back(make_block("id", "UInt32", 1, id));
    write_frame(n, make_block("points", "Float32", 3, pos), point_data, "radius", t);
}

void VtkSeries::write(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                      const std::vector<float>& radius, const std::vector<std::int32_t>& body,
                      Real t) {
    const std::size_t n = x.size();
    std::vector<float> pos(3 * n), vel(3 * n);
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) {
            pos[3 * i + std::size_t(d)] = float(x[i][d]);
            vel[3 * i + std::size_t(d)] = float(v[i][d]);
        }
    std::vector<Block> point_data;
    point_data.push_back(make_block("velocity", "Float32", 3, vel));
    point_data.push_back(make_block("radius", "Float32", 1, radius));
    point_data.push_back(make_block("body", "Int32", 1, body));
    write_frame(n, make_block("points", "Float32", 3, pos), point_data, "radius", t);
}

void VtkSeries::write(const std::vector<Vec3>& x,
                      const std::vector<std::pair<std::string, std::vector<float>>>& scalars,
                      Real t) {
    const std::size_t n = x.size();
    std::vector<float> pos(3 * n);
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) pos[3 * i + std::size_t(d)] = float(x[i][d]);
    std::vector<Block> point_data;
    for (const auto& [name, values] : scalars)
        point_data.push_back(make_block(name, "Float32", 1, values));
    write_frame(n, make_block("points", "Float32", 3, pos), point_data,
                scalars.empty() ? "" : scalars.front().first, t);
}

void VtkSeries::write_frame(std::size_t n, Block points, const std::vector<Block>& point_data,
                            const std::string& scalars, Real t) {
    std::vector<std::int32_t> conn(n), offs(n);
    std::vector<std::uint8_t> cell_types(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
        conn[i] = std::int32_t(i);
        offs[i] = std::int32_t(i + 1);
    }
    std::vector<Block> cells;
    cells.push_back(make_block("connectivity", "Int32", 1, conn));
    cells.push_back(make_block("offsets", "Int32", 1, offs));
    cells.push_back(make_block("types", "UInt8", 1, cell_types));
    write_grid(n, n, std::move(points), point_data, cells, {}, scalars, t);
}

void VtkSeries::write(const fem::FemSolver& fem, Real t) {
    const std::size_t n = fem.nodes();
    std::vector<float> pos(3 * n), disp(3 * n), vel(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 u = fem.displacement(i);
        for (int d = 0; d < 3; ++d) {
            pos[3 * i + std::size_t(d)] = float(fem.positions()[i][d]);
            disp[3 * i + std::size_t(d)] = float(u[d]);
            vel[3 * i + std::size_t(d)] = float(fem.velocities()[i][d]);
        }
    }
    std::vector<std::int32_t> conn, offs;
    std::vector<std::uint8_t> types, eroded;
    std::vector<float> stress, strain, mises, principal, damage;
    std::vector<std::int32_t> solid;
    for (std::size_t s = 0; s < fem.solids().size(); ++s) {
        const auto& so = fem.solids()[s];
        const int nn = fem::nodes_of(so.type);
        for (std::size_t e = 0; e < so.volume.size(); ++e) {
            for (int a = 0; a < nn; ++a)
                conn.push_back(so.conn[e * std::size_t(nn) + std::size_t(a)]);
            offs.push_back(std::int32_t(conn.size()));
            types.push_back(std::uint8_t(fem::vtk_cell_type(so.type)));
            const auto r = fem.element_result(s, e);
            for (int k = 0; k < 6; ++k) {
                stress.push_back(float(r.stress[std::size_t(k)]));
                strain.push_back(float(r.strain[std::size_t(k)]));
            }
            mises.push_back(float(r.von_mises));
            principal.push_back(float(r.max_principal_strain));
            damage.push_back(float(r.damage));
            eroded.push_back(r.eroded ? 1 : 0);
            solid.push_back(std::int32_t(s));
        }
    }
    std::vector<Block> point_data, cells, cell_data;
    point_data.push_back(make_block("displacement", "Float32", 3, disp));
    point_data.push_back(make_block("velocity", "Float32", 3, vel));
    cells.push_back(make_block("connectivity", "Int32", 1, conn));
    cells.push_back(make_block("offsets", "Int32", 1, offs));
    cells.push_back(make_block("types", "UInt8", 1, types));
    cell_data.push_back(make_block("stress", "Float32", 6, stress));   // [Pa]
    cell_data.push_back(make_block("strain", "Float32", 6, strain));   // tensor [-]
    cell_data.push_back(make_block("von_mises", "Float32", 1, mises)); // [Pa]
    cell_data.push_back(make_block("max_principal_strain", "Float32", 1, principal));
    cell_data.push_back(make_block("damage", "Float32", 1, damage));
    cell_data.push_back(make_block("eroded", "UInt8", 1, eroded));
    cell_data.push_back(make_block("solid", "Int32", 1, solid));
    write_grid(n, types.size(), make_block("points", "Float32", 3, pos), point_data, cells,
               cell_data, "displacement", t);
}

void VtkSeries::write_grid(std::size_t n, std::size_t cells_count, Block points,
                           const std::vector<Block>& point_data, const std::vector<Block>& cells,
                           const std::vector<Block>& cell_data, const std::string& scalars,
                           Real t) {
    const std::string file = fmt::format("{}_{:05d}.vtu", base_, entries_.size());
    std::ofstream out(dir_ + "/" + file, std::ios::binary);
    if (!out) throw InputError("cannot write " + dir_ + "/" + file);
    std::uint64_t offset = 0;
    auto header = [&](const Block& b) {
        std::string s = fmt::format("<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                                    "format=\"appended\" offset=\"{}\"/>\n",
                                    b.type, b.name, b.components, offset);
        offset += sizeof(std::uint64_t) + b.bytes.size();
        return s;
    };
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
           "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n";
    out << fmt::format("<FieldData><DataArray type=\"Float64\" Name=\"TimeValue\" "
                       "NumberOfTuples=\"1\" format=\"ascii\">{:.9g}</DataArray></FieldData>\n",
                       t);
    out << fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, cells_count);
    out << "<PointData Scalars=\"" << scalars << "\" Vectors=\"velocity\">\n";
    for (const auto& b : point_data) out << header(b);
    out << "</PointData>\n";
    if (!cell_data.empty()) {
        out << "<CellData>\n";
        for (const auto& b : cell_data) out << header(b);
        out << "</CellData>\n";
    }
    out << "<Points>\n" << header(points) << "</Points>\n<Cells>\n";
    for (const auto& b : cells) out << header(b);
    out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
    auto raw = [&](const Block& b) {
        const std::uint64_t size = b.bytes.size();
        out.write(reinterpret_cast<const char*>(&size), sizeof size);
        out.write(b.bytes.data(), std::streamsize(b.bytes.size()));
    };
    for (const auto& b : point_data) raw(b);
    for (const auto& b : cell_data) raw(b);
    raw(points);
    for (const auto& b : cells) raw(b);
    out << "\n</AppendedData>\n</VTKFile>\n";
    entries_.emplace_back(t, file);
    write_pvd();
}

void VtkSeries::write_pvd() const {
    std::ofstream out(dir_ + "/" + base_ + ".pvd");
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<Collection>\n";
    for (const auto& [t, f] : entries_)
        out << fmt::format("  <DataSet timestep=\"{:.9g}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                           t, f);
    out << "</Collection>\n</VTKFile>\n";
}

} // namespace debrisflow::io
