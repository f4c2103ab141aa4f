#include "src/verify/verify.h"

#include "src/verify/prepared.h"

#include <CGAL/number_utils.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <thread>

namespace tmcert {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Safe: return "safe";
    case Verdict::Collision: return "collision";
    case Verdict::Undecided: return "undecided";
  }
  return "undecided";
}

const char* to_string(KernelKind k) {
  switch (k) {
    case KernelKind::Filtered: return "filtered";
    case KernelKind::Exact: return "exact";
    case KernelKind::Fast: return "fast";
  }
  return "filtered";
}

const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::Epsilon: return "epsilon";
    case StopReason::Depth: return "depth";
    case StopReason::Limit: return "limit";
  }
  return "limit";
}

namespace {

// ------------------------------------------------------------------ pairs

struct PairRef {
  ContactKind kind;
  std::uint32_t i;  // in the moving body's table of that kind
  std::uint32_t j;  // in the other body's table
};

const FeatureTable& moving_table(const PreparedBody& b, ContactKind k) {
  return k == ContactKind::VertexFace ? b.vertices : k == ContactKind::EdgeEdge ? b.edges : b.faces;
}
const std::vector<FeatureGeometry<Exact>>& moving_exact(const PreparedBody& b, ContactKind k) {
  const ExactFeatures& e = b.exact();
  return k == ContactKind::VertexFace ? e.vertices : k == ContactKind::EdgeEdge ? e.edges : e.faces;
}
const std::vector<FeatureGeometry<Exact>>& other_exact(const PreparedBody& b, ContactKind k) {
  const ExactFeatures& e = b.exact();
  return k == ContactKind::VertexFace ? e.faces : k == ContactKind::EdgeEdge ? e.edges : e.vertices;
}
const FeatureTable& other_table(const PreparedBody& b, ContactKind k) {
  return k == ContactKind::VertexFace ? b.faces : k == ContactKind::EdgeEdge ? b.edges : b.vertices;
}

// The three contact types over all features: complete for the first contact
// after a contact-free start (proofs/contact-tests.md).
// Without a hierarchy every pair is carried: refuse sizes whose lists could
// not be held (about 1.2 GB at the limit) rather than thrash.
constexpr std::size_t kMaxPairs = 100'000'000;

std::vector<PairRef> all_pairs(const PreparedBody& m, const PreparedBody& f) {
  std::size_t total = 0;
  for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex})
    total += moving_table(m, k).size() * other_table(f, k).size();
  if (total > kMaxPairs)
    throw ResourceLimit("check of \"" + m.body->name + "\" and \"" + f.body->name + "\": " + std::to_string(total) +
                        " feature pairs exceed the limit of " + std::to_string(kMaxPairs) +
                        " (bodies this large need the bounding-volume hierarchy of a later version)");
  std::vector<PairRef> pairs;
  pairs.reserve(total);
  for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
    const std::size_t nx = moving_table(m, k).size(), ny = other_table(f, k).size();
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        pairs.push_back({k, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
  }
  return pairs;
}

// ------------------------------------------------------------------ kernels
// Each policy supplies the piece representation, its ball and the contact
// test in one number type; the search below is shared.  B = 1: body 1 moves,
// body 2 is fixed (world coordinates, no rho term); B = 2: both move along
// their joint curve, with the product metric.

template <int B, class FT>
Placement<FT> make_placement(const std::array<FT, 12 * B>& center, const FT& r2) {
  Placement<FT> p;
  for (int e = 0; e < 12; ++e) p.g1[e] = center[e];
  if constexpr (B == 2) {
    p.body2_moving = true;
    for (int e = 0; e < 12; ++e) p.g2[e] = center[12 + e];
  }
  p.r2 = r2;
  return p;
}

template <int B>
Metrics<B> metrics_of(const PreparedBody& m, const PreparedBody& f) {
  if constexpr (B == 1) return {&m.metric_data};
  else return {&m.metric_data, &f.metric_data};
}

template <int B>
struct FilteredPolicy {
  using Piece = HomogeneousCurve<Interval, B>;
  struct Ball {
    BallD<B> ball;
    Placement<Interval> interval;
    std::optional<Placement<Exact>> exact;  // built on the first exact fallback
    bool valid() const { return ball.valid; }
    double r2() const { return ball.r2; }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;

