// Contacts on the true shape of URDF cylinders and spheres (true_shape.h,
// proofs/robot-links.md section 6).
#include "src/verify/true_shape.h"

#include "src/model/segment_kind.h"
#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "src/verify/solid_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tmcert {

namespace {

using D3 = std::array<double, 3>;
using DPose = std::array<double, 12>;

const Mat34E kIdentityE = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

PoseInterval point_pose(const Mat34E& m) {
  PoseInterval out;
  for (int e = 0; e < 12; ++e) out[e] = to_interval(m[e]);
  return out;
}

DPose mid(const PoseInterval& m) {
  DPose out;
  for (int e = 0; e < 12; ++e) out[e] = 0.5 * (m[e].inf() + m[e].sup());
  return out;
}

D3 map_point(const DPose& m, const D3& x) {
  D3 r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

// The inverse of a rigid pose, approximately (a candidate's search only).
D3 map_inverse(const DPose& m, const D3& w) {
  const D3 d = {w[0] - m[3], w[1] - m[7], w[2] - m[11]};
  D3 r;
  for (int j = 0; j < 3; ++j) r[j] = m[j] * d[0] + m[4 + j] * d[1] + m[8 + j] * d[2];
  return r;
}

D3 to_d(const Vec3E& v) { return {CGAL::to_double(v[0]), CGAL::to_double(v[1]), CGAL::to_double(v[2])}; }

// The primitive's gauge at x (its frame): <= 1 inside, 1 on the boundary.
double gauge(const Body::Primitive& p, double r, double h, const D3& x) {
  if (p.kind == Body::Primitive::Kind::Sphere) return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / r;
  return std::max(std::sqrt(x[0] * x[0] + x[1] * x[1]) / r, std::abs(x[2]) / h);
}

struct PrimitiveFrame {
  const Body::Primitive* prim = nullptr;
  double r = 0, h = 0;  // radius, half-length (sphere: radius)
  DPose pose{};         // approximate, for candidates
};

PrimitiveFrame frame_of(const ShapeSide& s) {
  PrimitiveFrame f;
  f.prim = &*s.body->primitive;
  f.r = CGAL::to_double(f.prim->radius);
  f.h = f.prim->kind == Body::Primitive::Kind::Sphere ? f.r : CGAL::to_double(f.prim->length) / 2;
  f.pose = s.exact ? mid(point_pose(*s.exact)) : mid(s.enclosed);
  return f;
}

// ---------------------------------------------------------------- proofs

// Does the exact point x (the primitive's frame) lie in the true shape?
bool inside_exact(const Body::Primitive& p, const Vec3E& x) {
  if (p.kind == Body::Primitive::Kind::Sphere) return x[0] * x[0] + x[1] * x[1] + x[2] * x[2] <= p.radius * p.radius;
  const Exact h = p.length / 2;
  return x[0] * x[0] + x[1] * x[1] <= p.radius * p.radius && CGAL::abs(x[2]) <= h;
}

// Does every point of the box (the primitive's frame) lie in the true
// shape?  The largest square of a coordinate over [lo, hi] is the larger of
// lo^2 and hi^2, compared exactly.
bool inside_box(const Body::Primitive& p, const std::array<Interval, 3>& x) {
  std::array<Exact, 3> sq, abs;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(x[i].inf()) || !std::isfinite(x[i].sup())) return false;
    const Exact lo(x[i].inf()), hi(x[i].sup());
    abs[i] = std::max(CGAL::abs(lo), CGAL::abs(hi));
    sq[i] = abs[i] * abs[i];
  }
  if (p.kind == Body::Primitive::Kind::Sphere) return sq[0] + sq[1] + sq[2] <= p.radius * p.radius;
  return sq[0] + sq[1] <= p.radius * p.radius && abs[2] <= p.length / 2;
}

