// Contacts found where they are cheapest, before any search: the bodies'
// configurations at a few sampled parameters of the motion, each given
// the exact static test of the search (proofs/sample-first.md).  A planner's
// validator needs "not certified" fast: a contact proven at a sampled
// parameter decides the edge without the search, which would subdivide
// towards the first contact for its bracket.
//
// Used by FixedEnvironment::decide (the OMPL validator's checkMotion); a
// result built from a sampled contact claims nothing before the sample
// (the search did not run there) and nothing after it (not searched).
#pragma once

#include "src/model/model.h"
#include "src/verify/solid_contact.h"
#include "src/verify/verify.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace tmcert {

// The parameters tested, in the order they are tested: the end t1 first
// (a planner's edge runs towards a sampled state, which is often in
// contact), then the midpoints of a bisection of [t0, t1] level by level
// (t0 + (t1 - t0) x 1/2, 1/4, 3/4, 1/8, 3/8, ...), `count` in all.  Never
// t0 (the search's start test covers it).  Dyadic fractions of [t0, t1].
std::vector<Exact> sample_times(const Exact& t0, const Exact& t1, std::size_t count);

// A body's pose at scene parameter t of its trajectory (t within it):
// exact where the segment holding t knows it exactly (a rational segment;
// a keyframe with an exact rotation at its keyframe), always enclosed (the
// segment model's pose at the point t, under a rounding guard).  The first
// segment whose closed interval holds t (segments join continuously).
// `models`, when given, caches the segment models (one per segment of
// `motion`, built on first use) across calls for the same motion.
// `with_exact` false: no exact pose is computed (`exact` stays empty) and
// the map is the segment model's enclosure of the pose at t (also where an
// exact pose exists: a caller that may need it asks again with true, e.g.
// only when the static test is left with candidate pairs;
// proofs/sample-first.md section 2c).
class SegmentModel;
StartPose pose_at(const Trajectory& motion, const Exact& t,
                  std::vector<std::unique_ptr<SegmentModel>>* models = nullptr, bool with_exact = true);

// The result of a check decided by a contact at a sampled parameter
// `witness.t` inside (t0, t1]: verdict collision with that witness; the
// part [t0, witness.t) was not searched, so it is undecided with reason
// "limit" (a budget ended the search there: the validator's, which stops at
// the first proof of contact); the part after the witness is not searched
// (the partition of SCENE_FORMAT.md, "Every interval claim holds"); the
// first-contact bracket is [t0, witness.t] (the earliest contact is at or
// before the witness, and nothing before t0 is claimed), not exact.
CheckResult sampled_collision(std::array<int, 2> ids, const Exact& t0, const Exact& t1, Witness witness,
                              std::uint64_t configurations);

// The sample pass over `pairs` checks (time-major: every pair at the first
// time, then every pair at the next, ...): `test(k, t)` gives a witness
// at t for pair k, or nothing.  The first witness found, with its pair.
template <class Test>
std::optional<std::pair<std::size_t, Witness>> first_sampled_contact(const std::vector<Exact>& times,
                                                                      std::size_t pairs, Test&& test) {
  for (const Exact& t : times)
    for (std::size_t k = 0; k < pairs; ++k)
      if (std::optional<Witness> w = test(k, t)) return std::pair{k, std::move(*w)};
  return std::nullopt;
}

}  // namespace tmcert
