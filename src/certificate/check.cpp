// The independent certificate checker: docs/certificate-format.md is the
// contract, proofs/certificates.md the soundness argument.
//
// Everything is exact.  The scene's control points, the joint curve and its
// restriction to a piece are rationals (CGAL::Gmpq, as `Exact`); for the
// separation claims, which dominate the work, each piece's control points,
// the body's vertices and the direction are brought to integers over common
// positive denominators (multiplying an inequality by a positive number
// keeps it), and the linear forms over a group's vertices are evaluated in
// integers: a fixed-size multi-limb evaluation with 128-bit accumulators
// when the numbers fit (60-bit limbs, coordinates below 2^62), GMP integers
// otherwise.  No floating point is used anywhere.
#include "src/certificate/check.h"
#include "src/certificate/scope.h"
#include "src/certificate/algebraic_witness.h"
#include "src/certificate/motions.h"
#include "src/certificate/exact_claims.h"
#include "src/io/parse.h"
#include "src/io/read_file.h"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace tmcert::certificate {

namespace {

using json = nlohmann::json;

constexpr const char* kFormat = "tmcert-certificate/1";
// Vertex ids cached for groups, over a whole certificate; beyond it group
// vertex lists are recomputed on each use (slower, bounded memory).
constexpr std::size_t kGroupCacheBudget = 50'000'000;
constexpr int kMaxLimbs = 8;  // 60-bit limbs of a linear form in the fast path

// ---------------------------------------------------------------- integers

// A GMP integer with value semantics (CGAL::Gmpz shares its representation
// between copies, which in-place GMP calls must not touch).
struct Z {
  mpz_t v;
  Z() { mpz_init(v); }
  explicit Z(long x) { mpz_init_set_si(v, x); }
  Z(const Z& o) { mpz_init_set(v, o.v); }
  Z(Z&& o) noexcept {
    mpz_init(v);
    mpz_swap(v, o.v);
  }
  Z& operator=(const Z& o) {
    if (this != &o) mpz_set(v, o.v);
    return *this;
  }
  Z& operator=(Z&& o) noexcept {
    mpz_swap(v, o.v);
    return *this;
  }
  ~Z() { mpz_clear(v); }
};

mpz_srcptr num(const Exact& q) { return mpq_numref(q.mpq()); }
mpz_srcptr den(const Exact& q) { return mpq_denref(q.mpq()); }
int sgn(const Exact& q) { return mpq_sgn(q.mpq()); }

Exact from_z(mpz_srcptr n, mpz_srcptr d) {
  return Exact(CGAL::Gmpz(n), CGAL::Gmpz(d));
}

// ---------------------------------------------------------------- vectors

Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_zero(const Vec3E& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

Vec3E place_point(const Mat34E& m, const Vec3E& x) {
  Vec3E out;
  for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  return out;
}

Exact determinant(const Mat34E& m) {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
         m[2] * (m[4] * m[9] - m[5] * m[8]);
}

Mat34E identity_pose() {
  Mat34E m;
  for (Exact& x : m) x = Exact(0);
  m[0] = m[5] = m[10] = Exact(1);
  return m;
}

std::string str(const Exact& q) { return to_string(q); }
std::string str(const Vec3E& v) {
  std::string out = "(";
  for (int i = 0; i < 3; ++i) {
    if (i) out += ", ";
    out += str(v[i]);
  }
  out += ")";
  return out;
}

// ---------------------------------------------------------------- Bernstein
//
// Our own small routines (independent of src/motion): products of Bernstein
// polynomials, degree elevation as a product with the constant 1, and
// de Casteljau subdivision, all in exact rationals.

// C(n, k) for k = 0..n.
std::vector<Exact> binomials(int n) {
  std::vector<Exact> c(n + 1);
  c[0] = Exact(1);
  for (int k = 0; k < n; ++k) c[k + 1] = c[k] * Exact(n - k) / Exact(k + 1);
  return c;
}

// Coefficients of p q in the Bernstein basis of degree n + m, for p of
// degree n and q of degree m:
//   c_k = sum_{i+j=k} C(n,i) C(m,j) / C(n+m,k) p_i q_j.
std::vector<Exact> bernstein_product(const std::vector<Exact>& p, const std::vector<Exact>& q) {
  const int n = static_cast<int>(p.size()) - 1, m = static_cast<int>(q.size()) - 1;
  const std::vector<Exact> cn = binomials(n), cm = binomials(m), cnm = binomials(n + m);
  std::vector<Exact> c(n + m + 1, Exact(0));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) c[i + j] += cn[i] * cm[j] * p[i] * q[j];
  for (int k = 0; k <= n + m; ++k) c[k] /= cnm[k];
  return c;
}

// The joint curve: 25 coordinates per control point, N_a (12), N_b (12), W.
using CP = std::array<Exact, 25>;

struct HomogeneousMotion {
  std::vector<Mat34E> affine;  // A_k
  std::vector<Exact> weights;  // w_k
};

HomogeneousMotion motion_of(const Body& b) {
  if (!b.motion) return {{identity_pose()}, {Exact(1)}};
  return {b.motion->control_points, b.motion->weights};
}

bool constant_weights(const std::vector<Exact>& w) {
  return std::all_of(w.begin(), w.end(), [&](const Exact& x) { return x == w.front(); });
}

std::vector<CP> joint_curve(const HomogeneousMotion& ma, const HomogeneousMotion& mb) {
  const int na = static_cast<int>(ma.affine.size()) - 1, nb = static_cast<int>(mb.affine.size()) - 1;
  const bool polynomial = constant_weights(ma.weights) && constant_weights(mb.weights);
  const HomogeneousMotion* m[2] = {&ma, &mb};
  // Each block's numerator is multiplied by `factor` (the other motion's
  // weights, or the constant 1 of the elevation degree).
  std::vector<Exact> factor[2];
  std::vector<Exact> weight;
  if (polynomial) {
    const int n = std::max(na, nb);
    factor[0].assign(n - na + 1, Exact(1));
    factor[1].assign(n - nb + 1, Exact(1));
    weight.assign(n + 1, Exact(1));
  } else {
    factor[0] = mb.weights;
    factor[1] = ma.weights;
    weight = bernstein_product(ma.weights, mb.weights);
  }
  std::vector<CP> c(weight.size());
  for (int blk = 0; blk < 2; ++blk) {
    const HomogeneousMotion& mo = *m[blk];
    for (int e = 0; e < 12; ++e) {
      std::vector<Exact> numerator(mo.affine.size());
      for (std::size_t k = 0; k < numerator.size(); ++k)
        numerator[k] = polynomial ? mo.affine[k][e] : mo.weights[k] * mo.affine[k][e];
      const std::vector<Exact> product = bernstein_product(numerator, factor[blk]);
      for (std::size_t k = 0; k < c.size(); ++k) c[k][12 * blk + e] = product[k];
    }
  }
  for (std::size_t k = 0; k < c.size(); ++k) c[k][24] = weight[k];
  return c;
}

std::vector<CP> joint_curve(const Body& a, const Body& b) { return joint_curve(motion_of(a), motion_of(b)); }

// de Casteljau at s: the control points of [0, s] (left) or [s, 1] (right).
std::vector<CP> split(std::vector<CP> p, const Exact& s, bool keep_left) {
  const std::size_t n = p.size() - 1;
  std::vector<CP> out(n + 1);
  if (keep_left) out[0] = p[0];
  else out[n] = p[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = 0; i + r <= n; ++i)
      for (int e = 0; e < 25; ++e) p[i][e] += s * (p[i + 1][e] - p[i][e]);
    if (keep_left) out[r] = p[0];
    else out[n - r] = p[n - r];
  }
  return out;
}

// The curve restricted exactly to [ua, ub] within [0, 1] (0 <= ua < ub <= 1).
std::vector<CP> restrict_curve(const std::vector<CP>& c, const Exact& ua, const Exact& ub) {
  std::vector<CP> left = ub == 1 ? c : split(c, ub, true);
  if (sgn(ua) == 0) return left;
  return split(std::move(left), ua / ub, false);
}

// ---------------------------------------------------------------- integer coordinates

// Points as integers over one positive common denominator D: X = x D.
struct Coords {
  Z D{1};
  std::vector<Z> X;                 // 3 per point
  bool fits64 = false;              // every |X| < 2^62
  std::vector<std::int64_t> X64;    // 3 per point, when fits64
};

Coords make_coords(const std::vector<Vec3E>& points) {
  Coords c;
  for (const Vec3E& p : points)
    for (const Exact& x : p) mpz_lcm(c.D.v, c.D.v, den(x));
  c.X.resize(3 * points.size());
  c.fits64 = true;
  Z f;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const Exact& x = points[i][k];
      mpz_divexact(f.v, c.D.v, den(x));
      mpz_mul(c.X[3 * i + k].v, num(x), f.v);
      if (mpz_sizeinbase(c.X[3 * i + k].v, 2) > 62) c.fits64 = false;
    }
  if (c.fits64) {
    c.X64.resize(c.X.size());
    for (std::size_t i = 0; i < c.X.size(); ++i) c.X64[i] = mpz_get_si(c.X[i].v);
  }
  return c;
}

// A linear form (alpha_0, alpha_1, alpha_2) split into 60-bit limbs:
// alpha_i = sum_j a[i][j] 2^(60 j), |a[i][j]| < 2^60 (all limbs of one
// coefficient carry its sign).
struct Limbs {
  int m = 0;
  std::int64_t a[3][kMaxLimbs] = {};
};

bool to_limbs(const Z* alpha, Limbs& out) {
  std::size_t bits = 1;
  for (int i = 0; i < 3; ++i) bits = std::max(bits, mpz_sizeinbase(alpha[i].v, 2));
  const int m = static_cast<int>((bits + 59) / 60);
  if (m > kMaxLimbs) return false;
  out.m = m;
  for (int i = 0; i < 3; ++i) {
    std::uint64_t words[kMaxLimbs] = {};
    std::size_t count = 0;
    if (mpz_sgn(alpha[i].v) != 0) mpz_export(words, &count, -1, 8, 0, 4, alpha[i].v);  // 60 bits per word
    const bool negative = mpz_sgn(alpha[i].v) < 0;
    for (int j = 0; j < kMaxLimbs; ++j) {
      const std::int64_t w = j < static_cast<int>(count) ? static_cast<std::int64_t>(words[j]) : 0;
      out.a[i][j] = negative ? -w : w;
    }
  }
  return true;
}

// alpha . x as top * 2^(60 m) + sum_j digit[j] 2^(60 j), 0 <= digit < 2^60:
// the unique such form, so values compare lexicographically.
struct Value {
  __int128 top = 0;
  std::uint64_t digit[kMaxLimbs] = {};
};

constexpr std::uint64_t kMask60 = (std::uint64_t{1} << 60) - 1;

inline void evaluate(const Limbs& l, const std::int64_t* x, Value& out) {
  __int128 carry = 0;
  for (int j = 0; j < l.m; ++j) {
    // |a| < 2^60, |x| < 2^62: each product < 2^122, the sum < 2^124 + carry.
    const __int128 t = static_cast<__int128>(l.a[0][j]) * x[0] + static_cast<__int128>(l.a[1][j]) * x[1] +
                       static_cast<__int128>(l.a[2][j]) * x[2] + carry;
    out.digit[j] = static_cast<std::uint64_t>(t) & kMask60;  // t mod 2^60 (two's complement)
    carry = t >> 60;                                          // floor(t / 2^60) (C++20: arithmetic)
  }
  out.top = carry;
}

inline bool value_less(const Value& a, const Value& b, int m) {
  if (a.top != b.top) return a.top < b.top;
  for (int j = m - 1; j >= 0; --j)
    if (a.digit[j] != b.digit[j]) return a.digit[j] < b.digit[j];
  return false;
}

void to_mpz(const Value& v, int m, mpz_t out) {
  const __int128 top = v.top;
  const std::int64_t hi = static_cast<std::int64_t>(top >> 64);
  const std::uint64_t lo = static_cast<std::uint64_t>(top);
  mpz_set_si(out, hi);
  mpz_mul_2exp(out, out, 64);
  mpz_add_ui(out, out, lo);
  for (int j = m - 1; j >= 0; --j) {
    mpz_mul_2exp(out, out, 60);
    mpz_add_ui(out, out, v.digit[j]);
  }
}