// The exact inverse image of w under the affine map m (nullopt when singular).
std::optional<Vec3E> solve(const Mat34E& m, const Vec3E& w) {
  const Exact a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], i = m[10];
  const Exact det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  if (det == 0) return std::nullopt;
  const Vec3E y = {w[0] - m[3], w[1] - m[7], w[2] - m[11]};
  // Cramer's rule with the adjugate.
  return Vec3E{((e * i - f * h) * y[0] - (b * i - c * h) * y[1] + (b * f - c * e) * y[2]) / det,
               (-(d * i - f * g) * y[0] + (a * i - c * g) * y[1] - (a * f - c * d) * y[2]) / det,
               ((d * h - e * g) * y[0] - (a * h - b * g) * y[1] + (a * e - b * d) * y[2]) / det};
}

// The world point of `side` at its frame point y: exact when possible.
std::optional<Vec3E> world_exact(const ShapeSide& side, const Vec3E& y) {
  if (side.placed) return y;
  if (!side.exact) return std::nullopt;
  const Mat34E& m = *side.exact;
  Vec3E w;
  for (int i = 0; i < 3; ++i) w[i] = m[4 * i] * y[0] + m[4 * i + 1] * y[1] + m[4 * i + 2] * y[2] + m[4 * i + 3];
  return w;
}

// Encloses the world point of `side` at its frame point y.  Under RoundingGuard.
std::array<Interval, 3> world_box(const ShapeSide& side, const Vec3E& y) {
  std::array<Interval, 3> p = {to_interval(y[0]), to_interval(y[1]), to_interval(y[2])};
  if (side.placed) return p;
  const PoseInterval& m = side.enclosed;
  std::array<Interval, 3> w;
  for (int i = 0; i < 3; ++i) w[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
  return w;
}

// Encloses the point of the primitive's frame at world box w: the pose of
// a link is rigid, so its inverse is R^T (w - c) for the true R, c in the
// enclosure.  Under RoundingGuard.
std::array<Interval, 3> frame_box(const ShapeSide& prim, const std::array<Interval, 3>& w) {
  const PoseInterval& m = prim.enclosed;
  const std::array<Interval, 3> d = {w[0] - m[3], w[1] - m[7], w[2] - m[11]};
  std::array<Interval, 3> x;
  for (int j = 0; j < 3; ++j) x[j] = m[j] * d[0] + m[4 + j] * d[1] + m[8 + j] * d[2];
  return x;
}

// Is the world point (exact, or only its box) proven in the primitive?
// With an exact pose and an exact point: exactly.  Otherwise the box, with
// the primitive's pose enclosed.
bool proven_in(const ShapeSide& prim, const std::optional<Vec3E>& w_exact, const std::array<Interval, 3>& w_box) {
  if (w_exact && prim.exact) {
    const std::optional<Vec3E> x = solve(*prim.exact, *w_exact);
    if (x) return inside_exact(*prim.body->primitive, *x);
  }
  RoundingGuard guard;
  return inside_box(*prim.body->primitive, frame_box(prim, w_box));
}

std::array<std::array<Exact, 2>, 3> rational_box(const std::array<Interval, 3>& w) {
  std::array<std::array<Exact, 2>, 3> out;
  for (int i = 0; i < 3; ++i) out[i] = {Exact(w[i].inf()), Exact(w[i].sup())};
  return out;
}

std::string primitive_name(const Body& b) {
  return b.name + " " + (b.primitive->kind == Body::Primitive::Kind::Sphere ? "sphere" : "cylinder");
}

// ---------------------------------------------------------------- candidates

// The point of a simplex (barycentric weights) where the primitive's gauge
// is smallest, approximately: a grid, then a pattern search.
std::pair<std::array<double, 3>, double> deepest(const PrimitiveFrame& pf, const std::array<D3, 3>& v, int count) {
  auto at = [&](const std::array<double, 3>& l) {
    D3 x{0, 0, 0};
    for (int k = 0; k < count; ++k)
      for (int i = 0; i < 3; ++i) x[i] += l[k] * v[k][i];
    return gauge(*pf.prim, pf.r, pf.h, x);
  };
  std::array<double, 3> best = {1, 0, 0};
  double g = at(best);
  if (count == 1) return {best, g};
  constexpr int kGrid = 8;
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= (count == 3 ? kGrid - i : 0); ++j) {
      const std::array<double, 3> l = {double(kGrid - i - j) / kGrid, double(i) / kGrid, double(j) / kGrid};
      if (const double gl = at(l); gl < g) {
        g = gl;
        best = l;
      }
    }
  // Pattern search in the simplex: move weight between pairs of vertices.
  for (double step = 1.0 / kGrid; step > 1e-12; step /= 2) {
    bool moved = true;
    while (moved) {
      moved = false;
      for (int a = 0; a < count; ++a)
        for (int b = 0; b < count; ++b) {
          if (a == b || best[a] <= 0) continue;
          std::array<double, 3> l = best;
          const double d = std::min(step, l[a]);
          l[a] -= d;
          l[b] += d;
          const double gl = at(l);
          if (gl < g) {
            g = gl;
            best = l;
            moved = true;
          }
        }
    }
  }
  return {best, g};
}