  Piece root() const { return enclose(curve); }
  void split(const Piece& p, Piece& l, Piece& r) const {
    RoundingGuard guard;  // interval de Casteljau encloses the exact halves
    split_half(p, l, r);
  }
  Ball ball(const Piece& p) const {
    Ball b{bounding_ball<B>(p, metrics_of<B>(m, f)), {}, std::nullopt};
    if (b.ball.valid) {
      std::array<Interval, 12 * B> c;
      for (int e = 0; e < 12 * B; ++e) c[e] = Interval(b.ball.center[e]);
      b.interval = make_placement<B>(c, Interval(b.ball.r2));
    }
    return b;
  }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats) const {
    const FeatureTable& X = moving_table(m, p.kind);
    const FeatureTable& Y = other_table(f, p.kind);
    return filtered(
        [&] { return contact_sign<Interval>(p.kind, X.interval[p.i], Y.interval[p.j], b.interval); },
        [&] {
          if (!b.exact) {
            std::array<Exact, 12 * B> c;
            for (int e = 0; e < 12 * B; ++e) c[e] = Exact(b.ball.center[e]);
            b.exact = make_placement<B>(c, Exact(b.ball.r2));
          }
          return contact_sign<Exact>(p.kind, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j], *b.exact);
        },
        stats.by_kind[static_cast<int>(p.kind)]);
  }
};

template <int B>
struct ExactPolicy {
  using Piece = HomogeneousCurve<Exact, B>;
  struct Ball {
    Placement<Exact> placement;
    bool valid() const { return true; }
    double r2() const { return CGAL::to_double(placement.r2); }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;

  Piece root() const { return curve; }
  void split(const Piece& p, Piece& l, Piece& r) const { split_half(p, l, r); }
  Ball ball(const Piece& p) const {
    BallE<B> b = bounding_ball<B>(p, metrics_of<B>(m, f));
    return Ball{make_placement<B>(b.center, b.r2)};
  }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats) const {
    FilterCounters& c = stats.by_kind[static_cast<int>(p.kind)];
    ++c.calls;
    ++c.exact_fallbacks;  // every call is exact
    return contact_sign<Exact>(p.kind, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j],
                               b.placement);
  }
};

template <int B>
struct FastPolicy {
  using Piece = HomogeneousCurve<double, B>;
  struct Ball {
    BallD<B> ball;
    Placement<double> placement;
    bool valid() const { return ball.valid; }
    double r2() const { return ball.r2; }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;

  Piece root() const { return approximate(curve); }
  void split(const Piece& p, Piece& l, Piece& r) const { split_half(p, l, r); }
  Ball ball(const Piece& p) const {
    Ball b{bounding_ball<B>(p, metrics_of<B>(m, f)), {}};
    b.placement = make_placement<B>(b.ball.center, b.ball.r2);
    return b;
  }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats) const {
    ++stats.by_kind[static_cast<int>(p.kind)].calls;
    return contact_sign<double>(p.kind, moving_table(m, p.kind).approx[p.i], other_table(f, p.kind).approx[p.j],
                                b.placement);
  }
};

// ------------------------------------------------------------------ static tests

struct StaticHit {
  int part_moving, part_other;
  Vec3E point;
};

std::optional<StaticHit> first_hit(const std::vector<StaticPart>& a, const std::vector<StaticPart>& b,
                                   const std::set<std::pair<int, int>>* only, CheckStats& stats) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (only && !only->count({static_cast<int>(i), static_cast<int>(j)})) continue;
      for (const Simplex& s : a[i].simplices)
        for (const Simplex& t : b[j].simplices) {
          ++stats.static_tests;
          if (auto p = common_point(s, t)) return StaticHit{static_cast<int>(i), static_cast<int>(j), *p};
        }
    }
  return std::nullopt;
}

// ------------------------------------------------------------------ search

// The rational with the smallest denominator in the closed interval
// [lo, hi] (continued fractions, i.e. the Stern-Brocot descent).
Exact simplest_between(const Exact& lo, const Exact& hi) {
  if (lo <= 0 && hi >= 0) return Exact(0);
  if (hi < 0) return -simplest_between(-hi, -lo);
  CGAL::Gmpz fl;
  mpz_fdiv_q(fl.mpz(), lo.numerator().mpz(), lo.denominator().mpz());
  if (Exact(fl) == lo) return lo;
  if (Exact(fl + 1) <= hi) return Exact(fl + 1);
  // Both in (fl, fl + 1): recurse on the reciprocals of the fractional parts.
  return Exact(fl) + Exact(1) / simplest_between(Exact(1) / (hi - Exact(fl)), Exact(1) / (lo - Exact(fl)));
}

