#include "debrisflow/coupling/sph_fem.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/sph_params.hpp"
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::coupling {

namespace {

struct Box {
    Vec3 lo, hi;
    bool holds(Vec3 p, Real pad) const {
        for (int k = 0; k < 3; ++k)
            if (p[k] < lo[k] - pad || p[k] > hi[k] + pad) return false;
        return true;
    }
};

} // namespace

std::vector<Exchange> SphFemCoupling::exchanges() const {
    return {{"sph", "fem",
             "fluid force m_k a_k on the carried boundary particles, to the nodes "
             "with weights N_a(xi)",
             When::fem_loads},
            {"fem", "sph", "node positions and velocities, to the carried boundary particles",
             When::fem_motion},
            {"fem", "sph",
             "eroded elements remove their particles; the exposed surface gains particles",
             When::between_steps}};
}

void SphFemCoupling::connect() {
    fem_.add_load_source([this](std::vector<Vec3>& f) {
        collect_forces(f);
        fem_.report_interface_force("fluid", last_force());
    });
    fem_.add_surface_mover([this](Real ahead) { move_particles(ahead); });
}

std::string SphFemCoupling::erosion_note(Real t, std::size_t removed, std::size_t added) const {
    if (removed == 0 && added == 0) return {};
    return fmt::format("t = {:.6g} s: {} eroded elements; {} boundary particles removed, {} "
                       "added on the exposed surface",
                       t, fem_.eroded_elements(), removed, added);
}

SphFemCoupling::SphFemCoupling(fem::FemSolver& fem, particles::ParticleSet& set, Real dp,
                               int layers, Real rho, int dim)
    : fem_(fem), set_(set), dim_(dim), thickness_(layers * dp), rho_(rho),
      mass_(rho * sph::lattice_volume(dp, dim)) {
    facets_ = fem::boundary_facets(fem);
    const auto& X = fem.reference();
    // Element bounding boxes (reference configuration).
    std::vector<std::vector<Box>> boxes(fem.solids().size());
    for (std::size_t s = 0; s < fem.solids().size(); ++s) {
        const auto& so = fem.solids()[s];
        const int nn = fem::nodes_of(so.type);
        for (std::size_t e = 0; e < so.volume.size(); ++e) {
            Box b{X[std::size_t(so.conn[e * std::size_t(nn)])],
                  X[std::size_t(so.conn[e * std::size_t(nn)])]};
            for (int a = 1; a < nn; ++a) {
                const Vec3 p = X[std::size_t(so.conn[e * std::size_t(nn) + std::size_t(a)])];
                for (int k = 0; k < 3; ++k)
                    b.lo[k] = std::min(b.lo[k], p[k]), b.hi[k] = std::max(b.hi[k], p[k]);
            }
            boxes[s].push_back(b);
        }
    }
    // The live element holding reference point p.
    auto find = [&](Vec3 p, std::size_t& s_out, std::size_t& e_out, std::array<Real, 3>& xi) {
        for (std::size_t s = 0; s < boxes.size(); ++s)
            for (std::size_t e = 0; e < boxes[s].size(); ++e)
                if (!fem.solids()[s].eroded[e] && boxes[s][e].holds(p, 1e-9) &&
                    fem::locate(fem, s, e, p, xi)) {
                    s_out = s, e_out = e;
                    return true;
                }
        return false;
    };
    // Fluid inside a solid is removed.
    std::vector<std::uint8_t> keep(std::size_t(set.size()), 1);
    long removed = 0;
    for (Index i = 0; i < set.size(); ++i) {
        if (set.kind[i] != std::uint8_t(particles::Kind::fluid)) continue;
        std::size_t s, e;
        std::array<Real, 3> xi;
        if (find({set.x[i], set.y[i], set.z[i]}, s, e, xi)) keep[std::size_t(i)] = 0, ++removed;
    }
    if (removed > 0) set.compact(keep);
    // Samples on each solid's lattice: those within the boundary layer become particles, the
    // deeper ones wait until erosion exposes them.
    for (std::size_t s = 0; s < fem.solids().size(); ++s) {
        const auto& so = fem.solids()[s];
        Vec3 lo = X[std::size_t(so.first_node)], hi = lo;
        for (std::int32_t n = 0; n < so.nodes; ++n)
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], X[std::size_t(so.first_node + n)][k]);
                hi[k] = std::max(hi[k], X[std::size_t(so.first_node + n)][k]);
            }
        const int nx = int(std::floor((hi.x - lo.x) / dp + 1e-9));
        const int ny = dim == 2 ? 0 : int(std::floor((hi.y - lo.y) / dp + 1e-9));
        const int nz = int(std::floor((hi.z - lo.z) / dp + 1e-9));
        const std::size_t before = rows_.size();
        for (int k = 0; k <= nz; ++k)
            for (int j = 0; j <= ny; ++j)
                for (int i = 0; i <= nx; ++i) {
                    // Half-spacing offset: samples lie strictly inside, dp/2 under the surface.
                    const Vec3 p{lo.x + (i + Real(0.5)) * dp,
                                 dim == 2 ? 0 : lo.y + (j + Real(0.5)) * dp,
                                 lo.z + (k + Real(0.5)) * dp};
                    std::size_t hs, he;
                    std::array<Real, 3> xi;
                    if (!find(p, hs, he, xi) || hs != s) continue;
                    Row r{std::int32_t(s), std::int32_t(he), {}, -1, p};
                    const auto n = fem::shape_values(so.type, xi);
                    for (std::size_t a = 0; a < n.size(); ++a) r.n[a] = n[a];
                    Real depth;
                    r.facet = nearest_facet(p, depth);
                    if (r.facet >= 0 && depth < thickness_)
                        add_particle(r, depth);
                    else
                        hidden_.push_back(r);
                }
        if (rows_.size() == before)
            throw InputError(fmt::format("solid '{}' is thinner than the fluid's dp = {} m: no "
                                         "boundary particles",
                                         so.name, dp));
    }
    eroded_seen_ = fem.eroded_elements();
    refresh_members();
}

