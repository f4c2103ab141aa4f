#include "number_types.h"

#include <gmp.h>

#include <cctype>
#include <memory>

namespace tmcert {

std::string to_string(const Exact& q) {
  std::unique_ptr<char, void (*)(void*)> text(mpq_get_str(nullptr, 10, q.mpq()), free);
  return std::string(text.get());  // GMP prints "p/q" in lowest terms, or "p"
}

void ExactSum::add(const CGAL::Gmpz& num, const CGAL::Gmpz& den) {
  mpz_srcptr n = num.mpz(), d = den.mpz();
  if (mpz_sgn(n) == 0) return;
  if (!mpz_divisible_p(den_.mpz(), d)) {
    // New running denominator: lcm(den_, d); rescale the sum.
    mpz_t l, f;
    mpz_inits(l, f, nullptr);
    mpz_lcm(l, den_.mpz(), d);
    mpz_divexact(f, l, den_.mpz());
    mpz_mul(num_.mpz(), num_.mpz(), f);
    mpz_set(den_.mpz(), l);
    mpz_clears(l, f, nullptr);
  }
  mpz_t f;
  mpz_init(f);
  mpz_divexact(f, den_.mpz(), d);
  mpz_addmul(num_.mpz(), n, f);
  mpz_clear(f);
}

namespace {

bool is_digits(const std::string& s, std::size_t from, std::size_t to) {
  if (from >= to) return false;
  for (std::size_t i = from; i < to; ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}


// z = the integer written in s[from, to) as [+-]digits (no sign when
// `sign` is false); false, z unspecified, when it is not written so.
bool set_integer(const std::string& s, std::size_t from, std::size_t to, mpz_ptr z, bool sign) {
  const bool negative = sign && from < to && s[from] == '-';
  if (sign && from < to && (s[from] == '-' || s[from] == '+')) ++from;
  if (!is_digits(s, from, to)) return false;
  // mpz_set_str needs a terminated string: a copy on the stack when short.
  char small[128];
  std::string large;
  const std::size_t n = to - from;
  char* digits = small;
  if (n >= sizeof small) {
    large.assign(s, from, n);
    digits = large.data();
  } else {
    s.copy(small, n, from);
    small[n] = '\0';
  }
  if (mpz_set_str(z, digits, 10) != 0) return false;
  if (negative) mpz_neg(z, z);
  return true;
}

}  // namespace

bool parse_exact(const std::string& text, Exact& out) {
  if (text.empty() || text.size() > 100000) return false;
  const std::size_t slash = text.find('/');
  if (slash != std::string::npos) {
    // Numerator and denominator read in place into a value of its own (a
    // fresh Gmpq shares its representation with nothing), then reduced.
    Exact q;
    if (!set_integer(text, 0, slash, mpq_numref(q.mpq()), true)) return false;
    if (!set_integer(text, slash + 1, text.size(), mpq_denref(q.mpq()), false)) return false;
    if (mpz_sgn(mpq_denref(q.mpq())) == 0) return false;
    mpq_canonicalize(q.mpq());
    out = q;
    return true;
  }
  if (text.size() <= 18 && text.find_first_of(".eE") == std::string::npos) {
    // A short integer: no power of ten to apply.
    Exact q;
    if (!set_integer(text, 0, text.size(), mpq_numref(q.mpq()), true)) return false;
    out = q;
    return true;
  }
  // Decimal: [+-] digits [. digits] [(e|E) [+-] digits], at least one digit
  // before or after the point.
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
  std::string digits;
  long long frac_digits = 0;
  bool any_digit = false;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
    digits += text[i++];
    any_digit = true;
  }
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
      digits += text[i++];
      ++frac_digits;
      any_digit = true;
    }
  }
  if (!any_digit) return false;
  long long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    std::size_t start = i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    if (!is_digits(text, i, text.size()) || text.size() - i > 6) return false;  // |exp| < 10^6
    exponent = std::stoll(text.substr(start));
    i = text.size();
  }
  if (i != text.size()) return false;
  const long long scale = exponent - frac_digits;
  if (scale > 100000 || scale < -100000) return false;  // refuse absurd sizes
  CGAL::Gmpz mantissa(digits);
  if (negative) mantissa = -mantissa;
  CGAL::Gmpz power;
  mpz_ui_pow_ui(power.mpz(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  out = scale >= 0 ? Exact(mantissa * power) : Exact(mantissa, power);
  return true;
}

bool within_input_limit(const Exact& q) {
  // 10^10000 lies between 2^33219 and 2^33220: smaller sizes pass at once.
  static const CGAL::Gmpz limit = [] {
    CGAL::Gmpz z;
    mpz_ui_pow_ui(z.mpz(), 10, kMaxInputDigits);
    return z;
  }();
  for (mpz_srcptr z : {mpq_numref(q.mpq()), mpq_denref(q.mpq())}) {
    if (mpz_sizeinbase(z, 2) < 33219) continue;
    if (mpz_cmpabs(z, limit.mpz()) >= 0) return false;
  }
  return true;
}

}  // namespace tmcert
