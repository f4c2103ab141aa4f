// Shared by the tests of the search's pieces (tests/verify/test_*.cpp): a
// scene of two cubes, one fixed at the origin and one translating along a
// straight line, and a detail::Check<1> on it built as Verifier does.
#pragma once

#include "src/io/parse.h"
#include "src/motion/bezier.h"
#include "src/verify/prepared.h"
#include "src/verify/search.h"

#include <memory>
#include <string>

namespace tmcert::testing {

// The polygons of the axis-aligned cube [lo, hi]^3 (decimal strings).
inline std::string cube_polygons(const std::string& lo, const std::string& hi) {
  auto rect = [&](int axis, const std::string& c) {
    auto point = [&](const std::string& a, const std::string& b) {
      std::string p[3];
      p[axis] = c;
      p[(axis + 1) % 3] = a;
      p[(axis + 2) % 3] = b;
      return "[\"" + p[0] + "\",\"" + p[1] + "\",\"" + p[2] + "\"]";
    };
    return "[" + point(lo, lo) + "," + point(hi, lo) + "," + point(hi, hi) + "," + point(lo, hi) + "]";
  };
  std::string out;
  for (int axis = 0; axis < 3; ++axis)
    for (const std::string& c : {lo, hi}) out += (out.empty() ? "" : ",") + rect(axis, c);
  return "[" + out + "]";
}

// A cube "mover" [-1/2, 1/2]^3 translated from `from` to `to` (x y z, as
// JSON numbers) over t in [0, 1] past a fixed cube "post" [lo, hi]^3; both
// solid when `solid`.
inline Scene two_cubes(const std::string& from, const std::string& to, const std::string& lo = "-1/2",
                       const std::string& hi = "1/2", bool solid = false) {
  auto matrix = [](const std::string& xyz) {
    std::string c[3];
    std::size_t k = 0;
    for (int i = 0; i < 3; ++i) {
      const std::size_t e = xyz.find(' ', k);
      c[i] = xyz.substr(k, e == std::string::npos ? std::string::npos : e - k);
      k = e + 1;
    }
    return "[[1,0,0," + c[0] + "],[0,1,0," + c[1] + "],[0,0,1," + c[2] + "]]";
  };
  const std::string s = solid ? ", \"solid\": true" : "";
  return parse_scene_text("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"mover\", \"polygons\": " +
                              cube_polygons("-1/2", "1/2") + s +
                              ", \"motion\": {\"type\": \"rational_bezier\", \"control_points\": [" + matrix(from) + "," +
                              matrix(to) + "]}}, {\"name\": \"post\", \"polygons\": " + cube_polygons(lo, hi) + s + "}]}",
                          "two_cubes");
}

// The check of a scene's body 0 (moving) against body 1 (fixed), as
// Verifier builds it, with epsilon 1/1000.
struct CheckFixture {
  Scene scene;
  PreparedBody moving, other;
  VerifyOptions options;
  CheckResult result;
  explicit CheckFixture(Scene s) : scene(std::move(s)), moving(scene.bodies[0]), other(scene.bodies[1]) {
    options.epsilon = Exact(1, 1000);
  }
  detail::Check<1> check() {
    return detail::Check<1>{moving, other, false, moving.curve, enclose(moving.curve), *moving.body->motion,
                            1e-6, moving.max_rho2, options, result};
  }
};

}  // namespace tmcert::testing