// Exact barycentric weights from approximate ones: non-negative, summing
// to 1 exactly.
Vec3E on_simplex(const Simplex& s, const std::array<double, 3>& l) {
  std::array<Exact, 3> w;
  Exact sum = 0;
  for (int k = 0; k < s.count; ++k) {
    w[k] = Exact(std::max(0.0, l[k]));
    sum += w[k];
  }
  if (sum == 0) {
    w[0] = 1;
    sum = 1;
  }
  Vec3E y{Exact(0), Exact(0), Exact(0)};
  for (int k = 0; k < s.count; ++k)
    for (int i = 0; i < 3; ++i) y[i] += w[k] / sum * s.p[k][i];
  return y;
}

// Primitive `p` against the polygons, segments and points of `o`.
std::optional<TrueContact> against_features(const ShapeSide& p, const ShapeSide& o, CheckStats& stats) {
  const PrimitiveFrame pf = frame_of(p);
  const DPose od = o.placed ? DPose{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0} : (o.exact ? mid(point_pose(*o.exact)) : mid(o.enclosed));
  struct Candidate {
    double g;
    int part, simplex;
    std::array<double, 3> l;
  };
  std::vector<Candidate> candidates;
  const std::vector<StaticPart>& parts = *o.parts;
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (std::size_t s = 0; s < parts[k].simplices.size(); ++s) {
      const Simplex& simplex = parts[k].simplices[s];
      std::array<D3, 3> v;
      D3 lo{}, hi{};
      for (int i = 0; i < simplex.count; ++i) {
        v[i] = map_inverse(pf.pose, map_point(od, to_d(simplex.p[i])));
        for (int c = 0; c < 3; ++c) {
          lo[c] = i == 0 ? v[i][c] : std::min(lo[c], v[i][c]);
          hi[c] = i == 0 ? v[i][c] : std::max(hi[c], v[i][c]);
        }
      }
      // The primitive lies in [-r, r]^2 x [-h, h]: a simplex whose box
      // misses it (with a margin for the approximation) cannot touch it.
      const double m = 1e-6 * (pf.r + pf.h);
      if (lo[0] > pf.r + m || hi[0] < -pf.r - m || lo[1] > pf.r + m || hi[1] < -pf.r - m || lo[2] > pf.h + m ||
          hi[2] < -pf.h - m)
        continue;
      const auto [l, g] = deepest(pf, v, simplex.count);
      if (g < 1) candidates.push_back({g, static_cast<int>(k), static_cast<int>(s), l});
    }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.g < b.g; });
  constexpr std::size_t kTries = 16;
  for (std::size_t c = 0; c < candidates.size() && c < kTries; ++c) {
    const Candidate& cand = candidates[c];
    ++stats.static_tests;
    const Vec3E y = on_simplex(parts[cand.part].simplices[cand.simplex], cand.l);
    const std::optional<Vec3E> w = world_exact(o, y);
    std::array<Interval, 3> box;
    {
      RoundingGuard guard;
      box = world_box(o, y);
    }
    if (!proven_in(p, w, box)) continue;
    TrueContact out;
    out.features = {primitive_name(*p.body), o.body->name + " " + parts[cand.part].name};
    if (w) out.point = *w;
    else {
      out.point_box = rational_box(box);
      out.local_point = y;
    }
    return out;
  }
  // The primitive wholly inside a solid body: its centre (exact poses only).
  if (o.body->solid && p.exact && (o.exact || o.placed)) {
    const Vec3E centre = {(*p.exact)[3], (*p.exact)[7], (*p.exact)[11]};
    const Mat34E om = o.placed ? fixed_pose(*o.body) : *o.exact;
    if (const std::unique_ptr<ClosedSurface> surface = placed_surface(*o.body, om)) {
      ++stats.static_tests;
      if (surface->contains(centre)) {
        TrueContact out;
        out.features = {primitive_name(*p.body) + " centre", o.body->name + " interior"};
        out.point = centre;
        return out;
      }
    }
  }
  return std::nullopt;
}