// min over the listed points of alpha . X, exactly.  path: 0 automatic,
// 1 limbs only (must fit), 2 GMP only.
void min_dot(const Z* alpha, const Coords& c, const std::uint32_t* ids, std::size_t count, mpz_t out,
             int path = 0) {
  Limbs limbs;
  if (path != 2 && c.fits64 && to_limbs(alpha, limbs)) {
    Value best, v;
    evaluate(limbs, &c.X64[3 * ids[0]], best);
    for (std::size_t k = 1; k < count; ++k) {
      evaluate(limbs, &c.X64[3 * ids[k]], v);
      if (value_less(v, best, limbs.m)) best = v;
    }
    to_mpz(best, limbs.m, out);
    return;
  }
  if (path == 1) throw std::logic_error("min_dot: limb path requested for numbers that do not fit");
  Z acc;
  for (std::size_t k = 0; k < count; ++k) {
    const Z* x = &c.X[3 * ids[k]];
    mpz_mul(acc.v, alpha[0].v, x[0].v);
    mpz_addmul(acc.v, alpha[1].v, x[1].v);
    mpz_addmul(acc.v, alpha[2].v, x[2].v);
    if (k == 0 || mpz_cmp(acc.v, out) < 0) mpz_set(out, acc.v);
  }
}

// ---------------------------------------------------------------- ray test

// Does the closed ray {p + s d : s >= 0} meet the segment [a, b]?
bool ray_meets_segment(const Vec3E& p, const Vec3E& d, const Vec3E& a, const Vec3E& b) {
  const Vec3E e = sub(b, a), w = sub(a, p), c = cross(d, e);
  if (!is_zero(c)) {
    if (sgn(dot(w, c)) != 0) return false;  // skew lines
    // s d - r e = w: s c = w x e, r c = w x d.
    const Exact cc = dot(c, c);
    const Exact s = dot(cross(w, e), c) / cc, r = dot(cross(w, d), c) / cc;
    return sgn(s) >= 0 && sgn(r) >= 0 && r <= 1;
  }
  // d parallel to e (or e = 0): only on the ray's line.
  if (!is_zero(cross(w, d))) return false;
  return sgn(dot(w, d)) >= 0 || sgn(dot(sub(b, p), d)) >= 0;
}

}  // namespace

std::optional<int> ray_crossings(const std::vector<std::vector<Vec3E>>& placed_polygons, const Vec3E& p,
                                 const Vec3E& d) {
  const std::optional<std::vector<int>> per = ray_crossings(placed_polygons, std::vector<int>(placed_polygons.size(), 0), p, d);
  if (!per) return std::nullopt;
  return per->empty() ? 0 : (*per)[0];
}

std::optional<std::vector<int>> ray_crossings(const std::vector<std::vector<Vec3E>>& placed_polygons,
                                              const std::vector<int>& shell, const Vec3E& p, const Vec3E& d) {
  if (is_zero(d) || shell.size() != placed_polygons.size()) return std::nullopt;
  std::vector<int> count(placed_polygons.empty() ? 0 : static_cast<std::size_t>(*std::max_element(shell.begin(), shell.end())) + 1, 0);
  for (std::size_t index = 0; index < placed_polygons.size(); ++index) {
    const std::vector<Vec3E>& poly = placed_polygons[index];
    const std::size_t k = poly.size();
    if (k == 0) continue;
    // Area vector: nonzero exactly when the convex polygon is not flat.
    Vec3E n{Exact(0), Exact(0), Exact(0)};
    for (std::size_t i = 1; i + 1 < k; ++i) {
      const Vec3E c = cross(sub(poly[i], poly[0]), sub(poly[i + 1], poly[0]));
      for (int j = 0; j < 3; ++j) n[j] += c[j];
    }
    if (is_zero(n)) {
      // Flat (a segment or a point): degenerate when the ray meets it.
      for (std::size_t i = 0; i < k; ++i)
        if (ray_meets_segment(p, d, poly[i], poly[(i + 1) % k])) return std::nullopt;
      continue;
    }
    // Edge functions: e_i(x) = ((v_{i+1} - v_i) x (x - v_i)) . n >= 0 on the
    // polygon (vertices turn counter-clockwise about their area vector n).
    auto inside_closed = [&](const Vec3E& x) {
      for (std::size_t i = 0; i < k; ++i)
        if (sgn(dot(cross(sub(poly[(i + 1) % k], poly[i]), sub(x, poly[i])), n)) < 0) return false;
      return true;
    };
    const int nd = sgn(dot(n, d));
    const int h = sgn(dot(n, sub(p, poly[0])));  // side of p
    if (nd == 0) {
      if (h != 0) continue;  // parallel to the plane, off it
      // The ray lies in the plane: degenerate if it meets the polygon.
      // Along the ray e_i(p + s d) = c0 + s c1; feasible s >= 0?
      Exact lo(0);
      std::optional<Exact> hi;
      bool feasible = true;
      for (std::size_t i = 0; i < k && feasible; ++i) {
        const Vec3E edge = sub(poly[(i + 1) % k], poly[i]);
        const Exact c0 = dot(cross(edge, sub(p, poly[i])), n);
        const Exact c1 = dot(cross(edge, d), n);
        if (sgn(c1) == 0) {
          if (sgn(c0) < 0) feasible = false;
        } else if (sgn(c1) > 0) {
          lo = std::max(lo, -c0 / c1);
        } else {
          const Exact bound = -c0 / c1;
          hi = hi ? std::min(*hi, bound) : bound;
        }
      }
      if (feasible && (!hi || lo <= *hi)) return std::nullopt;
      continue;
    }
    if (h == 0) {
      // p in the plane, the ray leaves it at once.
      if (inside_closed(p)) return std::nullopt;
      continue;
    }
    if (h == nd) continue;  // the plane is behind p (s = -h/nd < 0)
    // The ray crosses the plane at s > 0, at q.  With v - p = (v - q) + s d,
    // o_i = d . ((v_i - p) x (v_{i+1} - p)) = mu_i (d . n), where mu_i > 0
    // iff q is strictly on the inner side of edge i.
    bool miss = false, boundary = false;
    for (std::size_t i = 0; i < k && !miss; ++i) {
      const int o = sgn(dot(d, cross(sub(poly[i], p), sub(poly[(i + 1) % k], p)))) * nd;
      if (o < 0) miss = true;
      else if (o == 0) boundary = true;
    }
    if (miss) continue;
    if (boundary) return std::nullopt;  // through an edge or a vertex
    ++count[shell[index]];
  }
  return count;
}

std::vector<std::vector<Vec3E>> elements(const Body& body) {
  std::vector<std::vector<Vec3E>> out;
  out.reserve(body.pieces.size() + body.segments.size() + body.points.size());
  for (const ConvexPiece& piece : body.pieces) out.push_back(piece.vertices);
  for (const auto& s : body.segments) out.push_back({s[0], s[1]});
  for (const Vec3E& p : body.points) out.push_back({p});
  return out;
}

Mat34E pose_at(const Body& body, const Exact& t) {
  if (!body.motion) return identity_pose();
  const Motion& m = *body.motion;
  const int n = m.degree();
  const Exact u = (t - m.t0) / (m.t1 - m.t0);
  const Exact v = Exact(1) - u;
  const std::vector<Exact> c = binomials(n);
  // B_k(u) = C(n,k) u^k (1-u)^(n-k)
  std::vector<Exact> upow(n + 1), vpow(n + 1);
  upow[0] = vpow[0] = Exact(1);
  for (int k = 1; k <= n; ++k) {
    upow[k] = upow[k - 1] * u;
    vpow[k] = vpow[k - 1] * v;
  }
  Mat34E numerator;
  for (Exact& x : numerator) x = Exact(0);
  Exact weight(0);
  for (int k = 0; k <= n; ++k) {
    const Exact b = c[k] * upow[k] * vpow[n - k] * m.weights[k];
    for (int e = 0; e < 12; ++e) numerator[e] += b * m.control_points[k][e];
    weight += b;
  }
  if (sgn(weight) == 0) throw std::domain_error("pose_at: the motion's weight vanishes at t = " + str(t));
  for (Exact& x : numerator) x /= weight;
  return numerator;
}

namespace {

// ---------------------------------------------------------------- messages


const char* describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return "an integer";
    case json::value_t::number_float: return "a number with a fraction or exponent";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    default: return "a binary value";
  }
}

std::string idx(const std::string& parent, std::size_t i) { return parent + "[" + std::to_string(i) + "]"; }
std::string mem(const std::string& parent, const char* key) { return parent.empty() ? key : parent + "." + key; }

// A claim that does not hold: the message, without the source prefix.
struct Rejected {
  std::string message;
};

// JSON access with messages naming the path; every malformed value is an
// InputError.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}
  const std::string& source() const { return source_; }

  [[noreturn]] void bad(const std::string& path, const std::string& what) const {
    throw InputError(source_ + ": " + (path.empty() ? std::string("document") : path) + ": " + what);
  }

  const json& object(const json& v, const std::string& path) const {
    if (!v.is_object()) bad(path, std::string("expected an object, got ") + describe(v));
    return v;
  }
  const json& array(const json& v, const std::string& path) const {
    if (!v.is_array()) bad(path, std::string("expected an array, got ") + describe(v));
    return v;
  }
  const json& array(const json& v, const std::string& path, std::size_t size) const {
    array(v, path);
    if (v.size() != size)
      bad(path, "expected " + std::to_string(size) + " entries, got " + std::to_string(v.size()));
    return v;
  }
  const json* find(const json& obj, const char* key) const {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }
  const json& member(const json& obj, const char* key, const std::string& path) const {
    const json* v = find(obj, key);
    if (!v) bad(mem(path, key), "missing required field");
    return *v;
  }
  const std::string& string(const json& v, const std::string& path) const {
    if (!v.is_string()) bad(path, std::string("expected a string, got ") + describe(v));
    return v.get_ref<const std::string&>();
  }
  std::size_t index(const json& v, const std::string& path, std::size_t limit, const std::string& what) const {
    if (!v.is_number_integer()) bad(path, std::string("expected a non-negative integer, got ") + describe(v));
    if (v.is_number_unsigned()) {
      const std::uint64_t x = v.get<std::uint64_t>();
      if (x < limit) return static_cast<std::size_t>(x);
    } else {
      const std::int64_t x = v.get<std::int64_t>();
      if (x >= 0 && static_cast<std::uint64_t>(x) < limit) return static_cast<std::size_t>(x);
    }
    bad(path, v.dump() + " is out of range (" + what + ")");
  }
  Exact rational(const json& v, const std::string& path) const {
    return rational_at(v, [&] { return path; });
  }
  // The same with the path built only for a message (hot loops).
  template <class PathFn>
  Exact rational_at(const json& v, const PathFn& path) const {
    if (v.is_number_unsigned()) return Exact(static_cast<unsigned long long>(v.get<std::uint64_t>()));
    if (v.is_number_integer()) return Exact(static_cast<long long>(v.get<std::int64_t>()));
    if (!v.is_string())
      bad(path(), std::string("expected a rational (a string \"p/q\", an integer or a decimal, or a JSON "
                            "integer), got ") + describe(v));
    const std::string& s = v.get_ref<const std::string&>();
    if (s.size() > kMaxNumberChars)
      bad(path(), "number of " + std::to_string(s.size()) + " characters (at most " +
                    std::to_string(kMaxNumberChars) + ")");
    if (s.find('/') == std::string::npos) {
      const std::size_t e = s.find_first_of("eE");
      if (e != std::string::npos) {
        std::size_t i = e + 1;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        const std::string digits = s.substr(i);
        const bool ok = !digits.empty() && digits.size() <= 6 &&
                        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (ok && std::stol(digits) > kMaxDecimalExponent)
          bad(path(), "decimal exponent beyond " + std::to_string(kMaxDecimalExponent) + " in magnitude");
        if (!ok) bad(path(), "not a rational: " + quote_text(s));
      }
    }
    Exact out;
    if (!parse_exact(s, out)) bad(path(), "not a rational: " + quote_text(s));
    return out;
  }
  Vec3E vec3(const json& v, const std::string& path) const {
    array(v, path, 3);
    return {rational(v[0], idx(path, 0)), rational(v[1], idx(path, 1)), rational(v[2], idx(path, 2))};
  }
  std::pair<Exact, Exact> pair(const json& v, const std::string& path) const {
    array(v, path, 2);
    return {rational(v[0], idx(path, 0)), rational(v[1], idx(path, 1))};
  }

 private:
  std::string source_;
};

