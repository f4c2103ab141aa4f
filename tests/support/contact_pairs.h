// Shared by the contact tests on random triangles (tests/kernels/
// test_contact.cpp, tests/verify/test_clearance.cpp): random points, a
// moving and a fixed triangle prepared as the search prepares bodies, and
// the three feature pairs of them that the tests sample (a vertex against
// a face, a face against a vertex, an edge against an edge), each with a
// map from (a, b) in [0, 1]^2 to a point of each feature.
#pragma once

#include "src/verify/prepared.h"
#include "tests/support/random_geometry.h"

#include <array>
#include <utility>

namespace tmcert::testing {

inline Vec3E rand_point(Rng& r) { return {r.q(-8, 8, 4), r.q(-8, 8, 4), r.q(-8, 8, 4)}; }

// m x, exactly.
inline Vec3E map_point(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

// The point (1 - a - b) t0 + a t1 + b t2.
inline Vec3E on_triangle(const std::array<Vec3E, 3>& t, const Exact& a, const Exact& b) {
  const Exact c = Exact(1) - a - b;
  return {c * t[0][0] + a * t[1][0] + b * t[2][0], c * t[0][1] + a * t[1][1] + b * t[2][1],
          c * t[0][2] + a * t[1][2] + b * t[2][2]};
}

// A point of triangle t for every (a, b) in [0, 1]^2 (the square folded
// onto the triangle).
inline Vec3E folded_on_triangle(const std::array<Vec3E, 3>& t, const Exact& a, const Exact& b) {
  return a + b <= 1 ? on_triangle(t, a, b) : on_triangle(t, Exact(1) - a, Exact(1) - b);
}

// Triangle `tm` translated by (1, 0, 0) over [0, 1] ("m") and triangle `tf`
// fixed ("f"), prepared.
struct TrianglePair {
  std::array<Vec3E, 3> tm, tf;
  Body bm, bf;
  PreparedBody pm, pf;

  TrianglePair(const std::array<Vec3E, 3>& m, const std::array<Vec3E, 3>& f)
      : tm(m), tf(f), bm(moving(triangle_body("m", m))), bf(triangle_body("f", f)), pm(bm), pf(bf) {}

  static Body moving(Body b) {
    b.motion = Motion{0, 1, {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}}, {1, 1}};
    return b;
  }

  // check(kind, X, Y, Xi, Yi, sample) for vertex 0 of the moving triangle
  // against the fixed face, the moving face against fixed vertex 0, and
  // edge 0 against edge 0 (edges are p0->p1 of the respective triangles);
  // sample(a, b) is a pair {x of X, y of Y}.
  template <typename Check>
  void for_each_sampled_pair(Check&& check) const {
    check(ContactKind::VertexFace, pm.exact().vertices[0], pf.exact().faces[0], pm.vertices.interval[0],
          pf.faces.interval[0],
          [&](const Exact& a, const Exact& b) { return std::pair{tm[0], folded_on_triangle(tf, a, b)}; });
    check(ContactKind::FaceVertex, pm.exact().faces[0], pf.exact().vertices[0], pm.faces.interval[0],
          pf.vertices.interval[0],
          [&](const Exact& a, const Exact& b) { return std::pair{folded_on_triangle(tm, a, b), tf[0]}; });
    const auto& em = pm.exact().edges[0];
    const auto& ef = pf.exact().edges[0];
    check(ContactKind::EdgeEdge, em, ef, pm.edges.interval[0], pf.edges.interval[0],
          [&em, &ef](const Exact& a, const Exact& b) {
            Vec3E x, y;
            for (int i = 0; i < 3; ++i) {
              x[i] = em.origin[i] + a * em.axis[0][i];
              y[i] = ef.origin[i] + b * ef.axis[0][i];
            }
            return std::pair{x, y};
          });
  }
};

}  // namespace tmcert::testing
