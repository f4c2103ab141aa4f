// Minimal use of the tmcert library: read a scene, verify it, print the
// verdict of each check.  Build against an installed tmcert with
//   find_package(tmcert REQUIRED)  target_link_libraries(app tmcert::tmcert)
#include "src/scene/parse.h"
#include "src/verify/verify.h"

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: minimal SCENE.json\n";
    return 3;
  }
  try {
    const tmcert::Scene scene = tmcert::parse_scene_file(argv[1]);
    tmcert::VerifyOptions options;  // filtered kernel: certified
    options.epsilon = scene.epsilon;  // absent: each check uses 1/1000 of its two bodies' box
    options.max_depth = scene.max_depth;
    const tmcert::SceneResult result = tmcert::verify_scene(scene, options);
    for (const tmcert::CheckResult& c : result.checks)
      std::cout << scene.bodies[c.bodies[0]].name << " x " << scene.bodies[c.bodies[1]].name << ": "
                << tmcert::to_string(c.verdict) << "\n";
    return result.verdict == tmcert::Verdict::Safe ? 0 : result.verdict == tmcert::Verdict::Collision ? 1 : 2;
  } catch (const tmcert::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
}