// ---------------------------------------------------------------- bodies

struct BodyData {
  const Body* body = nullptr;
  std::vector<std::vector<Vec3E>> elems;
  std::vector<std::vector<std::uint32_t>> elem_ids;  // distinct-vertex ids per element
  std::vector<Vec3E> vertices;                       // distinct vertices
  Coords coords;
  std::vector<std::size_t> component;  // per element: smallest element of its component (lazy)
};

std::unique_ptr<BodyData> make_body_data(const Body& b) {
  auto d = std::make_unique<BodyData>();
  d->body = &b;
  d->elems = elements(b);
  PointIds ids;
  d->elem_ids.resize(d->elems.size());
  for (std::size_t e = 0; e < d->elems.size(); ++e)
    for (const Vec3E& v : d->elems[e]) d->elem_ids[e].push_back(ids.id(v));
  d->vertices.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) d->vertices.push_back(ids.point(static_cast<std::uint32_t>(i)));
  d->coords = make_coords(d->vertices);
  return d;
}

// The shell of each convex piece of a solid body (SCENE_FORMAT.md "Solids":
// polygons linked by shared edges; the scene reader found them closed).
std::vector<int> piece_shells(const Body& body) {
  const std::vector<int> polygon_shell = polygon_shells(body);
  std::vector<int> out;
  out.reserve(body.pieces.size());
  for (const ConvexPiece& piece : body.pieces) out.push_back(polygon_shell[piece.polygon]);
  return out;
}

std::string counts_text(const std::vector<int>& counts) {
  std::string out;
  for (std::size_t k = 0; k < counts.size(); ++k)
    out += (k ? ", " : "") + std::to_string(counts[k]);
  return out;
}

// Components of a body: elements linked by shared (exactly equal) vertices.
const std::vector<std::size_t>& components(BodyData& d) {
  if (!d.component.empty() || d.elems.empty()) return d.component;
  std::vector<std::uint32_t> parent(d.vertices.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& ids : d.elem_ids)
    for (std::size_t k = 1; k < ids.size(); ++k) parent[find(ids[k])] = find(ids[0]);
  std::vector<std::size_t> first(d.vertices.size(), std::numeric_limits<std::size_t>::max());
  d.component.resize(d.elems.size());
  for (std::size_t e = 0; e < d.elems.size(); ++e) {
    std::size_t& f = first[find(d.elem_ids[e][0])];
    if (f == std::numeric_limits<std::size_t>::max()) f = e;
    d.component[e] = f;
  }
  return d.component;
}

// ---------------------------------------------------------------- groups

struct GroupSet {
  BodyData* body = nullptr;
  std::vector<char> leaf;                          // per group
  std::vector<std::vector<std::uint32_t>> items;   // elements or children
  std::vector<std::vector<std::uint32_t>> cache;   // distinct vertex ids (when cached)
  std::vector<char> cached;
  std::vector<std::uint32_t> group_stamp, vertex_stamp;
  std::uint32_t stamp = 0;

  // Distinct vertex ids of every element reachable from group g.
  const std::vector<std::uint32_t>& vertices(std::uint32_t g, std::vector<std::uint32_t>& scratch,
                                             std::size_t& budget) {
    if (cached[g]) return cache[g];
    if (++stamp == 0) {  // wrapped: reset the stamps
      std::fill(group_stamp.begin(), group_stamp.end(), 0);
      std::fill(vertex_stamp.begin(), vertex_stamp.end(), 0);
      stamp = 1;
    }
    scratch.clear();
    std::vector<std::uint32_t> stack{g};
    group_stamp[g] = stamp;
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      if (leaf[k]) {
        for (std::uint32_t e : items[k])
          for (std::uint32_t v : body->elem_ids[e])
            if (vertex_stamp[v] != stamp) {
              vertex_stamp[v] = stamp;
              scratch.push_back(v);
            }
      } else {
        for (std::uint32_t c : items[k])
          if (group_stamp[c] != stamp) {
            group_stamp[c] = stamp;
            stack.push_back(c);
          }
      }
    }
    if (scratch.size() <= budget) {
      budget -= scratch.size();
      cache[g] = scratch;
      cached[g] = 1;
      return cache[g];
    }
    return scratch;
  }
};

// ---------------------------------------------------------------- pieces

// A piece's restricted joint control points as integers: for each control
// point l, 24 integers Ñ = Q_l N (Q_l > 0, one per control point), the two
// 3x4 blocks row-major.
struct PieceInts {
  std::vector<Z> v;  // 24 per control point
  std::size_t count = 0;
  std::vector<Exact> q, w;  // Q_l and W_l per control point
  std::vector<Z> qz;        // Q_l as integers
};

PieceInts integer_control_points(const std::vector<CP>& c) {
  PieceInts out;
  out.count = c.size();
  out.v.resize(24 * c.size());
  Z q, f;
  for (std::size_t l = 0; l < c.size(); ++l) {
    // W_l > 0 (positive weights, positive Bernstein coefficients, de
    // Casteljau takes convex combinations); the separation argument needs it.
    if (sgn(c[l][24]) <= 0) throw std::logic_error("certificate check: joint weight not positive");
    mpz_set_ui(q.v, 1);
    for (int e = 0; e < 24; ++e) mpz_lcm(q.v, q.v, den(c[l][e]));
    out.q.push_back(from_z(q.v, Z(1).v));
    out.qz.push_back(q);
    out.w.push_back(c[l][24]);
    for (int e = 0; e < 24; ++e) {
      mpz_divexact(f.v, q.v, den(c[l][e]));
      mpz_mul(out.v[24 * l + e].v, num(c[l][e]), f.v);
    }
  }
  return out;
}

// ---------------------------------------------------------------- the checker

struct WitnessSide {
  bool interior = false;
  std::size_t element = 0;
  std::vector<Exact> weights;
  Vec3E ray;
  std::vector<std::size_t> vertices;  // an algebraic witness: the sub-feature's vertices
};

struct StartPoint {
  std::size_t element = 0, vertex = 0;
  Vec3E ray;
};

struct StartEntry {
  int solid = 0;  // 0: a, 1: b
  Exact t;        // the instant of the claim ("t", default t0)
  std::vector<StartPoint> points;
};

// One check of the certificate, read and validated (phase 2), judged in
// phase 3.
struct CheckContext {
  std::size_t index = 0;
  std::string path;     // "checks[3]"
  std::string label;    // "checks[3] (\"a\" x \"b\")"
  const json* doc = nullptr;
  const Body* body[2] = {nullptr, nullptr};
  BodyData* data[2] = {nullptr, nullptr};
  Exact t0, t1;
  std::string verdict;
  GroupSet groups[2];
  const json* pieces = nullptr;
  std::vector<std::pair<Exact, Exact>> pt;          // piece intervals
  std::vector<std::pair<Exact, Exact>> undecided;   // undecided intervals
  std::optional<std::pair<Exact, Exact>> first_contact;
  bool has_witness = false;
  Exact witness_t;  // an algebraic witness: the lower end of its interval
  Vec3E witness_point;
  std::optional<ClaimedRoot> witness_root;  // a witness at an irrational time
  WitnessSide side[2];
  std::vector<StartEntry> start;
  std::vector<CP> curve;
  Z dadb;  // D_a D_b
  std::size_t separations = 0;
  // Planner motions, tolerances and clearances (docs/certificate-format.md):
  // the pieces' curves come from each body's motion on the piece, and every
  // separation must hold with `margin` per unit of the direction's length
  // and weight: r_a rho_a + r_b rho_b + clearance.
  bool general = false;
  Exact clearance = 0;
  Exact margin = 0;
  std::array<Exact, 4> bounds[2];  // coordinate_bounds of each body
  // A witness's extras: a translation of one body within its tolerance, the
  // two points of a clearance violation, or (at an enclosed pose) an edge
  // crossing a triangle, each side's vertices in `side[s].vertices`.
  std::optional<Vec3E> displacement;
  int displaced = 0;
  std::optional<std::array<Vec3E, 2>> points;
  bool enclosed_witness = false;
  std::size_t exact_claims = 0;
  std::unique_ptr<CheckMotions> motions;  // for exact claims, built when first needed
  // A collision's "before_witness": the part of the witness's piece before
  // the witness time, from `before_from` (exact_claims.h).
  const json* before_witness = nullptr;
  Exact before_from;
};

class Checker {
 public:
  Checker(const Scene& scene, std::string source) : scene_(scene), in_(std::move(source)) {}

  CheckOutcome run(const json& doc) {
    CheckOutcome outcome;
    try {
      check_document(doc, outcome);
      outcome.ok = true;
    } catch (const Rejected& r) {
      outcome.ok = false;
      outcome.message = in_.source() + ": " + r.message;
      outcome.proven.clear();
    }
    return outcome;
  }

 private:
  const Scene& scene_;
  Reader in_;
  std::vector<std::unique_ptr<BodyData>> bodies_;
  std::size_t cache_budget_ = kGroupCacheBudget;
  std::vector<std::uint32_t> scratch_a_, scratch_b_;
  struct Scratch {
    Z L, f, nn[3], alpha[4], beta[4], mina, minb, lhs, t;
  } z_;

  [[noreturn]] static void reject(const std::string& message) { throw Rejected{message}; }

  BodyData& body_data(std::size_t i) {
    if (bodies_.empty()) bodies_.resize(scene_.bodies.size());
    if (!bodies_[i]) bodies_[i] = make_body_data(scene_.bodies[i]);
    return *bodies_[i];
  }

  static std::size_t element_count(const Body& b) { return b.pieces.size() + b.segments.size() + b.points.size(); }

  // Phase 1: the certificate belongs to this scene (else rejected: element
  // indices mean nothing in another scene).  Phase 2: every check is read
  // and validated (InputError), proof trees included.  Phase 3: the claims.
  void check_document(const json& doc, CheckOutcome& outcome) {
    in_.object(doc, "");
    const json& format = in_.member(doc, "format", "");
    if (!format.is_string() || format.get_ref<const std::string&>() != kFormat)
      in_.bad("format", std::string("unknown format ") + (format.is_string() ? quote_text(format.get<std::string>())
                                                                           : std::string(describe(format))) +
                            ", expected \"" + kFormat + "\"");

    const json& sb = in_.array(in_.member(doc, "scene_bodies", ""), "scene_bodies");
    if (sb.size() != scene_.bodies.size())
      reject("scene_bodies: " + std::to_string(sb.size()) + " bodies, the scene has " +
             std::to_string(scene_.bodies.size()) + " (the certificate belongs to another scene)");
    for (std::size_t i = 0; i < sb.size(); ++i) {
      const std::string path = idx("scene_bodies", i);
      in_.object(sb[i], path);
      const std::string& name = in_.string(in_.member(sb[i], "name", path), mem(path, "name"));
      const json& count = in_.member(sb[i], "elements", path);
      const std::size_t n = in_.index(count, mem(path, "elements"), std::numeric_limits<std::size_t>::max(),
                                      "an element count");
      const Body& b = scene_.bodies[i];
      if (name != b.name || n != element_count(b))
        reject(path + ": " + quote_text(name) + " with " + std::to_string(n) + " elements, but the scene's body " +
               std::to_string(i) + " is " + quote_text(b.name) + " with " + std::to_string(element_count(b)) +
               " elements (the certificate belongs to another scene)");
    }

    const json& checks = in_.array(in_.member(doc, "checks", ""), "checks");
    if (checks.size() != scene_.checks.size())
      reject("checks: " + std::to_string(checks.size()) + " checks, the scene has " +
             std::to_string(scene_.checks.size()) + " (the certificate belongs to another scene)");
    std::vector<std::unique_ptr<CheckContext>> ctx(checks.size());
    for (std::size_t i = 0; i < checks.size(); ++i) ctx[i] = bind_check(checks[i], i);
    for (std::size_t i = 0; i < checks.size(); ++i) read_check(*ctx[i]);
    for (std::size_t i = 0; i < checks.size(); ++i) {
      outcome.proven.push_back(judge_check(*ctx[i]));
      ctx[i].reset();  // frees its group caches
      cache_budget_ = kGroupCacheBudget;
    }
  }

