// Witnesses on the true shape of URDF cylinders and spheres
// (check_primitive.h, proofs/certificates.md §8).  Exact rational interval
// arithmetic only (check_enclosed.cpp); no floating point decides anything.
#include "src/certificate/check_primitive.h"

#include "src/certificate/check_enclosed.h"
#include "src/certificate/checker.h"
#include "src/certificate/check_numbers.h"
#include "src/io/parse.h"
#include "src/io/primitives.h"

#include <algorithm>

namespace tmcert::certificate::check_internal {

namespace {

// The largest |x| over [lo, hi].
Exact largest_abs(const RInterval& i) { return std::max(CGAL::abs(i.lo), CGAL::abs(i.hi)); }

}  // namespace

bool box_in_primitive(const Body::Primitive& p, const RBox& x) {
  Exact sq[3];
  for (int i = 0; i < 3; ++i) {
    if (x[i].lo > x[i].hi) return false;  // not a box
    const Exact m = largest_abs(x[i]);
    sq[i] = m * m;
  }
  const Exact r2 = p.radius * p.radius;
  if (p.kind == Body::Primitive::Kind::Sphere) return sq[0] + sq[1] + sq[2] <= r2;
  return sq[0] + sq[1] <= r2 && largest_abs(x[2]) * 2 <= p.length;
}

PoseBox identity_box() {
  PoseBox b;
  b.center = identity_pose();
  for (Exact& r : b.radius) r = 0;
  return b;
}

std::string true_shape_error(const Body& prim, const Exact& t, const PoseBox& other, const Vec3E& x) {
  if (!prim.primitive) return quote_text(prim.name) + " is not a URDF cylinder or sphere (it has no true shape)";
  const std::optional<Mat34E> exact = exact_pose_at(prim, t);
  std::optional<PoseBox> box;
  if (!exact) {
    box = pose_box_at(prim, t);
    if (!box) return "the pose of " + quote_text(prim.name) + " at t = " + str(t) + " has no finite enclosure";
  }
  const std::optional<RBox> y = solid_frame_box(exact ? identity_box() : *box, exact, other, x);
  if (!y) return "the pose of " + quote_text(prim.name) + " at t = " + str(t) + " is singular";
  if (!box_in_primitive(*prim.primitive, *y)) {
    const bool sphere = prim.primitive->kind == Body::Primitive::Kind::Sphere;
    return "the point is not proven inside the true " + std::string(sphere ? "sphere" : "cylinder") + " of " +
           quote_text(prim.name) + " at t = " + str(t) + " (in its frame it lies in [" + str((*y)[0].lo) + ", " +
           str((*y)[0].hi) + "] x [" + str((*y)[1].lo) + ", " + str((*y)[1].hi) + "] x [" + str((*y)[2].lo) + ", " +
           str((*y)[2].hi) + "])";
  }
  return {};
}

// ---------------------------------------------------------------- the checker's levels

void Checker::bind_levels(const json& c, CheckContext& ctx, std::size_t ia, std::size_t ib) {
  const json* levels = in_.find(c, "levels");
  if (!levels) return;
  const std::string lp = mem(ctx.path, "levels");
  in_.array(*levels, lp, 2);
  const std::size_t index[2] = {ia, ib};
  for (int s = 0; s < 2; ++s) {
    const std::string sp = idx(lp, s);
    const Body& base = scene_.bodies[index[s]];
    const int level = static_cast<int>(in_.index((*levels)[s], sp, kMaxCylinderLevel + 1,
                                                 "a level from 0 to " + std::to_string(kMaxCylinderLevel)));
    if (level == 0) continue;
    if (!base.primitive || base.primitive->level != 0)
      in_.bad(sp, quote_text(base.name) + " is no URDF cylinder or sphere of the scene: it has no finer level");
    const std::pair<std::size_t, int> key{index[s], level};
    if (!refined_.count(key)) {
      // The scene reader's own construction (src/io/primitives.h): every
      // level circumscribes the true shape (proofs/robot-links.md §3).
      auto body = std::make_unique<Body>(base);
      while (body->primitive->level < level)
        if (!refine_primitive(*body))
          in_.bad(sp, quote_text(base.name) + " has no level " + std::to_string(level) + " (a " +
                          (base.primitive->kind == Body::Primitive::Kind::Sphere ? "sphere" : "cylinder") +
                          "'s finest is " +
                          std::to_string(base.primitive->kind == Body::Primitive::Kind::Sphere ? kMaxSphereLevel
                                                                                               : kMaxCylinderLevel) +
                          ")");
      refined_data_[key] = make_body_data(*body);
      refined_[key] = std::move(body);
    }
    ctx.body[s] = refined_[key].get();
    ctx.data[s] = refined_data_[key].get();
  }
}

// ---------------------------------------------------------------- the checker's witness

bool Checker::has_true_shape_side(const json& w) {
  for (const char* key : {"a", "b"}) {
    const auto it = w.find(key);
    if (it != w.end() && it->is_object() && it->contains("true_shape")) return true;
  }
  return false;
}

void Checker::read_true_shape_witness(const json& w, CheckContext& ctx) {
  const std::string wp = mem(ctx.path, "witness");
  ctx.true_shape_witness = true;
  const json& t = in_.member(w, "t", wp);
  if (t.is_object()) in_.bad(mem(wp, "t"), "a witness on a true shape is at a rational t");
  ctx.witness_t = in_.rational(t, mem(wp, "t"));
  if (in_.find(w, "displacement") || in_.find(w, "points"))
    in_.bad(wp, "a witness on a true shape has no displacement and no points");
  if (const json* p = in_.find(w, "point")) {
    ctx.has_point = true;
    ctx.witness_point = in_.vec3(*p, mem(wp, "point"));
  }
  int shapes = 0, elements = 0;
  for (int s = 0; s < 2; ++s) {
    WitnessSide& side = ctx.side[s];
    const std::string sp = mem(wp, s == 0 ? "a" : "b");
    const json& x = in_.object(in_.member(w, s == 0 ? "a" : "b", wp), sp);
    const json* shape = in_.find(x, "true_shape");
    const json* interior = in_.find(x, "interior");
    const json* element = in_.find(x, "element");
    if ((shape != nullptr) + (interior != nullptr) + (element != nullptr) != 1)
      in_.bad(sp, "expected exactly one of \"true_shape\", \"interior\" and \"element\" (with \"weights\")");
    if (shape) {
      if (!(shape->is_boolean() && shape->get<bool>()))
        in_.bad(mem(sp, "true_shape"), std::string("expected true, got ") + describe(*shape));
      side.true_shape = true;
      ++shapes;
    } else if (interior) {
      read_interior_side(*interior, sp, side);
    } else {
      read_weighted_side(x, sp, *ctx.data[s], side);
      ++elements;
    }
  }
  if (!ctx.has_point && !(shapes == 1 && elements == 1))
    in_.bad(wp, "without \"point\", a witness on a true shape has one \"true_shape\" side and an element with "
                "weights on the other");
}

void Checker::require_true_shape_sides(const CheckContext& ctx) {
  for (int s = 0; s < 2; ++s)
    if (ctx.body[s]->primitive && !ctx.side[s].true_shape) {
      const bool sphere = ctx.body[s]->primitive->kind == Body::Primitive::Kind::Sphere;
      reject(ctx.label + ": witness." + (s == 0 ? "a" : "b") + ": " + quote_text(ctx.body[s]->name) +
             " is a URDF " + (sphere ? "sphere" : "cylinder") +
             ": a collision needs a point of its true shape (\"true_shape\"); a point of its circumscribed "
             "polyhedron proves none");
    }
}

void Checker::check_true_shape_witness(const CheckContext& ctx) {
  const Exact& t = ctx.witness_t;
  const std::string L = ctx.label + ": witness";
  if (t < ctx.t0 || t > ctx.t1)
    reject(L + ": t = " + str(t) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
  if (!ctx.has_point) {
    // The point is the element side's weighted vertices, placed by that
    // body's pose at t (exact or enclosed).
    const int o = ctx.side[0].true_shape ? 1 : 0, p = 1 - o;
    const char* key = o == 0 ? "a" : "b";
    const Body& body = *ctx.body[o];
    const WitnessSide& side = ctx.side[o];
    const std::vector<Vec3E>& verts = ctx.data[o]->elems[side.element];
    Exact sum(0);
    Vec3E y{Exact(0), Exact(0), Exact(0)};
    for (std::size_t i = 0; i < verts.size(); ++i) {
      const Exact& wi = side.weights[i];
      if (sgn(wi) < 0) reject(L + "." + key + ".weights[" + std::to_string(i) + "] = " + str(wi) + " is negative");
      sum += wi;
      for (int r = 0; r < 3; ++r) y[r] += wi * verts[i][r];
    }
    if (sum != 1) reject(L + "." + key + ".weights sum to " + str(sum) + ", not 1");
    const std::optional<PoseBox> other = pose_box_at(body, t);
    if (!other) reject(L + "." + key + ": the pose of " + quote_text(body.name) + " at t = " + str(t) + " has no finite enclosure");
    if (const std::string error = true_shape_error(*ctx.body[p], t, *other, y); !error.empty())
      reject(L + "." + (p == 0 ? "a" : "b") + ".true_shape: " + error);
    return;
  }
  for (int s = 0; s < 2; ++s)  // the true shapes first
    if (ctx.side[s].true_shape)
      if (const std::string error = true_shape_error(*ctx.body[s], t, identity_box(), ctx.witness_point); !error.empty())
        reject(L + "." + (s == 0 ? "a" : "b") + ".true_shape: " + error);
  for (int s = 0; s < 2; ++s) {
    const char* key = s == 0 ? "a" : "b";
    const Body& body = *ctx.body[s];
    if (ctx.side[s].true_shape) continue;
    const std::optional<Mat34E> pose = exact_pose_at(body, t);
    if (!pose)
      reject(L + "." + key + ": the pose of " + quote_text(body.name) + " at t = " + str(t) +
             " is not exact (an element or interior side at a world point needs an exact pose)");
    check_side_at(ctx, s, *pose, ctx.witness_point);
  }
}

}  // namespace tmcert::certificate::check_internal
