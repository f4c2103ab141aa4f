// The certificate checker's judging (checker.h, phase 3): each check's
// tiling of its interval, its verdict against its pieces and undecided
// intervals, its witness, its start claims, and its pieces' proofs in turn.
#include "src/certificate/checker.h"
#include "src/certificate/check_enclosed.h"
#include "src/certificate/check_ray.h"
#include "src/certificate/exact_claims.h"

#include <algorithm>
#include <limits>
#include <set>

namespace tmcert::certificate {

namespace check_internal {

std::string Checker::judge_check(CheckContext& ctx) {
  const std::string& L = ctx.label;
  const std::vector<std::pair<Exact, Exact>>& pt = ctx.pt;
  check_coverage(ctx);
  for (std::size_t k = 0; k < pt.size(); ++k)
    if (!(pt[k].first < pt[k].second))
      reject(L + ": pieces[" + std::to_string(k) + "] [" + str(pt[k].first) + ", " + str(pt[k].second) +
             "] is empty (a piece needs ta < tb)");

  std::string summary;
  Exact clear_until = ctx.t0;  // no contact before this parameter (proven below)
  if (ctx.verdict == "safe" || ctx.verdict == "collision") {
    // In order and contiguous from t0.
    Exact end = ctx.t0;
    for (std::size_t k = 0; k < pt.size(); ++k) {
      if (pt[k].first != end)
        reject(L + ": pieces[" + std::to_string(k) + "] [" + str(pt[k].first) + ", " + str(pt[k].second) +
               "] starts at " + str(pt[k].first) + ", but " +
               (k == 0 ? "the check starts at t0 = " + str(ctx.t0) : "the previous piece ends at " + str(end)) +
               (pt[k].first > end ? " (gap)" : " (overlap)"));
      end = pt[k].second;
      if (end > ctx.t1)
        reject(L + ": pieces[" + std::to_string(k) + "] [" + str(pt[k].first) + ", " + str(pt[k].second) +
               "] ends after t1 = " + str(ctx.t1));
    }
    if (ctx.verdict == "safe") {
      if (end != ctx.t1)
        reject(L + ": the pieces end at " + str(end) + ", not at t1 = " + str(ctx.t1) +
               " (safe needs the whole interval)");
      clear_until = ctx.t1;
    } else {
      const auto [lo, hi] = *ctx.first_contact;
      const Exact& t = ctx.witness_t;
      check_witness(ctx);
      const std::string fc = L + ": first_contact [" + str(lo) + ", " + str(hi) + "]";
      // With before_witness, the pieces end where it starts and it proves
      // the rest up to the witness time (the first contact, exactly).
      const Exact& pieces_end = ctx.before_witness ? ctx.before_from : lo;
      if (end != pieces_end)
        reject(fc + ": the pieces end at " + str(end) + ", not at " +
               (ctx.before_witness ? "before_witness.from = " : "lo = ") + str(pieces_end));
      if (lo > t) reject(fc + ": lo is after the witness t = " + str(t));
      if (t > hi) reject(fc + ": the witness t = " + str(t) + " is after hi");
      if (ctx.witness_root && hi < ctx.witness_root->hi && ctx.before_witness)
        reject(fc + ": hi is before the end of the witness time's interval " + str(ctx.witness_root->hi));
      clear_until = lo;
      const std::string at = ctx.witness_root ? "an irrational t in (" + str(ctx.witness_root->lo) + ", " +
                                                    str(ctx.witness_root->hi) + ")"
                                              : "t = " + str(t);
      summary = "collision proven at " + at +
                (ctx.before_witness ? "; no contact before it proven (the first contact)"
                                    : "; no contact before t = " + str(lo) + " proven");
    }
  } else {  // undecided
    const std::vector<std::pair<Exact, Exact>>& ut = ctx.undecided;
    for (std::size_t k = 0; k < ut.size(); ++k)
      if (!(ut[k].first < ut[k].second))
        reject(L + ": undecided[" + std::to_string(k) + "] [" + str(ut[k].first) + ", " + str(ut[k].second) +
               "] is empty (needs lo < hi)");
    if (ut.empty()) reject(L + ": an undecided check with no undecided interval");
    // Pieces and undecided intervals, in order, tile [t0, t1].
    Exact end = ctx.t0;
    std::size_t i = 0, j = 0;
    while (i < pt.size() || j < ut.size()) {
      if (i < pt.size() && pt[i].first == end) {
        end = pt[i++].second;
      } else if (j < ut.size() && ut[j].first == end) {
        end = ut[j++].second;
      } else {
        std::string next;
        if (i < pt.size()) next += "pieces[" + std::to_string(i) + "] starts at " + str(pt[i].first);
        if (j < ut.size())
          next += std::string(next.empty() ? "" : ", ") + "undecided[" + std::to_string(j) + "] starts at " +
                  str(ut[j].first);
        reject(L + ": the pieces and undecided intervals do not tile [" + str(ctx.t0) + ", " + str(ctx.t1) +
               "]: the previous one ends at " + str(end) + ", " + next);
      }
      if (end > ctx.t1)
        reject(L + ": the pieces and undecided intervals reach " + str(end) + ", after t1 = " + str(ctx.t1));
    }
    if (end != ctx.t1)
      reject(L + ": the pieces and undecided intervals end at " + str(end) + ", not at t1 = " + str(ctx.t1));
    clear_until = ut.front().first;
    if (ctx.first_contact) {
      const auto [lo, hi] = *ctx.first_contact;
      if (lo > hi) reject(L + ": first_contact [" + str(lo) + ", " + str(hi) + "] is empty");
      if (lo > clear_until)
        reject(L + ": first_contact [" + str(lo) + ", " + str(hi) +
               "]: lo is after the first undecided interval, which starts at " + str(clear_until));
    }
  }

  // Where runs of pieces start: t0 when the pieces (or before_witness)
  // start there, and every piece that follows an undecided interval.
  // Separations prove the surfaces apart on each piece; a solid's
  // inside needs its start claims at each run's start (a component that
  // entered during an undecided interval stays inside without touching
  // the surface: proofs/partition.md §5).
  std::vector<Exact> runs;
  if (ctx.verdict == "undecided") {
    std::set<Exact> undecided_ends;
    for (const auto& u : ctx.undecided) undecided_ends.insert(u.second);
    for (std::size_t k = 0; k < pt.size(); ++k)
      if (pt[k].first == ctx.t0 || undecided_ends.count(pt[k].first)) runs.push_back(pt[k].first);
  } else if (!pt.empty() || ctx.before_witness) {
    runs.push_back(ctx.t0);
  }
  const std::size_t start_points = check_start(ctx, runs);

  // The separation proofs, piece by piece.
  mpz_mul(ctx.dadb.v, ctx.data[0]->coords.D.v, ctx.data[1]->coords.D.v);
  if (!ctx.general) ctx.curve = joint_curve(*ctx.body[0], *ctx.body[1]);
  for (std::size_t k = 0; k < pt.size(); ++k) check_piece((*ctx.pieces)[k], k, pt[k], ctx);
  if (ctx.before_witness) check_before_witness(ctx);

  std::string counts = std::to_string(pt.size()) + (pt.size() == 1 ? " piece, " : " pieces, ") +
                       std::to_string(ctx.separations) + (ctx.separations == 1 ? " separation" : " separations");
  if (ctx.exact_claims)
    counts += ", " + std::to_string(ctx.exact_claims) + (ctx.exact_claims == 1 ? " exact claim" : " exact claims");
  if (start_points)
    counts += ", " + std::to_string(start_points) + (start_points == 1 ? " start point" : " start points");
  const std::string who = ctx.body[0]->name + " x " + ctx.body[1]->name + ": ";
  if (ctx.verdict == "safe") return who + "safe proven (" + counts + ")";
  if (ctx.verdict == "collision") return who + summary + " (" + counts + ")";
  const std::size_t u = ctx.undecided.size();
  return who + "undecided: no contact before t = " + str(clear_until) + " proven (" + counts + "; " +
         std::to_string(u) + (u == 1 ? " interval" : " intervals") + " not cleared)";
}

// Group 0 reaches every element (children come later, so one pass in
// index order propagates reachability).
void Checker::check_coverage(const CheckContext& ctx) {
  for (int side = 0; side < 2; ++side) {
    const GroupSet& gs = ctx.groups[side];
    const std::size_t G = gs.items.size(), E = gs.body->elems.size();
    std::vector<char> reach(G, 0), covered(E, 0);
    reach[0] = 1;
    for (std::size_t k = 0; k < G; ++k) {
      if (!reach[k]) continue;
      for (std::uint32_t x : gs.items[k]) (gs.leaf[k] ? covered : reach)[x] = 1;
    }
    for (std::size_t e = 0; e < E; ++e)
      if (!covered[e])
        reject(ctx.label + ": groups[" + std::to_string(side) + "]: group 0 does not reach element " +
               std::to_string(e) + " of " + quote_text(gs.body->body->name));
  }
}

// A witness at an irrational time: a valid root claim, and the two
// sub-features share a point at that root (exact signs at the root).
void Checker::check_algebraic_witness(const CheckContext& ctx) {
  const std::string L = ctx.label + ": witness";
  const ClaimedRoot& claim = *ctx.witness_root;
  if (const std::string error = root_claim_error(claim, ctx.t0, ctx.t1); !error.empty()) reject(L + ".t: " + error);
  std::optional<CheckMotions> general;
  RealRoot root;
  if (ctx.general) {
    // Keyframe or piecewise motions: both bodies on one rational segment
    // around the root's interval, in that segment's parameter.
    const auto span = rational_span(*ctx.body[0], *ctx.body[1], claim.lo, claim.hi, ctx.t0, ctx.t1);
    if (!span) reject(L + ".t: the interval (" + str(claim.lo) + ", " + str(claim.hi) +
                      ") is not inside one rational segment of both motions");
    std::string why;
    const auto ma = piece_motion(*ctx.body[0], span->first, span->second, why);
    const auto mb = piece_motion(*ctx.body[1], span->first, span->second, why);
    if (!ma || !mb || !ma->exact || !mb->exact) reject(L + ".t: " + why);
    general.emplace(*ma->exact, *mb->exact);
    root = check_parameter_root(claim, span->first, span->second);
  } else {
    root = check_parameter_root(claim, ctx.t0, ctx.t1);
  }
  const CheckMotions motions = general ? *general : CheckMotions(*ctx.body[0], *ctx.body[1]);
  std::vector<MovingPoint> points[2];
  for (int s = 0; s < 2; ++s)
    for (std::size_t v : ctx.side[s].vertices)
      points[s].push_back(motions.place(s, ctx.data[s]->elems[ctx.side[s].element][v]));
  if (!ContactSolver::touch(points[0], points[1], root))
    reject(L + ": the two sub-features do not meet at the root of t in (" + str(claim.lo) + ", " + str(claim.hi) + ")");
}

// A witness's displacement (if any) is a translation within the tolerance
// of the body it moves: a translation by v has norm |v| sqrt(sum w) in the
// body's metric.
// With `displacement_other`, the other body's translation likewise within
// its own tolerance (each body's tolerance bounds its own deviation).
void Checker::check_displacement(const CheckContext& ctx) {
  if (!ctx.displacement) return;
  for (int s = 0; s < 2; ++s) {
    const Vec3E* v = ctx.displacement_of(s);
    if (!v) continue;
    const Body& body = *ctx.body[s];
    Exact w = 0;
    for (const Exact& x : body.mass.weights) w += x;
    const Exact norm2 = ((*v)[0] * (*v)[0] + (*v)[1] * (*v)[1] + (*v)[2] * (*v)[2]) * w;
    if (norm2 > body.tolerance * body.tolerance)
      reject(ctx.label + ": witness." + (s == ctx.displaced ? "displacement" : "displacement_other") + ": " + str(*v) +
             " is not within the tolerance " + str(body.tolerance) + " of " + quote_text(body.name) +
             " (its norm squared in the body's metric is " + str(norm2) + ")");
  }
}

// A witness at an enclosed pose: an edge of one body crosses a triangle
// of the other transversally for every pose in the two pose boxes at t
// (the displaced body's box translated by the displacement, when given).
void Checker::check_enclosed_witness(const CheckContext& ctx) {
  const std::string L = ctx.label + ": witness";
  const Exact& t = ctx.witness_t;
  if (t < ctx.t0 || t > ctx.t1)
    reject(L + ": t = " + str(t) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
  std::vector<RBox> placed_vertices[2];
  for (int s = 0; s < 2; ++s) {
    std::optional<PoseBox> box = pose_box_at(*ctx.body[s], t);
    if (!box) reject(L + ": the pose of " + quote_text(ctx.body[s]->name) + " at t = " + str(t) + " has no finite enclosure");
    if (const Vec3E* d = ctx.displacement_of(s))
      for (int r = 0; r < 3; ++r) box->center[4 * r + 3] += (*d)[r];
    for (std::size_t v : ctx.side[s].vertices)
      placed_vertices[s].push_back(place_box(*box, ctx.data[s]->elems[ctx.side[s].element][v]));
  }
  const int e = placed_vertices[0].size() == 2 ? 0 : 1;  // the edge's side
  const std::vector<RBox>& edge = placed_vertices[e];
  const std::vector<RBox>& tri = placed_vertices[1 - e];
  if (edge.size() != 2 || tri.size() != 3)
    reject(L + ": an enclosed witness needs an edge (two vertices) on one side and a triangle (three) on the other");
  check_displacement(ctx);
  if (!certain_crossing(edge[0], edge[1], tri[0], tri[1], tri[2]))
    reject(L + ": the edge's crossing of the triangle at t = " + str(t) +
           " is not certain over the enclosed poses (grazing, or not crossing)");
}

// A clearance violation at an enclosed pose: the weighted points p, q of
// the two elements (in their bodies' frames) placed by the checker's own
// pose boxes at t as rational boxes; the largest squared distance between
// two points of the boxes, sum_r max(|hi_a - lo_b|, |hi_b - lo_a|)^2, exact,
// is at most the clearance squared, so |M_a p - M_b q| <= d for every pose
// of the boxes, the true poses at t among them (proofs/clearance.md §6).
// With a displacement (a tolerance too, §8), each displaced body's box is
// translated by its displacement, which must be within its tolerance.
void Checker::check_enclosed_clearance(const CheckContext& ctx) {
  const std::string L = ctx.label + ": witness";
  const Exact& t = ctx.witness_t;
  if (t < ctx.t0 || t > ctx.t1)
    reject(L + ": t = " + str(t) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
  if (!(ctx.clearance > 0)) reject(L + ": points_box: the check has no clearance");
  RBox placed_point[2];
  for (int s = 0; s < 2; ++s) {
    const char* key = s == 0 ? "a" : "b";
    const WitnessSide& side = ctx.side[s];
    if (side.interior) reject(L + "." + key + ": a clearance witness at an enclosed pose needs an element and weights");
    const Vec3E x = weighted_point(ctx.data[s]->elems[side.element], side, L + "." + key);
    std::optional<PoseBox> box = pose_box_at(*ctx.body[s], t);
    if (!box) reject(L + ": the pose of " + quote_text(ctx.body[s]->name) + " at t = " + str(t) + " has no finite enclosure");
    if (const Vec3E* d = ctx.displacement_of(s))
      for (int r = 0; r < 3; ++r) box->center[4 * r + 3] += (*d)[r];
    placed_point[s] = place_box(*box, x);
  }
  check_displacement(ctx);
  Exact far2(0);
  for (int r = 0; r < 3; ++r) {
    const Exact u = placed_point[0][r].hi - placed_point[1][r].lo, v = placed_point[1][r].hi - placed_point[0][r].lo;
    const Exact m = std::max(CGAL::abs(u), CGAL::abs(v));
    far2 += m * m;
  }
  if (far2 > ctx.clearance * ctx.clearance)
    reject(L + ": the two weighted points may be farther apart than the clearance " + str(ctx.clearance) + " at t = " +
           str(t) + " over the enclosed poses (squared distance up to " + str(far2) + ")");
}

void Checker::check_witness(const CheckContext& ctx) {
  require_true_shape_sides(ctx);
  if (ctx.true_shape_witness) return check_true_shape_witness(ctx);
  if (ctx.witness_root) return check_algebraic_witness(ctx);
  if (ctx.enclosed_witness) return check_enclosed_witness(ctx);
  if (ctx.enclosed_clearance) return check_enclosed_clearance(ctx);
  const Exact& t = ctx.witness_t;
  const std::string L = ctx.label + ": witness";
  if (t < ctx.t0 || t > ctx.t1)
    reject(L + ": t = " + str(t) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
  check_displacement(ctx);
  if (ctx.points) {
    const Vec3E d = sub((*ctx.points)[0], (*ctx.points)[1]);
    if (dot(d, d) > ctx.clearance * ctx.clearance)
      reject(L + ".points: " + str((*ctx.points)[0]) + " and " + str((*ctx.points)[1]) +
             " are farther apart than the clearance " + str(ctx.clearance));
  }
  for (int s = 0; s < 2; ++s) {
    const char* key = s == 0 ? "a" : "b";
    const Body& body = *ctx.body[s];
    const Vec3E& point = ctx.points ? (*ctx.points)[s] : ctx.witness_point;
    Mat34E pose;
    if (ctx.general) {
      const std::optional<Mat34E> p = exact_pose_at(body, t);
      if (!p)
        reject(L + "." + key + ": the pose of " + quote_text(body.name) + " at t = " + str(t) +
               " is not exact (an enclosed pose needs the edge-and-triangle witness)");
      pose = *p;
      if (const Vec3E* d = ctx.displacement_of(s))
        for (int r = 0; r < 3; ++r) pose[4 * r + 3] += (*d)[r];
    } else {
      pose = pose_at(body, t);
    }
    check_side_at(ctx, s, pose, point);
  }
}

Vec3E Checker::weighted_point(const std::vector<Vec3E>& verts, const WitnessSide& side, const std::string& where) {
  Exact sum(0);
  Vec3E x{Exact(0), Exact(0), Exact(0)};
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const Exact& wi = side.weights[i];
    if (sgn(wi) < 0) reject(where + ".weights[" + std::to_string(i) + "] = " + str(wi) + " is negative");
    sum += wi;
    for (int r = 0; r < 3; ++r) x[r] += wi * verts[i][r];
  }
  if (sum != 1) reject(where + ".weights sum to " + str(sum) + ", not 1");
  return x;
}

void Checker::check_side_at(const CheckContext& ctx, int s, const Mat34E& pose, const Vec3E& point) {
  const Exact& t = ctx.witness_t;
  const std::string L = ctx.label + ": witness";
  const WitnessSide& side = ctx.side[s];
  const char* key = s == 0 ? "a" : "b";
  const Body& body = *ctx.body[s];
  {
    if (side.interior) {
      if (!body.solid) reject(L + "." + key + ": " + quote_text(body.name) + " is not solid, it has no interior");
      if (sgn(determinant(pose)) == 0)
        reject(L + "." + key + ": the pose of " + quote_text(body.name) + " at t = " + str(t) +
               " is singular (no interior point can be proven)");
      const std::optional<std::vector<int>> n =
          ray_crossings(placed(*ctx.data[s], pose), piece_shells(body), point, side.ray);
      if (!n)
        reject(L + "." + key + ".interior: the ray from the point along " + str(side.ray) +
               " is degenerate (through a vertex or an edge, in a polygon's plane, or the point on the surface)");
      // Inside the union of the shells iff inside one of them.
      if (std::none_of(n->begin(), n->end(), [](int c) { return c % 2 != 0; }))
        reject(L + "." + key + ".interior: the ray crosses every shell of " + quote_text(body.name) +
               " an even number of times (" + counts_text(*n) + "): the point is not inside");
    } else {
      const Vec3E x = weighted_point(ctx.data[s]->elems[side.element], side, L + "." + key);
      const Vec3E placed_x = place_point(pose, x);
      if (placed_x != point)
        reject(L + "." + key + ": element " + std::to_string(side.element) + " of " + quote_text(body.name) +
               " with these weights is at " + str(placed_x) + " at t = " + str(t) + ", not at the point " +
               str(point));
    }
  }
}

std::vector<std::vector<Vec3E>> Checker::placed(const BodyData& d, const Mat34E& pose) {
  std::vector<std::vector<Vec3E>> out;
  out.reserve(d.body->pieces.size());
  for (const ConvexPiece& piece : d.body->pieces) {
    std::vector<Vec3E> poly;
    poly.reserve(piece.vertices.size());
    for (const Vec3E& v : piece.vertices) poly.push_back(place_point(pose, v));
    out.push_back(std::move(poly));
  }
  return out;
}

// The pose of check body s at scene parameter t for start claims: exact
// (a general check's body may be only enclosed there: nullopt).
std::optional<Mat34E> Checker::claim_pose(const CheckContext& ctx, int s, const Exact& t) const {
  if (!ctx.general) return pose_at(*ctx.body[s], t);
  return exact_pose_at(*ctx.body[s], t);
}

std::string Checker::at_text(const CheckContext& ctx, const Exact& t) {
  return t == ctx.t0 ? "t0 = " + str(t) : "t = " + str(t);
}

// Checks the start claims, and that one is given at every run start in
// `runs` for each solid body with a nonsingular pose there; returns the
// number of points checked.  Where both poses at a claim's instant are
// exact the other body's vertex is placed exactly; otherwise it is enclosed
// in the solid's frame (check_enclosed.h).
std::size_t Checker::check_start(CheckContext& ctx, const std::vector<Exact>& runs) {
  std::size_t checked = 0;
  const bool solid = ctx.body[0]->solid || ctx.body[1]->solid;
  // The poses at each instant a claim is made or needed: exact, or (when
  // either is not) both enclosed, the exact one with radius 0.
  struct Poses {
    std::array<std::optional<Mat34E>, 2> exact;
    std::array<PoseBox, 2> box;
    bool enclosed() const { return !exact[0] || !exact[1]; }
    // A nonsingular pose: exact with a nonzero determinant, or enclosed
    // (rigid: a keyframe or robot link motion).
    bool nonsingular(int s) const { return !exact[s] || sgn(determinant(*exact[s])) != 0; }
  };
  std::map<Exact, Poses> poses;
  auto poses_at = [&](const Exact& t) -> const Poses& {
    auto it = poses.find(t);
    if (it != poses.end()) return it->second;
    Poses p;
    for (int s = 0; s < 2; ++s) p.exact[s] = claim_pose(ctx, s, t);
    if (p.enclosed())
      for (int s = 0; s < 2; ++s) {
        if (p.exact[s]) {
          p.box[s].center = *p.exact[s];
          for (Exact& r : p.box[s].radius) r = 0;
          continue;
        }
        const std::optional<PoseBox> box = ctx.body[s]->motion ? std::nullopt : pose_box_at(*ctx.body[s], t);
        if (!box)
          reject(ctx.label + ": start: the pose of " + quote_text(ctx.body[s]->name) + " at " + at_text(ctx, t) +
                 " is neither exact nor finitely enclosed: start claims need exact or enclosed poses");
        p.box[s] = *box;
      }
    return poses.emplace(t, p).first->second;
  };
  if (solid)
    for (const Exact& t : runs) poses_at(t);
  std::set<std::pair<int, Exact>> seen;
  for (std::size_t k = 0; k < ctx.start.size(); ++k) {
    const StartEntry& entry = ctx.start[k];
    const int s = entry.solid;
    seen.insert({s, entry.t});
    const Body& solid_body = *ctx.body[s];
    BodyData& other = *ctx.data[1 - s];
    const std::string L = ctx.label + ": start[" + std::to_string(k) + "] (solid " + quote_text(solid_body.name) + ")";
    if (!solid_body.solid) reject(L + ": " + quote_text(solid_body.name) + " is not solid");
    const Poses& pose = poses_at(entry.t);
    const bool enclosed = pose.enclosed();
    // Exact: the solid's polygons placed; enclosed: in its own frame.
    const std::vector<std::vector<Vec3E>> polygons =
        enclosed ? placed(*ctx.data[s], identity_pose()) : placed(*ctx.data[s], *pose.exact[s]);
    const std::vector<int> shells = piece_shells(solid_body);
    for (std::size_t i = 0; i < entry.points.size(); ++i) {
      const StartPoint& p = entry.points[i];
      const Vec3E& vertex = other.elems[p.element][p.vertex];
      const std::string LP = L + ".points[" + std::to_string(i) + "] (" + quote_text(other.body->name) + " element " +
                             std::to_string(p.element) + " vertex " + std::to_string(p.vertex) + ")";
      Vec3E x;
      if (enclosed) {
        const std::optional<RBox> box = solid_frame_box(pose.box[s], pose.exact[s], pose.box[1 - s], vertex);
        if (!box) reject(LP + ": the pose of " + quote_text(solid_body.name) + " is singular");
        for (std::size_t q = 0; q < polygons.size(); ++q)
          if (!box_clear_of_polygon(*box, polygons[q]))
            reject(LP + ": the box enclosing the vertex at " + at_text(ctx, entry.t) + " in the frame of " +
                   quote_text(solid_body.name) + " is not clear of its element " + std::to_string(q));
        x = box_center(*box);
      } else {
        x = place_point(*pose.exact[1 - s], vertex);
      }
      const std::optional<std::vector<int>> n = ray_crossings(polygons, shells, x, p.ray);
      if (!n)
        reject(LP + ": the ray along " + str(p.ray) +
               " is degenerate (through a vertex or an edge, in a polygon's plane, or the vertex on the surface)");
      // Outside the union of the shells only if outside every one.
      for (std::size_t k2 = 0; k2 < n->size(); ++k2)
        if ((*n)[k2] % 2 != 0)
          reject(LP + ": the ray crosses shell " + std::to_string(k2) + " of " + quote_text(solid_body.name) + " " +
                 std::to_string((*n)[k2]) + (((*n)[k2] == 1) ? " time" : " times") +
                 ", an odd number: the vertex is inside " + quote_text(solid_body.name) + " at " +
                 (entry.t == ctx.t0 ? std::string("t0") : "t = " + str(entry.t)));
      ++checked;
    }
    // One listed point per component of the other body.
    const std::vector<std::size_t>& comp = components(other);
    std::vector<char> has(other.elems.size(), 0);
    for (const StartPoint& p : entry.points) has[comp[p.element]] = 1;
    for (std::size_t e = 0; e < comp.size(); ++e)
      if (comp[e] == e && !has[e])
        reject(L + ": no point of the component of " + quote_text(other.body->name) + " element " + std::to_string(e) +
               " is listed");
  }
  // Required: one entry per solid body of the check with a nonsingular
  // pose at each run's start.
  if (solid)
    for (const Exact& t : runs)
      for (int s = 0; s < 2; ++s)
        if (ctx.body[s]->solid && !seen.count({s, t}) && poses_at(t).nonsingular(s))
          reject(ctx.label + ": start: no claim for the solid " + quote_text(ctx.body[s]->name) + " (\"" +
                 (s == 0 ? "a" : "b") + "\")" + (t == ctx.t0 ? "" : " at t = " + str(t)) +
                 ": the other body could " +
                 (t == ctx.t0 ? std::string("start inside it")
                              : "be inside it there (it may have entered while undecided)"));
  return checked;
}

}  // namespace check_internal

}  // namespace tmcert::certificate
