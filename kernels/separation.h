// The swept-hull test of a feature pair on a motion piece
// (proofs/hull-test.md).
//
// A piece is given by its homogeneous control points P_l = (N1_l, [N2_l,] W_l),
// l = 0 .. n (src/motion/bezier.h: body 1's 12 entries, for B = 2 body 2's
// 12, then the weight).  Feature X belongs to body 1 (body frame), Y to
// body 2 (its body frame when B = 2, world coordinates when B = 1).  With
// d_l(x, y) = N1_l x^ - N2_l y^ (B = 1: N1_l x^ - W_l y, x^ = (x, 1)) and a
// plane normal n(u) = (1 - u) n0 + u n1 moving with the piece, the pair
// cannot touch anywhere on the piece if for k = 0 .. n + 1 and every vertex
// x of X and y of Y
//     c_k = (n + 1 - k) n0.d_k(x, y) + k n1.d_(k-1)(x, y) > 0
// (out-of-range terms dropped): the c_k are the Bernstein coefficients, times
// n + 1, of n(u).(N1(u) x^ - N2(u) y^), affine in x^ and y^, so positive on
// the hulls of the features.  With n0 = n1 = n this is implied by
// "min_x n.(N1_l x^) > max_y n.(N2_l y^) for every l".
//
// `hull_search` proposes planes in double (any plane is sound: they are only
// candidates); `hull_apart` decides the inequalities in NT: Interval (under
// RoundingGuard; an uncertain comparison means "not apart"), Exact, or double
// (the fast, uncertified kernel).
#pragma once

#include "kernels/contact.h"
#include "kernels/number_types.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

namespace tmcert {

namespace hull_detail {

// GJK stops once the margin is kAccept |n|^2, or after kIterations steps
// (a tuning choice: on the continuous-collision queries of bench/, 12 steps
// cleared one pair more than 6 in 4000 queries, while on nearly degenerate
// pairs resting within 1e-9..1e-5, where GJK does not converge, 6 steps cut
// the slowest check from 0.17 to 0.10 s).
constexpr double kAccept = 0.1;
constexpr int kIterations = 6;
// With a clearance d the plane must also keep D farther than d along it
// (claim HC of proofs/hull-test.md), which a margin of kAccept |n|^2 does
// not give when D lies just beyond d: GJK then runs on, up to
// kClearIterations steps, until the support along n exceeds d |n| or it
// converges (the direction is then GJK's closest point of D, the best one).
constexpr int kClearIterations = 24;

using V3 = std::array<double, 3>;

using vec3::cross;
using vec3::dot;
using vec3::sub;
inline V3 add_scaled(const V3& a, double t, const V3& b) { return {a[0] + t * b[0], a[1] + t * b[1], a[2] + t * b[2]}; }

// The point of a simplex (1 to 4 points) closest to the origin; the simplex
// is reduced to the face that holds it.  Returns false when the origin is
// (about) inside a tetrahedron.  Ericson, Real-Time Collision Detection,
// 5.1.5 and 5.1.6, with the query point at the origin.  A heuristic: its
// result is only a candidate direction.
struct Simplex3 {
  std::array<V3, 4> p;
  int n = 0;
};

inline V3 closest_triangle(Simplex3& s) {
  const V3 a = s.p[0], b = s.p[1], c = s.p[2];
  const V3 ab = sub(b, a), ac = sub(c, a);
  const double d1 = -dot(ab, a), d2 = -dot(ac, a);
  if (d1 <= 0 && d2 <= 0) { s.n = 1; s.p[0] = a; return a; }
  const double d3 = -dot(ab, b), d4 = -dot(ac, b);
  if (d3 >= 0 && d4 <= d3) { s.n = 1; s.p[0] = b; return b; }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    s.n = 2; s.p[0] = a; s.p[1] = b;
    return add_scaled(a, v, ab);
  }
  const double d5 = -dot(ab, c), d6 = -dot(ac, c);
  if (d6 >= 0 && d5 <= d6) { s.n = 1; s.p[0] = c; return c; }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    s.n = 2; s.p[0] = a; s.p[1] = c;
    return add_scaled(a, w, ac);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    s.n = 2; s.p[0] = b; s.p[1] = c;
    return add_scaled(b, w, sub(c, b));
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  s.n = 3;
  return add_scaled(add_scaled(a, v, ab), w, ac);
}

inline bool closest(Simplex3& s, V3& v) {
  switch (s.n) {
    case 1: v = s.p[0]; return true;
    case 2: {
      const V3 a = s.p[0], ab = sub(s.p[1], a);
      const double len2 = dot(ab, ab);
      const double t = len2 > 0 ? -dot(a, ab) / len2 : 0;
      if (t <= 0) { s.n = 1; v = a; }
      else if (t >= 1) { s.n = 1; s.p[0] = s.p[1]; v = s.p[0]; }
      else v = add_scaled(a, t, ab);
      return true;
    }
    case 3: v = closest_triangle(s); return true;
    default: {
      // Tetrahedron: the origin is inside unless it is outside a face's
      // plane (on the side away from the fourth point); then the closest
      // point is on one of those faces.
      static constexpr int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
      const double vol = dot(sub(s.p[1], s.p[0]), cross(sub(s.p[2], s.p[0]), sub(s.p[3], s.p[0])));
      bool any = false;
      double best = 0;
      Simplex3 best_s;
      const bool flat = !(std::fabs(vol) > 0);
      for (const auto& f : faces) {
        // The face of the previous simplex (without the newest point, p[3]):
        // the origin lies on the newest point's side of it (GJK's progress).
        if (!flat && f[3] == 3) continue;
        const V3 a = s.p[f[0]], b = s.p[f[1]], c = s.p[f[2]], d = s.p[f[3]];
        const V3 nrm = cross(sub(b, a), sub(c, a));
        const double sp = -dot(a, nrm), sd = dot(sub(d, a), nrm);
        // Outside this face, or a flat tetrahedron (every face is a candidate).
        if (!flat && !(sp * sd < 0)) continue;
        Simplex3 t;
        t.n = 3;
        t.p[0] = a; t.p[1] = b; t.p[2] = c;
        const V3 q = closest_triangle(t);
        const double q2 = dot(q, q);
        if (!any || q2 < best) { any = true; best = q2; best_s = t; v = q; }
      }
      if (!any) return false;
      s = best_s;
      return true;
    }
  }
}

}  // namespace hull_detail