  // Scene parameter interval of a check (docs: a if it moves, else b if it
  // moves, else a if it has a motion, else b if it has one, else [0, 1]).
  std::pair<Exact, Exact> check_interval(const Body& a, const Body& b, const std::string& label) const {
    const bool ma = a.moves(), mb = b.moves();
    if (ma && mb && *a.interval() != *b.interval())
      throw InputError(scene_.source + ": checks: [" + quote_text(a.name) + ", " + quote_text(b.name) +
                       "]: two moving bodies must share their motion interval (" + label + " cannot be certified)");
    const Body* m = ma ? &a : mb ? &b : a.interval() ? &a : b.interval() ? &b : nullptr;
    if (!m) return {Exact(0), Exact(1)};
    return *m->interval();
  }

  // ------------------------------------------------------------ phase 1

  std::unique_ptr<CheckContext> bind_check(const json& c, std::size_t ci) {
    auto ctx = std::make_unique<CheckContext>();
    ctx->index = ci;
    ctx->doc = &c;
    ctx->path = idx("checks", ci);
    const auto [ia, ib] = scene_.checks[ci];
    ctx->body[0] = &scene_.bodies[ia];
    ctx->body[1] = &scene_.bodies[ib];
    ctx->label = ctx->path + " (" + quote_text(ctx->body[0]->name) + " x " + quote_text(ctx->body[1]->name) + ")";
    const std::string& P = ctx->path;
    in_.object(c, P);
    const json& bodies = in_.array(in_.member(c, "bodies", P), mem(P, "bodies"), 2);
    const std::string& na = in_.string(bodies[0], idx(mem(P, "bodies"), 0));
    const std::string& nb = in_.string(bodies[1], idx(mem(P, "bodies"), 1));
    if (na != ctx->body[0]->name || nb != ctx->body[1]->name)
      reject(P + ".bodies: [" + quote_text(na) + ", " + quote_text(nb) + "], but the scene's check " + std::to_string(ci) +
             " is [" + quote_text(ctx->body[0]->name) + ", " + quote_text(ctx->body[1]->name) +
             "] (the certificate belongs to another scene)");
    std::tie(ctx->t0, ctx->t1) = check_interval(*ctx->body[0], *ctx->body[1], ctx->label);
    const auto [ilo, ihi] = in_.pair(in_.member(c, "interval", P), mem(P, "interval"));
    if (ilo != ctx->t0 || ihi != ctx->t1)
      reject(ctx->label + ": interval [" + str(ilo) + ", " + str(ihi) + "], but the check's parameter interval is [" +
             str(ctx->t0) + ", " + str(ctx->t1) + "] (the certificate belongs to another scene)");
    ctx->data[0] = &body_data(ia);
    ctx->data[1] = &body_data(ib);
    const Body& A = *ctx->body[0];
    const Body& Bb = *ctx->body[1];
    ctx->clearance = scene_.clearance_of(ci);
    ctx->general = A.trajectory || Bb.trajectory || A.tolerance > 0 || Bb.tolerance > 0 || ctx->clearance > 0;
    if (ctx->general) {
      ctx->margin = ctx->clearance;
      for (int s = 0; s < 2; ++s) {
        ctx->bounds[s] = coordinate_bounds(ctx->data[s]->elems);
        if (ctx->body[s]->tolerance > 0)
          ctx->margin += ctx->body[s]->tolerance * displacement_bound(*ctx->body[s], ctx->data[s]->elems);
      }
    }
    return ctx;
  }

  // ------------------------------------------------------------ phase 2

  void read_check(CheckContext& ctx) {
    const json& c = *ctx.doc;
    const std::string& P = ctx.path;
    ctx.verdict = in_.string(in_.member(c, "verdict", P), mem(P, "verdict"));
    const std::string& verdict = ctx.verdict;
    if (verdict != "safe" && verdict != "collision" && verdict != "undecided")
      in_.bad(mem(P, "verdict"), "expected \"safe\", \"collision\" or \"undecided\", got " + quote_text(verdict));

    read_groups(c, ctx);

    ctx.pieces = &in_.array(in_.member(c, "pieces", P), mem(P, "pieces"));
    const json& pieces = *ctx.pieces;
    ctx.pt.reserve(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const std::string pp = idx(mem(P, "pieces"), k);
      in_.object(pieces[k], pp);
      ctx.pt.push_back(in_.pair(in_.member(pieces[k], "t", pp), mem(pp, "t")));
      validate_proof(in_.member(pieces[k], "proof", pp), mem(pp, "proof"));
    }

    const json* witness = in_.find(c, "witness");
    const json* first_contact = in_.find(c, "first_contact");
    const json* undecided = in_.find(c, "undecided");
    if (witness && witness->is_null()) witness = nullptr;
    if (first_contact && first_contact->is_null()) first_contact = nullptr;
    if (undecided && undecided->is_null()) undecided = nullptr;
    const std::string up = mem(P, "undecided");
    if (verdict == "safe") {
      if (witness) in_.bad(mem(P, "witness"), "a safe check has no witness");
      if (first_contact) in_.bad(mem(P, "first_contact"), "a safe check has no first contact");
      if (undecided && !in_.array(*undecided, up).empty()) in_.bad(up, "a safe check has no undecided intervals");
    } else if (verdict == "collision") {
      if (!witness) in_.bad(mem(P, "witness"), "missing required field (a collision needs a witness)");
      if (!first_contact) in_.bad(mem(P, "first_contact"), "missing required field (a collision needs it)");
      read_witness(*witness, ctx);
    } else {
      if (witness) in_.bad(mem(P, "witness"), "an undecided check has no witness");
      if (!undecided) in_.bad(up, "missing required field (an undecided check lists its intervals)");
      in_.array(*undecided, up);
      for (std::size_t k = 0; k < undecided->size(); ++k) {
        const json& u = (*undecided)[k];
        const std::string p = idx(up, k);
        if (u.is_object()) ctx.undecided.push_back(in_.pair(in_.member(u, "t", p), mem(p, "t")));
        else if (u.is_array()) ctx.undecided.push_back(in_.pair(u, p));
        else in_.bad(p, std::string("expected {\"t\": [lo, hi]} or [lo, hi], got ") + describe(u));
      }
    }
    if (first_contact) ctx.first_contact = in_.pair(*first_contact, mem(P, "first_contact"));
    if (const json* bw = in_.find(c, "before_witness"); bw && !bw->is_null()) {
      const std::string bp = mem(P, "before_witness");
      if (verdict != "collision") in_.bad(bp, "only a collision has a witness");
      if (ctx.general)  // its exact claims use the check's one rational curve
        reject(ctx.label + ": before_witness is not part of certificates of planner motions, tolerances or clearances");
      in_.object(*bw, bp);
      ctx.before_from = in_.rational(in_.member(*bw, "from", bp), mem(bp, "from"));
      validate_proof(in_.member(*bw, "proof", bp), mem(bp, "proof"));
      ctx.before_witness = bw;
    }
    read_start(c, ctx);
  }

  // The shape of a proof tree (iteratively, depth-limited), so a malformed
  // tree is bad input whatever the claims before it.
  void validate_proof(const json& root, const std::string& root_path) {
    struct Item {
      const json* node;
      std::size_t parent;  // index into `items`, or npos
      std::size_t part;
      int depth;
    };
    constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
    std::vector<Item> items{{&root, npos, 0, 0}};
    std::vector<std::size_t> todo{0};
    auto path = [&](std::size_t i) {
      std::vector<std::size_t> parts;
      for (std::size_t k = i; items[k].parent != npos; k = items[k].parent) parts.push_back(items[k].part);
      std::string s = root_path;
      for (auto it = parts.rbegin(); it != parts.rend(); ++it) s += ".parts[" + std::to_string(*it) + "]";
      return s;
    };
    while (!todo.empty()) {
      const std::size_t i = todo.back();
      todo.pop_back();
      const json& node = *items[i].node;
      if (items[i].depth > kMaxProofDepth)
        in_.bad(path(i), "proof tree deeper than " + std::to_string(kMaxProofDepth) + " splits");
      if (!node.is_object()) in_.object(node, path(i));
      const json* sep = in_.find(node, "sep");
      const json* split_side = in_.find(node, "split");
      if (const json* exact = in_.find(node, "exact")) {  // an exact no-contact claim (exact_claims.h)
        validate_exact_leaf(node, *exact, sep || split_side, path(i));
        continue;
      }
      if ((sep != nullptr) == (split_side != nullptr))
        in_.bad(path(i), "expected exactly one of \"sep\", \"split\" and \"exact\"");
      if (sep) {
        if (!sep->is_array() || sep->size() != 3) in_.vec3(*sep, path(i) + ".sep");  // throws
        for (int r = 0; r < 3; ++r)
          in_.rational_at((*sep)[r], [&] { return idx(path(i) + ".sep", static_cast<std::size_t>(r)); });
        continue;
      }
      if (!(split_side->is_number_integer() && (*split_side == 0 || *split_side == 1)))
        in_.index(*split_side, path(i) + ".split", 2, "0 or 1");  // throws
      const json* parts = in_.find(node, "parts");
      if (!parts) in_.member(node, "parts", path(i));  // throws
      if (!parts->is_array()) in_.array(*parts, path(i) + ".parts");
      for (std::size_t k = 0; k < parts->size(); ++k) {
        items.push_back({&(*parts)[k], i, k, items[i].depth + 1});
        todo.push_back(items.size() - 1);
      }
    }
  }

  void read_groups(const json& c, CheckContext& ctx) {
    const std::string gp = mem(ctx.path, "groups");
    const json& groups = in_.array(in_.member(c, "groups", ctx.path), gp, 2);
    for (int side = 0; side < 2; ++side) {
      const std::string sp = idx(gp, side);
      const json& list = in_.array(groups[side], sp);
      if (list.empty()) in_.bad(sp, "no groups (group 0 is the root)");
      GroupSet& gs = ctx.groups[side];
      gs.body = ctx.data[side];
      const std::size_t G = list.size(), E = gs.body->elems.size();
      gs.leaf.assign(G, 0);
      gs.items.assign(G, {});
      gs.cache.assign(G, {});
      gs.cached.assign(G, 0);
      gs.group_stamp.assign(G, 0);
      gs.vertex_stamp.assign(gs.body->vertices.size(), 0);
      for (std::size_t k = 0; k < G; ++k) {
        const std::string p = idx(sp, k);
        in_.object(list[k], p);
        const json* elems = in_.find(list[k], "elements");
        const json* children = in_.find(list[k], "children");
        if ((elems != nullptr) == (children != nullptr))
          in_.bad(p, "expected exactly one of \"elements\" and \"children\"");
        if (elems) {
          const std::string ep = mem(p, "elements");
          in_.array(*elems, ep);
          if (elems->empty()) in_.bad(ep, "a group needs at least one element");
          gs.leaf[k] = 1;
          for (std::size_t i = 0; i < elems->size(); ++i)
            gs.items[k].push_back(static_cast<std::uint32_t>(
                in_.index((*elems)[i], idx(ep, i), E,
                          quote_text(gs.body->body->name) + " has " + std::to_string(E) + " elements")));
        } else {
          const std::string cp = mem(p, "children");
          in_.array(*children, cp);
          if (children->size() < 2) in_.bad(cp, "a group needs at least two children");
          for (std::size_t i = 0; i < children->size(); ++i) {
            const json& x = (*children)[i];
            const std::size_t child = in_.index(x, idx(cp, i), G, std::to_string(G) + " groups");
            if (child <= k) in_.bad(idx(cp, i), "child " + std::to_string(child) + " must be after its group " + std::to_string(k));
            gs.items[k].push_back(static_cast<std::uint32_t>(child));
          }
        }
      }
    }
  }

