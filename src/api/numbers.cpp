// Exact numbers of the public API (include/tmcert/numbers.h).
#include "kernels/number_types.h"

#include "src/api/internal.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace tmcert::api {

Number::Number(double value) {
  if (std::isnan(value)) text_ = "nan";  // refused, naming the field, when the scene is built
  else if (std::isinf(value)) text_ = value > 0 ? "inf" : "-inf";
  else text_ = tmcert::to_string(tmcert::to_exact(value));  // every finite double is a rational
}

Number::Number(const Rational& value) : text_(value.text) {}

namespace {

// The double nearest to q (ties to the even one), from the tightest
// enclosing interval [lo, hi] (adjacent doubles, or a point when q is a
// double): the nearer end, compared exactly.  Beyond the double range the
// largest finite double of q's sign.
double nearest_double(const tmcert::Exact& q) {
  const tmcert::Interval box = tmcert::to_interval(q);
  const double lo = box.inf(), hi = box.sup();
  if (lo == hi) return lo;
  if (!std::isfinite(lo)) return hi;
  if (!std::isfinite(hi)) return lo;
  const tmcert::Exact below = q - tmcert::Exact(lo), above = tmcert::Exact(hi) - q;
  if (below < above) return lo;
  if (above < below) return hi;
  // A tie: the one whose last significand bit is 0 (the magnitude's
  // last bit, doubles being sign and magnitude).
  return (std::bit_cast<std::uint64_t>(lo) & 1) == 0 ? lo : hi;
}

}  // namespace

Rational to_rational(const tmcert::Exact& q) {
  Rational r;
  r.text = tmcert::to_string(q);
  r.numerator = tmcert::to_string(tmcert::Exact(q.numerator()));
  r.denominator = tmcert::to_string(tmcert::Exact(q.denominator()));
  r.approx = nearest_double(q);
  return r;
}

std::string Time::text() const {
  if (const Rational* r = rational()) return r->text;
  const AlgebraicNumber& a = std::get<AlgebraicNumber>(value);
  std::string out = "root of [";
  for (std::size_t i = 0; i < a.root_of.size(); ++i) out += (i ? ", " : "") + a.root_of[i];
  return out + "] in (" + a.lower.text + ", " + a.upper.text + ")";
}

}  // namespace tmcert::api