// Two primitives: a point deep in both, found by a pattern search on the
// smaller of the two margins 1 - gauge, then proven in each.
std::optional<TrueContact> two_primitives(const ShapeSide& a, const ShapeSide& b, CheckStats& stats) {
  const PrimitiveFrame fa = frame_of(a), fb = frame_of(b);
  auto margin = [&](const D3& z) {
    return std::min(1 - gauge(*fa.prim, fa.r, fa.h, map_inverse(fa.pose, z)),
                    1 - gauge(*fb.prim, fb.r, fb.h, map_inverse(fb.pose, z)));
  };
  const D3 ca = {fa.pose[3], fa.pose[7], fa.pose[11]}, cb = {fb.pose[3], fb.pose[7], fb.pose[11]};
  D3 best = ca;
  double m = margin(best);
  for (int k = 1; k <= 16; ++k) {  // along the segment between the centres
    const double t = k / 16.0;
    const D3 z = {ca[0] + t * (cb[0] - ca[0]), ca[1] + t * (cb[1] - ca[1]), ca[2] + t * (cb[2] - ca[2])};
    if (const double mz = margin(z); mz > m) {
      m = mz;
      best = z;
    }
  }
  const double scale = std::max(fa.r + fa.h, fb.r + fb.h);
  for (double step = scale / 8; step > scale * 1e-13; step /= 2) {
    bool moved = true;
    for (int rounds = 0; moved && rounds < 64; ++rounds) {
      moved = false;
      for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
          D3 z = best;
          z[axis] += sign * step;
          if (const double mz = margin(z); mz > m) {
            m = mz;
            best = z;
            moved = true;
          }
        }
    }
  }
  if (!(m > 0)) return std::nullopt;
  ++stats.static_tests;
  const Vec3E z = {Exact(best[0]), Exact(best[1]), Exact(best[2])};
  std::array<Interval, 3> box = {to_interval(z[0]), to_interval(z[1]), to_interval(z[2])};
  if (!proven_in(a, z, box) || !proven_in(b, z, box)) return std::nullopt;
  TrueContact out;
  out.features = {primitive_name(*a.body), primitive_name(*b.body)};
  out.point = z;
  return out;
}

}  // namespace

ShapeSide fixed_side(const PreparedBody& body) {
  ShapeSide s;
  s.body = body.body;
  s.parts = &body.parts;
  s.placed = true;
  s.exact = fixed_pose(*body.body);
  s.enclosed = point_pose(*s.exact);
  return s;
}

