// Exact numbers of the public API (include/tmcert/numbers.h).
#include "kernels/decimal.h"
#include "kernels/number_types.h"

#include "src/api/internal.h"

#include <cmath>
#include <limits>
#include <optional>

namespace tmcert::api {

Number::Number(double value) {
  if (std::isnan(value)) text_ = "nan";  // refused, naming the field, when the scene is built
  else if (std::isinf(value)) text_ = value > 0 ? "inf" : "-inf";
  else text_ = tmcert::to_string(tmcert::to_exact(value));  // every finite double is a rational
}

Number::Number(const Rational& value) : text_(value.text) {}


Rational to_rational(const tmcert::Exact& q) {
  Rational r;
  r.text = tmcert::to_string(q);
  r.numerator = tmcert::to_string(tmcert::Exact(q.numerator()));
  r.denominator = tmcert::to_string(tmcert::Exact(q.denominator()));
  const std::optional<double> d = tmcert::nearest_double(q);
  r.approx = d ? *d : std::numeric_limits<double>::quiet_NaN();
  r.approx_text = tmcert::approximation(q);
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
