// src/model/de_casteljau.h: the verifier's exact subdivision gives the
// curve's own control points of a part (checked against the Bernstein
// form evaluated directly).
#include "src/model/de_casteljau.h"

#include <boost/test/unit_test.hpp>

#include <array>
#include <vector>

using tmcert::Exact;
using P = std::array<Exact, 2>;

namespace {

// The curve at u from its Bernstein form sum C(n,k) u^k (1-u)^(n-k) p_k.
P bernstein(const std::vector<P>& c, const Exact& u) {
  const std::size_t n = c.size() - 1;
  P out{Exact(0), Exact(0)};
  for (std::size_t k = 0; k <= n; ++k) {
    Exact b(1);
    for (std::size_t i = 0; i < k; ++i) b = b * Exact(static_cast<long>(n - i)) / Exact(static_cast<long>(i + 1));
    for (std::size_t i = 0; i < k; ++i) b *= u;
    for (std::size_t i = k; i < n; ++i) b *= 1 - u;
    for (int e = 0; e < 2; ++e) out[e] += b * c[k][e];
  }
  return out;
}

const std::vector<P> kCubic = {{Exact(0), Exact(1)}, {Exact(2), Exact(-3)}, {Exact(1, 3), Exact(5)}, {Exact(4), Exact(2, 7)}};

}  // namespace

BOOST_AUTO_TEST_SUITE(model_de_casteljau)

BOOST_AUTO_TEST_CASE(the_parts_are_the_curve_reparametrised) {
  const Exact s(2, 5);
  const std::vector<P> left = tmcert::de_casteljau_split(kCubic, s, true);
  const std::vector<P> right = tmcert::de_casteljau_split(kCubic, s, false);
  BOOST_TEST_REQUIRE(left.size() == kCubic.size());
  BOOST_TEST_REQUIRE(right.size() == kCubic.size());
  // Ends: the left part starts at p_0, the right ends at p_n, both meet at the curve's point at s.
  BOOST_TEST((left.front() == kCubic.front()));
  BOOST_TEST((right.back() == kCubic.back()));
  BOOST_TEST((left.back() == bernstein(kCubic, s)));
  BOOST_TEST((right.front() == bernstein(kCubic, s)));
  for (const Exact& v : {Exact(0), Exact(1, 3), Exact(3, 4), Exact(1)}) {
    BOOST_TEST((bernstein(left, v) == bernstein(kCubic, s * v)));
    BOOST_TEST((bernstein(right, v) == bernstein(kCubic, s + (1 - s) * v)));
  }
}

BOOST_AUTO_TEST_CASE(restriction_to_an_interval) {
  const Exact a(1, 6), b(5, 8);
  const std::vector<P> part = tmcert::de_casteljau_restrict(kCubic, a, b);
  for (const Exact& v : {Exact(0), Exact(1, 2), Exact(2, 9), Exact(1)})
    BOOST_TEST((bernstein(part, v) == bernstein(kCubic, a + (b - a) * v)));
  // [0, 1] is the curve itself; [0, b] and [a, 1] split once.
  BOOST_TEST((tmcert::de_casteljau_restrict(kCubic, Exact(0), Exact(1)) == kCubic));
  BOOST_TEST((tmcert::de_casteljau_restrict(kCubic, Exact(0), b) == tmcert::de_casteljau_split(kCubic, b, true)));
  BOOST_TEST((tmcert::de_casteljau_restrict(kCubic, a, Exact(1)) == tmcert::de_casteljau_split(kCubic, a, false)));
  // One point: a constant curve stays itself.
  const std::vector<P> point = {{Exact(3), Exact(-1)}};
  BOOST_TEST((tmcert::de_casteljau_restrict(point, a, b) == point));
}

BOOST_AUTO_TEST_SUITE_END()
