// Writing certificates (writer.h, docs/certificate-format.md).  The
// writer's files: writer_common.h (shared vocabulary, defined here),
// writer_groups.cpp (the groups of a body), writer_prover.cpp (proofs of a
// piece), this file (each check's pieces and its document),
// writer_claims.cpp (witnesses and start claims).
#include "src/certificate/writer.h"
#include "src/certificate/writer_check.h"

#include "src/certificate/check.h"
#include "src/certificate/exact_claims.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

namespace tmcert::certificate {

namespace writer_internal {

std::array<double, 3> rounded(const std::array<double, 3>& n) {
  const double m = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
  if (!(m > 0) || !std::isfinite(m)) return n;
  const double unit = std::ldexp(1.0, std::ilogb(m) - 20);
  return {std::nearbyint(n[0] / unit) * unit, std::nearbyint(n[1] / unit) * unit, std::nearbyint(n[2] / unit) * unit};
}

Motion motion_or_identity(const Body& b) {
  if (b.motion) return *b.motion;
  Motion m;
  m.control_points = {kIdentity};
  m.weights = {Exact(1)};
  return m;
}

bool general_check(const Body& a, const Body& b, const Exact& clearance) {
  return a.trajectory || b.trajectory || a.tolerance > 0 || b.tolerance > 0 || clearance > 0;
}

Vec3E apply(const Mat34E& m, const Vec3E& x) {
  Vec3E y;
  for (int i = 0; i < 3; ++i) y[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return y;
}

Mat34E pose(const Body& b, const Exact& t) {
  if (b.trajectory) {
    const std::optional<Mat34E> m = exact_pose_at(b, t);
    if (!m) throw ResourceLimit("certificate: the pose of " + b.name + " at t = " + to_string(t) + " is not exact");
    return *m;
  }
  if (!b.motion) return kIdentity;
  const Motion& m = *b.motion;
  return evaluate<1>(homogeneous_curve(m), (t - m.t0) / (m.t1 - m.t0));
}

json rational(const Exact& q) { return to_string(q); }

json vec(const Vec3E& v) { return json::array({rational(v[0]), rational(v[1]), rational(v[2])}); }

// ---------------------------------------------------------------- one check

Exact CheckWriter::scene_t(std::uint64_t index, int depth) const {
  CGAL::Gmpz den;
  mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
  const Exact u(CGAL::Gmpz(static_cast<unsigned long>(index)), den);
  return interval.first + u * (interval.second - interval.first);
}

Exact CheckWriter::curve_u(std::uint64_t index, int depth) const {
  CGAL::Gmpz den;
  mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
  return Exact(CGAL::Gmpz(static_cast<unsigned long>(index)), den);
}

void CheckWriter::set_no_contact(const Prover& prover, const Exact& u0, const Exact& u1, const RealRoot* before) const {
  if (!motions) motions = std::make_unique<CheckMotions>(a, b);
  prover.no_contact = [this, &prover, u0, u1, before](int ea, int eb) {
    try {
      return no_contact_error(*motions, prover.groups[0]->elements[ea], prover.groups[1]->elements[eb], u0, u1,
                              before)
          .empty();
    } catch (const ResourceLimit&) {
      return false;  // not proven: the writer bisects or fails as without the claim
    }
  };
}

void CheckWriter::fail(const std::string& what) const {
  throw ResourceLimit("certificate: " + a.name + " x " + b.name + ": " + what);
}

// Pieces covering the cleared part of the parameter interval: the
// search's pieces, or the whole interval for a check decided without a
// search.
// (The search reports its pieces in the order its tasks finish; they are
// disjoint, so sorting puts them in parameter order.)
std::vector<CoverPiece> CheckWriter::cover() const {
  if (r.verdict == Verdict::Safe && r.cleared.empty()) return {CoverPiece{0, 0}};
  std::vector<std::pair<Exact, CoverPiece>> sorted;
  for (const CoverPiece& c : r.cleared)
    if (r.verdict != Verdict::Collision || scene_t(c.index + 1, c.depth) <= r.first_contact->first)
      sorted.emplace_back(scene_t(c.index, c.depth), c);
  std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<CoverPiece> out;
  for (const auto& [t, c] : sorted) out.push_back(c);
  return out;
}

// The scene interval of a cleared piece.
std::pair<Exact, Exact> CheckWriter::piece_times(const CoverPiece& c) const {
  if (c.timed) return {c.t0, c.t1};
  return {scene_t(c.index, c.depth), scene_t(c.index + 1, c.depth)};
}

// A general check's cover as scene intervals in order, cut at every join
// of either body's motion (the checker wants each piece inside one
// segment of each motion).
std::vector<std::pair<Exact, Exact>> CheckWriter::general_cover() const {
  std::vector<std::pair<Exact, Exact>> times;
  if (r.verdict == Verdict::Safe && r.cleared.empty()) times.push_back(interval);
  for (const CoverPiece& c : r.cleared) {
    const auto t = piece_times(c);
    if (r.verdict != Verdict::Collision || t.second <= r.first_contact->first) times.push_back(t);
  }
  std::sort(times.begin(), times.end());
  std::vector<Exact> joins;
  for (const Body* body : {&a, &b})
    if (body->trajectory)
      for (const MotionSegment& seg : body->trajectory->segments) joins.push_back(seg.t1);
  std::sort(joins.begin(), joins.end());
  std::vector<std::pair<Exact, Exact>> out;
  for (auto [lo, hi] : times) {
    for (const Exact& j : joins)
      if (lo < j && j < hi) {
        out.push_back({lo, j});
        lo = j;
      }
    out.push_back({lo, hi});
  }
  return out;
}

// A piece of a general check (the checker's general_piece): the joint
// curve of the two exact restrictions, or one control point at the pose
// boxes' centres with their radii as a penalty; bisected (the boxes
// recomputed on each half) when no proof is found.
// Returns false (having written the pieces before it) when a piece
// cannot be proven and `partial` allows stopping there: a collision's
// certificate may prove less of the time before its witness than the
// verifier did (a tolerance's plane margin is coarser than the search's
// metric balls); its first-contact bracket then starts earlier.
bool CheckWriter::prove_general(const Prover& prover, const Exact& ta, const Exact& tb, int extra, const Exact& margin,
                   const std::array<Exact, 4> (&bounds)[2], bool partial, json& pieces) {
  std::optional<PieceMotion> m[2];
  const Body* bodies[2] = {&a, &b};
  std::string why;
  for (int k = 0; k < 2 && why.empty(); ++k) m[k] = piece_motion(*bodies[k], ta, tb, why);
  auto bisect = [&](const std::string& what) {
    if (extra == 0) ++stats.bisections;
    if (extra >= kMaxExtraDepth) {
      if (partial) return false;
      fail(what + " after " + std::to_string(extra) + " bisections");
    }
    const Exact mid = (ta + tb) / 2;
    return prove_general(prover, ta, mid, extra + 1, margin, bounds, partial, pieces) &&
           prove_general(prover, mid, tb, extra + 1, margin, bounds, partial, pieces);
  };
  if (!why.empty()) {
    if (why.find("inside one segment") != std::string::npos) fail(why);
    return bisect(why);  // an enclosure too wide to be finite: smaller pieces
  }
  CurveE exact_curve;
  CurveI curve;
  std::array<double, 3> penalty{0, 0, 0};
  const bool exact = m[0]->exact && m[1]->exact;
  if (exact) {
    exact_curve = joint_curve(*m[0]->exact, *m[1]->exact);
    curve = enclose(exact_curve);
  } else {
    std::array<Interval, 25> c;
    std::array<Exact, 3> pen{Exact(0), Exact(0), Exact(0)};
    for (int k = 0; k < 2; ++k) {
      const PoseBox box = m[k]->exact ? control_box(*m[k]->exact) : m[k]->box;
      for (int e = 0; e < 12; ++e) c[12 * k + e] = to_interval(box.center[e]);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) pen[i] += box.radius[4 * i + j] * bounds[k][j];
    }
    c[kWeight] = Interval(1);
    curve = {c};
    for (int i = 0; i < 3; ++i) penalty[i] = to_interval(pen[i]).sup();
  }
  PieceImages im = prover.images(curve);
  im.margin = to_interval(margin).sup();
  im.penalty = penalty;
  const std::function<const CurveE&()> exact_of =
      exact ? std::function<const CurveE&()>([&]() -> const CurveE& { return exact_curve; }) : nullptr;
  if (const std::optional<int> proof = prover.prove(im, exact_of, 0, 0)) {
    ++stats.pieces;
    pieces.push_back({{"t", json::array({rational(ta), rational(tb)})}, {"proof", *proof}});
    return true;
  }
  return bisect("no separation proof for the cleared piece [" + to_string(ta) + ", " + to_string(tb) + "] (elements " +
                std::to_string(prover.failed[0]) + " and " + std::to_string(prover.failed[1]) + ")");
}

// The exact control points of piece [index, index + 1] / 2^depth.
CurveE CheckWriter::exact_piece(std::uint64_t index, int depth) const {
  CurveE piece = joint, left, right;
  for (int level = depth - 1; level >= 0; --level) {
    split_half(piece, left, right);
    piece = (index >> level) & 1 ? std::move(right) : std::move(left);
  }
  return piece;
}

void CheckWriter::prove_piece(const Prover& prover, const CurveI& piece, std::uint64_t index, int depth, int extra,
                 json& pieces) {
  const PieceImages im = prover.images(piece);
  std::optional<CurveE> exact;
  const std::function<const CurveE&()> exact_of = [&]() -> const CurveE& {
    if (!exact) exact = exact_piece(index, depth);
    return *exact;
  };
  set_no_contact(prover, curve_u(index, depth), curve_u(index + 1, depth), nullptr);
  if (const std::optional<int> proof = prover.prove(im, exact_of, 0, 0)) {
    ++stats.pieces;
    pieces.push_back({{"t", json::array({rational(scene_t(index, depth)), rational(scene_t(index + 1, depth))})},
                      {"proof", *proof}});
    return;
  }
  if (extra == 0) ++stats.bisections;
  if (extra >= kMaxExtraDepth || depth >= 62)
    fail("no separation proof for the cleared piece [" + to_string(scene_t(index, depth)) + ", " +
         to_string(scene_t(index + 1, depth)) + "] after " + std::to_string(extra) + " bisections (elements " +
         std::to_string(prover.failed[0]) + " and " + std::to_string(prover.failed[1]) + ")");
  CurveI left, right;
  {
    RoundingGuard guard;
    split_half(piece, left, right);
  }
  prove_piece(prover, left, 2 * index, depth + 1, extra + 1, pieces);
  prove_piece(prover, right, 2 * index + 1, depth + 1, extra + 1, pieces);
}

json CheckWriter::write() {
  json out{{"bodies", json::array({a.name, b.name})},
           {"verdict", to_string(r.verdict)},
           {"interval", json::array({rational(interval.first), rational(interval.second)})}};
  const BodyGroups ga(a), gb(b);
  out["groups"] = json::array({ga.to_json(), gb.to_json()});
  json pieces = json::array();
  const bool gen = general();
  // The runs' starts (for start claims) and the undecided intervals, with
  // the runs no start claim can be written for.
  std::vector<Exact> starts;
  std::vector<std::pair<Exact, Exact>> undecided_times;
  const std::vector<CoverPiece> cover_pieces =
      gen ? std::vector<CoverPiece>{}
          : claimable(cover(), [&](const CoverPiece& c) { return piece_times(c); }, starts, undecided_times);
  const std::vector<std::pair<Exact, Exact>> general_pieces =
      gen ? claimable(general_cover(), [](const std::pair<Exact, Exact>& p) { return p; }, starts, undecided_times)
          : std::vector<std::pair<Exact, Exact>>{};
  if (!gen) joint = joint_curve(motion_or_identity(a), motion_or_identity(b));
  const Prover prover(ga, gb, stats);
  if (gen) {
    // Margins: the clearance, and each tolerance times how far a point of
    // its body can move per unit of metric (motions.h).  (No exact
    // no-contact claims: they decide the check's one rational curve.)
    Exact margin = r.clearance;
    std::array<Exact, 4> bounds[2];
    const Body* bodies[2] = {&a, &b};
    for (int k = 0; k < 2; ++k) {
      bounds[k] = coordinate_bounds(elements(*bodies[k]));
      if (bodies[k]->tolerance > 0)
        margin += bodies[k]->tolerance * displacement_bound(*bodies[k], elements(*bodies[k]));
    }
    const bool partial = r.verdict == Verdict::Collision;
    for (const auto& [ta, tb] : general_pieces)
      if (!prove_general(prover, ta, tb, 0, margin, bounds, partial, pieces)) break;
  } else if (!cover_pieces.empty()) {
    const CurveI root = enclose(joint);
    for (const CoverPiece& c : cover_pieces) {
      CurveI piece = root, left, right;
      {
        RoundingGuard guard;
        for (int level = c.depth - 1; level >= 0; --level) {
          split_half(piece, left, right);
          piece = (c.index >> level) & 1 ? std::move(right) : std::move(left);
        }
      }
      prove_piece(prover, piece, c.index, c.depth, 0, pieces);
    }
  }
  out["pieces"] = std::move(pieces);
  if (r.verdict == Verdict::Collision) {
    out["witness"] = witness();
    // The bracket the certificate proves: from the end of its pieces
    // (contiguous from t0).  An exact first contact (exact resolution)
    // also rests on "no contact between the piece's start and the
    // witness": carried as before_witness when its proof is found, and
    // then the bracket is the witness time itself.
    Exact clear_until = interval.first;
    if (gen) {
      for (const json& p : out["pieces"]) {
        const std::string& lo = p["t"][0].get_ref<const std::string&>();
        if (Exact(lo) == clear_until) clear_until = Exact(p["t"][1].get<std::string>());
      }
    }
    for (const CoverPiece& c : cover_pieces)
      if (scene_t(c.index, c.depth) == clear_until) clear_until = scene_t(c.index + 1, c.depth);
    if (clear_until > r.first_contact->first) clear_until = r.first_contact->first;
    out["first_contact"] = json::array({rational(clear_until), rational(r.first_contact->second)});
    if (r.first_contact_exact && !gen) before_witness(prover, clear_until, out);
  }
  // The proof nodes the pieces and before_witness use, shared
  // (docs/certificate-format.md "Shared proof nodes").
  std::vector<json*> roots;
  for (json& p : out["pieces"]) roots.push_back(&p["proof"]);
  if (out.contains("before_witness")) roots.push_back(&out["before_witness"]["proof"]);
  out["nodes"] = prover.nodes.compact(roots);
  json start_claims = json::array();
  if (!out["pieces"].empty() || out.contains("before_witness")) {
    if (starts.empty() || starts.front() != interval.first) {
      if (r.verdict != Verdict::Undecided) start(interval.first, start_claims);  // before_witness alone
    }
    for (const Exact& at : starts) start(at, start_claims);
  }
  out["start"] = std::move(start_claims);
  json undecided = json::array();
  for (const auto& [lo, hi] : undecided_times) undecided.push_back(json::array({rational(lo), rational(hi)}));
  out["undecided"] = r.verdict == Verdict::Undecided ? std::move(undecided) : json::array();
  return out;
}

}  // namespace writer_internal

using namespace writer_internal;

std::string certificate_json(const Scene& scene, const SceneResult& result, WriteStats* stats) {
  if (!result.certified) throw InputError("--certificate: the fast kernel is not certified; use filtered or exact");
  if (const std::string why = uncertifiable(scene); !why.empty())
    throw InputError("--certificate: certificates do not cover this scene: " + why);
  const auto started = std::chrono::steady_clock::now();
  WriteStats local;
  WriteStats& s = stats ? *stats : local;
  json doc{{"format", "tmcert-certificate/2"}};
  json bodies = json::array();
  for (const Body& body : scene.bodies)
    bodies.push_back({{"name", body.name}, {"elements", elements(body).size()}});
  doc["scene_bodies"] = std::move(bodies);
  json checks = json::array();
  for (const CheckResult& r : result.checks) {
    // A URDF cylinder or sphere at the finer level the result was found
    // on (writer_primitive.cpp).
    const std::optional<Body> fa = at_level(scene.bodies[r.bodies[0]], r.levels[0]);
    const std::optional<Body> fb = at_level(scene.bodies[r.bodies[1]], r.levels[1]);
    const Body& a = fa ? *fa : scene.bodies[r.bodies[0]];
    const Body& b = fb ? *fb : scene.bodies[r.bodies[1]];
    CheckWriter w{scene, r, a, b, s, check_interval(a, b), {}};
    checks.push_back(w.write());
    if (fa || fb) checks.back()["levels"] = json::array({r.levels[0], r.levels[1]});
  }
  doc["checks"] = std::move(checks);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return doc.dump() + "\n";
}

}  // namespace tmcert::certificate