// The deepest subdivision level: a node's parameter interval is
// [index, index + 1] / 2^depth with a 64-bit index.
constexpr int kDepthCap = 62;

struct Node {
  std::uint64_t index;  // the piece is [index, index + 1] / 2^depth of the curve parameter
  int depth;
  std::vector<PairRef> alive;

  Exact u0() const { return at(index); }
  Exact u1() const { return at(index + 1); }
  Exact mid() const { return (u0() + u1()) / 2; }
  Exact at(std::uint64_t k) const {
    CGAL::Gmpz den;
    mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
    return Exact(CGAL::Gmpz(static_cast<unsigned long>(k)), den);
  }
};

template <int B>
struct Check {
  const PreparedBody& moving;    // body 1
  const PreparedBody& other;     // body 2: fixed (B = 1) or moving (B = 2)
  bool swapped;                  // the check names body 2 first
  const HomogeneousCurve<Exact, B>& curve;
  HomogeneousCurve<Interval, B> root_interval;  // encloses `curve`
  const Motion& motion;          // body 1's: the parameter interval
  double eps2;                   // epsilon^2 for the stop test (a tolerance)
  double rho2_sum;               // max rho1^2 (+ max rho2^2): the fat size per unit R^2
  const VerifyOptions& options;
  CheckResult& result;

  Exact scene_t(const Exact& u) const { return motion.t0 + u * (motion.t1 - motion.t0); }
  Exact curve_u(const Exact& t) const { return (t - motion.t0) / (motion.t1 - motion.t0); }

  void set_witness(const Exact& u, const StaticHit& hit) {
    const std::string a = moving.body->name + " " + moving.parts[hit.part_moving].name;
    const std::string b = other.body->name + " " + other.parts[hit.part_other].name;
    Witness w{scene_t(u), swapped ? std::array{b, a} : std::array{a, b}, hit.point};
    result.witness = w;
    result.verdict = Verdict::Collision;
  }

  // The configuration at curve parameter u: interval maps first (cheap),
  // exact only for simplex pairs the interval filter cannot separate.
  std::optional<StaticHit> static_test(const Exact& u, const std::set<std::pair<int, int>>* only) {
    std::array<std::array<Interval, 12>, B> maps;
    {
      RoundingGuard guard;
      const Interval ui = to_interval(u), vi = Interval(1) - ui;
      HomogeneousCurve<Interval, B> work = root_interval;
      constexpr std::size_t W = kHomogeneousSize<B> - 1;
      for (std::size_t level = 1; level < work.size(); ++level)
        for (std::size_t k = 0; k + level < work.size(); ++k)
          for (std::size_t e = 0; e <= W; ++e) work[k][e] = vi * work[k][e] + ui * work[k + 1][e];
      for (int b = 0; b < B; ++b)
        for (int e = 0; e < 12; ++e) maps[b][e] = work[0][12 * b + e] / work[0][W];
    }
    auto placed = [](const Simplex& s, const std::array<Interval, 12>* m) {
      SimplexI out;
      out.count = s.count;
      for (int k = 0; k < s.count; ++k) {
        const std::array<Interval, 3> x = {to_interval(s.p[k][0]), to_interval(s.p[k][1]), to_interval(s.p[k][2])};
        if (!m) { out.p[k] = x; continue; }
        for (int i = 0; i < 3; ++i)
          out.p[k][i] = (*m)[4 * i] * x[0] + (*m)[4 * i + 1] * x[1] + (*m)[4 * i + 2] * x[2] + (*m)[4 * i + 3];
      }
      return out;
    };
    struct Candidate { int pi, si, pj, sj; };
    std::vector<Candidate> candidates;
    {
      RoundingGuard guard;
      for (std::size_t i = 0; i < moving.parts.size(); ++i)
        for (std::size_t j = 0; j < other.parts.size(); ++j) {
          if (only && !only->count({static_cast<int>(i), static_cast<int>(j)})) continue;
          const auto& A = moving.parts[i].simplices;
          const auto& Bs = other.parts[j].simplices;
          for (std::size_t si = 0; si < A.size(); ++si) {
            const SimplexI a = placed(A[si], &maps[0]);
            for (std::size_t sj = 0; sj < Bs.size(); ++sj) {
              const SimplexI b = placed(Bs[sj], B == 2 ? &maps[B - 1] : nullptr);
              if (!certainly_disjoint(a, b))
                candidates.push_back({static_cast<int>(i), static_cast<int>(si), static_cast<int>(j), static_cast<int>(sj)});
            }
          }
        }
    }
    if (candidates.empty()) return std::nullopt;
    const Mat34E m1 = evaluate<B>(curve, u, 0);
    std::optional<Mat34E> m2;
    if constexpr (B == 2) m2 = evaluate<B>(curve, u, 1);
    auto exact_placed = [](Simplex s, const Mat34E* m) {
      if (m)
        for (int k = 0; k < s.count; ++k) {
          Vec3E r;
          for (int i = 0; i < 3; ++i)
            r[i] = (*m)[4 * i] * s.p[k][0] + (*m)[4 * i + 1] * s.p[k][1] + (*m)[4 * i + 2] * s.p[k][2] + (*m)[4 * i + 3];
          s.p[k] = r;
        }
      return s;
    };
    for (const Candidate& c : candidates) {
      ++result.stats.static_tests;
      const Simplex a = exact_placed(moving.parts[c.pi].simplices[c.si], &m1);
      const Simplex b = exact_placed(other.parts[c.pj].simplices[c.sj], m2 ? &*m2 : nullptr);
      if (auto p = common_point(a, b)) return StaticHit{c.pi, c.pj, *p};
    }
    return std::nullopt;
  }

