#include "debrisflow/flow/solid_feed.hpp"
#include <fmt/format.h>

namespace debrisflow::flow {

namespace {
constexpr Real pi = 3.14159265358979323846;
// The debt a feed may carry before it is said to have fallen behind: it releases whole pieces,
// so a few pieces' volume is owed at any time; ten, and a twentieth of what was asked, is not.
constexpr Real lag_pieces = 10, lag_fraction = Real(0.05);
} // namespace

Real SolidFeed::piece_volume(Real d) const {
    const Real r = d / 2;
    return case_.dim == 2 ? pi * r * r * case_.dem.thickness : Real(4) / 3 * pi * r * r * r;
}

std::string SolidFeed::lag_note(Real t) {
    if (lag_warned_) return "";
    const Real piece = piece_volume(next_d_);
    const Real asked = volume_in_ + owed_;
    if (!(owed_ > lag_pieces * piece && owed_ > lag_fraction * asked)) return "";
    lag_warned_ = true;
    return fmt::format(
        "WARNING: t = {:.6g} s: feed '{}' falls behind its discharge: {:.4g} of the {:.4g} m^3 "
        "asked so far released ({} pieces), {:.4g} m^3 ({:.0f} %) owed. Its region ({:.4g}, "
        "{:.4g}, {:.4g})-({:.4g}, {:.4g}, {:.4g}) m is full: a piece is placed only clear of "
        "the others, so the feed releases only as fast as its pieces leave the region. Enlarge "
        "the region, give the pieces a velocity out of it, or lower the discharge "
        "({}); probes/{}.csv's column owed follows the debt",
        t, spec_.name, volume_in_, asked, count_, owed_, 100 * owed_ / asked, spec_.min.x,
        spec_.min.y, spec_.min.z, spec_.max.x, spec_.max.y, spec_.max.z,
        spec_.origin.at("discharge"), spec_.name);
}

} // namespace debrisflow::flow
