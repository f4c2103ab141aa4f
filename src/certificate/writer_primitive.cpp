// The certificate writer's witnesses on the true shape of a URDF cylinder
// or sphere (docs/certificate-format.md "Cylinders and spheres"): the side
// of a primitive is {"true_shape": true}; the other side is an element with
// weights (at the world point, or without one at an enclosed pose: the
// point is then that element's point), the interior of a solid, or a
// second true shape.  Each true shape side is confirmed with the checker's
// own test (check_primitive.h) before it is written.
#include "src/certificate/check.h"
#include "src/certificate/check_primitive.h"
#include "src/certificate/writer_check.h"
#include "src/io/primitives.h"

namespace tmcert::certificate::writer_internal {

std::optional<Body> at_level(const Body& body, int level) {
  if (level <= 0) return std::nullopt;
  if (!body.primitive) throw ResourceLimit("--certificate: a refinement level for " + body.name + ", which is no URDF cylinder or sphere");
  Body out = body;
  while (out.primitive->level < level)
    if (!refine_primitive(out)) throw ResourceLimit("--certificate: no level " + std::to_string(level) + " for " + body.name);
  return out;
}

json CheckWriter::true_shape_witness(const Witness& w) const {
  if (w.root || w.displacement || w.points) fail("a witness on a true shape is at a rational t, without displacement or points");
  const Body* bodies[2] = {&a, &b};
  const char* keys[2] = {"a", "b"};
  json out{{"t", rational(w.t)}};
  if (w.point_box) {
    // The other body's pose is enclosed: its element point, placed by the
    // checker's pose box, lies in the primitive for every pose.
    if (!w.local_point) fail("the true shape witness at an enclosed pose has no point on the other body");
    const int o = w.local_side, p = 1 - o;
    if (!bodies[p]->primitive || bodies[o]->primitive) fail("the true shape witness names the wrong side");
    const std::optional<PoseBox> box = pose_box_at(*bodies[o], w.t);
    if (!box) fail("the pose of " + bodies[o]->name + " at the witness's t = " + to_string(w.t) + " has no finite enclosure");
    if (const std::string error = check_internal::true_shape_error(*bodies[p], w.t, *box, *w.local_point); !error.empty())
      fail("the true shape witness does not hold over the checker's pose boxes: " + error);
    const std::vector<std::vector<Vec3E>> el = elements(*bodies[o]);
    for (int e : named_elements(*bodies[o], w.features[o])) {
      if (e < 0 || e >= static_cast<int>(el.size())) continue;
      if (auto weights = weights_at(el[e], kIdentity, *w.local_point)) {
        json ws = json::array();
        for (const Exact& x : *weights) ws.push_back(rational(x));
        out[keys[o]] = {{"element", e}, {"weights", std::move(ws)}};
        out[keys[p]] = {{"true_shape", true}};
        json box_json = json::array();
        for (const auto& range : *w.point_box) box_json.push_back(json::array({rational(range[0]), rational(range[1])}));
        out["point_box"] = std::move(box_json);
        return out;
      }
    }
    fail("the witness point was not found on " + w.features[o]);
  }
  out["point"] = vec(w.point);
  for (int k = 0; k < 2; ++k) {
    const Body& body = *bodies[k];
    if (body.primitive) {
      if (const std::string error = check_internal::true_shape_error(body, w.t, check_internal::identity_box(), w.point);
          !error.empty())
        fail("the true shape witness does not hold: " + error);
      out[keys[k]] = {{"true_shape", true}};
      continue;
    }
    const std::optional<Mat34E> m = exact_pose_at(body, w.t);
    if (!m) fail("the pose of " + body.name + " at the witness's t = " + to_string(w.t) + " is not exact");
    if (w.features[k] == body.name + " interior") {
      auto ray = ray_from(body, placed_pieces(body, *m), w.point);
      if (!ray || !ray->second) fail("the interior witness could not be confirmed by a ray");
      out[keys[k]] = {{"interior", {{"ray", vec(ray->first)}}}};
      continue;
    }
    const std::vector<std::vector<Vec3E>> el = elements(body);
    bool found = false;
    for (int e : named_elements(body, w.features[k])) {
      if (e < 0 || e >= static_cast<int>(el.size())) continue;
      if (auto weights = weights_at(el[e], *m, w.point)) {
        json ws = json::array();
        for (const Exact& x : *weights) ws.push_back(rational(x));
        out[keys[k]] = {{"element", e}, {"weights", std::move(ws)}};
        found = true;
        break;
      }
    }
    if (!found) fail("the witness point was not found on " + w.features[k]);
  }
  return out;
}

}  // namespace tmcert::certificate::writer_internal
