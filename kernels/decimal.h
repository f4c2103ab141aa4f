// Decimal display of exact numbers, for people: rounded from the exact
// value in integer arithmetic (never through a double, which could show a
// misleading digit or overflow for huge and tiny values).
#pragma once

#include "kernels/number_types.h"

#include <optional>
#include <string>

namespace tmcert {

struct Decimal {
  std::string text;  // e.g. "2.06812", "0.00248723", "1.5e-17", "-3"
  bool exact;        // the text is exactly the value (not rounded)
};

// q rounded to `significant` digits (>= 1), ties to even, written
// as printf's %g writes it: fixed notation for exponents from -4 to
// significant - 1, otherwise d.ddde[+-]XX; no trailing zeros.
Decimal to_decimal(const Exact& q, int significant = 6);

// The readable form of an exact number: its 6-digit decimal, followed by
// the exact fraction in parentheses when the decimal is not exact:
// "2.06812 (8471/4096)", "0.5", "-3".
std::string readable(const Exact& q);

// A decimal for messages that compare values (a joint at q outside its
// limits): the exact decimal when q has one of at most 17 significant
// digits ("3.5", "-2.8973"); a double given as one (a value from NumPy or
// a C++ double, exactly its binary value) as the shortest decimal that
// reads back as that double, followed by " (a double)"; anything else as
// "about " and its 17-digit decimal.  Never a bare p/q fraction.
std::string decimal_text(const Exact& q);

// Approximations that results print (SCENE_FORMAT.md: the nearest double
// of the exact value, or beyond the double range a 17-significant-digit
// decimal with exponent; never inf, never a wrong power of two).
//
// The double nearest to q (ties to the one with an even significand, as
// IEEE 754 rounds), or nullopt when q is beyond the double range: that
// double would be infinite (|q| >= 2^1024 - 2^970) or, for q != 0, zero
// (|q| <= 2^-1075).  Subnormal doubles count as in range.
std::optional<double> nearest_double(const Exact& q);

// q rounded to `significant` digits (ties to even), always with an
// exponent and with every digit written: "1.0000000000000000e+400" for
// 10^400 at 17 digits, "-2.5000000000000000e-401".
std::string scientific(const Exact& q, int significant = 17);

// The shortest decimal that reads back as the double d (std::to_chars),
// e.g. "0.1", "1.4142135623730951", "9.311e-21".
std::string shortest(double d);

// The printed approximation of q: shortest(nearest_double(q)) in range,
// else scientific(q).
std::string approximation(const Exact& q);

}  // namespace tmcert