  void read_witness(const json& w, CheckContext& ctx) {
    const std::string wp = mem(ctx.path, "witness");
    in_.object(w, wp);
    ctx.has_witness = true;
    const json& t = in_.member(w, "t", wp);
    if (t.is_object()) {  // {"root_of": [...], "interval": [lo, hi]}
      const std::string tp = mem(wp, "t");
      ClaimedRoot root;
      const json& coefficients = in_.array(in_.member(t, "root_of", tp), mem(tp, "root_of"));
      for (std::size_t k = 0; k < coefficients.size(); ++k) {
        const Exact c = in_.rational(coefficients[k], idx(mem(tp, "root_of"), k));
        if (c.denominator() != 1) in_.bad(idx(mem(tp, "root_of"), k), "not an integer");
        root.root_of.push_back(c.numerator());
      }
      const auto [lo, hi] = in_.pair(in_.member(t, "interval", tp), mem(tp, "interval"));
      root.lo = lo;
      root.hi = hi;
      ctx.witness_t = lo;
      ctx.witness_root = std::move(root);
    } else {
      ctx.witness_t = in_.rational(t, mem(wp, "t"));
      // At a pose that is only enclosed (a transcendental motion): a
      // point_box and, on each side, the vertices of an edge or a triangle.
      ctx.enclosed_witness = in_.find(w, "point") == nullptr && in_.find(w, "point_box") != nullptr;
      if (!ctx.enclosed_witness) ctx.witness_point = in_.vec3(in_.member(w, "point", wp), mem(wp, "point"));
    }
    if (const json* d = in_.find(w, "displacement")) {
      ctx.displacement = in_.vec3(*d, mem(wp, "displacement"));
      const std::string& which = in_.string(in_.member(w, "displaced", wp), mem(wp, "displaced"));
      if (which != "a" && which != "b") in_.bad(mem(wp, "displaced"), "expected \"a\" or \"b\", got " + quote_text(which));
      ctx.displaced = which == "a" ? 0 : 1;
    }
    if (const json* pts = in_.find(w, "points")) {
      const std::string pp = mem(wp, "points");
      in_.array(*pts, pp, 2);
      ctx.points = std::array<Vec3E, 2>{in_.vec3((*pts)[0], idx(pp, 0)), in_.vec3((*pts)[1], idx(pp, 1))};
    }
    if ((ctx.witness_root || ctx.enclosed_witness) && (ctx.displacement || ctx.points))
      in_.bad(wp, "a witness at an irrational time or an enclosed pose has no displacement and no points");
    for (int s = 0; s < 2; ++s) {
      WitnessSide& side = ctx.side[s];
      const std::string sp = mem(wp, s == 0 ? "a" : "b");
      const json& x = in_.object(in_.member(w, s == 0 ? "a" : "b", wp), sp);
      if (ctx.witness_root || ctx.enclosed_witness) {  // an element and a sub-feature's vertices
        const BodyData& bd = *ctx.data[s];
        side.element = in_.index(in_.member(x, "element", sp), mem(sp, "element"), bd.elems.size(),
                                 quote_text(bd.body->name) + " has " + std::to_string(bd.elems.size()) + " elements");
        const std::size_t nv = bd.elems[side.element].size();
        const json& vs = in_.array(in_.member(x, "vertices", sp), mem(sp, "vertices"));
        for (std::size_t i = 0; i < vs.size(); ++i)
          side.vertices.push_back(in_.index(vs[i], idx(mem(sp, "vertices"), i), nv,
                                            "element " + std::to_string(side.element) + " has " + std::to_string(nv) + " vertices"));
        if (ctx.enclosed_witness) {
          // Two vertices (an edge inside the convex element) or three (a
          // triangle inside it), distinct.
          const auto& v = side.vertices;
          const bool distinct = v.size() < 2 || (v[0] != v[1] && (v.size() < 3 || (v[2] != v[0] && v[2] != v[1])));
          if (!(v.size() == 2 || v.size() == 3) || !distinct)
            in_.bad(mem(sp, "vertices"), "expected two or three distinct vertices of the element (an edge or a triangle)");
          continue;
        }
        // A vertex, two vertices (a segment inside the convex element), or
        // all of them in order (the element itself).
        bool whole = side.vertices.size() == nv;
        for (std::size_t i = 0; whole && i < nv; ++i) whole = side.vertices[i] == i;
        if (!(side.vertices.size() == 1 || side.vertices.size() == 2 || whole))
          in_.bad(mem(sp, "vertices"), "expected one vertex, two vertices or all of the element's vertices in order");
        continue;
      }
      if (const json* interior = in_.find(x, "interior")) {
        if (in_.find(x, "element") || in_.find(x, "weights"))
          in_.bad(sp, "expected either \"interior\" or \"element\" and \"weights\"");
        side.interior = true;
        const std::string ip = mem(sp, "interior");
        in_.object(*interior, ip);
        side.ray = in_.vec3(in_.member(*interior, "ray", ip), mem(ip, "ray"));
      } else {
        const BodyData& bd = *ctx.data[s];
        side.element = in_.index(in_.member(x, "element", sp), mem(sp, "element"), bd.elems.size(),
                                 quote_text(bd.body->name) + " has " + std::to_string(bd.elems.size()) + " elements");
        const std::size_t nv = bd.elems[side.element].size();
        const json& ws = in_.array(in_.member(x, "weights", sp), mem(sp, "weights"));
        if (ws.size() != nv)
          in_.bad(mem(sp, "weights"), std::to_string(ws.size()) + " weights, element " + std::to_string(side.element) +
                                          " has " + std::to_string(nv) + " vertices");
        for (std::size_t i = 0; i < nv; ++i) side.weights.push_back(in_.rational(ws[i], idx(mem(sp, "weights"), i)));
      }
    }
  }

  void read_start(const json& c, CheckContext& ctx) {
    const std::string sp = mem(ctx.path, "start");
    const json* start = in_.find(c, "start");
    if (!start || start->is_null()) return;
    in_.array(*start, sp);
    std::set<std::pair<int, Exact>> seen;
    for (std::size_t k = 0; k < start->size(); ++k) {
      const json& e = (*start)[k];
      const std::string ep = idx(sp, k);
      in_.object(e, ep);
      const std::string& which = in_.string(in_.member(e, "solid", ep), mem(ep, "solid"));
      if (which != "a" && which != "b") in_.bad(mem(ep, "solid"), "expected \"a\" or \"b\", got " + quote_text(which));
      const int s = which == "a" ? 0 : 1;
      // The instant of the claim: the check's start unless "t" says (the
      // start of a run of pieces after an undecided interval).
      Exact at = ctx.t0;
      if (const json* t = in_.find(e, "t"); t && !t->is_null()) {
        at = in_.rational(*t, mem(ep, "t"));
        if (at < ctx.t0 || at > ctx.t1)
          in_.bad(mem(ep, "t"), str(at) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
      }
      if (!seen.insert({s, at}).second)
        in_.bad(mem(ep, "solid"), "a second entry for " + quote_text(which) + (at == ctx.t0 ? "" : " at t = " + str(at)));
      const BodyData& other = *ctx.data[1 - s];
      const json& pts = in_.array(in_.member(e, "points", ep), mem(ep, "points"));
      StartEntry entry{s, at, {}};
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::string pp = idx(mem(ep, "points"), i);
        in_.object(pts[i], pp);
        StartPoint p;
        p.element = in_.index(in_.member(pts[i], "element", pp), mem(pp, "element"), other.elems.size(),
                              quote_text(other.body->name) + " has " + std::to_string(other.elems.size()) + " elements");
        const std::size_t nv = other.elems[p.element].size();
        p.vertex = in_.index(in_.member(pts[i], "vertex", pp), mem(pp, "vertex"), nv,
                             "element " + std::to_string(p.element) + " has " + std::to_string(nv) + " vertices");
        p.ray = in_.vec3(in_.member(pts[i], "ray", pp), mem(pp, "ray"));
        entry.points.push_back(std::move(p));
      }
      ctx.start.push_back(std::move(entry));
    }
  }

  // ------------------------------------------------------------ phase 3

  std::string judge_check(CheckContext& ctx) {
    const std::string& L = ctx.label;
    const std::vector<std::pair<Exact, Exact>>& pt = ctx.pt;
    check_coverage(ctx);
    for (std::size_t k = 0; k < pt.size(); ++k)
      if (!(pt[k].first < pt[k].second))
        reject(L + ": pieces[" + std::to_string(k) + "] [" + str(pt[k].first) + ", " + str(pt[k].second) +
               "] is empty (a piece needs ta < tb)");

    std::string summary;
    Exact clear_until = ctx.t0;  // no contact before this parameter (proven below)
    if (ctx.verdict == "safe" || ctx.verdict == "collision") {
      // In order and contiguous from t0.
      Exact end = ctx.t0;
      for (std::size_t k = 0; k < pt.size(); ++k) {
        if (pt[k].first != end)
          reject(L + ": pieces[" + std::to_string(k) + "] [" + str(pt[k].first) + ", " + str(pt[k].second) +
                 "] starts at " + str(pt[k].first) + ", but " +
                 (k == 0 ? "the check starts at t0 = " + str(ctx.t0) : "the previous piece ends at " + str(end)) +
                 (pt[k].first > end ? " (gap)" : " (overlap)"));
        end = pt[k].second;
        if (end > ctx.t1)
          reject(L + ": pieces[" + std::to_string(k) + "] [" + str(pt[k].first) + ", " + str(pt[k].second) +
                 "] ends after t1 = " + str(ctx.t1));
      }
      if (ctx.verdict == "safe") {
        if (end != ctx.t1)
          reject(L + ": the pieces end at " + str(end) + ", not at t1 = " + str(ctx.t1) +
                 " (safe needs the whole interval)");
        clear_until = ctx.t1;
      } else {
        const auto [lo, hi] = *ctx.first_contact;
        const Exact& t = ctx.witness_t;
        check_witness(ctx);
        const std::string fc = L + ": first_contact [" + str(lo) + ", " + str(hi) + "]";
        // With before_witness, the pieces end where it starts and it proves
        // the rest up to the witness time (the first contact, exactly).
        const Exact& pieces_end = ctx.before_witness ? ctx.before_from : lo;
        if (end != pieces_end)
          reject(fc + ": the pieces end at " + str(end) + ", not at " +
                 (ctx.before_witness ? "before_witness.from = " : "lo = ") + str(pieces_end));
        if (lo > t) reject(fc + ": lo is after the witness t = " + str(t));
        if (t > hi) reject(fc + ": the witness t = " + str(t) + " is after hi");
        if (ctx.witness_root && hi < ctx.witness_root->hi && ctx.before_witness)
          reject(fc + ": hi is before the end of the witness time's interval " + str(ctx.witness_root->hi));
        clear_until = lo;
        const std::string at = ctx.witness_root ? "an irrational t in (" + str(ctx.witness_root->lo) + ", " +
                                                      str(ctx.witness_root->hi) + ")"
                                                : "t = " + str(t);
        summary = "collision proven at " + at +
                  (ctx.before_witness ? "; no contact before it proven (the first contact)"
                                      : "; no contact before t = " + str(lo) + " proven");
      }
    } else {  // undecided
      const std::vector<std::pair<Exact, Exact>>& ut = ctx.undecided;
      for (std::size_t k = 0; k < ut.size(); ++k)
        if (!(ut[k].first < ut[k].second))
          reject(L + ": undecided[" + std::to_string(k) + "] [" + str(ut[k].first) + ", " + str(ut[k].second) +
                 "] is empty (needs lo < hi)");
      if (ut.empty()) reject(L + ": an undecided check with no undecided interval");
      // Pieces and undecided intervals, in order, tile [t0, t1].
      Exact end = ctx.t0;
      std::size_t i = 0, j = 0;
      while (i < pt.size() || j < ut.size()) {
        if (i < pt.size() && pt[i].first == end) {
          end = pt[i++].second;
        } else if (j < ut.size() && ut[j].first == end) {
          end = ut[j++].second;
        } else {
          std::string next;
          if (i < pt.size()) next += "pieces[" + std::to_string(i) + "] starts at " + str(pt[i].first);
          if (j < ut.size())
            next += std::string(next.empty() ? "" : ", ") + "undecided[" + std::to_string(j) + "] starts at " +
                    str(ut[j].first);
          reject(L + ": the pieces and undecided intervals do not tile [" + str(ctx.t0) + ", " + str(ctx.t1) +
                 "]: the previous one ends at " + str(end) + ", " + next);
        }
        if (end > ctx.t1)
          reject(L + ": the pieces and undecided intervals reach " + str(end) + ", after t1 = " + str(ctx.t1));
      }
      if (end != ctx.t1)
        reject(L + ": the pieces and undecided intervals end at " + str(end) + ", not at t1 = " + str(ctx.t1));
      clear_until = ut.front().first;
      if (ctx.first_contact) {
        const auto [lo, hi] = *ctx.first_contact;
        if (lo > hi) reject(L + ": first_contact [" + str(lo) + ", " + str(hi) + "] is empty");
        if (lo > clear_until)
          reject(L + ": first_contact [" + str(lo) + ", " + str(hi) +
                 "]: lo is after the first undecided interval, which starts at " + str(clear_until));
      }
    }

    // Where runs of pieces start: t0 when the pieces (or before_witness)
    // start there, and every piece that follows an undecided interval.
    // Separations prove the surfaces apart on each piece; a solid's
    // inside needs its start claims at each run's start (a component that
    // entered during an undecided interval stays inside without touching
    // the surface: proofs/partition.md §5).
    std::vector<Exact> runs;
    if (ctx.verdict == "undecided") {
      std::set<Exact> undecided_ends;
      for (const auto& u : ctx.undecided) undecided_ends.insert(u.second);
      for (std::size_t k = 0; k < pt.size(); ++k)
        if (pt[k].first == ctx.t0 || undecided_ends.count(pt[k].first)) runs.push_back(pt[k].first);
    } else if (!pt.empty() || ctx.before_witness) {
      runs.push_back(ctx.t0);
    }
    const std::size_t start_points = check_start(ctx, runs);

    // The separation proofs, piece by piece.
    mpz_mul(ctx.dadb.v, ctx.data[0]->coords.D.v, ctx.data[1]->coords.D.v);
    if (!ctx.general) ctx.curve = joint_curve(*ctx.body[0], *ctx.body[1]);
    for (std::size_t k = 0; k < pt.size(); ++k) check_piece((*ctx.pieces)[k], k, pt[k], ctx);
    if (ctx.before_witness) check_before_witness(ctx);

    std::string counts = std::to_string(pt.size()) + (pt.size() == 1 ? " piece, " : " pieces, ") +
                         std::to_string(ctx.separations) + (ctx.separations == 1 ? " separation" : " separations");
    if (ctx.exact_claims)
      counts += ", " + std::to_string(ctx.exact_claims) + (ctx.exact_claims == 1 ? " exact claim" : " exact claims");
    if (start_points)
      counts += ", " + std::to_string(start_points) + (start_points == 1 ? " start point" : " start points");
    const std::string who = ctx.body[0]->name + " x " + ctx.body[1]->name + ": ";
    if (ctx.verdict == "safe") return who + "safe proven (" + counts + ")";
    if (ctx.verdict == "collision") return who + summary + " (" + counts + ")";
    const std::size_t u = ctx.undecided.size();
    return who + "undecided: no contact before t = " + str(clear_until) + " proven (" + counts + "; " +
           std::to_string(u) + (u == 1 ? " interval" : " intervals") + " not cleared)";
  }

