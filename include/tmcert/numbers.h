// Numbers of the public API: exact inputs (Number) and exact results
// (Rational, AlgebraicNumber, Time), each result with a double for people.
//
// Every verdict is about the scene as written, exactly.  Doubles in results
// are there to be printed and plotted; a proof uses the exact values.
#pragma once

#include "tmcert/export.h"

#include <array>
#include <concepts>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace tmcert::api {

struct Rational;

// A number of a scene, held exactly as the text of a tmcert-scene/1 number.
//  * From a double: exactly its binary value, never rounded:
//    Number(0.1) is 3602879701896397/36028797018963968, not 1/10.  Write
//    Number("0.1") for one tenth.  A NaN or an infinity is an InputError
//    naming the field when the scene is built.
//  * From an integer: that integer.
//  * From text: an integer, "p/q" (q > 0) or a decimal such as "-1.25e-3",
//    meaning exactly what it spells; anything else is an InputError naming
//    the field when the scene is built.
class TMCERT_API Number {
 public:
  Number() : text_("0") {}
  Number(double value);  // NOLINT: implicit, so that {0.5, 1, "1/3"} works
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  Number(T value) : text_(std::to_string(value)) {}  // NOLINT
  Number(const char* text) : text_(text ? text : "") {}  // NOLINT
  Number(std::string text) : text_(std::move(text)) {}  // NOLINT
  Number(std::string_view text) : text_(text) {}  // NOLINT
  Number(const Rational& value);  // NOLINT: a result's exact value fed back

  // The exact value as text ("p/q", an integer or a decimal as given;
  // "nan"/"inf" for a non-finite double).
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// A point or vector (x, y, z), exact.
using Point = std::array<Number, 3>;

// An affine map x -> A x + a as the 3x4 matrix [A | a], row by row:
// {A00, A01, A02, a0, A10, A11, A12, a1, A20, A21, A22, a2}.
using AffineMap = std::array<Number, 12>;

// An exact rational result, with its nearest double.
struct Rational {
  std::string text = "0";         // "p/q" in lowest terms (q > 1), or "p" when q = 1
  std::string numerator = "0";    // p, with its sign
  std::string denominator = "1";  // q > 0
  // The double nearest to p/q (ties to even), for people; NaN when p/q is
  // beyond the double range (that double would be infinite, or 0 for
  // p != 0), never an infinity or a clamped value.
  double approx = 0;
  // The approximation as results print it: the shortest decimal that reads
  // back as `approx`, or beyond the double range p/q's 17-significant-digit
  // decimal with exponent ("1.0000000000000000e+400").
  std::string approx_text = "0";
};

// An irrational real number: the only root of the polynomial `root_of`
// (integer coefficients, constant term first, square-free) in the open
// interval (lower, upper) (SCENE_FORMAT.md "Exact contact times").
struct AlgebraicNumber {
  std::vector<std::string> root_of;  // integer coefficients, constant term first
  Rational lower, upper;             // the isolating interval, open
  // For people: the shortest decimal that reads back as the double nearest
  // to the root, or beyond the double range its 17-significant-digit
  // decimal with exponent; and that double (NaN beyond the range).
  std::string approx_text;
  double approx = 0;
};

// A parameter (time) of a result: rational, or an algebraic number when a
// contact happens at an irrational instant.
struct Time {
  std::variant<Rational, AlgebraicNumber> value;

  bool is_rational() const { return std::holds_alternative<Rational>(value); }
  // Null when the time is not of that kind.
  const Rational* rational() const { return std::get_if<Rational>(&value); }
  const AlgebraicNumber* algebraic() const { return std::get_if<AlgebraicNumber>(&value); }
  // The time as a double, for people.
  double approx() const { return is_rational() ? std::get<Rational>(value).approx : std::get<AlgebraicNumber>(value).approx; }
  // Exact text: "p/q", or "root of [c0, c1, ...] in (lower, upper)".
  TMCERT_API std::string text() const;
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