std::int32_t SphFemCoupling::nearest_facet(Vec3 X, Real& depth) const {
    depth = std::numeric_limits<Real>::max();
    std::int32_t nearest = -1;
    for (std::size_t f = 0; f < facets_.size(); ++f) {
        const Real d = fem::facet_distance(facets_[f], fem_.reference(), X);
        if (d < depth) depth = d, nearest = std::int32_t(f);
    }
    return nearest;
}

FemCarrier SphFemCoupling::carrier_of(const Row& r) const {
    const auto& so = fem_.solids()[std::size_t(r.solid)];
    const int nn = fem::nodes_of(so.type);
    FemCarrier c{};
    c.nodes = nn;
    c.facet = r.facet;
    for (int a = 0; a < nn; ++a) {
        c.node[a] = so.conn[std::size_t(r.element) * std::size_t(nn) + std::size_t(a)];
        c.n[a] = r.n[std::size_t(a)];
    }
    return c;
}

particles::NewParticle SphFemCoupling::new_particle(const Row& r, Real depth,
                                                    rigid::ShellPoint& wall) const {
    const FemCarrier c = carrier_of(r);
    Vec3 p{}, u{};
    for (int a = 0; a < c.nodes; ++a) {
        p = p + c.n[a] * fem_.positions()[std::size_t(c.node[a])];
        u = u + c.n[a] * fem_.velocities()[std::size_t(c.node[a])];
    }
    if (dim_ == 2) p.y = 0, u.y = 0;
    wall = {p, fem::facet_normal(facets_[std::size_t(r.facet)], fem_.positions()), depth};
    return {p, u, rho_, mass_, particles::Kind::boundary, std::int16_t(-1)};
}

void SphFemCoupling::add_particle(const Row& r, Real depth) {
    rigid::ShellPoint wall;
    const auto q = new_particle(r, depth, wall);
    set_.add(q.pos, q.vel, q.rho, q.mass, q.kind, q.group);
    set_.set_wall(set_.size() - 1, wall.n, wall.depth);
    row_of_id_.emplace(set_.id.back(), std::uint32_t(rows_.size()));
    rows_.push_back(r);
    carriers_.push_back(carrier_of(r));
}

void SphFemCoupling::attach(FemParticles* particles) {
    resident_ = particles; // which takes the carriers when it takes the particles over
}

std::vector<Vec3> SphFemCoupling::facet_normals() const {
    std::vector<Vec3> n(facets_.size());
    for (std::size_t f = 0; f < facets_.size(); ++f)
        n[f] = fem::facet_normal(facets_[f], fem_.positions());
    return n;
}

void SphFemCoupling::refresh_members() {
    if (set_.layout_version() == layout_seen_) return;
    layout_seen_ = set_.layout_version();
    members_.clear();
    member_rows_.clear();
    for (Index i = 0; i < set_.size(); ++i) {
        const auto it = row_of_id_.find(set_.id[i]);
        if (it == row_of_id_.end()) continue;
        members_.push_back(i);
        member_rows_.push_back(it->second);
    }
}

void SphFemCoupling::move_particles(Real ahead) {
    const auto normals = facet_normals();
    const auto& x = fem_.positions();
    const auto& v = fem_.velocities();
    if (resident_) return resident_->move(x, v, normals, ahead);
    refresh_members();
    const auto pv = set_.view();
    const Index* mem = members_.data();
    const std::uint32_t* rows = member_rows_.data();
    const FemCarrier* carriers = carriers_.data();
    const Vec3 *xp = x.data(), *vp = v.data(), *np = normals.data();
    const bool two_d = dim_ == 2;
    exec::for_each(Index(members_.size()), [=](Index k) {
        place_on_element(pv, mem[k], carriers[rows[k]], xp, vp, np, ahead, two_d);
    });
}