// A plane moving with the piece: normal n(u) = (1 - u) n0 + u n1 over the
// piece's local parameter u in [0, 1] (n0 = n1: a fixed plane).
struct HullPlane {
  std::array<double, 3> n0, n1;
};

namespace hull_detail {

// The vertex images N1_l x^ and N2_l y^ (B = 1: W_l y) of a feature pair
// under the control points of a piece, in double, and GJK (Gilbert,
// Johnson, Keerthi) on the differences D_l = {N1_l x^ - N2_l y^} of a range
// of control points.  Heuristics only: their directions are candidates.
struct Images {
  static constexpr std::size_t kLocal = 48;
  V3 xs_local[kLocal], ys_local[kLocal], a_local[kLocal], b_local[kLocal];
  std::vector<V3> heap[4];  // large features or many control points
  const V3 *a = nullptr, *b = nullptr;
  std::size_t L = 0, nx = 0, ny = 0;

  template <int B, class NT>
  bool build(const std::vector<std::array<NT, 12 * B + 1>>& piece, const FeatureGeometry<double>& X,
             const FeatureGeometry<double>& Y) {
    L = piece.size();
    nx = X.dim == 2 ? X.domain.size() : X.dim + 1;
    ny = Y.dim == 2 ? Y.domain.size() : Y.dim + 1;
    if (L == 0 || nx == 0 || ny == 0) return false;
    auto buffer = [&](V3* local, std::vector<V3>& h, std::size_t n) {
      if (n <= kLocal) return local;
      h.resize(n);
      return h.data();
    };
    V3* xs = buffer(xs_local, heap[0], nx);
    V3* ys = buffer(ys_local, heap[1], ny);
    V3* ai = buffer(a_local, heap[2], L * nx);
    V3* bi = buffer(b_local, heap[3], L * ny);
    auto vertices = [](const FeatureGeometry<double>& f, V3* out) {
      if (f.dim < 2) {
        out[0] = f.origin;
        if (f.dim == 1) out[1] = add_scaled(f.origin, 1, f.axis[0]);
        return;
      }
      for (std::size_t k = 0; k < f.domain.size(); ++k)
        out[k] = add_scaled(add_scaled(f.origin, f.domain[k][0], f.axis[0]), f.domain[k][1], f.axis[1]);
    };
    vertices(X, xs);
    vertices(Y, ys);
    for (std::size_t l = 0; l < L; ++l) {
      double P[12 * B + 1];
      for (std::size_t e = 0; e < 12 * B + 1; ++e) {
        if constexpr (std::is_same_v<NT, double>) P[e] = piece[l][e];
        else P[e] = CGAL::to_double(piece[l][e]);
      }
      for (std::size_t k = 0; k < nx; ++k) {
        const V3& x = xs[k];
        V3& r = ai[l * nx + k];
        for (int i = 0; i < 3; ++i) r[i] = P[4 * i] * x[0] + P[4 * i + 1] * x[1] + P[4 * i + 2] * x[2] + P[4 * i + 3];
      }
      for (std::size_t k = 0; k < ny; ++k) {
        const V3& y = ys[k];
        V3& r = bi[l * ny + k];
        if constexpr (B == 2) {
          for (int i = 0; i < 3; ++i)
            r[i] = P[12 + 4 * i] * y[0] + P[12 + 4 * i + 1] * y[1] + P[12 + 4 * i + 2] * y[2] + P[12 + 4 * i + 3];
        } else {
          for (int i = 0; i < 3; ++i) r[i] = P[12] * y[i];
        }
      }
    }
    a = ai;
    b = bi;
    return true;
  }

