// src/model/chain.h: a chain description's exact parts (the rational pose
// at joint values, rational segments), its checks, and the slot that keeps
// one preparation of it (the verifier's enclosures, src/motion/chain.cpp).
#include "src/model/chain.h"

#include <boost/test/unit_test.hpp>

#include <stdexcept>
#include <string>

using namespace tmcert;

namespace {

Pose shifted(const char* x, const char* y, const char* z) {
  Pose p;
  p.translation = {Exact(std::string(x)), Exact(std::string(y)), Exact(std::string(z))};
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(model_chain)

// Base shifted by (1, 0, 0), a revolute joint about z, a constant shift by
// (0, 2, 0), a prismatic joint along (3, 0, 4) (length 5: rational unit
// axis), a prismatic joint along (1, 1, 0) (length sqrt 2), no last shift.
BOOST_AUTO_TEST_CASE(exact_pose_and_rational_segments) {
  std::vector<ChainJoint> joints(3);
  joints[0].axis = {Exact(0), Exact(0), Exact(1)};
  joints[1].kind = ChainJoint::Kind::Prismatic;
  joints[1].axis = {Exact(3), Exact(0), Exact(4)};
  joints[2].kind = ChainJoint::Kind::Prismatic;
  joints[2].axis = {Exact(1), Exact(1), Exact(0)};
  const ChainDescription chain({{shifted("1", "0", "0")}, {shifted("0", "2", "0")}, {}, {}}, joints);
  BOOST_TEST(chain.joint_count() == 3u);
  BOOST_TEST(chain.exact_unit_axis(1).has_value());
  BOOST_TEST(!chain.exact_unit_axis(2).has_value());
  BOOST_TEST(chain.axis_norm2(2) == Exact(2));
  // q = (0, 10, 0): the translation (1, 0, 0) + (0, 2, 0) + 10 (3/5, 0, 4/5).
  const std::optional<Mat34E> m = chain.exact_pose({Exact(0), Exact(10), Exact(0)});
  BOOST_TEST_REQUIRE(m.has_value());
  const Mat34E expected = {1, 0, 0, 7, 0, 1, 0, 2, 0, 0, 1, 8};
  BOOST_TEST((*m == expected));
  BOOST_TEST(!chain.exact_pose({Exact(1, 2), Exact(0), Exact(0)}));  // a revolute joint off 0
  BOOST_TEST(!chain.exact_pose({Exact(0), Exact(0), Exact(1)}));     // along an irrational unit axis
  BOOST_TEST(chain.rational_between({Exact(0), Exact(-1), Exact(0)}, {Exact(0), Exact(3), Exact(0)}));
  BOOST_TEST(!chain.rational_between({Exact(0), Exact(0), Exact(0)}, {Exact(1), Exact(0), Exact(0)}));
  BOOST_TEST(!chain.rational_between({Exact(0), Exact(0), Exact(0)}, {Exact(0), Exact(0), Exact(1)}));
  // An rpy constant is not exact: no rational pose, no rational segment.
  Pose rpy = shifted("0", "0", "0");
  rpy.rotation.kind = Rotation::Kind::Rpy;
  rpy.rotation.rpy = {Exact(1, 10), Exact(0), Exact(0)};
  const ChainDescription with_rpy({{rpy}, {}, {}, {}}, joints);
  BOOST_TEST(!with_rpy.exact_constant(0).has_value());
  BOOST_TEST(with_rpy.exact_constant(1).has_value());
  BOOST_TEST(!with_rpy.exact_pose({Exact(0), Exact(0), Exact(0)}));
  BOOST_TEST(!with_rpy.rational_between({Exact(0), Exact(0), Exact(0)}, {Exact(0), Exact(0), Exact(0)}));
}

BOOST_AUTO_TEST_CASE(invalid_descriptions_throw) {
  std::vector<ChainJoint> joints(1);
  joints[0].axis = {Exact(0), Exact(0), Exact(0)};
  BOOST_CHECK_THROW(ChainDescription({{}, {}}, joints), std::invalid_argument);
  joints[0].axis = {Exact(0), Exact(0), Exact(1)};
  BOOST_CHECK_THROW(ChainDescription({{}}, joints), std::invalid_argument);
}

// prepared() makes its value once and hands the same one to every caller.
BOOST_AUTO_TEST_CASE(one_preparation_per_description) {
  const ChainDescription chain({{}}, {});
  int made = 0;
  auto make = [&](const ChainDescription& d) {
    ++made;
    return std::make_shared<const std::size_t>(d.joint_count() + 42);
  };
  const std::shared_ptr<const std::size_t> a = chain.prepared<std::size_t>(make);
  const std::shared_ptr<const std::size_t> b = chain.prepared<std::size_t>(make);
  BOOST_TEST(made == 1);
  BOOST_TEST(a.get() == b.get());
  BOOST_TEST(*a == 42u);
}

BOOST_AUTO_TEST_SUITE_END()
