// The certificate checker's proof trees (checker.h): each piece's curve
// (exact or enclosed), its separations, splits and exact no-contact claims,
// and a collision's before_witness.
#include "src/certificate/checker.h"
#include "src/certificate/exact_claims.h"

namespace tmcert::certificate {

namespace check_internal {

void Checker::check_piece(const json& piece, std::size_t k, const std::pair<Exact, Exact>& t, CheckContext& ctx) {
  PieceContext pc;
  pc.index = k;
  pc.path = idx(mem(ctx.path, "pieces"), k);
  pc.label = ctx.label + ": pieces[" + std::to_string(k) + "] [" + str(t.first) + ", " + str(t.second) + "]";
  if (ctx.general) {
    general_piece(t, pc, ctx);
  } else {
    const Exact span = ctx.t1 - ctx.t0;
    const Exact ua = (t.first - ctx.t0) / span, ub = (t.second - ctx.t0) / span;
    pc.ints = integer_control_points(restrict_curve(ctx.curve, ua, ub));
    pc.ua = ua;
    pc.ub = ub;
  }
  std::vector<int> trail;
  prove(piece.at("proof"), 0, 0, trail, pc, ctx);
}

// A piece of a general check: each body's motion on the piece, exact (a
// rational curve; then the joint curve of the two) or enclosed (a pose
// box; then one control point, the boxes' centres, and the radii as a
// penalty: |n . (M - C) x^| <= sum_i |n_i| sum_j radius_ij |x_j| <=
// sum_i |n_i| sum_j radius_ij bound_j).
void Checker::general_piece(const std::pair<Exact, Exact>& t, PieceContext& pc, const CheckContext& ctx) {
  std::optional<PieceMotion> m[2];
  for (int s = 0; s < 2; ++s) {
    std::string why;
    m[s] = piece_motion(*ctx.body[s], t.first, t.second, why);
    if (!m[s]) reject(pc.label + ": " + why);
  }
  std::vector<CP> curve;
  if (m[0]->exact && m[1]->exact) {
    curve = joint_curve(HomogeneousMotion{m[0]->exact->control_points, m[0]->exact->weights},
                        HomogeneousMotion{m[1]->exact->control_points, m[1]->exact->weights});
  } else {
    CP c;
    for (int s = 0; s < 2; ++s) {
      const PoseBox box = m[s]->exact ? control_box(*m[s]->exact) : m[s]->box;
      for (int e = 0; e < 12; ++e) c[12 * s + e] = box.center[e];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) pc.penalty[i] += box.radius[4 * i + j] * ctx.bounds[s][j];
    }
    c[24] = 1;
    curve = {c};
  }
  pc.ints = integer_control_points(curve);
  pc.margins = ctx.margin > 0 || sgn(pc.penalty[0]) != 0 || sgn(pc.penalty[1]) != 0 || sgn(pc.penalty[2]) != 0;
  for (int i = 0; i < 3; ++i) mpz_lcm(pc.penalty_den.v, pc.penalty_den.v, den(pc.penalty[i]));
  Z f;
  for (int i = 0; i < 3; ++i) {
    mpz_divexact(f.v, pc.penalty_den.v, den(pc.penalty[i]));
    mpz_mul(pc.penalty_num[i].v, num(pc.penalty[i]), f.v);
  }
}

void Checker::validate_exact_leaf(const json& node, const json& exact, bool other_keys, const std::string& path) {
  if (other_keys) in_.bad(path, "expected exactly one of \"sep\", \"split\" and \"exact\"");
  if (!(exact.is_string() && exact.get_ref<const std::string&>() == "no_contact"))
    in_.bad(path + ".exact", std::string("expected \"no_contact\", got ") + describe(exact));
  (void)node;
}

// Elements reachable from group g of one side.
std::vector<std::uint32_t> Checker::group_elements(const GroupSet& gs, std::uint32_t g) {
  std::vector<std::uint32_t> out, stack{g};
  std::vector<char> seen_group(gs.items.size(), 0), seen_element(gs.body->elems.size(), 0);
  seen_group[g] = 1;
  while (!stack.empty()) {
    const std::uint32_t k = stack.back();
    stack.pop_back();
    for (std::uint32_t x : gs.items[k]) {
      std::vector<char>& seen = gs.leaf[k] ? seen_element : seen_group;
      if (seen[x]) continue;
      seen[x] = 1;
      if (gs.leaf[k]) out.push_back(x);
      else stack.push_back(x);
    }
  }
  return out;
}

// The claim "no element of g touches an element of h on the piece"
// (before pc.before when set): empty when it holds.
std::string Checker::exact_leaf_error(std::uint32_t g, std::uint32_t h, const PieceContext& pc, CheckContext& ctx) {
  if (!ctx.motions) ctx.motions = std::make_unique<CheckMotions>(*ctx.body[0], *ctx.body[1]);
  for (std::uint32_t ea : group_elements(ctx.groups[0], g))
    for (std::uint32_t eb : group_elements(ctx.groups[1], h)) {
      const std::string error =
          no_contact_error(*ctx.motions, ctx.data[0]->elems[ea], ctx.data[1]->elems[eb], pc.ua, pc.ub, pc.before);
      if (!error.empty()) return "elements " + std::to_string(ea) + " and " + std::to_string(eb) + ": " + error;
    }
  return {};
}

// before_witness: a proof tree for the part [from, T) of the witness's
// piece, T the witness time.  Its separations are checked on the closed
// [from, T] (rational T) or [from, hi] (T in (lo, hi)), its exact claims
// on [from, T).
void Checker::check_before_witness(CheckContext& ctx) {
  const json& bw = *ctx.before_witness;
  const std::string L = ctx.label + ": before_witness";
  const Exact span = ctx.t1 - ctx.t0;
  RealRoot root = ctx.witness_root ? check_parameter_root(*ctx.witness_root, ctx.t0, ctx.t1)
                                   : rational_root((ctx.witness_t - ctx.t0) / span);
  const Exact end = ctx.witness_root ? ctx.witness_root->hi : ctx.witness_t;
  RealRoot start = rational_root((ctx.before_from - ctx.t0) / span);
  bool before;
  try {
    before = compare(start, root) == CGAL::SMALLER;
  } catch (const ExactLimit& e) {
    throw ResourceLimit(std::string("before_witness: ") + e.what());
  }
  if (ctx.before_from < ctx.t0 || !before)
    reject(L + ": from = " + str(ctx.before_from) + " is not before the witness time (or not in the check's interval)");
  PieceContext pc;
  pc.index = ctx.pt.size();
  pc.path = mem(ctx.path, "before_witness");
  pc.label = L + " [" + str(ctx.before_from) + ", witness)";
  pc.ua = (ctx.before_from - ctx.t0) / span;
  pc.ub = (end - ctx.t0) / span;
  pc.ints = integer_control_points(restrict_curve(ctx.curve, pc.ua, pc.ub));
  pc.before = &root;
  std::vector<int> trail;
  prove(bw.at("proof"), 0, 0, trail, pc, ctx);
}

std::string Checker::trail_path(const std::vector<int>& trail) {
  std::string s = "proof";
  for (int i : trail) s += ".parts[" + std::to_string(i) + "]";
  return s;
}

// The proof tree was validated in phase 2 (shape, rationals, depth,
// references); the checks below repeat only what guards memory safety.  A
// shared node (an integer) is judged where it is used, for the pair of
// groups there, like the same tree written out.
void Checker::prove(const json& node_in, std::uint32_t g, std::uint32_t h, std::vector<int>& trail,
                    const PieceContext& pc, CheckContext& ctx) {
  auto path = [&] { return pc.path + "." + trail_path(trail); };
  if (trail.size() > static_cast<std::size_t>(kMaxProofDepth))
    in_.bad(path(), "proof tree deeper than " + std::to_string(kMaxProofDepth) + " splits");
  const json* resolved = &node_in;
  while (resolved->is_number_integer())  // validated: each entry refers to earlier ones only
    resolved = &(*ctx.nodes)[in_.index_at(*resolved, path, ctx.nodes->size(), "an index into nodes")];
  const json& node = *resolved;
  auto here = [&] {
    return pc.label + ": " + trail_path(trail) + " (groups " + std::to_string(g) + ", " + std::to_string(h) + ")";
  };
  const json* parts = nullptr;
  std::size_t first = 0, side = 0;
  if (node.is_array()) {  // a split [s, P1, ..., Pm]
    if (node.empty()) in_.index(json(), path() + "[0]", 2, "0 or 1");  // throws
    side = in_.index_at(node[0], [&] { return path() + "[0]"; }, 2, "0 or 1");
    parts = &node;
    first = 1;
  } else {
    if (!node.is_object()) in_.object(node, path());
    const json* sep = in_.find(node, "sep");
    const bool only_sep = sep && node.size() == 1;  // (most nodes: no other member to look for)
    const json* split_side = only_sep ? nullptr : in_.find(node, "split");
    if (const json* exact = only_sep ? nullptr : in_.find(node, "exact")) {
      validate_exact_leaf(node, *exact, sep || split_side, path());
      if (ctx.general)  // exact claims decide the check's one rational curve, which a general check has not
        reject(here() + ": exact no-contact claims are not part of certificates of planner motions, tolerances or "
                        "clearances");
      ++ctx.exact_claims;
      if (const std::string error = exact_leaf_error(g, h, pc, ctx); !error.empty())
        reject(here() + ": exact no-contact claim fails: " + error);
      return;
    }
    if ((sep != nullptr) == (split_side != nullptr))
      in_.bad(path(), "expected exactly one of \"sep\", \"split\" and \"exact\"");
    if (sep) {
      if (!sep->is_array() || sep->size() != 3) in_.vec3(*sep, path() + ".sep");  // throws
      Vec3E n;
      for (int r = 0; r < 3; ++r)
        n[r] = in_.rational_at((*sep)[r], [&] { return idx(path() + ".sep", static_cast<std::size_t>(r)); });
      ++ctx.separations;
      if (const std::optional<std::size_t> fails = separation_fails_at(n, g, h, pc, ctx))
        reject(here() + ": separation fails at control point " + std::to_string(*fails));
      return;
    }
    side = split_side->is_number_integer() && (*split_side == 0 || *split_side == 1)
               ? (*split_side == 0 ? 0 : 1)
               : in_.index(*split_side, path() + ".split", 2, "0 or 1");
    parts = in_.find(node, "parts");
    if (!parts) in_.member(node, "parts", path());  // throws
    if (!parts->is_array()) in_.array(*parts, path() + ".parts");
  }
  const std::size_t count = parts->size() - first;
  const GroupSet& gs = ctx.groups[side];
  const std::uint32_t split_group = side == 0 ? g : h;
  if (gs.leaf[split_group])
    reject(here() + ": split " + std::to_string(side) + " of group " + std::to_string(split_group) +
           ", which has no children");
  const std::vector<std::uint32_t>& children = gs.items[split_group];
  if (count != children.size())
    reject(here() + ": split " + std::to_string(side) + " has " + std::to_string(count) + " parts, group " +
           std::to_string(split_group) + " has " + std::to_string(children.size()) + " children");
  for (std::size_t i = 0; i < count; ++i) {
    trail.push_back(static_cast<int>(i));
    prove((*parts)[first + i], side == 0 ? children[i] : g, side == 1 ? children[i] : h, trail, pc, ctx);
    trail.pop_back();
  }
}

// The first control point at which the separation claim fails, or nothing.
std::optional<std::size_t> Checker::separation_fails_at(const Vec3E& n, std::uint32_t g, std::uint32_t h, const PieceContext& pc,
                                 CheckContext& ctx) {
  const std::vector<std::uint32_t>& va = ctx.groups[0].vertices(g, scratch_a_, cache_budget_);
  const std::vector<std::uint32_t>& vb = ctx.groups[1].vertices(h, scratch_b_, cache_budget_);
  return check_internal::separation_fails_at(n, va, ctx.data[0]->coords, vb, ctx.data[1]->coords, pc, ctx.dadb,
                                             ctx.margin, z_);
}

}  // namespace check_internal

}  // namespace tmcert::certificate
