#include "src/verify/edge_slices.h"

#include "src/motion/segment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

namespace tmcert {

std::vector<std::array<Interval, 3>> enclosed_vertices(const Body& body) {
  std::set<Vec3E> distinct;
  for (const auto& poly : body.polygons) distinct.insert(poly.begin(), poly.end());
  for (const auto& s : body.segments) distinct.insert(s.begin(), s.end());
  distinct.insert(body.points.begin(), body.points.end());
  std::vector<std::array<Interval, 3>> out;
  out.reserve(distinct.size());
  for (const Vec3E& x : distinct) out.push_back({to_interval(x[0]), to_interval(x[1]), to_interval(x[2])});
  return out;
}

std::array<Interval, 3> enclosed_bounds(const std::vector<std::array<Interval, 3>>& vertices) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::array<Interval, 3> out{Interval(nan), Interval(nan), Interval(nan)};
  if (vertices.empty()) return out;
  for (int i = 0; i < 3; ++i) {
    double lo = vertices.front()[i].inf(), hi = vertices.front()[i].sup();
    for (const auto& x : vertices) {
      if (std::isnan(x[i].inf()) || std::isnan(x[i].sup())) {
        lo = hi = nan;
        break;
      }
      lo = std::min(lo, x[i].inf());
      hi = std::max(hi, x[i].sup());
    }
    out[i] = std::isnan(lo) ? Interval(nan) : Interval(lo, hi);
  }
  return out;
}

EdgeSlices edge_slices(const Trajectory& motion, const std::vector<std::array<Interval, 3>>& vertices,
                       int per_segment, const SliceFilter* filter,
                       std::vector<std::unique_ptr<SegmentModel>>* models) {
  EdgeSlices out;
  const double inf = std::numeric_limits<double>::infinity();
  out.whole.lo.fill(inf);
  out.whole.hi.fill(-inf);
  out.whole.valid = !vertices.empty();
  bool contiguous = true;
  for (std::size_t i = 0; i + 1 < motion.segments.size(); ++i)
    contiguous = contiguous && motion.segments[i].t1 == motion.segments[i + 1].t0;
  if (models && models->size() != motion.segments.size()) models->resize(motion.segments.size());
  for (std::size_t index = 0; index < motion.segments.size(); ++index) {
    const MotionSegment& seg = motion.segments[index];
    std::unique_ptr<SegmentModel> own;
    std::unique_ptr<SegmentModel>& slot = models ? (*models)[index] : own;
    if (!slot) slot = make_segment_model(seg);
    const SegmentModel* model = slot.get();
    for (int k = 0; k < per_segment; ++k) {
      std::array<double, 3> lo, hi;
      lo.fill(inf);
      hi.fill(-inf);
      bool ok = !vertices.empty();
      {
        RoundingGuard guard;
        // Every pose of the slice s in [k/n, (k + 1)/n] of the segment's
        // parameter (dyadic bounds, exact in doubles for n a power of two;
        // otherwise the interval is rounded outward by Interval's division).
        const Interval a = Interval(k) / Interval(per_segment), b = Interval(k + 1) / Interval(per_segment);
        const Interval s(a.inf(), b.sup());
        const std::array<Interval, 12> m = model->pose_values(s);
        // The coarse box first (section 1b): the map applied to the box
        // holding every vertex enclosure; kept when the caller's test
        // clears it.
        bool coarse = false;
        if (filter && ok) {
          const std::array<Interval, 3>& x = filter->bounds;
          std::array<double, 3> clo, chi;
          bool fine = true;
          for (int i = 0; i < 3; ++i) {
            const Interval y = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
            clo[i] = y.inf();
            chi[i] = y.sup();
            fine = fine && std::isfinite(clo[i]) && std::isfinite(chi[i]) && clo[i] <= chi[i];
          }
          if (fine && filter->clears(clo, chi)) {
            coarse = true;
            lo = clo;
            hi = chi;
          }
        }
        if (!coarse)
          for (const auto& x : vertices)
            for (int i = 0; i < 3; ++i) {
              const Interval y = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
              if (std::isnan(y.inf()) || std::isnan(y.sup())) ok = false;  // std::min would drop it
              lo[i] = std::min(lo[i], y.inf());
              hi[i] = std::max(hi[i], y.sup());
            }
      }
      for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(lo[i]) || !std::isfinite(hi[i]) || !(lo[i] <= hi[i])) ok = false;
        out.whole.lo[i] = std::min(out.whole.lo[i], lo[i]);
        out.whole.hi[i] = std::max(out.whole.hi[i], hi[i]);
      }
      out.whole.valid = out.whole.valid && ok;
      out.lo.push_back(lo);
      out.hi.push_back(hi);
      out.valid.push_back(ok ? 1 : 0);
      out.t.push_back(seg.t0 + (seg.t1 - seg.t0) * Exact(k, per_segment));
    }
  }
  out.t.push_back(motion.segments.empty() ? Exact(0) : motion.segments.back().t1);
  if (!contiguous || motion.segments.empty()) {
    // Not one run of joined segments: one slice, the whole box.
    out.lo = {out.whole.lo};
    out.hi = {out.whole.hi};
    out.valid = {static_cast<char>(out.whole.valid ? 1 : 0)};
    out.t = {motion.segments.empty() ? Exact(0) : motion.segments.front().t0, out.t.back()};
    if (motion.segments.empty()) out.whole.valid = false;
  }
  return out;
}

}  // namespace tmcert