  // A direction n with n.d >= kAccept |n|^2 > 0 for every d in D_first ..
  // D_last, from the difference of the centroids; nothing when GJK finds
  // the origin in their hull, makes no progress or runs out of steps.
  std::optional<V3> gjk(std::size_t first, std::size_t last, double clear = 0) const {
    V3 ca{0, 0, 0}, cb{0, 0, 0};
    for (std::size_t k = first * nx; k < (last + 1) * nx; ++k)
      for (int i = 0; i < 3; ++i) ca[i] += a[k][i];
    for (std::size_t k = first * ny; k < (last + 1) * ny; ++k)
      for (int i = 0; i < 3; ++i) cb[i] += b[k][i];
    const double count = static_cast<double>(last + 1 - first);
    V3 v;
    for (int i = 0; i < 3; ++i) v[i] = ca[i] / (count * nx) - cb[i] / (count * ny);
    // The point of D minimizing dir.d: per control point, the lowest image
    // of X minus the highest image of Y.
    auto support = [&](const V3& dir) {
      double best = 0;
      V3 w{0, 0, 0};
      for (std::size_t l = first; l <= last; ++l) {
        const V3* al = a + l * nx;
        const V3* bl = b + l * ny;
        std::size_t ix = 0, iy = 0;
        double lo = dot(dir, al[0]), hi = dot(dir, bl[0]);
        for (std::size_t k = 1; k < nx; ++k) {
          const double d = dot(dir, al[k]);
          if (d < lo) { lo = d; ix = k; }
        }
        for (std::size_t k = 1; k < ny; ++k) {
          const double d = dot(dir, bl[k]);
          if (d > hi) { hi = d; iy = k; }
        }
        if (l == first || lo - hi < best) { best = lo - hi; w = sub(al[ix], bl[iy]); }
      }
      return w;
    };
    Simplex3 s;
    const int steps = clear > 0 ? kClearIterations : kIterations;
    for (int it = 0; it < steps; ++it) {
      const double v2 = dot(v, v);
      if (!(v2 > 0) || !std::isfinite(v2)) return std::nullopt;
      const V3 w = support(v);
      const double vw = dot(v, w);
      // separating, with a margin (and beyond the clearance along v)
      if (vw >= kAccept * v2 && (clear <= 0 || vw > clear * std::sqrt(v2) * (1 + 0x1p-30))) return v;
      if (v2 - vw <= 1e-12 * v2) {  // converged: with a clearance, v is the best direction
        if (clear > 0 && vw > 0) return v;
        return std::nullopt;
      }
      s.p[s.n++] = w;
      if (!closest(s, v)) return std::nullopt;         // the origin is in the hull
    }
    return std::nullopt;
  }
};

inline V3 unit(const V3& v) {
  const double n = std::sqrt(dot(v, v));
  return {v[0] / n, v[1] / n, v[2] / n};
}

}  // namespace hull_detail

// The candidate planes for the hull test of a feature pair on a piece, in
// order, until `certify(plane)` accepts one: a fixed plane whose normal
// separates the origin from all of D (GJK over every control point), then a
// moving plane from the separating directions of the first and of the last
// control point's D alone (which can succeed while the origin is inside the
// hull of D, e.g. when a face turns while a vertex approaches it).  Computed
// from the control points rounded to doubles and the approximate features;
// any plane is sound: `certify` (hull_apart) decides.  Round-to-nearest
// whatever the caller's mode (prune runs under the upward guard, the
// reference path does not): the same candidates, and so the same verdict,
// on both paths.
template <int B, class NT, class Certify>
bool hull_search(const std::vector<std::array<NT, 12 * B + 1>>& piece, const FeatureGeometry<double>& X,
                 const FeatureGeometry<double>& Y, Certify&& certify, double clear = 0) {
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  hull_detail::Images im;
  if (!im.build<B>(piece, X, Y)) return false;
  if (const auto n = im.gjk(0, im.L - 1, clear)) {
    const auto u = hull_detail::unit(*n);
    if (certify(HullPlane{u, u})) return true;
  }
  if (im.L < 2) return false;
  const auto n0 = im.gjk(0, 0, clear);
  if (!n0) return false;
  const auto n1 = im.gjk(im.L - 1, im.L - 1, clear);
  if (!n1) return false;
  return certify(HullPlane{hull_detail::unit(*n0), hull_detail::unit(*n1)});
}

