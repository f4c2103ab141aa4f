// Internal to src/verify: exact resolution of the feature pairs alive on a
// piece of a rational motion (proofs/exact-resolution.md).  Every alive
// pair's earliest contact in the closed piece is computed exactly
// (kernels/moving_contact.h); none means the piece is cleared, otherwise
// the earliest over all pairs is the first contact in the piece, and
// becomes the witness (a rational time gets the usual exact static test and
// point, an irrational one its root and a rational point box).
#pragma once

#include "kernels/moving_contact.h"
#include "src/verify/pairs.h"
#include "src/verify/verify.h"

#include <memory>
#include <mutex>
#include <optional>
#include <tuple>
#include <vector>

namespace tmcert::detail {

// A curve's coordinates as polynomials in u (power basis), from its
// Bernstein control points.
template <int B>
std::vector<PolyQ> power_basis(const HomogeneousCurve<Exact, B>& curve) {
  // sum_k b_k B_k(u) = sum_i C(n, i) (Delta^i b)_0 u^i (forward differences:
  // subtractions and one integer product per coefficient, no divisions).
  const int n = static_cast<int>(curve.size()) - 1;
  std::vector<Exact> binom(n + 1);
  binom[0] = 1;
  for (int k = 1; k <= n; ++k) binom[k] = binom[k - 1] * (n - k + 1) / k;
  std::vector<PolyQ> out(kHomogeneousSize<B>);
  std::vector<Exact> d(n + 1);
  for (std::size_t e = 0; e < kHomogeneousSize<B>; ++e) {
    for (int k = 0; k <= n; ++k) d[k] = curve[k][e];
    PolyQ p(n + 1);
    for (int i = 0; i <= n; ++i) {
      if (d[0] != 0) p[i] = d[0] * binom[i];
      for (int j = 0; j + i < n; ++j) d[j] = d[j + 1] - d[j];
    }
    trim(p);
    out[e] = std::move(p);
  }
  return out;
}

// A check's curve in the power basis, computed once (the search's forks
// share it across threads).
struct PowerBasisCache {
  std::once_flag once;
  std::vector<PolyQ> power;
};

// The moving points of one body's feature: block `block` of the curve in
// power basis (or, block < 0, a fixed body: w(u) times its world points).
inline MovingPoint moving_point(const std::vector<PolyQ>& power, int block, const Vec3E& x) {
  MovingPoint m;
  const PolyQ& w = power.back();
  for (int i = 0; i < 3; ++i) {
    if (block < 0) {
      for (const Exact& c : w) m.x[i].push_back(c * x[i]);
      trim(m.x[i]);
      continue;
    }
    const std::size_t base = 12 * static_cast<std::size_t>(block) + 4 * i;
    PolyQ acc = power[base + 3];
    for (int j = 0; j < 3; ++j) {
      if (x[j] == 0) continue;
      PolyQ term = power[base + j];
      for (Exact& c : term) c *= x[j];
      acc = add(acc, term);
    }
    m.x[i] = std::move(acc);
  }
  return m;
}

// The exact vertices of the features of a pair's kind, per body.
inline const std::vector<std::vector<Vec3E>>& moving_vertices(const PreparedBody& b, ContactKind k) {
  const ExactFeatureVertices& e = b.exact_vertices();
  return k == ContactKind::VertexFace ? e.vertices : k == ContactKind::EdgeEdge ? e.edges : e.faces;
}
inline const std::vector<std::vector<Vec3E>>& other_vertices(const PreparedBody& b, ContactKind k) {
  const ExactFeatureVertices& e = b.exact_vertices();
  return k == ContactKind::VertexFace ? e.faces : k == ContactKind::EdgeEdge ? e.edges : e.vertices;
}

struct PairContact {
  PairRef pair;
  int part_moving, part_other;
  Contact contact;
};

// The earliest contact of the alive feature pairs in the curve piece
// [u0, u1], or nothing when none touches there; with several at that time,
// the one of the smallest (moving part, other part).  nullopt in `decided`
// means not decided (a node pair alive, an unexpected feature, an
// iteration cap): the caller keeps the piece.
struct PieceResolution {
  bool decided = false;
  std::optional<PairContact> first;
};

template <int B>
PieceResolution resolve_piece(const PreparedBody& moving, const PreparedBody& other,
                              const HomogeneousCurve<Exact, B>& curve, const std::vector<PolyQ>& power,
                              const Exact& u0, const Exact& u1, const std::vector<PairRef>& alive) {
  PieceResolution out;
  for (const PairRef& p : alive)
    if (p.nodes) return out;
  (void)curve;
  // The common weight w(u) > 0 on [0, 1] (positive weights): its factors
  // are divided out of the contact polynomials.
  const ContactSolver solver(u0, u1, primitive(power.back()));
  const int other_block = B == 2 ? 1 : -1;
  try {
    for (const PairRef& p : alive) {
      const std::vector<Vec3E>& fm = moving_vertices(moving, p.kind)[p.i];
      const std::vector<Vec3E>& fo = other_vertices(other, p.kind)[p.j];
      std::vector<MovingPoint> xm, xo;
      for (const Vec3E& v : fm) xm.push_back(moving_point(power, 0, v));
      for (const Vec3E& v : fo) xo.push_back(moving_point(power, other_block, v));
      std::optional<Contact> c;
      if (xm.size() == 1 && xo.size() >= 3) c = solver.vertex_face(xm[0], xo);
      else if (xm.size() >= 3 && xo.size() == 1) c = solver.vertex_face(xo[0], xm);
      else if (xm.size() == 2 && xo.size() == 2) c = solver.edge_edge(xm[0], xm[1], xo[0], xo[1]);
      else return out;  // not one of the three contact types
      if (!c) continue;
      const int pm = moving_table(moving, p.kind).part[p.i], po = other_table(other, p.kind).part[p.j];
      if (out.first) {
        const CGAL::Comparison_result order = compare(c->t, out.first->contact.t);
        if (order == CGAL::LARGER) continue;
        const PairRef& q = out.first->pair;
        if (order == CGAL::EQUAL && std::tuple(pm, po, p.kind, p.i, p.j) >=
                                        std::tuple(out.first->part_moving, out.first->part_other, q.kind, q.i, q.j))
          continue;
      }
      out.first = PairContact{p, pm, po, std::move(*c)};
      solver.set_bound(out.first->contact.t);  // later contacts cannot be the first
    }
  } catch (const ExactLimit&) {
    out.first.reset();
    return out;
  }
  out.decided = true;
  return out;
}

enum class ExactOutcome { Cleared, Witness, Undecided };

// Decides a piece of `check` (search.h's Check) exactly: Cleared when no
// alive pair touches in it, Witness (the check's witness and first contact
// set) at the earliest contact, Undecided when resolve_piece could not
// decide.  The first contact is exact when nothing before the piece was
// left undecided.
template <int B, class CheckT, class NodeT>
ExactOutcome decide_piece(CheckT& check, const NodeT& node) {
  CheckStats& stats = check.result.stats;
  PowerBasisCache& cache = *check.exact_power;
  std::call_once(cache.once, [&] { cache.power = power_basis<B>(check.curve); });
  const std::vector<PolyQ>& power = cache.power;
  PieceResolution r = resolve_piece<B>(check.moving, check.other, check.curve, power, node.u0(), node.u1(), node.alive);
  if (!r.decided) {
    ++stats.exact_unknown;
    return ExactOutcome::Undecided;
  }
  ++stats.exact_pieces;
  if (!r.first) return ExactOutcome::Cleared;
  PairContact& pc = *r.first;
  const bool exact_first = !check.result.first_contact;
  // The root's interval as isolated on the whole curve [0, 1]: the same
  // whichever piece found it (with or without the hierarchy, any thread
  // count).
  RealRoot isolated = pc.contact.t;
  try {
    if (!isolated.is_rational() && !(node.u0() == 0 && node.u1() == 1)) {  // on [0, 1] already
      RealRoot probe = isolated;
      for (const RealRoot& c : real_roots(isolated.poly, Exact(0), Exact(1))) {
        RealRoot candidate = c;  // compare narrows its arguments
        if (compare(candidate, probe) == CGAL::EQUAL) {
          isolated = c;
          break;
        }
      }
    }
  } catch (const ExactLimit&) {
    ++stats.exact_unknown;
    return ExactOutcome::Undecided;
  }
  pc.contact.t = isolated;
  try {
    settle_rational(pc.contact.t);
    if (pc.contact.t.is_rational()) {
      // A rational time: the exact static test of the two parts there (it
      // must hit: the pair touches at u; if it does not, the piece stays
      // undecided rather than trusting either computation).
      const Exact u = pc.contact.t.lo;
      if (!check.try_witness(u, std::vector<PairRef>{pc.pair})) {
        ++stats.exact_unknown;
        return ExactOutcome::Undecided;
      }
      const Exact t = check.scene_t(u);
      check.result.first_contact = std::pair{exact_first ? t : check.result.first_contact->first, t};
      check.result.first_contact_exact = exact_first;
      return ExactOutcome::Witness;
    }
    const Motion& m = check.motion;
    const Exact length = m.t1 - m.t0;
    Witness w;
    const std::string a = check.moving.body->name + " " + check.moving.parts[pc.part_moving].name;
    const std::string b = check.other.body->name + " " + check.other.parts[pc.part_other].name;
    w.features = check.swapped ? std::array{b, a} : std::array{a, b};
    AlgebraicTime at;
    at.root_of = compose_affine(isolated.poly, -m.t0 / length, Exact(1) / length);
    at.lo = m.t0 + isolated.lo * length;
    at.hi = m.t0 + isolated.hi * length;
    w.point_box = point_box(pc.contact, power.back());  // narrows pc.contact.t
    at.approx = approximate(RealRoot{at.root_of, m.t0 + pc.contact.t.lo * length, m.t0 + pc.contact.t.hi * length});
    w.t = at.lo;
    w.root = std::move(at);
    check.result.first_contact = std::pair{exact_first ? w.root->lo : check.result.first_contact->first, w.root->hi};
    check.result.first_contact_exact = exact_first;
    check.result.witness = std::move(w);
    check.result.verdict = Verdict::Collision;
    return ExactOutcome::Witness;
  } catch (const ExactLimit&) {
    ++stats.exact_unknown;
    return ExactOutcome::Undecided;
  }
}

}  // namespace tmcert::detail