  // Group 0 reaches every element (children come later, so one pass in
  // index order propagates reachability).
  void check_coverage(const CheckContext& ctx) {
    for (int side = 0; side < 2; ++side) {
      const GroupSet& gs = ctx.groups[side];
      const std::size_t G = gs.items.size(), E = gs.body->elems.size();
      std::vector<char> reach(G, 0), covered(E, 0);
      reach[0] = 1;
      for (std::size_t k = 0; k < G; ++k) {
        if (!reach[k]) continue;
        for (std::uint32_t x : gs.items[k]) (gs.leaf[k] ? covered : reach)[x] = 1;
      }
      for (std::size_t e = 0; e < E; ++e)
        if (!covered[e])
          reject(ctx.label + ": groups[" + std::to_string(side) + "]: group 0 does not reach element " +
                 std::to_string(e) + " of " + quote_text(gs.body->body->name));
    }
  }

  // ------------------------------------------------------------ witness

  // A witness at an irrational time: a valid root claim, and the two
  // sub-features share a point at that root (exact signs at the root).
  void check_algebraic_witness(const CheckContext& ctx) {
    const std::string L = ctx.label + ": witness";
    const ClaimedRoot& claim = *ctx.witness_root;
    if (const std::string error = root_claim_error(claim, ctx.t0, ctx.t1); !error.empty()) reject(L + ".t: " + error);
    std::optional<CheckMotions> general;
    RealRoot root;
    if (ctx.general) {
      // Keyframe or piecewise motions: both bodies on one rational segment
      // around the root's interval, in that segment's parameter.
      const auto span = rational_span(*ctx.body[0], *ctx.body[1], claim.lo, claim.hi, ctx.t0, ctx.t1);
      if (!span) reject(L + ".t: the interval (" + str(claim.lo) + ", " + str(claim.hi) +
                        ") is not inside one rational segment of both motions");
      std::string why;
      const auto ma = piece_motion(*ctx.body[0], span->first, span->second, why);
      const auto mb = piece_motion(*ctx.body[1], span->first, span->second, why);
      if (!ma || !mb || !ma->exact || !mb->exact) reject(L + ".t: " + why);
      general.emplace(*ma->exact, *mb->exact);
      root = check_parameter_root(claim, span->first, span->second);
    } else {
      root = check_parameter_root(claim, ctx.t0, ctx.t1);
    }
    const CheckMotions motions = general ? *general : CheckMotions(*ctx.body[0], *ctx.body[1]);
    std::vector<MovingPoint> points[2];
    for (int s = 0; s < 2; ++s)
      for (std::size_t v : ctx.side[s].vertices)
        points[s].push_back(motions.place(s, ctx.data[s]->elems[ctx.side[s].element][v]));
    if (!ContactSolver::touch(points[0], points[1], root))
      reject(L + ": the two sub-features do not meet at the root of t in (" + str(claim.lo) + ", " + str(claim.hi) + ")");
  }

