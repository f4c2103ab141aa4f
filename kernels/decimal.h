// Decimal display of exact numbers, for people: rounded from the exact
// value in integer arithmetic (never through a double, which could show a
// misleading digit or overflow for huge and tiny values).
#pragma once

#include "kernels/number_types.h"

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

// The double nearest to q's 17-significant-digit decimal (within one unit
// in the last place of the nearest double), for JSON approximations;
// +-infinity beyond the double range.
double approximate(const Exact& q);

}  // namespace tmcert
