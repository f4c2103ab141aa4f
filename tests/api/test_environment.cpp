// tmcert::Environment (include/tmcert/environment.h), as a user links it:
// motions of one body against obstacles prepared once agree with verify()
// of the same scene; certify() from several threads at once gives the
// sequential results; bad bodies, obstacles and motions are InputErrors
// naming the field.
#include <boost/test/unit_test.hpp>

#include <tmcert/tmcert.h>

#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

// A fixed triangle in z = 0 and a small moving triangle ("probe", in its
// own frame at the origin).
void add_bodies(tmcert::SceneBuilder& b) {
  b.add_body("floor").polygon({tmcert::Point{-1, -1, 0}, tmcert::Point{1, -1, 0}, tmcert::Point{0, 1, 0}});
  b.add_body("probe").polygon({tmcert::Point{0, 0, 0}, tmcert::Point{"1/10", 0, 0}, tmcert::Point{0, "1/10", 0}});
  b.epsilon("1/1000");
}

tmcert::Scene environment_scene() {
  tmcert::SceneBuilder b;
  add_bodies(b);
  return b.build();
}

// Down from z = 1 to z = to_z over [0, 1], shifted by x in x.
tmcert::Motion down(const std::string& x, const std::string& to_z) {
  return tmcert::Motion::translation({x, 0, 1}, {x, 0, to_z});
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const tmcert::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(environment)

// CertifyOptions::decide (the OMPL validator's checkMotion): safe exactly
// when certify() is, a collision with its witness, through the same
// prepared copies.
BOOST_AUTO_TEST_CASE(decide_agrees_on_safety) {
  const tmcert::Environment env(environment_scene(), "probe");
  tmcert::CertifyOptions decide;
  decide.decide = true;
  for (const auto& [x, to_z] : std::vector<std::pair<std::string, std::string>>{
           {"0", "-1"}, {"0", "1/2"}, {"3", "-1"}, {"1/4", "-1/3"}, {"0", "0"}}) {
    const tmcert::MotionResult full = env.certify(down(x, to_z));
    const tmcert::MotionResult quick = env.certify(down(x, to_z), decide);
    BOOST_TEST_CONTEXT("x " << x << " to z " << to_z) {
      BOOST_TEST(static_cast<int>(quick.verdict) == static_cast<int>(full.verdict));
      if (quick.verdict == tmcert::Verdict::Collision) {
        BOOST_TEST(quick.witness.has_value());
        BOOST_TEST(quick.bodies[0] == "probe");
      }
    }
  }
  BOOST_TEST(env.prepared_copies() == 1u);
}

BOOST_AUTO_TEST_CASE(motions_agree_with_verify) {
  const tmcert::Environment env(environment_scene(), "probe");
  for (const auto& [x, to_z] : std::vector<std::pair<std::string, std::string>>{
           {"0", "-1"}, {"0", "1/2"}, {"3", "-1"}, {"1/4", "-1/3"}, {"0", "0"}}) {
    const tmcert::MotionResult r = env.certify(down(x, to_z));
    tmcert::SceneBuilder b;
    add_bodies(b);
    b.add_body("mover").polygon({tmcert::Point{0, 0, 0}, tmcert::Point{"1/10", 0, 0}, tmcert::Point{0, "1/10", 0}})
        .motion(down(x, to_z));
    b.check("mover", "floor");
    const tmcert::Result v = tmcert::verify(b.build());
    BOOST_TEST_CONTEXT("x " << x << " to z " << to_z) {
      BOOST_TEST(static_cast<int>(r.verdict) == static_cast<int>(v.verdict()));
      if (r.verdict == tmcert::Verdict::Safe) {
        BOOST_TEST(!r.safe_until);
        BOOST_TEST(!r.first_contact);
      } else {
        BOOST_REQUIRE(r.first_contact);
        BOOST_REQUIRE(r.safe_until);
      }
      if (r.verdict == tmcert::Verdict::Collision) {
        // z crosses 0 at t = 1 / (1 - to_z): the first contact is there.
        BOOST_REQUIRE(r.witness);
        BOOST_TEST(r.bodies[0] == "probe");
        BOOST_TEST(r.bodies[1] == "obstacles");
        BOOST_TEST(r.first_contact->at(0).approx <= r.first_contact->at(1).approx);
        BOOST_TEST(r.witness->t.approx() == r.first_contact->at(1).approx);
      }
    }
  }
  BOOST_TEST((env.certify(down("0", "-1")).verdict == tmcert::Verdict::Collision));
  BOOST_TEST((env.certify(down("0", "1/2")).verdict == tmcert::Verdict::Safe));
  BOOST_TEST((env.certify(down("3", "-1")).verdict == tmcert::Verdict::Safe));
}

BOOST_AUTO_TEST_CASE(concurrent_calls_give_the_sequential_results) {
  const tmcert::Environment env(environment_scene(), "probe");
  std::vector<tmcert::Motion> motions;
  for (int k = 0; k < 24; ++k)
    motions.push_back(down(std::to_string(k % 6) + "/4", k % 3 == 0 ? "-1" : k % 3 == 1 ? "1/3" : "-1/5"));
  std::vector<tmcert::MotionResult> sequential;
  for (const tmcert::Motion& m : motions) sequential.push_back(env.certify(m));
  int collisions = 0, safe = 0;
  for (const tmcert::MotionResult& r : sequential) {
    collisions += r.verdict == tmcert::Verdict::Collision;
    safe += r.verdict == tmcert::Verdict::Safe;
  }
  BOOST_TEST(collisions > 0);
  BOOST_TEST(safe > 0);
  BOOST_TEST(env.prepared_copies() == 1u);  // sequential calls reuse one copy
  constexpr int kThreads = 8;
  std::vector<std::vector<tmcert::MotionResult>> got(kThreads);
  std::vector<std::string> errors(kThreads);
  {
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        try {
          for (int round = 0; round < 2; ++round)
            for (std::size_t k = 0; k < motions.size(); ++k)
              got[t].push_back(env.certify(motions[(k + static_cast<std::size_t>(t)) % motions.size()]));
        } catch (const std::exception& e) {
          errors[t] = e.what();
        }
      });
    for (std::thread& th : threads) th.join();
  }
  for (int t = 0; t < kThreads; ++t) {
    BOOST_TEST(errors[t] == "");
    BOOST_REQUIRE(got[t].size() == 2 * motions.size());
    for (std::size_t k = 0; k < got[t].size(); ++k) {
      const tmcert::MotionResult& a = got[t][k];
      const tmcert::MotionResult& b = sequential[(k + static_cast<std::size_t>(t)) % motions.size()];
      BOOST_TEST(static_cast<int>(a.verdict) == static_cast<int>(b.verdict));
      BOOST_TEST(a.safe_until.has_value() == b.safe_until.has_value());
      if (a.safe_until && b.safe_until) BOOST_TEST(a.safe_until->text == b.safe_until->text);
      BOOST_TEST(a.first_contact.has_value() == b.first_contact.has_value());
      if (a.first_contact && b.first_contact) {
        BOOST_TEST(a.first_contact->at(0).text == b.first_contact->at(0).text);
        BOOST_TEST(a.first_contact->at(1).text == b.first_contact->at(1).text);
      }
      BOOST_TEST(a.witness.has_value() == b.witness.has_value());
      if (a.witness && b.witness) BOOST_TEST(a.witness->t.text() == b.witness->t.text());
    }
  }
  BOOST_TEST(env.prepared_copies() >= 1u);
  BOOST_TEST(env.prepared_copies() <= static_cast<std::size_t>(kThreads));
}