  // A witness at an enclosed pose: an edge of one body crosses a triangle
  // of the other transversally for every pose in the two pose boxes at t.
  void check_enclosed_witness(const CheckContext& ctx) {
    const std::string L = ctx.label + ": witness";
    const Exact& t = ctx.witness_t;
    if (t < ctx.t0 || t > ctx.t1)
      reject(L + ": t = " + str(t) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
    std::vector<RBox> placed_vertices[2];
    for (int s = 0; s < 2; ++s) {
      const std::optional<PoseBox> box = pose_box_at(*ctx.body[s], t);
      if (!box) reject(L + ": the pose of " + quote_text(ctx.body[s]->name) + " at t = " + str(t) + " has no finite enclosure");
      for (std::size_t v : ctx.side[s].vertices)
        placed_vertices[s].push_back(place_box(*box, ctx.data[s]->elems[ctx.side[s].element][v]));
    }
    const int e = placed_vertices[0].size() == 2 ? 0 : 1;  // the edge's side
    const std::vector<RBox>& edge = placed_vertices[e];
    const std::vector<RBox>& tri = placed_vertices[1 - e];
    if (edge.size() != 2 || tri.size() != 3)
      reject(L + ": an enclosed witness needs an edge (two vertices) on one side and a triangle (three) on the other");
    if (!certain_crossing(edge[0], edge[1], tri[0], tri[1], tri[2]))
      reject(L + ": the edge's crossing of the triangle at t = " + str(t) +
             " is not certain over the enclosed poses (grazing, or not crossing)");
  }

  void check_witness(const CheckContext& ctx) {
    if (ctx.witness_root) return check_algebraic_witness(ctx);
    if (ctx.enclosed_witness) return check_enclosed_witness(ctx);
    const Exact& t = ctx.witness_t;
    const std::string L = ctx.label + ": witness";
    if (t < ctx.t0 || t > ctx.t1)
      reject(L + ": t = " + str(t) + " is outside the check's interval [" + str(ctx.t0) + ", " + str(ctx.t1) + "]");
    if (ctx.displacement) {
      // A translation by v has norm |v| sqrt(sum w) in the body's metric.
      const Body& body = *ctx.body[ctx.displaced];
      const Vec3E& v = *ctx.displacement;
      Exact w = 0;
      for (const Exact& x : body.mass.weights) w += x;
      const Exact norm2 = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * w;
      if (norm2 > body.tolerance * body.tolerance)
        reject(L + ".displacement: " + str(v) + " is not within the tolerance " + str(body.tolerance) + " of " +
               quote_text(body.name) + " (its norm squared in the body's metric is " + str(norm2) + ")");
    }
    if (ctx.points) {
      const Vec3E d = sub((*ctx.points)[0], (*ctx.points)[1]);
      if (dot(d, d) > ctx.clearance * ctx.clearance)
        reject(L + ".points: " + str((*ctx.points)[0]) + " and " + str((*ctx.points)[1]) +
               " are farther apart than the clearance " + str(ctx.clearance));
    }
    for (int s = 0; s < 2; ++s) {
      const WitnessSide& side = ctx.side[s];
      const char* key = s == 0 ? "a" : "b";
      const Body& body = *ctx.body[s];
      const Vec3E& point = ctx.points ? (*ctx.points)[s] : ctx.witness_point;
      Mat34E pose;
      if (ctx.general) {
        const std::optional<Mat34E> p = exact_pose_at(body, t);
        if (!p)
          reject(L + "." + key + ": the pose of " + quote_text(body.name) + " at t = " + str(t) +
                 " is not exact (an enclosed pose needs the edge-and-triangle witness)");
        pose = *p;
        if (ctx.displacement && ctx.displaced == s)
          for (int r = 0; r < 3; ++r) pose[4 * r + 3] += (*ctx.displacement)[r];
      } else {
        pose = pose_at(body, t);
      }
      if (side.interior) {
        if (!body.solid) reject(L + "." + key + ": " + quote_text(body.name) + " is not solid, it has no interior");
        if (sgn(determinant(pose)) == 0)
          reject(L + "." + key + ": the pose of " + quote_text(body.name) + " at t = " + str(t) +
                 " is singular (no interior point can be proven)");
        const std::optional<std::vector<int>> n =
            ray_crossings(placed(*ctx.data[s], pose), piece_shells(body), point, side.ray);
        if (!n)
          reject(L + "." + key + ".interior: the ray from the point along " + str(side.ray) +
                 " is degenerate (through a vertex or an edge, in a polygon's plane, or the point on the surface)");
        // Inside the union of the shells iff inside one of them.
        if (std::none_of(n->begin(), n->end(), [](int c) { return c % 2 != 0; }))
          reject(L + "." + key + ".interior: the ray crosses every shell of " + quote_text(body.name) +
                 " an even number of times (" + counts_text(*n) + "): the point is not inside");
      } else {
        const std::vector<Vec3E>& verts = ctx.data[s]->elems[side.element];
        Exact sum(0);
        Vec3E x{Exact(0), Exact(0), Exact(0)};
        for (std::size_t i = 0; i < verts.size(); ++i) {
          const Exact& wi = side.weights[i];
          if (sgn(wi) < 0) reject(L + "." + key + ".weights[" + std::to_string(i) + "] = " + str(wi) + " is negative");
          sum += wi;
          for (int r = 0; r < 3; ++r) x[r] += wi * verts[i][r];
        }
        if (sum != 1) reject(L + "." + key + ".weights sum to " + str(sum) + ", not 1");
        const Vec3E placed_x = place_point(pose, x);
        if (placed_x != point)
          reject(L + "." + key + ": element " + std::to_string(side.element) + " of " + quote_text(body.name) +
                 " with these weights is at " + str(placed_x) + " at t = " + str(t) + ", not at the point " +
                 str(point));
      }
    }
  }

  static std::vector<std::vector<Vec3E>> placed(const BodyData& d, const Mat34E& pose) {
    std::vector<std::vector<Vec3E>> out;
    out.reserve(d.body->pieces.size());
    for (const ConvexPiece& piece : d.body->pieces) {
      std::vector<Vec3E> poly;
      poly.reserve(piece.vertices.size());
      for (const Vec3E& v : piece.vertices) poly.push_back(place_point(pose, v));
      out.push_back(std::move(poly));
    }
    return out;
  }

  // ------------------------------------------------------------ start claims

  // The pose of check body s at scene parameter t for start claims: exact
  // (a general check's body may be only enclosed there: nullopt).
  std::optional<Mat34E> claim_pose(const CheckContext& ctx, int s, const Exact& t) const {
    if (!ctx.general) return pose_at(*ctx.body[s], t);
    return exact_pose_at(*ctx.body[s], t);
  }

  static std::string at_text(const CheckContext& ctx, const Exact& t) {
    return t == ctx.t0 ? "t0 = " + str(t) : "t = " + str(t);
  }

  // Checks the start claims, and that one is given at every run start in
  // `runs` for each solid body with a nonsingular pose there; returns the
  // number of points checked.
  std::size_t check_start(CheckContext& ctx, const std::vector<Exact>& runs) {
    std::size_t checked = 0;
    const bool solid = ctx.body[0]->solid || ctx.body[1]->solid;
    // The poses at each instant a claim is made or needed, exact.
    std::map<Exact, std::array<Mat34E, 2>> poses;
    auto poses_at = [&](const Exact& t) -> const std::array<Mat34E, 2>& {
      auto it = poses.find(t);
      if (it != poses.end()) return it->second;
      std::array<Mat34E, 2> p;
      for (int s = 0; s < 2; ++s) {
        const std::optional<Mat34E> m = claim_pose(ctx, s, t);
        if (!m)
          reject(ctx.label + ": start: the pose of " + quote_text(ctx.body[s]->name) + " at " + at_text(ctx, t) +
                 " is not exact (a transcendental rotation): start claims need exact poses");
        p[s] = *m;
      }
      return poses.emplace(t, p).first->second;
    };
    if (solid)
      for (const Exact& t : runs) poses_at(t);
    std::set<std::pair<int, Exact>> seen;
    for (std::size_t k = 0; k < ctx.start.size(); ++k) {
      const StartEntry& entry = ctx.start[k];
      const int s = entry.solid;
      seen.insert({s, entry.t});
      const Body& solid_body = *ctx.body[s];
      BodyData& other = *ctx.data[1 - s];
      const std::string L = ctx.label + ": start[" + std::to_string(k) + "] (solid " + quote_text(solid_body.name) + ")";
      if (!solid_body.solid) reject(L + ": " + quote_text(solid_body.name) + " is not solid");
      const std::array<Mat34E, 2>& pose = poses_at(entry.t);
      const std::vector<std::vector<Vec3E>> polygons = placed(*ctx.data[s], pose[s]);
      const std::vector<int> shells = piece_shells(solid_body);
      for (std::size_t i = 0; i < entry.points.size(); ++i) {
        const StartPoint& p = entry.points[i];
        const Vec3E x = place_point(pose[1 - s], other.elems[p.element][p.vertex]);
        const std::string LP = L + ".points[" + std::to_string(i) + "] (" + quote_text(other.body->name) + " element " +
                               std::to_string(p.element) + " vertex " + std::to_string(p.vertex) + ")";
        const std::optional<std::vector<int>> n = ray_crossings(polygons, shells, x, p.ray);
        if (!n)
          reject(LP + ": the ray along " + str(p.ray) +
                 " is degenerate (through a vertex or an edge, in a polygon's plane, or the vertex on the surface)");
        // Outside the union of the shells only if outside every one.
        for (std::size_t k2 = 0; k2 < n->size(); ++k2)
          if ((*n)[k2] % 2 != 0)
            reject(LP + ": the ray crosses shell " + std::to_string(k2) + " of " + quote_text(solid_body.name) + " " +
                   std::to_string((*n)[k2]) + (((*n)[k2] == 1) ? " time" : " times") +
                   ", an odd number: the vertex is inside " + quote_text(solid_body.name) + " at " +
                   (entry.t == ctx.t0 ? std::string("t0") : "t = " + str(entry.t)));
        ++checked;
      }
      // One listed point per component of the other body.
      const std::vector<std::size_t>& comp = components(other);
      std::vector<char> has(other.elems.size(), 0);
      for (const StartPoint& p : entry.points) has[comp[p.element]] = 1;
      for (std::size_t e = 0; e < comp.size(); ++e)
        if (comp[e] == e && !has[e])
          reject(L + ": no point of the component of " + quote_text(other.body->name) + " element " + std::to_string(e) +
                 " is listed");
    }
    // Required: one entry per solid body of the check with a nonsingular
    // pose at each run's start.
    if (solid)
      for (const Exact& t : runs)
        for (int s = 0; s < 2; ++s)
          if (ctx.body[s]->solid && !seen.count({s, t}) && sgn(determinant(poses_at(t)[s])) != 0)
            reject(ctx.label + ": start: no claim for the solid " + quote_text(ctx.body[s]->name) + " (\"" +
                   (s == 0 ? "a" : "b") + "\")" + (t == ctx.t0 ? "" : " at t = " + str(t)) +
                   ": the other body could " +
                   (t == ctx.t0 ? std::string("start inside it")
                                : "be inside it there (it may have entered while undecided)"));
    return checked;
  }

  // ------------------------------------------------------------ proofs

  struct PieceContext {
    std::size_t index;
    std::string path;   // "checks[0].pieces[17]"
    std::string label;  // "checks[0] (..): pieces[17] [3/16, 7/32]"
    PieceInts ints;
    // A general check: every separation holds with W_l |n| margin +
    // sum_i |n_i| penalty_i to spare (penalty: the pose boxes' radii).
    bool margins = false;
    std::array<Exact, 3> penalty{Exact(0), Exact(0), Exact(0)};
    // The penalty as integers over one positive denominator (the integer
    // path when there is no margin).
    std::array<Z, 3> penalty_num;
    Z penalty_den{1};
    Exact ua, ub;                     // the piece in curve parameters
    const RealRoot* before = nullptr;  // before_witness: the claims hold before this time only
  };

  void check_piece(const json& piece, std::size_t k, const std::pair<Exact, Exact>& t, CheckContext& ctx) {
    PieceContext pc;
    pc.index = k;
    pc.path = idx(mem(ctx.path, "pieces"), k);
    pc.label = ctx.label + ": pieces[" + std::to_string(k) + "] [" + str(t.first) + ", " + str(t.second) + "]";
    if (ctx.general) {
      general_piece(t, pc, ctx);
    } else {
      const Exact span = ctx.t1 - ctx.t0;
      const Exact ua = (t.first - ctx.t0) / span, ub = (t.second - ctx.t0) / span;
      pc.ints = integer_control_points(restrict_curve(ctx.curve, ua, ub));
      pc.ua = ua;
      pc.ub = ub;
    }
    std::vector<int> trail;
    prove(piece.at("proof"), 0, 0, trail, pc, ctx);
  }

  // A piece of a general check: each body's motion on the piece, exact (a
  // rational curve; then the joint curve of the two) or enclosed (a pose
  // box; then one control point, the boxes' centres, and the radii as a
  // penalty: |n . (M - C) x^| <= sum_i |n_i| sum_j radius_ij |x_j| <=
  // sum_i |n_i| sum_j radius_ij bound_j).
  void general_piece(const std::pair<Exact, Exact>& t, PieceContext& pc, const CheckContext& ctx) {
    std::optional<PieceMotion> m[2];
    for (int s = 0; s < 2; ++s) {
      std::string why;
      m[s] = piece_motion(*ctx.body[s], t.first, t.second, why);
      if (!m[s]) reject(pc.label + ": " + why);
    }
    std::vector<CP> curve;
    if (m[0]->exact && m[1]->exact) {
      curve = joint_curve(HomogeneousMotion{m[0]->exact->control_points, m[0]->exact->weights},
                          HomogeneousMotion{m[1]->exact->control_points, m[1]->exact->weights});
    } else {
      CP c;
      for (int s = 0; s < 2; ++s) {
        const PoseBox box = m[s]->exact ? control_box(*m[s]->exact) : m[s]->box;
        for (int e = 0; e < 12; ++e) c[12 * s + e] = box.center[e];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 4; ++j) pc.penalty[i] += box.radius[4 * i + j] * ctx.bounds[s][j];
      }
      c[24] = 1;
      curve = {c};
    }
    pc.ints = integer_control_points(curve);
    pc.margins = ctx.margin > 0 || sgn(pc.penalty[0]) != 0 || sgn(pc.penalty[1]) != 0 || sgn(pc.penalty[2]) != 0;
    for (int i = 0; i < 3; ++i) mpz_lcm(pc.penalty_den.v, pc.penalty_den.v, den(pc.penalty[i]));
    Z f;
    for (int i = 0; i < 3; ++i) {
      mpz_divexact(f.v, pc.penalty_den.v, den(pc.penalty[i]));
      mpz_mul(pc.penalty_num[i].v, num(pc.penalty[i]), f.v);
    }
  }

  // ------------------------------------------------------------ exact claims

  void validate_exact_leaf(const json& node, const json& exact, bool other_keys, const std::string& path) {
    if (other_keys) in_.bad(path, "expected exactly one of \"sep\", \"split\" and \"exact\"");
    if (!(exact.is_string() && exact.get_ref<const std::string&>() == "no_contact"))
      in_.bad(path + ".exact", std::string("expected \"no_contact\", got ") + describe(exact));
    (void)node;
  }

