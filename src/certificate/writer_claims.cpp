// The certificate writer's witnesses and start claims (writer_check.h):
// an exact witness of a collision in the form the checker re-verifies
// (interior, algebraic or at an enclosed pose), a collision's
// before_witness, and the start claims of solid bodies.
#include "src/certificate/writer_check.h"
#include "src/certificate/algebraic_witness.h"
#include "src/certificate/check.h"
#include "src/certificate/check_enclosed.h"
#include "src/certificate/exact_claims.h"
#include "src/model/de_casteljau.h"
#include "src/model/solid.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

namespace tmcert::certificate::writer_internal {

// ---------------------------------------------------------------- witness helpers

std::optional<std::vector<Exact>> weights_at(const std::vector<Vec3E>& element, const Mat34E& m, const Vec3E& p) {
  std::vector<Vec3E> P;
  for (const Vec3E& v : element) P.push_back(apply(m, v));
  const std::size_t n = P.size();
  auto sub = [](const Vec3E& a, const Vec3E& b) { return Vec3E{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto dotE = [](const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto valid = [&](const std::vector<Exact>& w) {
    Vec3E s{0, 0, 0};
    Exact total(0);
    for (std::size_t i = 0; i < n; ++i) {
      if (w[i] < 0) return false;
      total += w[i];
      for (int k = 0; k < 3; ++k) s[k] += w[i] * P[i][k];
    }
    return total == 1 && s == p;
  };
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Exact> w(n, Exact(0));
    w[i] = 1;
    if (valid(w)) return w;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3E d = sub(P[j], P[i]);
      const Exact dd = dotE(d, d);
      if (dd == 0) continue;
      const Exact s = dotE(sub(p, P[i]), d) / dd;
      std::vector<Exact> w(n, Exact(0));
      w[i] = 1 - s;
      w[j] = s;
      if (valid(w)) return w;
    }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec3E e1 = sub(P[i], P[0]), e2 = sub(P[i + 1], P[0]), r = sub(p, P[0]);
    const Exact a11 = dotE(e1, e1), a12 = dotE(e1, e2), a22 = dotE(e2, e2);
    const Exact det = a11 * a22 - a12 * a12;
    if (det == 0) continue;
    const Exact b1 = dotE(r, e1), b2 = dotE(r, e2);
    const Exact x = (b1 * a22 - b2 * a12) / det, y = (a11 * b2 - a12 * b1) / det;
    std::vector<Exact> w(n, Exact(0));
    w[0] = 1 - x - y;
    w[i] = x;
    w[i + 1] = y;
    if (valid(w)) return w;
  }
  return std::nullopt;
}

// The elements a witness feature name ("<body> polygon 2", "<body> segment
// 0 end 1", "<body> point 3") can stand for.
std::vector<int> named_elements(const Body& body, const std::string& feature) {
  std::string rest = feature.substr(std::min(feature.size(), body.name.size() + 1));
  std::istringstream in(rest);
  std::string kind;
  int index = -1;
  in >> kind >> index;
  std::vector<int> out;
  const int P = static_cast<int>(body.pieces.size()), S = static_cast<int>(body.segments.size());
  if (kind == "polygon") {
    for (int e = 0; e < P; ++e)
      if (body.pieces[e].polygon == index) out.push_back(e);
  } else if (kind == "segment") {
    out.push_back(P + index);
  } else if (kind == "point") {
    out.push_back(P + S + index);
  } else if ((kind == "cylinder" || kind == "sphere") && body.primitive) {
    // A contact proven on a URDF cylinder or sphere (its true shape, inside
    // the body's polyhedron): any element of the polyhedron.
    for (int e = 0; e < P; ++e) out.push_back(e);
  }
  return out;
}

std::vector<std::vector<Vec3E>> placed_pieces(const Body& solid, const Mat34E& m) {
  std::vector<std::vector<Vec3E>> out;
  for (const ConvexPiece& piece : solid.pieces) {
    std::vector<Vec3E> poly;
    for (const Vec3E& v : piece.vertices) poly.push_back(apply(m, v));
    out.push_back(std::move(poly));
  }
  return out;
}

// A ray direction from p whose crossings with the placed pieces of `solid`
// are well defined, from a fixed sequence of directions, and whether p is
// inside (an odd count for some shell: the inside is the union of the
// shells' insides).
std::optional<std::pair<Vec3E, bool>> ray_from(const Body& solid, const std::vector<std::vector<Vec3E>>& polygons,
                                               const Vec3E& p) {
  const std::vector<int> polygon_shell = polygon_shells(solid);
  std::vector<int> shell;
  for (const ConvexPiece& piece : solid.pieces) shell.push_back(polygon_shell[piece.polygon]);
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> coordinate(-97, 97);
  for (int attempt = 0; attempt < 200; ++attempt) {
    Vec3E d;
    if (attempt == 0) d = {Exact(1), Exact(1, 3), Exact(1, 7)};
    else d = {Exact(coordinate(rng), 89), Exact(coordinate(rng), 83), Exact(coordinate(rng), 79)};
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
    if (auto count = ray_crossings(polygons, shell, p, d))
      return std::pair{d, std::any_of(count->begin(), count->end(), [](int c) { return c % 2 != 0; })};
  }
  return std::nullopt;
}

bool singular(const Mat34E& m) {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
             m[2] * (m[4] * m[9] - m[5] * m[8]) == 0;
}

// Per element the root of its component (elements linked by exactly equal
// vertices), the first element of each component its own root.
std::vector<std::size_t> component_roots(const std::vector<std::vector<Vec3E>>& el) {
  std::vector<std::size_t> parent(el.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<Vec3E, std::size_t> owner;
  for (std::size_t e = 0; e < el.size(); ++e)
    for (const Vec3E& v : el[e]) {
      auto [it, fresh] = owner.emplace(v, e);
      if (!fresh) parent[find(e)] = find(it->second);
    }
  std::vector<std::size_t> root(el.size());
  for (std::size_t e = 0; e < el.size(); ++e) root[e] = find(e);
  return root;
}

// ---------------------------------------------------------------- witnesses and start claims

namespace {

// The translation of body k (0: a, 1: b) that a witness states, if any:
// `displacement` for body `displaced`, `displacement_other` for the other.
const Vec3E* displacement_of(const Witness& w, int k) {
  if (!w.displacement) return nullptr;
  if (w.displaced == k) return &*w.displacement;
  return w.displacement_other ? &*w.displacement_other : nullptr;
}

// A witness's translations as the certificate states them
// (docs/certificate-format.md).
void add_displacements(json& out, const Witness& w) {
  if (!w.displacement) return;
  out["displacement"] = vec(*w.displacement);
  out["displaced"] = w.displaced == 0 ? "a" : "b";
  if (w.displacement_other) out["displacement_other"] = vec(*w.displacement_other);
}

}  // namespace

// A witness at an enclosed pose (a transcendental motion): an edge of one
// named element crossing a triangle of the other, certain over the
// checker's own pose boxes at t (motions.h).
json CheckWriter::enclosed_witness(const Witness& w) const {
  const Body* bodies[2] = {&a, &b};
  std::optional<PoseBox> box[2];
  for (int k = 0; k < 2; ++k) {
    box[k] = pose_box_at(*bodies[k], w.t);
    if (!box[k]) fail("the pose of " + bodies[k]->name + " at the witness's t = " + to_string(w.t) + " has no finite enclosure");
    if (const Vec3E* v = displacement_of(w, k))  // a toleranced contact: that body translated
      for (int r = 0; r < 3; ++r) box[k]->center[4 * r + 3] += (*v)[r];
  }
  const std::vector<std::vector<Vec3E>> el[2] = {elements(a), elements(b)};
  for (int ea : named_elements(a, w.features[0]))
    for (int eb : named_elements(b, w.features[1])) {
      if (ea < 0 || eb < 0 || ea >= static_cast<int>(el[0].size()) || eb >= static_cast<int>(el[1].size())) continue;
      const int e[2] = {ea, eb};
      std::vector<RBox> placed[2];
      for (int k = 0; k < 2; ++k)
        for (const Vec3E& v : el[k][e[k]]) placed[k].push_back(place_box(*box[k], v));
      for (int edge_side = 0; edge_side < 2; ++edge_side) {
        const std::vector<RBox>& P = placed[edge_side];
        const std::vector<RBox>& T = placed[1 - edge_side];
        if (P.size() < 2 || T.size() < 3) continue;
        for (std::size_t i = 0; i < P.size(); ++i)
          for (std::size_t j = i + 1; j < P.size(); ++j)
            for (std::size_t x = 0; x < T.size(); ++x)
              for (std::size_t y = x + 1; y < T.size(); ++y)
                for (std::size_t z = y + 1; z < T.size(); ++z) {
                  if (!certain_crossing(P[i], P[j], T[x], T[y], T[z])) continue;
                  json box_json = json::array();
                  for (const auto& range : *w.point_box)
                    box_json.push_back(json::array({rational(range[0]), rational(range[1])}));
                  json sides[2];
                  sides[edge_side] = {{"element", e[edge_side]}, {"vertices", json::array({i, j})}};
                  sides[1 - edge_side] = {{"element", e[1 - edge_side]}, {"vertices", json::array({x, y, z})}};
                  json out{{"t", rational(w.t)}, {"point_box", box_json}, {"a", sides[0]}, {"b", sides[1]}};
                  add_displacements(out, w);
                  return out;
                }
      }
    }
  fail("the enclosed witness at t = " + to_string(w.t) + " is not a certain edge-triangle crossing over the checker's pose boxes");
}

// A clearance violation at an enclosed pose: each side's point in its
// body's frame as the weights of a named element; the checker places them
// by its own pose boxes at t and bounds their distance (check_judge.cpp).
json CheckWriter::enclosed_clearance_witness(const Witness& w) const {
  if (!w.local_points) fail("the clearance witness at an enclosed pose has no points in the bodies' frames");
  const Body* bodies[2] = {&a, &b};
  const char* keys[2] = {"a", "b"};
  const Mat34E identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  json boxes = json::array();
  for (const auto& box : *w.points_box) {
    json b3 = json::array();
    for (const auto& range : box) b3.push_back(json::array({rational(range[0]), rational(range[1])}));
    boxes.push_back(std::move(b3));
  }
  json out{{"t", rational(w.t)}, {"points_box", std::move(boxes)}};
  add_displacements(out, w);
  for (int k = 0; k < 2; ++k) {
    const std::vector<std::vector<Vec3E>> el = elements(*bodies[k]);
    bool found = false;
    for (int e : named_elements(*bodies[k], w.features[k])) {
      if (e < 0 || e >= static_cast<int>(el.size())) continue;
      if (auto weights = weights_at(el[e], identity, (*w.local_points)[k])) {
        json ws = json::array();
        for (const Exact& x : *weights) ws.push_back(rational(x));
        out[keys[k]] = {{"element", e}, {"weights", std::move(ws)}};
        found = true;
        break;
      }
    }
    if (!found) fail("the clearance witness's point was not found on " + w.features[k]);
  }
  return out;
}

json CheckWriter::witness() const {
  const Witness& w = *r.witness;
  if (w.true_shape) return true_shape_witness(w);
  if (w.root) return algebraic_witness(w);
  if (w.points_box) return enclosed_clearance_witness(w);
  if (w.point_box) return enclosed_witness(w);
  json out{{"t", rational(w.t)}, {"point", vec(w.point)}};
  add_displacements(out, w);
  if (w.points) out["points"] = json::array({vec((*w.points)[0]), vec((*w.points)[1])});
  const Body* bodies[2] = {&a, &b};
  const char* keys[2] = {"a", "b"};
  for (int k = 0; k < 2; ++k) {
    const Body& body = *bodies[k];
    const std::string& feature = w.features[k];
    Mat34E m = pose(body, w.t);
    if (const Vec3E* v = displacement_of(w, k))
      for (int i = 0; i < 3; ++i) m[4 * i + 3] += (*v)[i];
    const Vec3E& target = w.points ? (*w.points)[k] : w.point;
    if (feature == body.name + " interior") {
      auto ray = ray_from(body, placed_pieces(body, m), target);
      if (!ray || !ray->second) fail("the interior witness could not be confirmed by a ray");
      out[keys[k]] = {{"interior", {{"ray", vec(ray->first)}}}};
      continue;
    }
    const std::vector<std::vector<Vec3E>> el = elements(body);
    bool found = false;
    for (int e : named_elements(body, feature)) {
      if (e < 0 || e >= static_cast<int>(el.size())) continue;
      if (auto weights = weights_at(el[e], m, target)) {
        json ws = json::array();
        for (const Exact& x : *weights) ws.push_back(rational(x));
        out[keys[k]] = {{"element", e}, {"weights", std::move(ws)}};
        found = true;
        break;
      }
    }
    if (!found) fail("the witness point was not found on " + feature);
  }
  return out;
}

// A witness at an irrational time: the root as the result gives it, and
// on each side an element and the vertices of a sub-feature of it (a
// vertex, an edge or the whole element) such that the two sub-features
// provably share a point at the root (algebraic_witness.h).
json CheckWriter::algebraic_witness(const Witness& w) const {
  const AlgebraicTime& at = *w.root;
  const ClaimedRoot claim{at.root_of, at.lo, at.hi};
  if (const std::string error = root_claim_error(claim, interval.first, interval.second); !error.empty())
    fail("the witness time is not a valid root claim: " + error);
  RealRoot root;
  std::optional<CheckMotions> general_motions;
  if (general()) {  // on the rational segment of each motion around the root
    const auto span = rational_span(a, b, at.lo, at.hi, interval.first, interval.second);
    if (!span) fail("the witness time is not inside one rational segment of both motions");
    std::string why;
    const auto ma = piece_motion(a, span->first, span->second, why);
    const auto mb = piece_motion(b, span->first, span->second, why);
    if (!ma || !mb || !ma->exact || !mb->exact) fail("the witness's segment is not rational: " + why);
    general_motions.emplace(*ma->exact, *mb->exact);
    root = check_parameter_root(claim, span->first, span->second);
  } else {
    root = check_parameter_root(claim, interval.first, interval.second);
  }
  const CheckMotions motions = general_motions ? *general_motions : CheckMotions(a, b);
  const std::vector<std::vector<Vec3E>> el[2] = {elements(a), elements(b)};
  const std::vector<int> named[2] = {named_elements(a, w.features[0]), named_elements(b, w.features[1])};
  for (int ea : named[0])
    for (int eb : named[1]) {
      if (ea < 0 || eb < 0 || ea >= static_cast<int>(el[0].size()) || eb >= static_cast<int>(el[1].size())) continue;
      const std::vector<Vec3E>& va = el[0][ea];
      const std::vector<Vec3E>& vb = el[1][eb];
      for (const std::vector<int>& sa : sub_features(va.size()))
        for (const std::vector<int>& sb : sub_features(vb.size())) {
          std::vector<MovingPoint> pa, pb;
          for (int i : sa) pa.push_back(motions.place(0, va[i]));
          for (int j : sb) pb.push_back(motions.place(1, vb[j]));
          if (!ContactSolver::touch(pa, pb, root)) continue;
          json coefficients = json::array();
          for (const CGAL::Gmpz& c : at.root_of) coefficients.push_back(rational(Exact(c)));
          json box = json::array();
          for (const auto& range : *w.point_box) box.push_back(json::array({rational(range[0]), rational(range[1])}));
          return json{{"t", {{"root_of", coefficients}, {"interval", json::array({rational(at.lo), rational(at.hi)})}}},
                      {"point_box", box},
                      {"a", {{"element", ea}, {"vertices", sa}}},
                      {"b", {{"element", eb}, {"vertices", sb}}}};
        }
    }
  fail("no two sub-features of the witness's elements meet at its time " + at.approx);
}

// The part [from, T) before the witness time T of an exact first contact:
// a proof tree (separations on [from, T] or [from, hi], exact claims
// before T); on success, before_witness is set and the bracket becomes
// [T, T] (rational T) or the witness's interval, narrowed.
void CheckWriter::before_witness(const Prover& prover, const Exact& from, json& out) const {
  const Witness& w = *r.witness;
  const Exact length = interval.second - interval.first;
  const Exact u0 = (from - interval.first) / length;
  RealRoot root;
  Exact u1;
  try {
    if (w.root) {
      root = check_parameter_root(ClaimedRoot{w.root->root_of, w.root->lo, w.root->hi}, interval.first,
                                  interval.second);
      RealRoot start = rational_root(u0);
      if (compare(start, root) != CGAL::SMALLER) return;
      // Narrow the root's interval to a small fraction of [from, root).
      for (int k = 0; k < 200 && !root.is_rational() && (root.lo <= u0 || (root.hi - root.lo) * 64 > root.lo - u0);
           ++k)
        refine(root);
      if (root.is_rational() || root.lo <= u0) return;
      u1 = root.hi;
    } else {
      u1 = (w.t - interval.first) / length;
      if (!(u0 < u1)) return;
      root = rational_root(u1);
    }
  } catch (const ExactLimit&) {
    return;
  }
  // The exact control points on [u0, u1].
  const CurveE piece = de_casteljau_restrict(joint, u0, u1);
  const PieceImages im = prover.images(enclose(piece));
  const std::function<const CurveE&()> exact_of = [&]() -> const CurveE& { return piece; };
  set_no_contact(prover, u0, u1, &root);
  const std::optional<int> proof = prover.prove(im, exact_of, 0, 0);
  prover.no_contact = nullptr;
  if (!proof) return;
  out["before_witness"] = {{"from", rational(from)}, {"proof", *proof}};
  if (w.root) {
    const Exact lo = interval.first + root.lo * length, hi = interval.first + root.hi * length;
    out["witness"]["t"]["interval"] = json::array({rational(lo), rational(hi)});
    out["first_contact"] = json::array({rational(lo), rational(hi)});
  } else {
    out["first_contact"] = json::array({rational(w.t), rational(w.t)});
  }
}

// Start claims: one outside point per component of the other body for
// each solid body with a regular pose at `at` (t0, or the start of a run
// of pieces after an undecided interval: then with "t").
void CheckWriter::start(const Exact& at, json& out) const {
  const Body* bodies[2] = {&a, &b};
  for (int k = 0; k < 2; ++k) {
    const Body& solid = *bodies[k];
    const Body& other = *bodies[1 - k];
    if (!solid.solid) continue;
    if (!exact_start_pose(solid, at) || !exact_start_pose(other, at)) {
      enclosed_start(k, at, out);
      continue;
    }
    const Mat34E ms = pose(solid, at);
    if (singular(ms)) continue;
    const auto polygons = placed_pieces(solid, ms);
    const Mat34E mo = pose(other, at);
    const auto el = elements(other);
    const std::vector<std::size_t> root = component_roots(el);
    json points = json::array();
    for (std::size_t e = 0; e < el.size(); ++e) {
      if (root[e] != e) continue;
      const Vec3E p = apply(mo, el[e][0]);
      auto ray = ray_from(solid, polygons, p);
      if (!ray || ray->second)
        fail("no outside ray for element " + std::to_string(e) + " of " + other.name + " against solid " + solid.name);
      points.push_back({{"element", e}, {"vertex", 0}, {"ray", vec(ray->first)}});
    }
    json entry{{"solid", k == 0 ? "a" : "b"}};
    if (at != interval.first) entry["t"] = rational(at);
    entry["points"] = std::move(points);
    out.push_back(std::move(entry));
  }
}

std::optional<Mat34E> CheckWriter::exact_start_pose(const Body& body, const Exact& at) const {
  if (body.trajectory) return exact_pose_at(body, at);
  return pose(body, at);
}

void CheckWriter::enclosed_start(int k, const Exact& at, json& out) const {
  const Body* bodies[2] = {&a, &b};
  const Body& solid = *bodies[k];
  const Body& other = *bodies[1 - k];
  // The two poses as the checker encloses them (the exact one with radius 0).
  std::optional<Mat34E> exact[2];
  PoseBox box[2];
  const Body* pair[2] = {&solid, &other};
  for (int s = 0; s < 2; ++s) {
    exact[s] = exact_start_pose(*pair[s], at);
    if (exact[s]) {
      box[s].center = *exact[s];
      for (Exact& r : box[s].radius) r = 0;
      continue;
    }
    const std::optional<PoseBox> b = pair[s]->motion ? std::nullopt : pose_box_at(*pair[s], at);
    if (!b) fail("the pose of " + pair[s]->name + " at t = " + to_string(at) + " is neither exact nor enclosed");
    box[s] = *b;
  }
  if (exact[0] && singular(*exact[0])) return;
  // The solid in its own frame; each vertex of the other body as a box there.
  const auto polygons = placed_pieces(solid, kIdentity);
  const auto el = elements(other);
  const std::vector<std::size_t> root = component_roots(el);
  std::vector<std::vector<std::size_t>> members(el.size());
  for (std::size_t e = 0; e < el.size(); ++e) members[root[e]].push_back(e);
  json points = json::array();
  for (std::size_t e = 0; e < el.size(); ++e) {
    if (root[e] != e) continue;
    bool found = false;
    for (std::size_t m : members[e]) {
      for (std::size_t v = 0; v < el[m].size() && !found; ++v) {
        const std::optional<RBox> y =
            check_internal::solid_frame_box(box[0], exact[0], box[1], el[m][v]);
        if (!y) continue;
        if (!std::all_of(polygons.begin(), polygons.end(),
                         [&](const std::vector<Vec3E>& poly) { return check_internal::box_clear_of_polygon(*y, poly); }))
          continue;
        auto ray = ray_from(solid, polygons, check_internal::box_center(*y));
        if (!ray || ray->second) continue;
        points.push_back({{"element", m}, {"vertex", v}, {"ray", vec(ray->first)}});
        found = true;
      }
      if (found) break;
    }
    if (!found)
      fail("no vertex of the component of element " + std::to_string(e) + " of " + other.name +
           " proven outside solid " + solid.name + " at its enclosed pose at t = " + to_string(at));
  }
  json entry{{"solid", k == 0 ? "a" : "b"}};
  if (at != interval.first) entry["t"] = rational(at);
  entry["points"] = std::move(points);
  out.push_back(std::move(entry));
}

}  // namespace tmcert::certificate::writer_internal
