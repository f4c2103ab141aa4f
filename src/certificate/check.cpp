// The independent certificate checker: docs/certificate-format.md is the
// contract, proofs/certificates.md the soundness argument.
//
// Everything is exact.  The scene's control points, the joint curve and its
// restriction to a piece are rationals (CGAL::Gmpq, as `Exact`); for the
// separation claims, which dominate the work, each piece's control points,
// the body's vertices and the direction are brought to integers over common
// positive denominators (multiplying an inequality by a positive number
// keeps it), and the linear forms over a group's vertices are evaluated in
// integers (check_separation.h).  No floating point is used anywhere.
//
// The checker's files: check_numbers.h (its exact vocabulary),
// check_bernstein.cpp (Bernstein arithmetic, the joint curve, poses),
// check_separation.cpp (separations in integers, bodies, groups),
// check_ray.cpp (ray parity), check_document.cpp (reading the document),
// this file (the document's checks read and validated: phases 1 and 2),
// check_judge.cpp (phase 3: tilings, verdicts, witnesses, start claims),
// check_proof.cpp (proof trees of the pieces).
#include "src/certificate/check.h"
#include "src/certificate/checker.h"
#include "src/certificate/exact_claims.h"
#include "src/certificate/scope.h"

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>

namespace tmcert::certificate {

namespace check_internal {

// ---------------------------------------------------------------- the checker

CheckOutcome Checker::run(const json& doc) {
  CheckOutcome outcome;
  try {
    check_document(doc, outcome);
    outcome.ok = true;
  } catch (const Rejected& r) {
    outcome.ok = false;
    outcome.message = in_.source() + ": " + r.message;
    outcome.proven.clear();
  }
  return outcome;
}

BodyData& Checker::body_data(std::size_t i) {
  if (bodies_.empty()) bodies_.resize(scene_.bodies.size());
  if (!bodies_[i]) bodies_[i] = make_body_data(scene_.bodies[i]);
  return *bodies_[i];
}

// Phase 1: the certificate belongs to this scene (else rejected: element
// indices mean nothing in another scene).  Phase 2: every check is read
// and validated (InputError), proof trees included.  Phase 3: the claims.
void Checker::check_document(const json& doc, CheckOutcome& outcome) {
  in_.object(doc, "");
  const json& format = in_.member(doc, "format", "");
  if (!format.is_string() ||
      (format.get_ref<const std::string&>() != kFormat && format.get_ref<const std::string&>() != kFormatV1))
    in_.bad("format", std::string("unknown format ") + (format.is_string() ? quote_text(format.get<std::string>())
                                                                         : std::string(describe(format))) +
                          ", expected \"" + kFormat + "\" (or \"" + kFormatV1 + "\")");

  const json& sb = in_.array(in_.member(doc, "scene_bodies", ""), "scene_bodies");
  if (sb.size() != scene_.bodies.size())
    reject("scene_bodies: " + std::to_string(sb.size()) + " bodies, the scene has " +
           std::to_string(scene_.bodies.size()) + " (the certificate belongs to another scene)");
  for (std::size_t i = 0; i < sb.size(); ++i) {
    const std::string path = idx("scene_bodies", i);
    in_.object(sb[i], path);
    const std::string& name = in_.string(in_.member(sb[i], "name", path), mem(path, "name"));
    const json& count = in_.member(sb[i], "elements", path);
    const std::size_t n = in_.index(count, mem(path, "elements"), std::numeric_limits<std::size_t>::max(),
                                    "an element count");
    const Body& b = scene_.bodies[i];
    if (name != b.name || n != element_count(b))
      reject(path + ": " + quote_text(name) + " with " + std::to_string(n) + " elements, but the scene's body " +
             std::to_string(i) + " is " + quote_text(b.name) + " with " + std::to_string(element_count(b)) +
             " elements (the certificate belongs to another scene)");
  }

  const json& checks = in_.array(in_.member(doc, "checks", ""), "checks");
  if (checks.size() != scene_.checks.size())
    reject("checks: " + std::to_string(checks.size()) + " checks, the scene has " +
           std::to_string(scene_.checks.size()) + " (the certificate belongs to another scene)");
  std::vector<std::unique_ptr<CheckContext>> ctx(checks.size());
  for (std::size_t i = 0; i < checks.size(); ++i) ctx[i] = bind_check(checks[i], i);
  for (std::size_t i = 0; i < checks.size(); ++i) read_check(*ctx[i]);
  for (std::size_t i = 0; i < checks.size(); ++i) {
    outcome.proven.push_back(judge_check(*ctx[i]));
    ctx[i].reset();  // frees its group caches
    cache_budget_ = kGroupCacheBudget;
  }
}

// Scene parameter interval of a check (docs: a if it moves, else b if it
// moves, else a if it has a motion, else b if it has one, else [0, 1]).
std::pair<Exact, Exact> Checker::check_interval(const Body& a, const Body& b, const std::string& label) const {
  const bool ma = a.moves(), mb = b.moves();
  if (ma && mb && *a.interval() != *b.interval())
    throw InputError(scene_.source + ": checks: [" + quote_text(a.name) + ", " + quote_text(b.name) +
                     "]: two moving bodies must share their motion interval (" + label + " cannot be certified)");
  const Body* m = ma ? &a : mb ? &b : a.interval() ? &a : b.interval() ? &b : nullptr;
  if (!m) return {Exact(0), Exact(1)};
  return *m->interval();
}

std::unique_ptr<CheckContext> Checker::bind_check(const json& c, std::size_t ci) {
  auto ctx = std::make_unique<CheckContext>();
  ctx->index = ci;
  ctx->doc = &c;
  ctx->path = idx("checks", ci);
  const auto [ia, ib] = scene_.checks[ci];
  ctx->body[0] = &scene_.bodies[ia];
  ctx->body[1] = &scene_.bodies[ib];
  ctx->label = ctx->path + " (" + quote_text(ctx->body[0]->name) + " x " + quote_text(ctx->body[1]->name) + ")";
  const std::string& P = ctx->path;
  in_.object(c, P);
  const json& bodies = in_.array(in_.member(c, "bodies", P), mem(P, "bodies"), 2);
  const std::string& na = in_.string(bodies[0], idx(mem(P, "bodies"), 0));
  const std::string& nb = in_.string(bodies[1], idx(mem(P, "bodies"), 1));
  if (na != ctx->body[0]->name || nb != ctx->body[1]->name)
    reject(P + ".bodies: [" + quote_text(na) + ", " + quote_text(nb) + "], but the scene's check " + std::to_string(ci) +
           " is [" + quote_text(ctx->body[0]->name) + ", " + quote_text(ctx->body[1]->name) +
           "] (the certificate belongs to another scene)");
  std::tie(ctx->t0, ctx->t1) = check_interval(*ctx->body[0], *ctx->body[1], ctx->label);
  const auto [ilo, ihi] = in_.pair(in_.member(c, "interval", P), mem(P, "interval"));
  if (ilo != ctx->t0 || ihi != ctx->t1)
    reject(ctx->label + ": interval [" + str(ilo) + ", " + str(ihi) + "], but the check's parameter interval is [" +
           str(ctx->t0) + ", " + str(ctx->t1) + "] (the certificate belongs to another scene)");
  ctx->data[0] = &body_data(ia);
  ctx->data[1] = &body_data(ib);
  bind_levels(c, *ctx, ia, ib);
  const Body& A = *ctx->body[0];
  const Body& Bb = *ctx->body[1];
  ctx->clearance = scene_.clearance_of(ci);
  ctx->general = A.trajectory || Bb.trajectory || A.tolerance > 0 || Bb.tolerance > 0 || ctx->clearance > 0;
  if (ctx->general) {
    ctx->margin = ctx->clearance;
    for (int s = 0; s < 2; ++s) {
      ctx->bounds[s] = coordinate_bounds(ctx->data[s]->elems);
      if (ctx->body[s]->tolerance > 0)
        ctx->margin += ctx->body[s]->tolerance * displacement_bound(*ctx->body[s], ctx->data[s]->elems);
    }
  }
  return ctx;
}

void Checker::read_check(CheckContext& ctx) {
  const json& c = *ctx.doc;
  const std::string& P = ctx.path;
  ctx.verdict = in_.string(in_.member(c, "verdict", P), mem(P, "verdict"));
  const std::string& verdict = ctx.verdict;
  if (verdict != "safe" && verdict != "collision" && verdict != "undecided")
    in_.bad(mem(P, "verdict"), "expected \"safe\", \"collision\" or \"undecided\", got " + quote_text(verdict));

  read_groups(c, ctx);

  // Shared proof nodes (optional): each entry refers only to earlier ones.
  static const json kNoNodes = json::array();
  ctx.nodes = &kNoNodes;
  if (const json* nodes = in_.find(c, "nodes"); nodes && !nodes->is_null())
    ctx.nodes = &in_.array(*nodes, mem(P, "nodes"));
  ctx.expanded.resize(ctx.nodes->size());
  ctx.node_depth.resize(ctx.nodes->size());
  for (std::size_t k = 0; k < ctx.nodes->size(); ++k)
    std::tie(ctx.expanded[k], ctx.node_depth[k]) = validate_proof((*ctx.nodes)[k], idx(mem(P, "nodes"), k), k, ctx);

  ctx.pieces = &in_.array(in_.member(c, "pieces", P), mem(P, "pieces"));
  const json& pieces = *ctx.pieces;
  ctx.pt.reserve(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::string pp = idx(mem(P, "pieces"), k);
    in_.object(pieces[k], pp);
    ctx.pt.push_back(in_.pair(in_.member(pieces[k], "t", pp), mem(pp, "t")));
    validate_root(in_.member(pieces[k], "proof", pp), mem(pp, "proof"), ctx);
  }

  const json* witness = in_.find(c, "witness");
  const json* first_contact = in_.find(c, "first_contact");
  const json* undecided = in_.find(c, "undecided");
  if (witness && witness->is_null()) witness = nullptr;
  if (first_contact && first_contact->is_null()) first_contact = nullptr;
  if (undecided && undecided->is_null()) undecided = nullptr;
  const std::string up = mem(P, "undecided");
  if (verdict == "safe") {
    if (witness) in_.bad(mem(P, "witness"), "a safe check has no witness");
    if (first_contact) in_.bad(mem(P, "first_contact"), "a safe check has no first contact");
    if (undecided && !in_.array(*undecided, up).empty()) in_.bad(up, "a safe check has no undecided intervals");
  } else if (verdict == "collision") {
    if (!witness) in_.bad(mem(P, "witness"), "missing required field (a collision needs a witness)");
    if (!first_contact) in_.bad(mem(P, "first_contact"), "missing required field (a collision needs it)");
    read_witness(*witness, ctx);
  } else {
    if (witness) in_.bad(mem(P, "witness"), "an undecided check has no witness");
    if (!undecided) in_.bad(up, "missing required field (an undecided check lists its intervals)");
    in_.array(*undecided, up);
    for (std::size_t k = 0; k < undecided->size(); ++k) {
      const json& u = (*undecided)[k];
      const std::string p = idx(up, k);
      if (u.is_object()) ctx.undecided.push_back(in_.pair(in_.member(u, "t", p), mem(p, "t")));
      else if (u.is_array()) ctx.undecided.push_back(in_.pair(u, p));
      else in_.bad(p, std::string("expected {\"t\": [lo, hi]} or [lo, hi], got ") + describe(u));
    }
  }
  if (first_contact) ctx.first_contact = in_.pair(*first_contact, mem(P, "first_contact"));
  if (const json* bw = in_.find(c, "before_witness"); bw && !bw->is_null()) {
    const std::string bp = mem(P, "before_witness");
    if (verdict != "collision") in_.bad(bp, "only a collision has a witness");
    if (ctx.general)  // its exact claims use the check's one rational curve
      reject(ctx.label + ": before_witness is not part of certificates of planner motions, tolerances or clearances");
    in_.object(*bw, bp);
    ctx.before_from = in_.rational(in_.member(*bw, "from", bp), mem(bp, "from"));
    validate_root(in_.member(*bw, "proof", bp), mem(bp, "proof"), ctx);
    ctx.before_witness = bw;
  }
  read_start(c, ctx);
}

// The shape of a proof tree (iteratively, depth-limited), so a malformed
// tree is bad input whatever the claims before it.  References to shared
// nodes (integers) must be below `bound` (an entry of nodes refers only to
// earlier entries, so references never loop); each is counted with its
// entry's expanded size and depth.  Returns the tree's expanded size (nodes
// judged, saturated at kMaxExpanded) and its depth in splits, references
// followed.
std::pair<std::uint64_t, int> Checker::validate_proof(const json& root, const std::string& root_path, std::size_t bound,
                                      const CheckContext& ctx) {
  struct Item {
    const json* node;
    std::size_t parent;  // index into `items`, or npos
    std::size_t part;    // index of the node in its parent's JSON array
    bool array_form;     // the parent is a split written [s, P1, ..., Pm]
    int depth;
  };
  constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
  std::vector<Item> items{{&root, npos, 0, false, 0}};
  std::vector<std::size_t> todo{0};
  std::uint64_t expanded = 0;
  int deepest = 0;
  auto add = [&](std::uint64_t n) { expanded = std::min(kMaxExpanded, expanded + std::min(n, kMaxExpanded)); };
  auto path = [&](std::size_t i) {
    std::vector<std::size_t> parts;
    for (std::size_t k = i; items[k].parent != npos; k = items[k].parent) parts.push_back(k);
    std::string s = root_path;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it)
      s += items[*it].array_form ? "[" + std::to_string(items[*it].part) + "]"
                                 : ".parts[" + std::to_string(items[*it].part) + "]";
    return s;
  };
  while (!todo.empty()) {
    const std::size_t i = todo.back();
    todo.pop_back();
    const json& node = *items[i].node;
    if (items[i].depth > kMaxProofDepth)
      in_.bad(path(i), "proof tree deeper than " + std::to_string(kMaxProofDepth) + " splits");
    if (node.is_number_integer()) {  // a shared node
      const std::size_t k = in_.index(node, path(i), bound,
                                      bound == ctx.nodes->size() ? "an index into nodes" : "an earlier entry of nodes");
      add(ctx.expanded[k]);
      if (items[i].depth + ctx.node_depth[k] > kMaxProofDepth)
        in_.bad(path(i), "proof tree deeper than " + std::to_string(kMaxProofDepth) + " splits (nodes[" +
                             std::to_string(k) + "] included)");
      deepest = std::max(deepest, items[i].depth + ctx.node_depth[k]);
      continue;
    }
    deepest = std::max(deepest, items[i].depth);
    add(1);
    const json* parts = nullptr;
    std::size_t first = 0;
    if (node.is_array()) {  // a split [s, P1, ..., Pm]
      if (node.empty() || !(node[0].is_number_integer() && (node[0] == 0 || node[0] == 1)))
        in_.index(node.empty() ? json() : node[0], path(i) + "[0]", 2, "0 or 1");  // throws
      parts = &node;
      first = 1;
    } else {
      if (!node.is_object()) in_.object(node, path(i));
      const json* sep = in_.find(node, "sep");
      const json* split_side = in_.find(node, "split");
      if (const json* exact = in_.find(node, "exact")) {  // an exact no-contact claim (exact_claims.h)
        validate_exact_leaf(node, *exact, sep || split_side, path(i));
        continue;
      }
      if ((sep != nullptr) == (split_side != nullptr))
        in_.bad(path(i), "expected exactly one of \"sep\", \"split\" and \"exact\"");
      if (sep) {
        if (!sep->is_array() || sep->size() != 3) in_.vec3(*sep, path(i) + ".sep");  // throws
        for (int r = 0; r < 3; ++r)
          in_.rational_at((*sep)[r], [&] { return idx(path(i) + ".sep", static_cast<std::size_t>(r)); });
        continue;
      }
      if (!(split_side->is_number_integer() && (*split_side == 0 || *split_side == 1)))
        in_.index(*split_side, path(i) + ".split", 2, "0 or 1");  // throws
      parts = in_.find(node, "parts");
      if (!parts) in_.member(node, "parts", path(i));  // throws
      if (!parts->is_array()) in_.array(*parts, path(i) + ".parts");
    }
    for (std::size_t k = first; k < parts->size(); ++k) {
      items.push_back({&(*parts)[k], i, k, first == 1, items[i].depth + 1});
      todo.push_back(items.size() - 1);
    }
  }
  return {expanded, deepest};
}

// A piece's (or before_witness's) proof: valid, and judging it takes at
// most 2 (groups of a) (groups of b) + 64 nodes (a proof over the writer's
// group trees has each pair of groups at most once; the slack keeps small
// tampered trees rejections, not bad input).
void Checker::validate_root(const json& root, const std::string& path, const CheckContext& ctx) {
  const std::uint64_t n = validate_proof(root, path, ctx.nodes->size(), ctx).first;
  const std::uint64_t ga = ctx.groups[0].items.size(), gb = ctx.groups[1].items.size();
  const std::uint64_t limit = ga != 0 && gb > (kMaxExpanded / 4) / ga ? kMaxExpanded : 2 * ga * gb + 64;
  if (n > limit)
    in_.bad(path, "the proof expands to more than " + std::to_string(limit) +
                      " nodes (twice the groups of a times the groups of b, and 64)");
}

void Checker::read_groups(const json& c, CheckContext& ctx) {
  const std::string gp = mem(ctx.path, "groups");
  const json& groups = in_.array(in_.member(c, "groups", ctx.path), gp, 2);
  for (int side = 0; side < 2; ++side) {
    const std::string sp = idx(gp, side);
    const json& list = in_.array(groups[side], sp);
    if (list.empty()) in_.bad(sp, "no groups (group 0 is the root)");
    GroupSet& gs = ctx.groups[side];
    gs.body = ctx.data[side];
    const std::size_t G = list.size(), E = gs.body->elems.size();
    gs.leaf.assign(G, 0);
    gs.items.assign(G, {});
    gs.cache.assign(G, {});
    gs.cached.assign(G, 0);
    gs.group_stamp.assign(G, 0);
    gs.vertex_stamp.assign(gs.body->vertices.size(), 0);
    for (std::size_t k = 0; k < G; ++k) {
      const std::string p = idx(sp, k);
      in_.object(list[k], p);
      const json* elems = in_.find(list[k], "elements");
      const json* children = in_.find(list[k], "children");
      if ((elems != nullptr) == (children != nullptr))
        in_.bad(p, "expected exactly one of \"elements\" and \"children\"");
      if (elems) {
        const std::string ep = mem(p, "elements");
        in_.array(*elems, ep);
        if (elems->empty()) in_.bad(ep, "a group needs at least one element");
        gs.leaf[k] = 1;
        for (std::size_t i = 0; i < elems->size(); ++i)
          gs.items[k].push_back(static_cast<std::uint32_t>(
              in_.index((*elems)[i], idx(ep, i), E,
                        quote_text(gs.body->body->name) + " has " + std::to_string(E) + " elements")));
      } else {
        const std::string cp = mem(p, "children");
        in_.array(*children, cp);
        if (children->size() < 2) in_.bad(cp, "a group needs at least two children");
        for (std::size_t i = 0; i < children->size(); ++i) {
          const json& x = (*children)[i];
          const std::size_t child = in_.index(x, idx(cp, i), G, std::to_string(G) + " groups");
          if (child <= k) in_.bad(idx(cp, i), "child " + std::to_string(child) + " must be after its group " + std::to_string(k));
          gs.items[k].push_back(static_cast<std::uint32_t>(child));
        }
      }
    }
  }
}

void Checker::read_witness(const json& w, CheckContext& ctx) {
  const std::string wp = mem(ctx.path, "witness");
  in_.object(w, wp);
  ctx.has_witness = true;
  if (has_true_shape_side(w)) return read_true_shape_witness(w, ctx);
  const json& t = in_.member(w, "t", wp);
  if (t.is_object()) {  // {"root_of": [...], "interval": [lo, hi]}
    const std::string tp = mem(wp, "t");
    ClaimedRoot root;
    const json& coefficients = in_.array(in_.member(t, "root_of", tp), mem(tp, "root_of"));
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
      const Exact c = in_.rational(coefficients[k], idx(mem(tp, "root_of"), k));
      if (c.denominator() != 1) in_.bad(idx(mem(tp, "root_of"), k), "not an integer");
      root.root_of.push_back(c.numerator());
    }
    const auto [lo, hi] = in_.pair(in_.member(t, "interval", tp), mem(tp, "interval"));
    root.lo = lo;
    root.hi = hi;
    ctx.witness_t = lo;
    ctx.witness_root = std::move(root);
  } else {
    ctx.witness_t = in_.rational(t, mem(wp, "t"));
    // At a pose that is only enclosed (a transcendental motion): a
    // point_box and, on each side, the vertices of an edge or a triangle.
    ctx.enclosed_witness = in_.find(w, "point") == nullptr && in_.find(w, "point_box") != nullptr;
    // A clearance violation at an enclosed pose: "points_box" (informative)
    // and, on each side, an element and weights in the body's frame.
    ctx.enclosed_clearance = !ctx.enclosed_witness && in_.find(w, "point") == nullptr && in_.find(w, "points_box") != nullptr;
    if (!ctx.enclosed_witness && !ctx.enclosed_clearance) ctx.witness_point = in_.vec3(in_.member(w, "point", wp), mem(wp, "point"));
  }
  if (const json* d = in_.find(w, "displacement")) {
    ctx.displacement = in_.vec3(*d, mem(wp, "displacement"));
    const std::string& which = in_.string(in_.member(w, "displaced", wp), mem(wp, "displaced"));
    if (which != "a" && which != "b") in_.bad(mem(wp, "displaced"), "expected \"a\" or \"b\", got " + quote_text(which));
    ctx.displaced = which == "a" ? 0 : 1;
    if (const json* o = in_.find(w, "displacement_other"))
      ctx.displacement_other = in_.vec3(*o, mem(wp, "displacement_other"));
  } else if (in_.find(w, "displacement_other")) {
    in_.bad(mem(wp, "displacement_other"), "needs \"displacement\" and \"displaced\"");
  }
  if (const json* pts = in_.find(w, "points")) {
    const std::string pp = mem(wp, "points");
    in_.array(*pts, pp, 2);
    ctx.points = std::array<Vec3E, 2>{in_.vec3((*pts)[0], idx(pp, 0)), in_.vec3((*pts)[1], idx(pp, 1))};
  }
  if (ctx.witness_root && (ctx.displacement || ctx.points))
    in_.bad(wp, "a witness at an irrational time has no displacement and no points");
  if (ctx.enclosed_witness && ctx.points) in_.bad(wp, "a witness at an enclosed pose has no points");
  if (ctx.enclosed_clearance && ctx.points) in_.bad(wp, "a clearance witness at an enclosed pose has no points");
  for (int s = 0; s < 2; ++s) {
    WitnessSide& side = ctx.side[s];
    const std::string sp = mem(wp, s == 0 ? "a" : "b");
    const json& x = in_.object(in_.member(w, s == 0 ? "a" : "b", wp), sp);
    if (ctx.witness_root || ctx.enclosed_witness) {  // an element and a sub-feature's vertices
      const BodyData& bd = *ctx.data[s];
      side.element = in_.index(in_.member(x, "element", sp), mem(sp, "element"), bd.elems.size(),
                               quote_text(bd.body->name) + " has " + std::to_string(bd.elems.size()) + " elements");
      const std::size_t nv = bd.elems[side.element].size();
      const json& vs = in_.array(in_.member(x, "vertices", sp), mem(sp, "vertices"));
      for (std::size_t i = 0; i < vs.size(); ++i)
        side.vertices.push_back(in_.index(vs[i], idx(mem(sp, "vertices"), i), nv,
                                          "element " + std::to_string(side.element) + " has " + std::to_string(nv) + " vertices"));
      if (ctx.enclosed_witness) {
        // Two vertices (an edge inside the convex element) or three (a
        // triangle inside it), distinct.
        const auto& v = side.vertices;
        const bool distinct = v.size() < 2 || (v[0] != v[1] && (v.size() < 3 || (v[2] != v[0] && v[2] != v[1])));
        if (!(v.size() == 2 || v.size() == 3) || !distinct)
          in_.bad(mem(sp, "vertices"), "expected two or three distinct vertices of the element (an edge or a triangle)");
        continue;
      }
      // A vertex, two vertices (a segment inside the convex element), or
      // all of them in order (the element itself).
      bool whole = side.vertices.size() == nv;
      for (std::size_t i = 0; whole && i < nv; ++i) whole = side.vertices[i] == i;
      if (!(side.vertices.size() == 1 || side.vertices.size() == 2 || whole))
        in_.bad(mem(sp, "vertices"), "expected one vertex, two vertices or all of the element's vertices in order");
      continue;
    }
    if (const json* interior = in_.find(x, "interior")) {
      if (in_.find(x, "element") || in_.find(x, "weights"))
        in_.bad(sp, "expected either \"interior\" or \"element\" and \"weights\"");
      read_interior_side(*interior, sp, side);
    } else {
      read_weighted_side(x, sp, *ctx.data[s], side);
    }
  }
}

