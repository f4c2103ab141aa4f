#include "src/certificate/scope.h"

#include "src/certificate/motions.h"

namespace tmcert::certificate {

// The check's parameter interval (docs/certificate-format.md).
std::pair<Exact, Exact> check_interval(const Body& a, const Body& b) {
  if (a.moves()) return *a.interval();
  if (b.moves()) return *b.interval();
  if (a.interval()) return *a.interval();
  if (b.interval()) return *b.interval();
  return {Exact(0), Exact(1)};
}

std::string uncertifiable(const Scene& scene) {
  // Start claims place the other body's vertices at the start, exactly or
  // (where a pose there is not exact: an rpy rotation, a joint away from 0)
  // enclosed by the checker's own pose boxes: a check with a solid body
  // needs a finite enclosure of both poses there.
  for (const auto& [ia, ib] : scene.checks) {
    const Body& a = scene.bodies[ia];
    const Body& b = scene.bodies[ib];
    if (a.solid || b.solid) {
      const Exact t0 = check_interval(a, b).first;
      for (const Body* body : {&a, &b})
        if (!exact_pose_at(*body, t0) && (body->motion || !pose_box_at(*body, t0)))
          return "check [\"" + a.name + "\", \"" + b.name + "\"] has a solid body and the pose of \"" + body->name +
                 "\" at its start is neither exact nor enclosed";
    }
    // A URDF cylinder or sphere is certified: its safe parts on the
    // circumscribed polyhedron the checker rebuilds from the scene (the
    // verifier does not refine it while recording), its collisions by a
    // witness on the true shape (check_primitive.h, proofs/certificates.md §8).
  }
  return {};
}

}  // namespace tmcert::certificate
