#include "debrisflow/rigid/load_recorder.hpp"
#include <fmt/format.h>

namespace debrisflow::rigid {

void LoadRecorder::record(Real t, const std::vector<BodyLoads>& loads,
                          const std::vector<StrongestContact>& strongest) {
    if (t >= start_ + window_) { // a new window: the current one becomes the previous
        previous_ = t < start_ + 2 * window_ ? current_ : std::vector<Peak>{};
        current_.assign(current_.size(), Peak{});
        start_ = t;
    }
    current_.resize(loads.size());
    previous_.resize(loads.size());
    for (std::size_t b = 0; b < loads.size(); ++b) {
        Peak& p = current_[b];
        const Real f = norm(loads[b].fluid_force), c = norm(loads[b].contact_force);
        if (f > p.fluid) p.fluid = f, p.t_fluid = t;
        if (c > p.contact) {
            p.contact = c, p.t_contact = t;
            p.at_contact = b < strongest.size() ? strongest[b] : StrongestContact{};
        }
    }
}

std::string LoadRecorder::describe(std::size_t b, Real weight,
                                   const std::vector<std::string>& wall_names,
                                   const std::vector<std::string>& body_names) const {
    if (b >= current_.size()) return {};
    const Peak &c = current_[b], &p = previous_[b];
    const Peak& f = p.fluid > c.fluid ? p : c;
    const Peak& k = p.contact > c.contact ? p : c;
    std::string s =
        fmt::format("largest loads on it over the last {:.3g}-{:.3g} s (weight {:.3g} N): fluid "
                    "{:.4g} N at t = {:.6g} s, contacts {:.4g} N at t = {:.6g} s",
                    window_, 2 * window_, weight, f.fluid, f.t_fluid, k.contact, k.t_contact);
    const StrongestContact& sc = k.at_contact;
    if (sc.wall >= 0 || sc.body >= 0) {
        const std::string partner =
            sc.wall >= 0
                ? "wall '" +
                      (std::size_t(sc.wall) < wall_names.size() ? wall_names[sc.wall]
                                                                : std::to_string(sc.wall)) +
                      "'"
                : "body '" +
                      (std::size_t(sc.body) < body_names.size() ? body_names[sc.body]
                                                                : std::to_string(sc.body)) +
                      "'";
        s += fmt::format(
            " (strongest single contact: {:.4g} N, overlap {:.3g} mm, with {} at ({:.4g}, "
            "{:.4g}, {:.4g}) m)",
            sc.fn, 1e3 * sc.delta, partner, sc.point.x, sc.point.y, sc.point.z);
    }
    return s;
}

} // namespace debrisflow::rigid
