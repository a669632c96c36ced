// Checkpoint and restart of a Simulation: one symmetric pass over its state
// (checkpoint/archive.hpp), written safely to OUT/checkpoint/ (checkpoint/checkpoint_file.hpp).
#include "debrisflow/app/simulation.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/checkpoint/checkpoint_file.hpp"
#include "debrisflow/core/stopwatch.hpp"
#include "debrisflow/exec/parallel.hpp"
#include <filesystem>
#include <fmt/format.h>
#include <sstream>

namespace debrisflow::app {

namespace {

// The first line where two texts differ, for a message ("" when equal).
std::string first_difference(const std::string& a, const std::string& b) {
    std::istringstream sa(a), sb(b);
    std::string la, lb;
    for (int line = 1;; ++line) {
        const bool ea = !std::getline(sa, la), eb = !std::getline(sb, lb);
        if (ea && eb) return {};
        if (ea || eb || la != lb)
            return fmt::format("line {} of the resolved case: checkpoint '{}', this case '{}'",
                               line, ea ? "(end)" : la.substr(0, 80),
                               eb ? "(end)" : lb.substr(0, 80));
    }
}

} // namespace

void Simulation::state(checkpoint::Archive& ar) {
    ar.section("debrisflow case");
    std::string name = spec_.name, physics = spec_.physics_toml;
    ar(name, physics);
    if (ar.is_loading() && physics != spec_.physics_toml)
        ar.fail(fmt::format("was written for another case (only [output] and time.end may "
                            "change on a restart); first difference at {}",
                            first_difference(physics, spec_.physics_toml)));
    ar.section("time loop");
    std::int32_t threads = exec::max_threads();
    std::uint8_t settled = settled_;
    ar(t_, resume_.step, resume_.first_dt, threads, settled, wall_removed_);
    resume_.threads = threads;
    settled_ = settled != 0;
    if (wall_removed_.size() != spec_.walls.size()) ar.fail("its wall count differs");
    if (solver_) solver_->state(ar);
    if (dem_) dem_->state(ar);
    if (rigid_) rigid_->state(ar);
    if (fem_) fem_->state(ar);
    if (sph_fem_) sph_fem_->state(ar);
    if (sph_dem_) sph_dem_->state(ar);
    if (dem_fem_) dem_fem_->state(ar);
    if (dem_body_) dem_body_->state(ar);
    if (sph_body_) sph_body_->state(ar);
    for (auto& f : feeds_) f->state(ar);
    for (auto& f : rock_feeds_) f->state(ar);
    for (auto& in : inlets_) in->state(ar);
    for (auto& out : outlets_) out->state(ar);
    domain_exit_.state(ar);
    for (auto& p : probes_) p->state(ar);
    ar.section("vtk");
    const std::array<io::VtkSeries*, 4> series{vtk_.get(), vtk_grains_.get(), vtk_bodies_.get(),
                                               vtk_fem_.get()};
    for (std::size_t k = 0; k < series.size(); ++k) {
        if (!ar.is_loading())
            resume_.frames[k] = series[k] ? series[k]->entries() : io::VtkSeries::Entries{};
        checkpoint::io_frames(ar, resume_.frames[k]);
    }
    ar.section("end");
    ar.finish();
}

std::string Simulation::write_checkpoint(const std::string& out_dir, long step, Real t,
                                         Real first_dt) {
    double wall = 0;
    const std::string dir = out_dir + "/checkpoint";
    const std::string path = dir + "/" + checkpoint::file_name(step);
    auto ar = checkpoint::Archive::saving();
    {
        ScopedTimer timer(wall);
        std::filesystem::create_directories(dir);
        t_ = t;
        resume_.step = step;
        resume_.first_dt = first_dt;
        state(ar);
        checkpoint::write_file(path, ar.bytes());
        checkpoint::prune(dir, 2);
    }
    log_.line(fmt::format("t = {:.6g} s: checkpoint {} ({:.3g} MB, {:.2f} s)", t_, path,
                          double(ar.bytes().size()) / 1e6, wall));
    return path;
}

void Simulation::restore(const std::string& file) {
    auto ar = checkpoint::Archive::loading(checkpoint::read_file(file), file);
    state(ar);
    if (resident_) resident_->reload();         // the restored particles replace the resident ones
    if (resident_dem_) resident_dem_->reload(); // and the restored grains the resident ones
    resume_.active = true;
    resume_.file = file;
}

} // namespace debrisflow::app