  // Exact static test of the configuration at curve parameter u, restricted
  // to the parts that still have a live feature pair.
  bool try_witness(const Exact& u, const std::vector<PairRef>& alive) {
    std::set<std::pair<int, int>> parts;
    for (const PairRef& p : alive)
      parts.insert({moving_table(moving, p.kind).part[p.i], other_table(other, p.kind).part[p.j]});
    if (auto hit = static_test(u, &parts)) {
      set_witness(u, *hit);
      return true;
    }
    return false;
  }

  void record(const Node& n, StopReason reason) {
    const Exact t0 = scene_t(n.u0()), t1 = scene_t(n.u1());
    if (!result.undecided.empty() && result.undecided.back().t1 == t0 && result.undecided.back().reason == reason)
      result.undecided.back().t1 = t1;
    else
      result.undecided.push_back({t0, t1, reason});
    if (!result.first_contact) result.first_contact = std::pair{t0, t1};
  }

  template <class Policy>
  void search(const Policy& policy) {
    struct Item {
      Node node;
      typename Policy::Piece piece;
    };
    std::vector<Item> stack;
    stack.push_back({Node{0, 0, all_pairs(moving, other)}, policy.root()});
    const int max_depth = std::min(options.max_depth, kDepthCap);
    CheckStats& stats = result.stats;
    while (!stack.empty()) {
      Item item = std::move(stack.back());
      stack.pop_back();
      Node& node = item.node;
      if (stats.nodes >= options.max_nodes) {  // resource limit: not cleared
        record(node, StopReason::Limit);
        continue;
      }
      ++stats.nodes;
      stats.max_depth = std::max(stats.max_depth, node.depth);
      typename Policy::Ball ball = policy.ball(item.piece);
      if (ball.valid())  // keep the pairs not cleared on this piece
        std::erase_if(node.alive, [&](const PairRef& p) { return policy.test(ball, p, stats) == CGAL::POSITIVE; });
      if (node.alive.empty()) continue;  // cleared on the whole piece
      std::optional<StopReason> stop;
      if (node.depth >= max_depth) stop = StopReason::Depth;
      else if (ball.valid() && ball.r2() * rho2_sum < eps2) stop = StopReason::Epsilon;
      if (stop) {
        // Witness candidates: the midpoint, the end, and the scene time with
        // the smallest denominator in the piece (a contact at a "round"
        // rational time, such as 1/3 or 0.137, is found exactly there).
        const Exact mid = node.mid();
        const Exact end = node.u1();
        const Exact simple = curve_u(simplest_between(scene_t(node.u0()), scene_t(end)));
        for (const Exact* u : {&mid, &end, &simple}) {
          if (try_witness(*u, node.alive)) {
            const Exact lo = result.first_contact ? result.first_contact->first : scene_t(node.u0());
            result.first_contact = std::pair{lo, scene_t(*u)};
            return;
          }
        }
        record(node, *stop);
        continue;
      }
      Item left{Node{2 * node.index, node.depth + 1, node.alive}, {}};
      Item right{Node{2 * node.index + 1, node.depth + 1, std::move(node.alive)}, {}};
      policy.split(item.piece, left.piece, right.piece);
      stack.push_back(std::move(right));
      stack.push_back(std::move(left));  // parameter order: left first
    }
  }

