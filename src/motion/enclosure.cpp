#include "src/motion/enclosure.h"

#include <cmath>
#include <limits>

namespace tmcert {

double metric_norm_upper(const PoseInterval& x, const std::array<Interval, 16>& g) {
  Interval sum(0);
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) sum += x[4 * r + i] * g[4 * i + j] * x[4 * r + j];
  const double up = sum.sup();
  if (!std::isfinite(up)) return std::numeric_limits<double>::infinity();
  return CGAL::sqrt(Interval(0, std::max(0.0, up))).sup();  // upward rounded under the guard
}

PoseInterval enclose_pose(const SegmentModel& model, const Exact& s) {
  RoundingGuard guard;
  return model.pose_values(to_interval(s));
}

PieceEnclosure enclose_piece(const SegmentModel& model, const Exact& s0, const Exact& s1,
                             const std::array<Interval, 16>& g) {
  PieceEnclosure out;
  const Exact mid = (s0 + s1) / 2, half = (s1 - s0) / 2;
  RoundingGuard guard;
  const Interval m = to_interval(mid), h = to_interval(half);
  const PoseJet at_mid = model.pose(Jet::variable(m));
  const Interval lo = to_interval(s0), hi = to_interval(s1);
  const PoseJet over = model.pose(Jet::variable(Interval(lo.inf(), hi.sup())));
  PoseInterval second;
  bool finite = true;
  for (int e = 0; e < 12; ++e) {
    out.controls[0][e] = at_mid[e].v - h * at_mid[e].d;
    out.controls[1][e] = at_mid[e].v + h * at_mid[e].d;
    second[e] = over[e].dd;
    for (const Interval* x : {&out.controls[0][e], &out.controls[1][e]})
      finite = finite && std::isfinite(x->inf()) && std::isfinite(x->sup());
  }
  const double bound = metric_norm_upper(second, g);
  if (!finite || !std::isfinite(bound)) return out;
  // sup |M''| h^2 / 2, rounded upward (the guard rounds toward +infinity).
  const Interval tube = Interval(bound) * h * h / Interval(2);
  out.tube = tube.sup();
  out.valid = std::isfinite(out.tube);
  return out;
}

}  // namespace tmcert