void Checker::read_interior_side(const json& interior, const std::string& sp, WitnessSide& side) {
  side.interior = true;
  const std::string ip = mem(sp, "interior");
  in_.object(interior, ip);
  side.ray = in_.vec3(in_.member(interior, "ray", ip), mem(ip, "ray"));
}

void Checker::read_weighted_side(const json& x, const std::string& sp, const BodyData& bd, WitnessSide& side) {
  side.element = in_.index(in_.member(x, "element", sp), mem(sp, "element"), bd.elems.size(),
                           quote_text(bd.body->name) + " has " + std::to_string(bd.elems.size()) + " elements");
  const std::size_t nv = bd.elems[side.element].size();
  const json& ws = in_.array(in_.member(x, "weights", sp), mem(sp, "weights"));
  if (ws.size() != nv)
    in_.bad(mem(sp, "weights"), std::to_string(ws.size()) + " weights, element " + std::to_string(side.element) +
                                    " has " + std::to_string(nv) + " vertices");
  for (std::size_t i = 0; i < nv; ++i) side.weights.push_back(in_.rational(ws[i], idx(mem(sp, "weights"), i)));
}

void Checker::read_start(const json& c, CheckContext& ctx) {
  const std::string sp = mem(ctx.path, "start");
  const json* start = in_.find(c, "start");
  if (!start || start->is_null()) return;
  in_.array(*start, sp);
  std::set<std::pair<int, Exact>> seen;
  for (std::size_t k = 0; k < start->size(); ++k) {
    const json& e = (*start)[k];
    const std::string ep = idx(sp, k);
    in_.object(e, ep);
    const std::string& which = in_.string(in_.member(e, "solid", ep), mem(ep, "solid"));
    if (which != "a" && which != "b") in_.bad(mem(ep, "solid"), "expected \"a\" or \"b\", got " + quote_text(which));
    const int s = which == "a" ? 0 : 1;
    // The instant of the claim: the check's start unless "t" says (the
    // start of a run of pieces after an undecided interval).
    Exact at = ctx.t0;
    if (const json* t = in_.find(e, "t"); t && !t->is_null()) {
      at = in_.rational(*t, mem(ep, "t"));
      if (at < ctx.t0 || at > ctx.t1)
        in_.bad(mem(ep, "t"), str(at) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
    }
    if (!seen.insert({s, at}).second)
      in_.bad(mem(ep, "solid"), "a second entry for " + quote_text(which) + (at == ctx.t0 ? "" : " at t = " + str(at)));
    const BodyData& other = *ctx.data[1 - s];
    const json& pts = in_.array(in_.member(e, "points", ep), mem(ep, "points"));
    StartEntry entry{s, at, {}};
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::string pp = idx(mem(ep, "points"), i);
      in_.object(pts[i], pp);
      StartPoint p;
      p.element = in_.index(in_.member(pts[i], "element", pp), mem(pp, "element"), other.elems.size(),
                            quote_text(other.body->name) + " has " + std::to_string(other.elems.size()) + " elements");
      const std::size_t nv = other.elems[p.element].size();
      p.vertex = in_.index(in_.member(pts[i], "vertex", pp), mem(pp, "vertex"), nv,
                           "element " + std::to_string(p.element) + " has " + std::to_string(nv) + " vertices");
      p.ray = in_.vec3(in_.member(pts[i], "ray", pp), mem(pp, "ray"));
      entry.points.push_back(std::move(p));
    }
    ctx.start.push_back(std::move(entry));
  }
}

}  // namespace check_internal

using check_internal::Checker;

CheckOutcome check_certificate(const Scene& scene, const nlohmann::json& certificate, const std::string& source) {
  // The checker models only rational Bezier motions without tolerance or
  // clearance: anything else would be checked against a motion other than
  // the scene's.
  if (const std::string why = uncertifiable(scene); !why.empty())
    throw InputError(source + ": certificates do not cover this scene: " + why);
  return Checker(scene, source).run(certificate);
}

}  // namespace tmcert::certificate
