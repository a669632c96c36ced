#pragma once
#include "debrisflow/dem/grain_set.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <string>

namespace debrisflow::scenario {

// How deep the contacts at the bottom of a grain block's bed sink under the bed's own weight:
// the weight M g of the block spread over its footprint A (perpendicular to gravity) is a
// vertical stress sigma = M g / A at the bed's base, and one grain there carries sigma (2 r)^2
// (3D; 2D: sigma 2 r t), where r is the block's mean radius and t the disc thickness. The
// overlap is where the pair's contact law, at rest, carries that force (the laws' own normal
// response, so Hertz, DCDEM and JKR adhesion count as they act). Exact for a simple-cubic
// column; a denser packing shares the load over more contacts and sinks less.
struct BedOverlap {
    Real fraction = 0; // overlap / mean radius, the largest over blocks and pairs
    Real overlap = 0;  // [m]
    Real force = 0;    // [N] per contact
    std::string where; // "grains 'column', glass-floor contact"
};

// Above this fraction of the radius a bed would not rest on its contacts but sink through
// them: grains pass through one another and through walls, and the deposit's height, the
// loads on a barrier and the run-out are those of a different material.
inline constexpr Real max_bed_overlap = Real(0.1);

// The block's estimate (grains [first, last) of `g`); throws InputError naming the block, the
// pair's material and its stiffness key, with the stiffness that keeps the overlap at 1 %,
// when the overlap exceeds max_bed_overlap of the mean radius.
BedOverlap require_bed_rests_on_contacts(const io::CaseSpec& c, const io::GrainsSpec& block,
                                         const dem::GrainSet& g, Index first, Index last);

// A grain thrown at a wall stops at the overlap where the pair's elastic work takes up its
// kinetic energy, 1/2 m v^2 (undamped: the dashpot only shortens it). Beyond half the radius
// a grain comes within half a radius of the wall's surface, thin walls let it through and its
// neighbours' contacts change: the impact of a different material.
inline constexpr Real max_impact_overlap = Real(0.5);

// The fastest a grain can hit a wall: its release speed v0 and the fall h from its release
// to the domain's lowest point, |v|^2 = v0^2 + 2 g h (no other force adds energy for long).
// For a grain of the block's mean size, at the block's fastest given velocity and released
// from its highest grain, against every wall material: throws InputError naming the block
// (its velocity), the pair and its stiffness key, with the stiffness that keeps the impact's
// overlap at max_bed_overlap, when the overlap exceeds max_impact_overlap of the mean radius.
void require_impact_within_contact(const io::CaseSpec& c, const io::GrainsSpec& block,
                                   const dem::GrainSet& g, Index first, Index last);

// The same for a feed's grains: the largest it releases (`largest`, one grain), at the feed's
// velocity from the top of its region.
void require_feed_within_contact(const io::CaseSpec& c, const io::FeedSpec& feed,
                                 const dem::GrainSet& largest);

} // namespace debrisflow::scenario
