// The certificate checker's separation test (check_separation.h): exact
// integer evaluation of the linear forms of separation claims, no floating
// point anywhere.
#include "src/certificate/check_separation.h"

#include <optional>
#include "src/certificate/check.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tmcert::certificate {

namespace check_internal {

// ---------------------------------------------------------------- integer coordinates

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
void min_dot(const Z* alpha, const Coords& c, const std::uint32_t* ids, std::size_t count, mpz_t out, int path) {
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

// ---------------------------------------------------------------- bodies

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

// ---------------------------------------------------------------- pieces

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

// ---------------------------------------------------------------- separations

std::optional<std::size_t> separation_fails_at(const Vec3E& n, const std::vector<std::uint32_t>& va, const Coords& ca,
                        const std::vector<std::uint32_t>& vb, const Coords& cb, const SeparationPiece& pc,
                        const Z& dadb, const Exact& margin, SeparationScratch& z) {
  // Integer direction: ñ = L n, L > 0.
  Z& L = z.L;
  Z& f = z.f;
  Z* nn = z.nn;
  mpz_set_ui(L.v, 1);
  for (int r = 0; r < 3; ++r) mpz_lcm(L.v, L.v, den(n[r]));
  for (int r = 0; r < 3; ++r) {
    mpz_divexact(f.v, L.v, den(n[r]));
    mpz_mul(nn[r].v, num(n[r]), f.v);
  }
  Z* alpha = z.alpha;
  Z* beta = z.beta;
  Z &mina = z.mina, &minb = z.minb, &lhs = z.lhs, &t = z.t;
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
    mpz_mul(lhs.v, t.v, dadb.v);
    mpz_addmul(lhs.v, cb.D.v, mina.v);
    mpz_addmul(lhs.v, ca.D.v, minb.v);
    if (pc.margins && sgn(margin) == 0) {
      // Only the penalty, in integers: lhs den > D_a D_b Q_l sum_r |ñ_r| num_r
      // (the rational condition below, times den > 0).
      mpz_set_ui(t.v, 0);
      for (int r = 0; r < 3; ++r) {
        mpz_abs(f.v, nn[r].v);
        mpz_addmul(t.v, f.v, pc.penalty_num[r].v);
      }
      mpz_mul(t.v, t.v, dadb.v);
      mpz_mul(t.v, t.v, pc.ints.qz[l].v);
      mpz_mul(f.v, lhs.v, pc.penalty_den.v);
      if (mpz_cmp(f.v, t.v) <= 0) return l;
      continue;
    }
    if (pc.margins) {
      // lhs = D_a D_b L Q_l (gap); the claim needs
      // gap > W_l |n| margin + sum_i |n_i| penalty_i, i.e.
      // lhs - S pen > 0 and (lhs - S pen)^2 > (S W_l)^2 |ñ|^2 margin^2
      // with S = D_a D_b Q_l, pen = sum_i |ñ_i| penalty_i.
      const Exact scale = from_z(dadb.v, Z(1).v) * pc.ints.q[l];
      Exact pen = 0, n2 = 0;
      for (int r = 0; r < 3; ++r) {
        const Exact nr = from_z(nn[r].v, Z(1).v);
        pen += CGAL::abs(nr) * pc.penalty[r];
        n2 += nr * nr;
      }
      const Exact gap = from_z(lhs.v, Z(1).v) - scale * pen;
      if (sgn(gap) <= 0) return l;
      if (sgn(margin) > 0) {
        const Exact rhs = scale * pc.ints.w[l] * margin;
        if (gap * gap <= rhs * rhs * n2) return l;
      }
      continue;
    }
    if (mpz_sgn(lhs.v) <= 0) return l;
  }
  return std::nullopt;
}

}  // namespace check_internal

using namespace check_internal;

std::vector<std::vector<Vec3E>> elements(const Body& body) {
  std::vector<std::vector<Vec3E>> out;
  out.reserve(body.pieces.size() + body.segments.size() + body.points.size());
  for (const ConvexPiece& piece : body.pieces) out.push_back(piece.vertices);
  for (const auto& s : body.segments) out.push_back({s[0], s[1]});
  for (const Vec3E& p : body.points) out.push_back({p});
  return out;
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

}  // namespace detail

}  // namespace tmcert::certificate