// The candidate planes hull_search tries, in order (for tests).
template <int B, class NT>
std::vector<HullPlane> hull_candidates(const std::vector<std::array<NT, 12 * B + 1>>& piece,
                                       const FeatureGeometry<double>& X, const FeatureGeometry<double>& Y) {
  std::vector<HullPlane> out;
  hull_search<B>(piece, X, Y, [&](const HullPlane& p) {
    out.push_back(p);
    return false;
  });
  return out;
}

namespace hull_detail {

inline bool certainly_greater(const Interval& a, const Interval& b) { return a.inf() > b.sup(); }
inline bool certainly_greater(double a, double b) { return a > b; }
inline bool certainly_greater(const Exact& a, const Exact& b) { return a > b; }

// The range of the values m.x^ over the vertices x of a feature, for a
// linear form m = (m0, m1, m2, m3): x = origin + s1 a0 + s2 a1 gives
// m.x^ = (m.origin^) + s1 (m.a0) + s2 (m.a1).  `lowest`/`highest` receive
// enclosures of the smallest and largest value: for Interval an interval
// whose lower (upper) end bounds the true minimum (maximum) from below
// (above); NaN makes `ok` false.
template <class NT>
struct Range {
  NT lo, hi;
  bool set = false;
  bool ok = true;
  void add(const NT& v) {
    if constexpr (std::is_same_v<NT, Interval>) {
      if (std::isnan(v.inf()) || std::isnan(v.sup())) ok = false;
      if (!set) { lo = hi = v; set = true; return; }
      lo = Interval(std::min(lo.inf(), v.inf()), std::min(lo.sup(), v.sup()));
      hi = Interval(std::max(hi.inf(), v.inf()), std::max(hi.sup(), v.sup()));
    } else if constexpr (std::is_same_v<NT, double>) {
      if (std::isnan(v)) ok = false;
      if (!set) { lo = hi = v; set = true; return; }
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    } else {
      if (!set) { lo = hi = v; set = true; return; }
      if (v < lo) lo = v;
      if (hi < v) hi = v;
    }
  }
};

template <class NT>
void add_feature_values(const FeatureGeometry<NT>& f, const NT& m0, const NT& m1, const NT& m2, const NT& m3,
                        Range<NT>& r) {
  const NT o = m0 * f.origin[0] + m1 * f.origin[1] + m2 * f.origin[2] + m3;
  r.add(o);
  if (f.dim == 0) return;
  const NT al = m0 * f.axis[0][0] + m1 * f.axis[0][1] + m2 * f.axis[0][2];
  if (f.dim == 1) {
    r.add(o + al);
    return;
  }
  const NT be = m0 * f.axis[1][0] + m1 * f.axis[1][1] + m2 * f.axis[1][2];
  for (const auto& s : f.domain) r.add(o + s[0] * al + s[1] * be);
}

}  // namespace hull_detail

namespace hull_detail {

// With a clearance the hull test needs an upper bound of |n0| and |n1|:
// the planes hull_search proposes are unit vectors in double, whose n.n,
// computed in any rounding mode (at most 5 operations, each within a
// relative 2^-52, plus at most 3 * 2^-1074 from underflow), is at most
// 1 + 2^-45 only if the true |n|^2 is below 1 + 2^-44, so |n| <
// kNormBound (proofs/hull-test.md, "With a clearance").
constexpr double kNormBound = 1 + 0x1p-44;
inline bool norm_bounded(const std::array<double, 3>& n) {
  return n[0] * n[0] + n[1] * n[1] + n[2] * n[2] <= 1 + 0x1p-45;
}

}  // namespace hull_detail

