// Minimal use of the tmcert library: read a scene file, verify it, print
// the verdict of each check.  Exits 0 safe, 1 collision, 2 undecided,
// 3 bad input (as `tmcert verify`).
#include <tmcert/tmcert.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: minimal SCENE.json\n";
    return 3;
  }
  try {
    const tmcert::Scene scene = tmcert::Scene::from_file(argv[1]);
    const tmcert::Result result = tmcert::verify(scene);  // filtered kernel: certified
    for (const tmcert::CheckResult& c : result.checks())
      std::cout << c.bodies[0] << " x " << c.bodies[1] << ": " << tmcert::to_string(c.verdict) << "\n";
    return result.verdict() == tmcert::Verdict::Safe ? 0 : result.verdict() == tmcert::Verdict::Collision ? 1 : 2;
  } catch (const tmcert::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
}
