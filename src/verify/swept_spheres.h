// The swept-sphere test of a hierarchy node of a moving body against a node
// of a fixed body on a piece of an enclosed motion (proofs/hierarchy.md §1c).
//
// An enclosed piece (src/motion/enclosure.h) holds every pose within `tube`
// (the body's metric) of the segment L(l) = (1 - l) P0 + l P1, l in [0, 1].
// A node S(c, r) with p >= max rho over its features then stays within
//     n r + tube p,   n >= max(|A0|_2, |A1|_2)
// of the world segment [P0(c), P1(c)] (a capsule): for a mostly
// translating piece much thinner than the ball around its middle pose that
// the sphere test uses (whose radius holds the whole sweep times rho).
// The test clears the node pair when the fixed node's centre is farther
// than the two radii from that segment.
#pragma once

#include "kernels/contact.h"
#include "kernels/number_types.h"
#include "src/verify/hierarchy.h"

#include <CGAL/FPU.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tmcert {

// The piece as the swept test needs it: enclosures of the segment's end
// maps, an upper bound of the operator norm of every linear part on the
// segment, and of the tube.
struct SweptFrame {
  std::array<Interval, 12> g0, g1;
  double n_up = 0;
  double tube_up = 0;
  double clear_up = 0;  // an upper bound of the check's clearance (proofs/clearance.md)
  bool valid = false;
};

// Call under RoundingGuard.  Not valid when a bound is not finite.
inline SweptFrame swept_frame(const std::array<Interval, 12>& p0, const std::array<Interval, 12>& p1, double tube,
                              double clear = 0) {
  SweptFrame f;
  f.g0 = p0;
  f.g1 = p1;
  // |A(l)|_2 <= (1 - l)|A0|_2 + l |A1|_2 <= max of the two (the norm is convex).
  const double n0 = detail::operator_norm_bound(p0).sup(), n1 = detail::operator_norm_bound(p1).sup();
  f.n_up = std::max(n0, n1);
  f.tube_up = tube;
  f.clear_up = clear;
  f.valid = std::isfinite(f.n_up) && n0 >= 0 && n1 >= 0 && std::isfinite(tube) && tube >= 0 && std::isfinite(clear) &&
            clear >= 0;
  return f;
}

// A node of the moving body under the frame: the segment's start a0, its
// direction d = a1 - a0 (enclosed) and an upper bound of the capsule's radius.
struct SweptSphere {
  Vec3<Interval> a0, d;
  std::array<double, 3> mid{};  // about a0 + d/2 (a point of the segment up to rounding; a filter only)
  double f_up = 0;
  bool valid = false;
};

// Call under RoundingGuard.
inline SweptSphere swept_sphere(const SweptFrame& fr, const BvNode& n) {
  SweptSphere s;
  const Vec3<Interval> c{Interval(n.c[0]), Interval(n.c[1]), Interval(n.c[2])};
  s.a0 = detail::apply_point(fr.g0, c);
  const Vec3<Interval> a1 = detail::apply_point(fr.g1, c);
  for (int i = 0; i < 3; ++i) {
    s.d[i] = a1[i] - s.a0[i];
    s.mid[i] = 0.5 * (CGAL::to_double(s.a0[i]) + CGAL::to_double(a1[i]));
  }
  // Non-negative factors: the products and the sum round up under the guard.
  // With a clearance d the capsule is fattened by d too: a fixed point
  // farther than f + d from every point of the node's sweep is farther than
  // d from the node (proofs/hierarchy.md §1c).
  s.f_up = CGAL::IA_opacify(fr.n_up * n.r + fr.tube_up * n.p + fr.clear_up);
  s.valid = fr.valid && std::isfinite(s.f_up) && s.f_up >= 0;
  return s;
}

