// A scene built in code from vertex and index arrays (no JSON), verified
// with the public API: a box dropped onto a table.  Prints the verdict, the
// time of first contact as a decimal and the witness point, and exits 0
// safe, 1 collision, 2 undecided, 3 bad input (as `tmcert verify`).
#include <tmcert/tmcert.h>

#include <cstddef>
#include <iomanip>
#include <iostream>
#include <vector>

int main() {
  // The table: the square [-1, 1]^2 at z = 0, two triangles.
  const std::vector<double> table_xyz = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::vector<std::size_t> table_faces = {0, 1, 2, 0, 2, 3};
  // The box [-1/4, 1/4]^2 x [0, 1/2]: eight corners, twelve triangles.
  // Doubles are taken exactly as their binary values (0.25 is 1/4).
  std::vector<double> box_xyz;
  for (int k = 0; k < 8; ++k)
    box_xyz.insert(box_xyz.end(), {k & 1 ? 0.25 : -0.25, k & 2 ? 0.25 : -0.25, k & 4 ? 0.5 : 0.0});
  const std::vector<std::size_t> box_faces = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                              2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  try {
    tmcert::SceneBuilder builder;
    builder.add_body("table").triangles(table_xyz, table_faces);
    // Lowered from z = 1 to z = -1/2 over the parameter interval [0, 1].
    builder.add_body("box").triangles(box_xyz, box_faces).motion(tmcert::Motion::translation({0, 0, 1}, {0, 0, "-1/2"}));
    builder.check("box", "table");  // without checks: every moving body against every other one
    const tmcert::Scene scene = builder.build();

    const tmcert::Result result = tmcert::verify(scene);  // filtered kernel: certified
    std::cout << "verdict: " << tmcert::to_string(result.verdict()) << "\n";
    for (const tmcert::CheckResult& check : result.checks()) {
      if (!check.witness) continue;
      const tmcert::Witness& w = *check.witness;
      std::cout << std::setprecision(15) << check.bodies[0] << " meets " << check.bodies[1] << " at t = "
                << w.t.approx() << " (exactly " << w.t.text() << ")\n"
                << "witness point: (" << w.point_approx[0] << ", " << w.point_approx[1] << ", " << w.point_approx[2]
                << ")\n";
    }
    return result.verdict() == tmcert::Verdict::Safe ? 0 : result.verdict() == tmcert::Verdict::Collision ? 1 : 2;
  } catch (const tmcert::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
}
