// A first test over the whole motion of a planner's edge, slice by slice
// (proofs/edge-slices.md): the motion's parameter interval cut into equal
// slices, each with a box holding every point of the body at every
// parameter of the slice (the box of its vertices placed by an interval
// map enclosing every pose of the slice).  A slice whose box meets no
// obstacle's box is free of surface contact; the search then runs only on
// the slices left (FixedEnvironment, src/verify/fixed_environment.cpp).
// The vertices are enclosed once per body (prepared with the environment),
// not per edge.
#pragma once

#include "src/model/model.h"
#include "src/verify/prepared.h"

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace tmcert {

// A body's distinct vertices (polygons, segments, points) in its own frame,
// each enclosed by intervals; computed once.
std::vector<std::array<Interval, 3>> enclosed_vertices(const Body& body);

struct EdgeSlices {
  // The union of the slices' boxes: a box holding everything the body sweeps
  // over the whole interval (as swept_box, without kept points).
  SweptBox whole;
  // Slice k: the scene parameters [t[k], t[k + 1]] and its box [lo, hi]
  // (`valid` false when a bound is not finite: never clears).
  std::vector<Exact> t;
  std::vector<std::array<double, 3>> lo, hi;
  std::vector<char> valid;
  std::size_t size() const { return lo.size(); }
};

// A first, coarse box per slice (proofs/edge-slices.md section 1b): the
// interval map of the slice applied to `bounds`, an interval box holding
// every vertex enclosure of the body (enclosed_bounds).  A slice whose
// coarse box `clears` (the caller's own test of a slice box, e.g. "meets
// no obstacle's box") keeps the coarse box; only the others get the box of
// their vertices.  Since the vertex box lies inside the coarse box, a
// caller whose test clears every sub-box of a box it clears decides every
// slice as with the vertex boxes alone.
struct SliceFilter {
  std::array<Interval, 3> bounds;
  std::function<bool(const std::array<double, 3>& lo, const std::array<double, 3>& hi)> clears;
};

// The interval hull of the vertex enclosures (empty: not valid, NaN ends).
std::array<Interval, 3> enclosed_bounds(const std::vector<std::array<Interval, 3>>& vertices);

// The slices of `motion` (a body's trajectory over [t0, t1]): `per_segment`
// equal slices of each segment's parameter, every pose of a slice enclosed
// by its segment model at the interval of the slice
// (SegmentModel::pose_values); `vertices` from enclosed_vertices of the
// body.  With `filter`, a slice whose coarse box the filter clears keeps
// that box (the box of its vertices is not computed).  `models`, when
// given, caches the segment models (one per segment, built when absent),
// as pose_at does (src/verify/sample_first.h).
class SegmentModel;
EdgeSlices edge_slices(const Trajectory& motion, const std::vector<std::array<Interval, 3>>& vertices,
                       int per_segment, const SliceFilter* filter = nullptr,
                       std::vector<std::unique_ptr<SegmentModel>>* models = nullptr);

// The maximal runs of slices for which `keep(k)` is true, as scene
// parameter intervals [t[first], t[last + 1]], in order.
template <class Keep>
std::vector<std::pair<Exact, Exact>> slice_runs(const EdgeSlices& s, Keep&& keep) {
  std::vector<std::pair<Exact, Exact>> out;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (!keep(k)) continue;
    if (!out.empty() && out.back().second == s.t[k]) out.back().second = s.t[k + 1];
    else out.push_back({s.t[k], s.t[k + 1]});
  }
  return out;
}

}  // namespace tmcert