std::vector<std::uint8_t> SphFemCoupling::eroded_keep_mask() {
    const long eroded = fem_.eroded_elements();
    if (eroded == eroded_seen_) return {};
    eroded_seen_ = eroded;
    surface_stale_ = true;
    refresh_members();
    std::vector<std::uint8_t> keep(std::size_t(set_.size()), 1);
    bool any = false;
    for (std::size_t k = 0; k < members_.size(); ++k) {
        const Row& r = rows_[member_rows_[k]];
        if (!fem_.solids()[std::size_t(r.solid)].eroded[std::size_t(r.element)]) continue;
        keep[std::size_t(members_[k])] = 0;
        row_of_id_.erase(set_.id[members_[k]]);
        any = true;
    }
    if (!any) return {};
    layout_seen_ = ~std::uint64_t(0); // members are found again after the removal
    return keep;
}

std::vector<std::uint8_t> SphFemCoupling::newly_dead_rows() {
    const long eroded = fem_.eroded_elements();
    if (eroded == eroded_seen_) return {};
    eroded_seen_ = eroded;
    surface_stale_ = true;
    std::vector<std::uint8_t> dead(rows_.size(), 0);
    bool any = false;
    for (auto it = row_of_id_.begin(); it != row_of_id_.end();) {
        const Row& r = rows_[it->second];
        if (fem_.solids()[std::size_t(r.solid)].eroded[std::size_t(r.element)]) {
            dead[it->second] = 1;
            any = true;
            it = row_of_id_.erase(it);
        } else {
            ++it;
        }
    }
    if (!any) return {};
    return dead;
}

std::size_t SphFemCoupling::expose_new_surface() {
    if (!surface_stale_) return 0;
    surface_stale_ = false;
    facets_ = fem::boundary_facets(fem_);
    // Survivors: the nearest facet (normal) and depth now refer to the new surface.
    if (resident_) {
        std::vector<Real> depth(rows_.size(), Real(0));
        for (const auto& [id, row] : row_of_id_) {
            Row& r = rows_[row];
            r.facet = nearest_facet(r.X, depth[row]);
            carriers_[row].facet = r.facet;
        }
        resident_->carriers_changed();
        resident_->resurface(facet_normals(), depth);
    } else {
        refresh_members();
        for (std::size_t k = 0; k < members_.size(); ++k) {
            Row& r = rows_[member_rows_[k]];
            Real depth;
            r.facet = nearest_facet(r.X, depth);
            carriers_[member_rows_[k]].facet = r.facet;
            set_.set_wall(members_[k],
                          fem::facet_normal(facets_[std::size_t(r.facet)], fem_.positions()),
                          depth);
        }
    }
    // Hidden samples of live elements that the new surface brings within the layer.
    std::vector<Row> still_hidden;
    std::vector<particles::NewParticle> fresh;
    std::vector<rigid::ShellPoint> walls;
    std::vector<std::int32_t> fresh_rows;
    std::size_t added = 0;
    for (Row& r : hidden_) {
        if (fem_.solids()[std::size_t(r.solid)].eroded[std::size_t(r.element)]) continue;
        Real depth;
        r.facet = nearest_facet(r.X, depth);
        if (depth >= thickness_) {
            still_hidden.push_back(r);
        } else if (resident_) {
            walls.emplace_back();
            fresh.push_back(new_particle(r, depth, walls.back()));
            fresh_rows.push_back(std::int32_t(rows_.size()));
            rows_.push_back(r);
            carriers_.push_back(carrier_of(r));
            ++added;
        } else {
            add_particle(r, depth);
            ++added;
        }
    }
    hidden_ = std::move(still_hidden);
    if (resident_ && !fresh.empty()) {
        resident_->carriers_changed();
        const ParticleId first = resident_->append(fresh, walls, fresh_rows);
        for (std::size_t j = 0; j < fresh_rows.size(); ++j)
            row_of_id_.emplace(first + ParticleId(j), std::uint32_t(fresh_rows[j]));
    }
    if (added > 0) layout_seen_ = ~std::uint64_t(0);
    return added;
}

void SphFemCoupling::collect_forces(std::vector<Vec3>& f) {
    std::vector<CarriedLoad> loads;
    if (resident_) {
        loads = resident_->loads();
    } else {
        refresh_members();
        const auto pv = set_.view();
        loads.reserve(members_.size());
        for (std::size_t k = 0; k < members_.size(); ++k)
            loads.push_back({std::int32_t(member_rows_[k]), carried_load(pv, members_[k])});
    }
    // F_a += N_a(xi) m_k a_k, in index order
    Vec3 total{};
    for (const CarriedLoad& l : loads) {
        total = total + l.force;
        const FemCarrier& c = carriers_[std::size_t(l.row)];
        for (int a = 0; a < c.nodes; ++a)
            f[std::size_t(c.node[a])] = f[std::size_t(c.node[a])] + c.n[a] * l.force;
    }
    last_force_ = total;
}

} // namespace debrisflow::coupling