  // The start check (DESIGN.md section 4: the contact tests are complete
  // only after a contact-free start), then the search.
  void run() {
    if (auto hit = static_test(Exact(0), nullptr)) {
      set_witness(Exact(0), *hit);
      result.first_contact = std::pair{motion.t0, motion.t0};
      return;
    }
    switch (options.kernel) {
      case KernelKind::Filtered: search(FilteredPolicy<B>{moving, other, curve}); break;
      case KernelKind::Exact: search(ExactPolicy<B>{moving, other, curve}); break;
      case KernelKind::Fast: search(FastPolicy<B>{moving, other, curve}); break;
    }
  }
};

Vec3E apply_map(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

std::vector<Vec3E> body_vertices(const Body& b) {
  std::vector<Vec3E> v;
  for (const auto& poly : b.polygons) v.insert(v.end(), poly.begin(), poly.end());
  for (const auto& s : b.segments) v.insert(v.end(), s.begin(), s.end());
  v.insert(v.end(), b.points.begin(), b.points.end());
  return v;
}

}  // namespace

Exact default_epsilon(const Scene& scene) {
  std::optional<Vec3E> lo, hi;
  for (const Body& b : scene.bodies) {
    std::vector<Mat34E> maps;
    if (b.motion) maps = b.motion->control_points;
    else maps.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
    for (const Vec3E& v : body_vertices(b))
      for (const Mat34E& m : maps) {
        const Vec3E w = apply_map(m, v);
        if (!lo) { lo = w; hi = w; continue; }
        for (int i = 0; i < 3; ++i) {
          if (w[i] < (*lo)[i]) (*lo)[i] = w[i];
          if (w[i] > (*hi)[i]) (*hi)[i] = w[i];
        }
      }
  }
  if (!lo) return Exact(1, 1000);
  Exact d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += ((*hi)[i] - (*lo)[i]) * ((*hi)[i] - (*lo)[i]);
  const double eps = std::sqrt(CGAL::to_double(d2)) / 1000;
  if (!(eps > 0) || !std::isfinite(eps)) return Exact(1, 1000);
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", eps);
  Exact out;
  if (!parse_exact(text, out) || !(out > 0)) return Exact(1, 1000);
  return out;
}

void require_supported(const Scene& scene) {
  for (const Body& b : scene.bodies)
    if (b.solid) throw InputError(scene.source + ": body \"" + b.name + "\": solid bodies are not supported yet");
  // Nothing to check would be reported "safe" vacuously: a user who forgot
  // the motion or the checks must hear about it instead.
  if (scene.checks.empty())
    throw InputError(scene.source + ": checks: nothing to check (no body has a motion and no checks are given, "
                     "or the list is empty)");
  for (const auto& [a, b] : scene.checks) {
    const Body& x = scene.bodies[a];
    const Body& y = scene.bodies[b];
    const bool mx = x.motion && x.motion->degree() >= 1, my = y.motion && y.motion->degree() >= 1;
    if (mx && my && (x.motion->t0 != y.motion->t0 || x.motion->t1 != y.motion->t1))
      throw InputError(scene.source + ": checks: [\"" + x.name + "\", \"" + y.name +
                       "\"]: two moving bodies must share their motion interval");
  }
}

