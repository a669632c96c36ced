#include "debrisflow/probes/pressure_map.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/probes/fluid_reader.hpp"
#include "debrisflow/rigid/body_solver.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::probes {

std::unique_ptr<Probe> PressureMapProbe::from_config(const ProbeSetup& s) {
    const auto& c = s.c;
    s.require(!c.fluids.empty() || c.has_dem || c.has_bodies(), "a fluid, grains or bodies");
    const int wall = s.wall();
    const auto& w = c.walls[std::size_t(wall)];
    if (w.type == "plane" || w.type == "stl")
        s.t.fail("wall", "a pressure map tiles a face of the wall's bounding box; wall \"" +
                             w.name + "\" is a " + w.type +
                             " (use a box, an open_tank or a [[structure]])");
    if (norm(w.velocity) > 0)
        s.t.fail("wall", "wall \"" + w.name +
                             "\" moves (its velocity); a pressure map tiles a face that stays put");
    const std::string a = s.t.choice("axis", {"x", "y", "z"}, "x");
    const int axis = a == "x" ? 0 : (a == "y" ? 1 : 2);
    const Vec3 normal = s.t.vec3("normal", c.dim, {});
    if (!(std::abs(norm(normal) - 1) < 1e-9) || std::abs(normal[axis]) != 1)
        s.t.fail("normal", "must be the unit vector along axis, pointing into the fluid");
    const auto n = s.t.reals("panels");
    if (n.size() != 2 || std::any_of(n.begin(), n.end(), [](Real v) {
            return !(v >= 1 && v <= 1000 && v == std::floor(v));
        }))
        s.t.fail("panels",
                 "expected [n_u, n_v] panels over the face, whole numbers from 1 to 1000");
    // 2D: one row across the unit width
    return std::make_unique<PressureMapProbe>(s.name(), s.every(), wall, axis, normal, int(n[0]),
                                              c.dim == 2 ? 1 : int(n[1]), c);
}