BOOST_AUTO_TEST_CASE(bad_input_names_the_field) {
  const tmcert::Scene scene = environment_scene();
  BOOST_TEST(message_of([&] { tmcert::Environment(scene, "nobody"); }) ==
             "SceneBuilder: bodies: no body named \"nobody\"");
  tmcert::VerifyOptions fast;
  fast.kernel = tmcert::Kernel::Fast;
  BOOST_TEST(message_of([&] { tmcert::Environment(scene, "probe", fast); }) ==
             "kernel: the fast kernel is not certified; an Environment certifies motions only with a certified kernel");
  tmcert::SceneBuilder moving;
  add_bodies(moving);
  moving.add_body("cart").point({0, 0, 5}).motion(tmcert::Motion::translation({0, 0, 0}, {1, 0, 0}));
  BOOST_TEST(message_of([&] { tmcert::Environment(moving.build(), "probe"); }) ==
             "SceneBuilder: bodies[2] (\"cart\").motion: the obstacles of an Environment must be fixed (every body but "
             "the moving one)");
  const tmcert::Environment env(scene, "probe");
  const std::string bad = message_of([&] {
    env.certify(tmcert::RationalBezier{{tmcert::AffineMap{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}, {1, 2}, {0, 1}});
  });
  BOOST_TEST(bad.rfind("Environment: motion", 0) == 0, bad);
}

BOOST_AUTO_TEST_SUITE_END()