  // Elements reachable from group g of one side.
  static std::vector<std::uint32_t> group_elements(const GroupSet& gs, std::uint32_t g) {
    std::vector<std::uint32_t> out, stack{g};
    std::vector<char> seen_group(gs.items.size(), 0), seen_element(gs.body->elems.size(), 0);
    seen_group[g] = 1;
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      for (std::uint32_t x : gs.items[k]) {
        std::vector<char>& seen = gs.leaf[k] ? seen_element : seen_group;
        if (seen[x]) continue;
        seen[x] = 1;
        if (gs.leaf[k]) out.push_back(x);
        else stack.push_back(x);
      }
    }
    return out;
  }

  // The claim "no element of g touches an element of h on the piece"
  // (before pc.before when set): empty when it holds.
  std::string exact_leaf_error(std::uint32_t g, std::uint32_t h, const PieceContext& pc, CheckContext& ctx) {
    if (!ctx.motions) ctx.motions = std::make_unique<CheckMotions>(*ctx.body[0], *ctx.body[1]);
    for (std::uint32_t ea : group_elements(ctx.groups[0], g))
      for (std::uint32_t eb : group_elements(ctx.groups[1], h)) {
        const std::string error =
            no_contact_error(*ctx.motions, ctx.data[0]->elems[ea], ctx.data[1]->elems[eb], pc.ua, pc.ub, pc.before);
        if (!error.empty()) return "elements " + std::to_string(ea) + " and " + std::to_string(eb) + ": " + error;
      }
    return {};
  }

  // before_witness: a proof tree for the part [from, T) of the witness's
  // piece, T the witness time.  Its separations are checked on the closed
  // [from, T] (rational T) or [from, hi] (T in (lo, hi)), its exact claims
  // on [from, T).
  void check_before_witness(CheckContext& ctx) {
    const json& bw = *ctx.before_witness;
    const std::string L = ctx.label + ": before_witness";
    const Exact span = ctx.t1 - ctx.t0;
    RealRoot root = ctx.witness_root ? check_parameter_root(*ctx.witness_root, ctx.t0, ctx.t1)
                                     : rational_root((ctx.witness_t - ctx.t0) / span);
    const Exact end = ctx.witness_root ? ctx.witness_root->hi : ctx.witness_t;
    RealRoot start = rational_root((ctx.before_from - ctx.t0) / span);
    bool before;
    try {
      before = compare(start, root) == CGAL::SMALLER;
    } catch (const ExactLimit& e) {
      throw ResourceLimit(std::string("before_witness: ") + e.what());
    }
    if (ctx.before_from < ctx.t0 || !before)
      reject(L + ": from = " + str(ctx.before_from) + " is not before the witness time (or not in the check's interval)");
    PieceContext pc;
    pc.index = ctx.pt.size();
    pc.path = mem(ctx.path, "before_witness");
    pc.label = L + " [" + str(ctx.before_from) + ", witness)";
    pc.ua = (ctx.before_from - ctx.t0) / span;
    pc.ub = (end - ctx.t0) / span;
    pc.ints = integer_control_points(restrict_curve(ctx.curve, pc.ua, pc.ub));
    pc.before = &root;
    std::vector<int> trail;
    prove(bw.at("proof"), 0, 0, trail, pc, ctx);
  }

  static std::string trail_path(const std::vector<int>& trail) {
    std::string s = "proof";
    for (int i : trail) s += ".parts[" + std::to_string(i) + "]";
    return s;
  }

  // The proof tree was validated in phase 2 (shape, rationals, depth); the
  // checks below repeat only what guards memory safety.
  void prove(const json& node, std::uint32_t g, std::uint32_t h, std::vector<int>& trail, const PieceContext& pc,
             CheckContext& ctx) {
    auto path = [&] { return pc.path + "." + trail_path(trail); };
    if (trail.size() > static_cast<std::size_t>(kMaxProofDepth))
      in_.bad(path(), "proof tree deeper than " + std::to_string(kMaxProofDepth) + " splits");
    if (!node.is_object()) in_.object(node, path());
    const json* sep = in_.find(node, "sep");
    const json* split_side = in_.find(node, "split");
    auto here = [&] {
      return pc.label + ": " + trail_path(trail) + " (groups " + std::to_string(g) + ", " + std::to_string(h) + ")";
    };
    if (const json* exact = in_.find(node, "exact")) {
      validate_exact_leaf(node, *exact, sep || split_side, path());
      if (ctx.general)  // exact claims decide the check's one rational curve, which a general check has not
        reject(here() + ": exact no-contact claims are not part of certificates of planner motions, tolerances or "
                        "clearances");
      ++ctx.exact_claims;
      if (const std::string error = exact_leaf_error(g, h, pc, ctx); !error.empty())
        reject(here() + ": exact no-contact claim fails: " + error);
      return;
    }
    if ((sep != nullptr) == (split_side != nullptr))
      in_.bad(path(), "expected exactly one of \"sep\", \"split\" and \"exact\"");
    if (sep) {
      if (!sep->is_array() || sep->size() != 3) in_.vec3(*sep, path() + ".sep");  // throws
      Vec3E n;
      for (int r = 0; r < 3; ++r)
        n[r] = in_.rational_at((*sep)[r], [&] { return idx(path() + ".sep", static_cast<std::size_t>(r)); });
      ++ctx.separations;
      const int fails = separation_fails_at(n, g, h, pc, ctx);
      if (fails >= 0) reject(here() + ": separation fails at control point " + std::to_string(fails));
      return;
    }
    const std::size_t side =
        split_side->is_number_integer() && (*split_side == 0 || *split_side == 1)
            ? (*split_side == 0 ? 0 : 1)
            : in_.index(*split_side, path() + ".split", 2, "0 or 1");
    const json* parts = in_.find(node, "parts");
    if (!parts) in_.member(node, "parts", path());  // throws
    if (!parts->is_array()) in_.array(*parts, path() + ".parts");
    const GroupSet& gs = ctx.groups[side];
    const std::uint32_t split_group = side == 0 ? g : h;
    if (gs.leaf[split_group])
      reject(here() + ": split " + std::to_string(side) + " of group " + std::to_string(split_group) +
             ", which has no children");
    const std::vector<std::uint32_t>& children = gs.items[split_group];
    if (parts->size() != children.size())
      reject(here() + ": split " + std::to_string(side) + " has " + std::to_string(parts->size()) +
             " parts, group " + std::to_string(split_group) + " has " + std::to_string(children.size()) + " children");
    for (std::size_t i = 0; i < parts->size(); ++i) {
      trail.push_back(static_cast<int>(i));
      prove((*parts)[i], side == 0 ? children[i] : g, side == 1 ? children[i] : h, trail, pc, ctx);
      trail.pop_back();
    }
  }

  // The first control point at which the separation claim fails, or -1.
  int separation_fails_at(const Vec3E& n, std::uint32_t g, std::uint32_t h, const PieceContext& pc,
                          CheckContext& ctx) {
    // Integer direction: ñ = L n, L > 0.  (Scratch integers are members.)
    Z& L = z_.L;
    Z& f = z_.f;
    Z* nn = z_.nn;
    mpz_set_ui(L.v, 1);
    for (int r = 0; r < 3; ++r) mpz_lcm(L.v, L.v, den(n[r]));
    for (int r = 0; r < 3; ++r) {
      mpz_divexact(f.v, L.v, den(n[r]));
      mpz_mul(nn[r].v, num(n[r]), f.v);
    }
    const std::vector<std::uint32_t>& va = ctx.groups[0].vertices(g, scratch_a_, cache_budget_);
    const std::vector<std::uint32_t>& vb = ctx.groups[1].vertices(h, scratch_b_, cache_budget_);
    const Coords& ca = ctx.data[0]->coords;
    const Coords& cb = ctx.data[1]->coords;
    Z* alpha = z_.alpha;
    Z* beta = z_.beta;
    Z &mina = z_.mina, &minb = z_.minb, &lhs = z_.lhs, &t = z_.t;
    for (std::size_t l = 0; l < pc.ints.count; ++l) {
      const Z* N = &pc.ints.v[24 * l];
      // alpha_c = sum_r ñ_r Ña[4r + c];  beta = -(sum_r ñ_r Ñb[4r + c]) (so
      // max over b becomes a min).
      for (int col = 0; col < 4; ++col) {
        mpz_mul(alpha[col].v, nn[0].v, N[col].v);
        mpz_addmul(alpha[col].v, nn[1].v, N[4 + col].v);
        mpz_addmul(alpha[col].v, nn[2].v, N[8 + col].v);
        mpz_mul(beta[col].v, nn[0].v, N[12 + col].v);
        mpz_addmul(beta[col].v, nn[1].v, N[16 + col].v);
        mpz_addmul(beta[col].v, nn[2].v, N[20 + col].v);
        mpz_neg(beta[col].v, beta[col].v);
      }
      // min_x n.(Ña x̂) > max_y n.(Ñb ŷ), times D_a D_b > 0:
      //   D_b min(alpha.X) + D_a min(beta.Y) + D_a D_b (alpha_3 + beta_3) > 0.
      min_dot(alpha, ca, va.data(), va.size(), mina.v);
      min_dot(beta, cb, vb.data(), vb.size(), minb.v);
      mpz_add(t.v, alpha[3].v, beta[3].v);
      mpz_mul(lhs.v, t.v, ctx.dadb.v);
      mpz_addmul(lhs.v, cb.D.v, mina.v);
      mpz_addmul(lhs.v, ca.D.v, minb.v);
      if (pc.margins && sgn(ctx.margin) == 0) {
        // Only the penalty, in integers: lhs den > D_a D_b Q_l sum_r |ñ_r| num_r
        // (the rational condition below, times den > 0).
        mpz_set_ui(t.v, 0);
        for (int r = 0; r < 3; ++r) {
          mpz_abs(f.v, nn[r].v);
          mpz_addmul(t.v, f.v, pc.penalty_num[r].v);
        }
        mpz_mul(t.v, t.v, ctx.dadb.v);
        mpz_mul(t.v, t.v, pc.ints.qz[l].v);
        mpz_mul(f.v, lhs.v, pc.penalty_den.v);
        if (mpz_cmp(f.v, t.v) <= 0) return static_cast<int>(l);
        continue;
      }
      if (pc.margins) {
        // lhs = D_a D_b L Q_l (gap); the claim needs
        // gap > W_l |n| margin + sum_i |n_i| penalty_i, i.e.
        // lhs - S pen > 0 and (lhs - S pen)^2 > (S W_l)^2 |ñ|^2 margin^2
        // with S = D_a D_b Q_l, pen = sum_i |ñ_i| penalty_i.
        const Exact scale = from_z(ctx.dadb.v, Z(1).v) * pc.ints.q[l];
        Exact pen = 0, n2 = 0;
        for (int r = 0; r < 3; ++r) {
          const Exact nr = from_z(nn[r].v, Z(1).v);
          pen += CGAL::abs(nr) * pc.penalty[r];
          n2 += nr * nr;
        }
        const Exact gap = from_z(lhs.v, Z(1).v) - scale * pen;
        if (sgn(gap) <= 0) return static_cast<int>(l);
        if (sgn(ctx.margin) > 0) {
          const Exact rhs = scale * pc.ints.w[l] * ctx.margin;
          if (gap * gap <= rhs * rhs * n2) return static_cast<int>(l);
        }
        continue;
      }
      if (mpz_sgn(lhs.v) <= 0) return static_cast<int>(l);
    }
    return -1;
  }
};

// Deepest nesting of arrays and objects in a JSON text (outside strings).
std::size_t nesting(const std::string& text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    else if ((c == ']' || c == '}') && depth > 0) --depth;
  }
  return deepest;
}

}  // namespace

CheckOutcome check_certificate(const Scene& scene, const nlohmann::json& certificate, const std::string& source) {
  // The checker models only rational Bezier motions without tolerance or
  // clearance: anything else would be checked against a motion other than
  // the scene's.
  if (const std::string why = uncertifiable(scene); !why.empty())
    throw InputError(source + ": certificates do not cover this scene: " + why);
  return Checker(scene, source).run(certificate);
}

nlohmann::json parse_certificate_text(const std::string& text, const std::string& source) {
  if (nesting(text) > kMaxJsonNesting)
    throw InputError(source + ": document: nested deeper than " + std::to_string(kMaxJsonNesting) + " levels");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();
    const std::size_t bracket = what.find("] ");  // drop "[json.exception.parse_error.101] "
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what.erase(0, bracket + 2);
    for (char& ch : what)
      if (static_cast<unsigned char>(ch) < 0x20) ch = ' ';
    throw InputError(source + ": not JSON: " + what);
  }
}

nlohmann::json read_certificate_file(const std::string& path) {
  // Only a regular file, and at most kMaxFileBytes of it.
  const std::string text = read_regular_file(path, kMaxFileBytes);
  return parse_certificate_text(text, path);
}

namespace detail {

Exact min_dot_for_testing(const std::array<Exact, 3>& alpha, const std::vector<Vec3E>& points, int path) {
  if (points.empty()) throw std::invalid_argument("min_dot_for_testing: no points");
  const Coords c = make_coords(points);
  // alpha . x = (ã . X) / (L D) with ã = L alpha integer.
  Z L(1), f, a[3], out;
  for (int i = 0; i < 3; ++i) mpz_lcm(L.v, L.v, den(alpha[i]));
  for (int i = 0; i < 3; ++i) {
    mpz_divexact(f.v, L.v, den(alpha[i]));
    mpz_mul(a[i].v, num(alpha[i]), f.v);
  }
  std::vector<std::uint32_t> ids(points.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  min_dot(a, c, ids.data(), ids.size(), out.v, path);
  mpz_mul(f.v, L.v, c.D.v);
  return from_z(out.v, f.v);
}

std::vector<std::array<Exact, 25>> joint_control_points(const Body& a, const Body& b, const Exact& ua,
                                                        const Exact& ub) {
  if (!(sgn(ua) >= 0 && ua < ub && ub <= 1)) throw std::invalid_argument("joint_control_points: need 0 <= ua < ub <= 1");
  return restrict_curve(joint_curve(a, b), ua, ub);
}

}  // namespace detail

}  // namespace tmcert::certificate