PressureMapProbe::PressureMapProbe(std::string name, Real every, int wall, int axis, Vec3 normal,
                                   int nu, int nv, const io::CaseSpec& c)
    : Probe(std::move(name), every), wall_(wall), axis_(axis), nu_(nu), nv_(nv), normal_(normal),
      lo_(c.walls[std::size_t(wall)].shape.min), hi_(c.walls[std::size_t(wall)].shape.max),
      dp_(c.dp), dim_(c.dim) {
    const auto& w = c.walls[std::size_t(wall)];
    // The face's axes: the two others in order (2D: u = the in-plane one, v = y, one panel).
    const int others[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    u_ = others[axis_][0], v_ = others[axis_][1];
    if (dim_ == 2) {
        u_ = axis_ == 0 ? 2 : 0, v_ = 1, nv_ = 1;
        lo_.y = Real(-0.5), hi_.y = Real(0.5);
    }
    // The face the fluid loads: a solid's (box, structure) side facing along the normal; a
    // tank's (open_tank, channel) inner side facing along it, i.e. the box's opposite side.
    const bool solid = w.type == "box" || w.type == "boxes";
    face_ = (normal_[axis_] < 0) == solid ? lo_[axis_] : hi_[axis_];
    du_ = (hi_[u_] - lo_[u_]) / nu_, dv_ = (hi_[v_] - lo_[v_]) / nv_;
    depth_ = Real(0.5) * (hi_[axis_] - lo_[axis_]);
    // side-face particles count within a kernel support of the face (and on its half)
    reach_ = std::min(depth_, c.fluids.empty() ? Real(0) : 2 * c.sph.h);
    // 2D grains are discs of the case's thickness: per metre, their force is F / thickness
    // (the fluid and bodies of a 2D case are per metre already).
    grain_scale_ = dim_ == 2 && c.dem.thickness > 0 ? 1 / c.dem.thickness : 1;
}

std::vector<std::string> PressureMapProbe::columns() const {
    std::vector<std::string> c;
    for (int i = 0; i < nu_; ++i)
        for (int j = 0; j < nv_; ++j) c.push_back(fmt::format("p_{}_{} [Pa]", i, j));
    return c;
}

long PressureMapProbe::panel_of(Real u, Real v) const {
    const Real fu = (u - lo_[u_]) / du_, fv = dim_ == 2 ? 0 : (v - lo_[v_]) / dv_;
    if (!(fu >= 0 && fu <= nu_ && fv >= 0 && fv <= nv_)) return -1;
    const int iu = std::min(int(fu), nu_ - 1), iv = std::min(int(fv), nv_ - 1);
    return long(iu) * nv_ + iv;
}

void PressureMapProbe::spread(Real u0, Real u1, Real v0, Real v1, Real load, Real tile_area,
                              std::vector<Real>& force, std::vector<Real>& area) const {
    const int a0 = std::max(0, int(std::floor((u0 - lo_[u_]) / du_)));
    const int a1 = std::min(nu_ - 1, int(std::floor((u1 - lo_[u_]) / du_)));
    const int b0 = dim_ == 2 ? 0 : std::max(0, int(std::floor((v0 - lo_[v_]) / dv_)));
    const int b1 = dim_ == 2 ? 0 : std::min(nv_ - 1, int(std::floor((v1 - lo_[v_]) / dv_)));
    const Real tu = u1 - u0, tv = v1 - v0;
    for (int a = a0; a <= a1; ++a) {
        const Real pu0 = lo_[u_] + a * du_;
        const Real ou = std::min(u1, pu0 + du_) - std::max(u0, pu0);
        if (ou <= 0) continue;
        for (int b = b0; b <= b1; ++b) {
            Real ov = tv;
            if (dim_ == 3) {
                const Real pv0 = lo_[v_] + b * dv_;
                ov = std::min(v1, pv0 + dv_) - std::max(v0, pv0);
                if (ov <= 0) continue;
            }
            const Real share = (ou / tu) * (ov / tv);
            const std::size_t k = std::size_t(a * nv_ + b);
            force[k] += share * load;
            area[k] += share * tile_area;
        }
    }
}

void PressureMapProbe::wall_geometry(const sph::SphSolver& solver) {
    // The host's copy: its ids and wall geometry agree, even where a resident backend has
    // moved on since it was last published (the geometry of a wall that stays put does not
    // change).
    const auto& s = solver.particles();
    for (Index i = 0; i < s.size(); ++i)
        if (s.kind[i] != 0 && s.group[i] == wall_)
            geometry_.push_back({s.id[i], {s.wnx[i], s.wny[i], s.wnz[i]}, s.wd[i]});
    std::sort(geometry_.begin(), geometry_.end(),
              [](const WallParticle& a, const WallParticle& b) { return a.id < b.id; });
    geometry_read_ = true;
}

std::vector<Real> PressureMapProbe::sample(Real, const ProbeContext& ctx) {
    const std::size_t np = std::size_t(nu_) * std::size_t(nv_);
    std::vector<Real> force(np, 0), tiles(np, 0);
    if (ctx.fluid) {
        if (!geometry_read_) wall_geometry(*ctx.sph);
        const Real half = Real(0.5) * dp_;
        const Real tile_area = dim_ == 2 ? dp_ : dp_ * dp_; // 2D: per metre of width
        // The wall's particles in the order of their ids, as is its geometry.
        auto g = geometry_.begin();
        for (const ParticleRow& r : ctx.fluid->rows(RowSelection::wall_particles(wall_))) {
            while (g != geometry_.end() && g->id < r.id) ++g;
            if (g == geometry_.end() || g->id != r.id) continue; // none: not a wall particle
            // This face's particles only (a solid's back face does not load its front panels):
            // those that stand for it, and those of the side faces within a kernel support of
            // it (and on its half of the wall), which the fluid in a corner pushes along the
            // normal too; the side faces' surface-layer column (a box's corner column) is part
            // of this face's extent.
            const Vec3 x = r.x;
            const Real along = dot(g->normal, normal_);
            const Real from_face = std::abs(x[axis_] - face_);
            const bool side = std::abs(along) < Real(0.5) && from_face < reach_;
            const bool edge = side && from_face < dp_;
            if (along < Real(0.5) && !side) continue;
            const Real load = -r.mass * dot(r.a, normal_);
            // the column's tile counts once, at its surface-layer particle (depth dp/2)
            const Real a = edge || (!side && g->depth < dp_) ? tile_area : 0;
            spread(x[u_] - half, x[u_] + half, x[v_] - half, x[v_] + half, load, a, force, tiles);
        }
    }
    auto add_contact = [&](const dem::ContactLoad& c, Real scale) {
        if (!(std::abs(c.point[axis_] - face_) <= depth_)) return; // another face of the wall
        const long k = panel_of(c.point[u_], c.point[v_]);
        if (k >= 0) force[std::size_t(k)] -= scale * dot(c.force, normal_);
    };
    if (ctx.dem)
        for (const auto& c : ctx.dem->walls().walls()[std::size_t(wall_)].contacts)
            add_contact(c, grain_scale_);
    if (ctx.rigid)
        for (const auto& c : ctx.rigid->wall_contacts(wall_)) add_contact(c, 1);
    const Real geometric = dim_ == 2 ? du_ : du_ * dv_; // 2D: per metre
    area_.resize(np);
    std::vector<Real> p(np);
    for (std::size_t k = 0; k < np; ++k) {
        // a sliver of tile (< 1 % of the panel) at the face's edge is not a panel's area
        area_[k] = tiles[k] > Real(0.01) * geometric ? tiles[k] : geometric;
        p[k] = force[k] / area_[k];
    }
    force_ = std::move(force);
    return p;
}

void PressureMapProbe::open_extra(const std::string& dir) {
    // dir is OUT/probes: the frames go beside the particle frames in OUT/vtk.
    vtk_ = std::make_unique<io::VtkSeries>(dir + "/../vtk", name());
    if (!resume_frames_.empty()) vtk_->resume(std::move(resume_frames_));
}

void PressureMapProbe::extra_state(checkpoint::Archive& ar) {
    io::VtkSeries::Entries frames = vtk_ ? vtk_->entries() : io::VtkSeries::Entries{};
    checkpoint::io_frames(ar, frames);
    if (ar.is_loading()) resume_frames_ = std::move(frames);
}

void PressureMapProbe::after_sample(Real t, const std::vector<Real>& p) {
    if (!vtk_) return;
    std::vector<Vec3> x;
    std::vector<float> pressure, force, area;
    for (int i = 0; i < nu_; ++i)
        for (int j = 0; j < nv_; ++j) {
            Vec3 c;
            c[axis_] = face_;
            c[u_] = lo_[u_] + (i + Real(0.5)) * du_;
            c[v_] = dim_ == 2 ? 0 : lo_[v_] + (j + Real(0.5)) * dv_;
            x.push_back(c);
            const std::size_t k = std::size_t(i * nv_ + j);
            pressure.push_back(float(p[k]));
            force.push_back(float(force_[k]));
            area.push_back(float(area_[k]));
        }
    vtk_->write(x, {{"pressure", pressure}, {"force", force}, {"area", area}}, t);
}

} // namespace debrisflow::probes