namespace {

CheckResult run_check(int a, int b, const PreparedBody& pa, const PreparedBody& pb,
                      const VerifyOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  CheckResult result;
  result.bodies = {a, b};
  const bool swapped = !pa.moving && pb.moving;
  const PreparedBody& moving = swapped ? pb : pa;
  const PreparedBody& other = swapped ? pa : pb;

  auto finish = [&] {
    for (const FilterCounters& c : result.stats.by_kind) result.stats.contact += c;
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
  };

  if (!moving.moving) {
    // Two motionless bodies: one exact static test decides.
    if (auto hit = first_hit(moving.parts, other.parts, nullptr, result.stats)) {
      const std::string x = moving.body->name + " " + moving.parts[hit->part_moving].name;
      const std::string y = other.body->name + " " + other.parts[hit->part_other].name;
      const Exact t0 = moving.body->motion ? moving.body->motion->t0 : Exact(0);
      result.verdict = Verdict::Collision;
      result.witness = Witness{t0, swapped ? std::array{y, x} : std::array{x, y}, hit->point};
      result.first_contact = std::pair{t0, t0};
    } else {
      result.verdict = Verdict::Safe;
    }
    return finish();
  }

  const Motion& motion = *moving.body->motion;
  const double eps = CGAL::to_double(options.epsilon);
  if (!other.moving) {
    Check<1> check{moving, other, swapped, moving.curve, enclose(moving.curve), motion, eps * eps, moving.max_rho2, options, result};
    check.run();
  } else {
    const HomogeneousCurve<Exact, 2> joint = joint_curve(motion, *other.body->motion);
    Check<2> check{moving, other, false, joint, enclose(joint), motion, eps * eps, moving.max_rho2 + other.max_rho2, options, result};
    check.run();
  }
  if (result.verdict != Verdict::Collision)
    result.verdict = result.undecided.empty() ? Verdict::Safe : Verdict::Undecided;
  if (result.verdict == Verdict::Safe) result.first_contact.reset();
  return finish();
}

}  // namespace

Verifier::Verifier(const Scene& scene, const VerifyOptions& options)
    : scene_(scene), options_(options), once_(new std::once_flag[scene.bodies.size()]),
      prepared_(scene.bodies.size()) {
  boxes_.reserve(scene.bodies.size());
  for (const Body& b : scene.bodies) boxes_.push_back(swept_box(b));
}

Verifier::~Verifier() = default;

const PreparedBody& Verifier::prepared(int body) const {
  std::call_once(once_[body], [&] { prepared_[body] = std::make_unique<PreparedBody>(scene_.bodies[body]); });
  return *prepared_[body];
}

CheckResult Verifier::check(int a, int b) const {
  const Body& x = scene_.bodies[a];
  const Body& y = scene_.bodies[b];
  const bool mx = x.motion && x.motion->degree() >= 1, my = y.motion && y.motion->degree() >= 1;
  // A solid's inside counts as contact: that needs an exact containment
  // test this version does not have, so it refuses rather than treat the
  // solid as its surface (which could certify a false "safe").
  for (const Body* body : {&x, &y})
    if (body->solid)
      throw InputError(scene_.source + ": body \"" + body->name + "\": solid bodies are not supported yet");
  // The joint curve pairs the motions by curve parameter: that is the same
  // instant only when the scene intervals agree.
  if (mx && my && (x.motion->t0 != y.motion->t0 || x.motion->t1 != y.motion->t1))
    throw InputError(scene_.source + ": checks: [\"" + x.name + "\", \"" + y.name +
                     "\"]: two moving bodies must share their motion interval");
  if (disjoint(boxes_[a], boxes_[b])) {
    // Certified prefilter: the boxes hold everything the bodies sweep.
    CheckResult result;
    result.bodies = {a, b};
    result.verdict = Verdict::Safe;
    result.stats.prefiltered = true;
    return result;
  }
  return run_check(a, b, prepared(a), prepared(b), options_);
}

CheckResult verify_check(const Scene& scene, int body_a, int body_b, const VerifyOptions& options) {
  return Verifier(scene, options).check(body_a, body_b);
}

SceneResult verify_scene(const Scene& scene, const VerifyOptions& options, int threads) {
  require_supported(scene);
  SceneResult out;
  out.kernel = options.kernel;
  out.certified = options.kernel != KernelKind::Fast;
  out.epsilon = options.epsilon;

  const Verifier verifier(scene, options);
  out.checks.resize(scene.checks.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    try {
      for (std::size_t k = next++; k < scene.checks.size(); k = next++) {
        const auto [a, b] = scene.checks[k];
        out.checks[k] = verifier.check(a, b);
      }
    } catch (...) {  // reported by the caller; never a verdict
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = scene.checks.size();
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(scene.checks.size())));
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  out.verdict = Verdict::Safe;
  for (const CheckResult& c : out.checks) {
    if (c.verdict == Verdict::Collision) out.verdict = Verdict::Collision;
    else if (c.verdict == Verdict::Undecided && out.verdict == Verdict::Safe) out.verdict = Verdict::Undecided;
  }
  return out;
}

}  // namespace tmcert