ShapeSide moving_side(const PreparedBody& body, const std::optional<Mat34E>& exact, const PoseInterval& enclosed) {
  ShapeSide s;
  s.body = body.body;
  s.parts = &body.parts;
  s.placed = false;
  s.exact = exact;
  s.enclosed = exact ? point_pose(*exact) : enclosed;
  return s;
}

Witness witness_of(const Exact& t, const TrueContact& c, bool swapped) {
  Witness w;
  w.t = t;
  w.features = c.features;
  if (swapped) std::swap(w.features[0], w.features[1]);
  if (c.point) w.point = *c.point;
  w.point_box = c.point_box;
  w.true_shape = true;
  w.local_point = c.local_point;
  w.local_side = swapped ? 1 - c.local_side : c.local_side;
  return w;
}

ShapeSide side_at(const PreparedBody& body, const Exact& t) {
  if (!body.moving) return fixed_side(body);
  const Body& b = *body.body;
  std::optional<Mat34E> exact;
  PoseInterval enclosed;
  const MotionSegment* segment = nullptr;
  if (b.trajectory) {
    for (const MotionSegment& seg : b.trajectory->segments)
      if (seg.t0 <= t && t <= seg.t1) {
        segment = &seg;
        break;
      }
    if (!segment) segment = t < b.trajectory->t0() ? &b.trajectory->segments.front() : &b.trajectory->segments.back();
  }
  const Motion* rational = segment ? kind_of(*segment).rational(*segment) : nullptr;
  if (segment && !rational) {
    const std::unique_ptr<SegmentModel> model = make_segment_model(*segment);
    const Exact s = (t - segment->t0) / (segment->t1 - segment->t0);
    exact = model->exact_pose(s);
    if (!exact) enclosed = enclose_pose(*model, s);
  } else {
    const Motion& m = segment ? *rational : *b.motion;
    exact = m.degree() == 0 ? m.control_points[0] : motion_pose(m, t);
  }
  return moving_side(body, exact, enclosed);
}

void settle_enlarged(CheckResult& r, const PreparedBody& a, const PreparedBody& b, const Exact& t_end) {
  if (r.verdict != Verdict::Collision || !r.witness || r.witness->true_shape || !enlarged_pair(*a.body, *b.body)) return;
  const Exact t = r.witness->t;
  if (!r.witness->root) {  // a rational instant: the true shapes there
    CheckStats stats;
    const std::optional<TrueContact> c = true_contact(side_at(a, t), side_at(b, t), stats);
    r.stats.static_tests += stats.static_tests;
    if (c) {
      r.witness = witness_of(t, *c);
      return;
    }
  }
  // Undecided from where nothing was proven any more: the start of the
  // bracket before the witness, or the end of the last undecided part.
  Exact from = r.first_contact ? r.first_contact->first : t;
  for (const UndecidedInterval& u : r.undecided) from = std::max(from, u.t1);
  from = std::min(from, t);
  const Exact to = std::max(from, t_end);
  r.verdict = Verdict::Undecided;
  r.witness.reset();
  r.first_contact_exact = false;
  r.undecided.push_back({from, to, StopReason::EnlargedModel});
  if (!r.first_contact) r.first_contact = std::pair{from, to};
  else r.first_contact->second = std::max(r.first_contact->second, to);
}

std::optional<TrueContact> true_contact(const ShapeSide& a, const ShapeSide& b, CheckStats& stats) {
  const bool pa = a.body->primitive.has_value(), pb = b.body->primitive.has_value();
  if (pa && pb) return two_primitives(a, b, stats);
  if (pa) return against_features(a, b, stats);
  if (pb) {
    std::optional<TrueContact> c = against_features(b, a, stats);
    if (c) {
      std::swap(c->features[0], c->features[1]);
      c->local_side = 0;
    }
    return c;
  }
  return std::nullopt;
}

}  // namespace tmcert