// True when the sphere S(c_b, r_b) of a fixed node (world coordinates)
// certainly misses the capsule of `s`: the distance from c_b to the
// segment a0 + l d, l in [0, 1], exceeds f + r_b.  The line through the
// segment first (|w x d|^2 > t^2 |d|^2 with w = c_b - a0); then, when the
// nearest point of the segment is certainly an end (w.d <= 0, or
// w.d >= |d|^2), that end's distance.  Call under RoundingGuard; a NaN or
// an interval straddling a bound gives false.
inline bool swept_apart(const SweptSphere& s, const BvNode& b) {
  CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
  if (!s.valid) return false;
  const double t = CGAL::IA_opacify(s.f_up + b.r);  // rounds up
  if (!(t >= 0) || !std::isfinite(t)) return false;
  // A filter that decides nothing: the segment's distance from c_b is at
  // most its middle's, so when (approximately) the middle is within t the
  // test below cannot clear; skip it (the sphere test failed on most
  // such pairs already).
  double m2 = 0;
  for (int i = 0; i < 3; ++i) m2 += (b.c[i] - s.mid[i]) * (b.c[i] - s.mid[i]);
  if (m2 <= t * t) return false;
  const Interval t2 = CGAL::square(Interval(t));
  Vec3<Interval> w;
  for (int i = 0; i < 3; ++i) w[i] = Interval(b.c[i]) - s.a0[i];
  const Vec3<Interval>& d = s.d;
  const Interval dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const Interval cx = w[1] * d[2] - w[2] * d[1], cy = w[2] * d[0] - w[0] * d[2], cz = w[0] * d[1] - w[1] * d[0];
  const Interval cross2 = CGAL::square(cx) + CGAL::square(cy) + CGAL::square(cz);
  const Interval line = t2 * dd;
  if (cross2.inf() > line.sup() && std::isfinite(cross2.inf())) return true;  // the whole line is far
  const Interval wd = w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
  if (wd.sup() <= 0) {  // the nearest point is a0
    const Interval w2 = CGAL::square(w[0]) + CGAL::square(w[1]) + CGAL::square(w[2]);
    return w2.inf() > t2.sup() && std::isfinite(w2.inf());
  }
  if ((wd - dd).inf() >= 0) {  // the nearest point is a1 = a0 + d
    Interval e2(0);
    for (int i = 0; i < 3; ++i) e2 += CGAL::square(w[i] - d[i]);
    return e2.inf() > t2.sup() && std::isfinite(e2.inf());
  }
  return false;
}

// The swept slab test of a flat node a of the moving body against a flat
// fixed node b on an enclosed piece (proofs/hierarchy.md §1d).  For a
// feature point x of a, n_b.L(l)(x) = (1 - l) n_b.P0(x) + l n_b.P1(x) lies
// between its values at the segment's two ends, each within the
// unfattened range of slab_base under that end's map; a pose of the piece
// adds n_b.delta(x) with |delta(x)| <= tube rho(x) <= tube p_a, and the
// clearance d |n_b|.  `apart`: the union of the two ranges, so widened,
// misses b's slab.  `s0`, `s1`: slab_side(P0, b), slab_side(P1, b).  Call
// under RoundingGuard; a NaN or an infinite bound gives false.
inline bool swept_slab_apart(const SweptFrame& fr, const SlabSide& s0, const SlabSide& s1, const BvNode& a,
                             const BvNode& b) {
  CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
  if (!fr.valid || !a.slab || !b.slab) return false;
  const SlabBase r0 = slab_base(s0, a), r1 = slab_base(s1, a);
  if (!r0.valid || !r1.valid) return false;
  // Products and sums of non-negative upper bounds round up under the guard.
  const double nb_up = std::max(s0.nb_up, s1.nb_up);
  const double fat_up = nb_up * CGAL::IA_opacify(fr.tube_up * a.p + fr.clear_up);
  // Each end's range [-(base_negdown + size + fat), base_up + size + fat].
  const double hi_up = CGAL::IA_opacify(std::max(r0.base_up + r0.size_up + fat_up, r1.base_up + r1.size_up + fat_up));
  const double lo_negdown =
      CGAL::IA_opacify(std::max(r0.base_negdown + r0.size_up + fat_up, r1.base_negdown + r1.size_up + fat_up));
  if (!std::isfinite(hi_up) || !std::isfinite(lo_negdown) || !(-lo_negdown <= hi_up)) return false;
  return hi_up < b.slab_lo || -lo_negdown > b.slab_hi;
}

// slab_side of a fixed node under the segment's two end maps.
struct SweptSlabSide {
  SlabSide s0, s1;
};
inline SweptSlabSide swept_slab_side(const SweptFrame& fr, const BvNode& b) {
  return {slab_side(fr.g0, b), slab_side(fr.g1, b)};
}

// The swept spheres of one tree's (or one feature table's) nodes, computed
// once per piece.
using SweptCache = StampedCache<SweptSphere>;
// The fixed body's side of the swept slab test, per node and piece.
using SweptSlabCache = StampedCache<SweptSlabSide>;

}  // namespace tmcert
