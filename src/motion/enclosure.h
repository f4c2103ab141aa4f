// Taylor enclosures of a motion piece (proofs/enclosures.md section 4):
// over segment parameters [s0, s1] with midpoint m and half-width h,
//     M(s) = M(m) + M'(m) (s - m) + R(s),  |R(s)|_mu <= sup |M''|_mu h^2 / 2,
// so every pose of the piece lies within `tube` (in the body's metric) of
// the segment between P0 = M(m) - h M'(m) and P1 = M(m) + h M'(m): a
// degree-1 Bezier piece whose ball, widened by the tube, holds the piece.
// The radius shrinks with h as a rational piece's does, and the tube with h^2.
#pragma once

#include "src/motion/segment.h"

#include <array>

namespace tmcert {

struct PieceEnclosure {
  std::array<PoseInterval, 2> controls;  // enclose P0 and P1
  double tube = 0;                       // upper bound, in the body's metric
  bool valid = false;                    // false: something was not finite
};

// `g`: the body's moment matrix, enclosed (MetricData::g_interval).  Call
// outside any rounding guard.
PieceEnclosure enclose_piece(const SegmentModel& model, const Exact& s0, const Exact& s1,
                             const std::array<Interval, 16>& g);

// The pose at s, enclosed.  Call outside any rounding guard.
PoseInterval enclose_pose(const SegmentModel& model, const Exact& s);

// An upper bound of |X|_mu = sqrt(trace(X G X^T)) over every matrix in the
// interval matrix X (infinity when not finite).  Call under RoundingGuard.
double metric_norm_upper(const PoseInterval& x, const std::array<Interval, 16>& g);

}  // namespace tmcert