// The hull test of a feature pair on a piece for the plane n(u) =
// (1 - u) n0 + u n1, in NT (Interval: call under RoundingGuard).  With
// L = n + 1 control points, for k = 0 .. n + 1 the linear forms
//   m_k = (n + 1 - k) n0^T N1_k + k n1^T N1_(k-1)        (terms out of range dropped)
// and likewise with N2 (B = 1: W_l (n0, 0), W_l (n1, 0)) are the Bernstein
// coefficients, times n + 1, of n(u).(N1(u) x^ - N2(u) y^); true only when
// for every k the smallest value of body 1's form over X's vertices is
// certainly greater than the largest of body 2's over Y's
// (proofs/hull-test.md, claim H).  With a clearance `clear` > 0 (an upper
// bound of d), greater by at least clear * kNormBound * ((n + 1 - k) W_k +
// k W_(k-1)) (the weights W_l of the control points): then the feature
// pair stays farther apart than d on the whole piece (claim HC); a plane
// whose normals are not provably within kNormBound clears nothing.
template <int B, class NT>
bool hull_apart(const std::vector<std::array<NT, 12 * B + 1>>& piece, const FeatureGeometry<NT>& X,
                const FeatureGeometry<NT>& Y, const HullPlane& plane, double clear = 0) {
  using hull_detail::Range;
  using Form = std::array<NT, 4>;
  const std::size_t L = piece.size();
  if (L == 0) return false;
  if (!(clear >= 0)) return false;
  if (clear > 0 && !(hull_detail::norm_bounded(plane.n0) && hull_detail::norm_bounded(plane.n1))) return false;
  const bool fixed = plane.n0 == plane.n1;
  // Per control point and plane end: the forms of body 1 (x) and body 2 (y).
  constexpr std::size_t kLocal = 16;
  std::array<Form, kLocal> local[4];
  std::vector<Form> heap[4];
  Form* forms[4];
  for (int f = 0; f < 4; ++f) {
    if (L <= kLocal) forms[f] = local[f].data();
    else {
      heap[f].resize(L);
      forms[f] = heap[f].data();
    }
  }
  for (int end = 0; end < (fixed ? 1 : 2); ++end) {
    const std::array<double, 3>& d = end == 0 ? plane.n0 : plane.n1;
    const NT n0(d[0]), n1(d[1]), n2(d[2]);
    for (std::size_t l = 0; l < L; ++l) {
      const auto& P = piece[l];
      Form& fx = forms[end][l];
      for (int j = 0; j < 4; ++j) fx[j] = n0 * P[j] + n1 * P[4 + j] + n2 * P[8 + j];
      Form& fy = forms[2 + end][l];
      if constexpr (B == 2) {
        for (int j = 0; j < 4; ++j) fy[j] = n0 * P[12 + j] + n1 * P[16 + j] + n2 * P[20 + j];
      } else {
        // W_l (n.y) = (W_l n, 0).y^.
        const NT& w = P[12];
        fy = {w * n0, w * n1, w * n2, NT(0)};
      }
    }
  }
  const Form* x0 = forms[0];
  const Form* x1 = fixed ? forms[0] : forms[1];
  const Form* y0 = forms[2];
  const Form* y1 = fixed ? forms[2] : forms[3];
  for (std::size_t k = 0; k <= L; ++k) {
    Form mx, my;
    const NT a(static_cast<double>(L - k)), b(static_cast<double>(k));  // small integers: exact
    for (int j = 0; j < 4; ++j) {
      if (k == 0) mx[j] = a * x0[0][j], my[j] = a * y0[0][j];
      else if (k == L) mx[j] = b * x1[L - 1][j], my[j] = b * y1[L - 1][j];
      else mx[j] = a * x0[k][j] + b * x1[k - 1][j], my[j] = a * y0[k][j] + b * y1[k - 1][j];
    }
    Range<NT> rx, ry;
    hull_detail::add_feature_values(X, mx[0], mx[1], mx[2], mx[3], rx);
    hull_detail::add_feature_values(Y, my[0], my[1], my[2], my[3], ry);
    if (!rx.ok || !ry.ok) return false;
    if (clear > 0) {
      // d |n(u)| W(u) <= clear kNormBound ((1 - u) + u) W(u), whose Bernstein
      // coefficients (times n + 1) are clear kNormBound ((n + 1 - k) W_k + k W_(k-1)).
      constexpr std::size_t w = 12 * B;
      NT weights;
      if (k == 0) weights = a * piece[0][w];
      else if (k == L) weights = b * piece[L - 1][w];
      else weights = a * piece[k][w] + b * piece[k - 1][w];
      const NT margin = NT(clear) * NT(hull_detail::kNormBound) * weights;
      if constexpr (std::is_same_v<NT, Interval>) {
        if (std::isnan(margin.inf()) || std::isnan(margin.sup())) return false;
      }
      if (!hull_detail::certainly_greater(rx.lo, ry.hi + margin)) return false;
    } else if (!hull_detail::certainly_greater(rx.lo, ry.hi)) {
      return false;
    }
  }
  return true;
}

}  // namespace tmcert
