// src/api/shared_environment: prepared copies of fixed obstacles and
// movers, certified from several threads at once.  Calls give the results
// of sequential calls; a copy is prepared only when every copy is busy;
// the public Environment wraps the same pool.  (Part of the unit tests,
// with src/api/internal.h: see tests/api/test_internal.cpp.)
#include "src/api/shared_environment.h"
#include "src/model/pose_algebra.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <thread>
#include <vector>

using namespace tmcert;
using tmcert::testing::two_cubes;

namespace {

// The cube mover translated from `from` to `to` (x coordinates, y given) over [0, 1].
Trajectory slide(const Exact& y, const Exact& from, const Exact& to) {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.from.translation = {from, y, 0};
  seg.to.translation = {to, y, 0};
  seg.interpolation = Interpolation::Slerp;
  seg.rational = rational_keyframe_segment(seg.from, seg.to, seg.interpolation, seg.t0, seg.t1);
  return Trajectory{{seg}};
}

VerifyOptions options() {
  VerifyOptions o;
  o.epsilon = Exact(1, 1000);
  return o;
}

// The post [-1/2, 1/2]^3 as the obstacles, the unit cube as the mover.
struct Bodies {
  Scene scene = two_cubes("0 0 0", "0 0 0");
  Body obstacles() const { return scene.bodies[1]; }
  Body mover() const {
    Body b = scene.bodies[0];
    b.motion.reset();
    return b;
  }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(shared_environment_pool)

BOOST_AUTO_TEST_CASE(sequential_results) {
  const Bodies b;
  const EnvironmentPool pool(b.obstacles(), {b.mover()}, {}, options());
  BOOST_TEST(pool.copies() == 1u);
  BOOST_TEST(!pool.has_primitives());
  BOOST_REQUIRE(pool.labels().size() == 2u);
  BOOST_TEST(pool.labels()[1].name == "mover");
  const MotionCheck hit = pool.check({slide(0, -3, 3)}, false);
  BOOST_TEST((hit.verdict == Verdict::Collision));
  BOOST_REQUIRE(hit.safe_until);
  BOOST_TEST(*hit.safe_until == Exact(1, 3));  // faces meet when -3 + 6t = -1
  const MotionCheck miss = pool.check({slide(3, -3, 3)}, true);
  BOOST_TEST((miss.verdict == Verdict::Safe));
  BOOST_TEST(pool.copies() == 1u);  // sequential calls share one copy
  // Static contact at given poses.
  BOOST_TEST(pool.static_contact({Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}).has_value());
  BOOST_TEST(!pool.static_contact({Mat34E{1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0}}).has_value());
}

BOOST_AUTO_TEST_CASE(concurrent_calls_agree_with_sequential_ones) {
  const Bodies b;
  const EnvironmentPool pool(b.obstacles(), {b.mover()}, {}, options());
  const Verdict expected[2] = {pool.check({slide(0, -3, 3)}, false).verdict, pool.check({slide(3, -3, 3)}, false).verdict};
  std::vector<Verdict> got(8);
  std::vector<std::thread> threads;
  for (int k = 0; k < 8; ++k)
    threads.emplace_back([&, k] { got[k] = pool.check({k % 2 ? slide(3, -3, 3) : slide(0, -3, 3)}, false).verdict; });
  for (std::thread& t : threads) t.join();
  for (int k = 0; k < 8; ++k) BOOST_TEST((got[k] == expected[k % 2]));
  BOOST_TEST(pool.copies() >= 1u);
  BOOST_TEST(pool.copies() <= 8u);
}

BOOST_AUTO_TEST_CASE(public_environment_wraps_a_pool) {
  const Bodies b;
  const std::shared_ptr<const api::Environment> env = shared_environment(b.obstacles(), {b.mover()}, {}, options());
  BOOST_REQUIRE(env);
  const EnvironmentPool& pool = pool_of(*env);
  BOOST_TEST(pool.labels()[1].name == "mover");
  BOOST_TEST((pool.check({slide(0, -3, 3)}, false).verdict == Verdict::Collision));
  // Bad bodies: an InputError, as FixedEnvironment's constructor says.
  BOOST_CHECK_THROW(EnvironmentPool(b.obstacles(), {}, {}, options()), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
