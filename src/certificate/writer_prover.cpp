// The certificate writer's proofs (writer_prover.h).
#include "src/certificate/writer_prover.h"
#include "kernels/separation.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace tmcert::certificate::writer_internal {

Prover::Prover(const BodyGroups& a, const BodyGroups& b, WriteStats& s) : groups{&a, &b}, stats(s) {
  for (int k = 0; k < 2; ++k) {
    const PointIds& ids = groups[k]->ids;
    for (std::size_t v = 0; v < ids.size(); ++v) {
      const Vec3E& p = ids.point(static_cast<std::uint32_t>(v));
      vertex_box[k].push_back({to_interval(p[0]), to_interval(p[1]), to_interval(p[2])});
    }
  }
}

PieceImages Prover::images(const CurveI& piece) const {
  PieceImages im;
  im.count = static_cast<int>(piece.size());
  RoundingGuard guard;
  for (int k = 0; k < 2; ++k) {
    const std::size_t V = vertex_box[k].size();
    im.size[k] = V;
    im.box[k].resize(piece.size() * V);
    im.point[k].resize(piece.size() * V);
    if (k == 0)
      for (const auto& c : piece) im.weight.push_back(c[kWeight]);
    for (std::size_t l = 0; l < piece.size(); ++l) {
      const auto& c = piece[l];
      const double w = CGAL::to_double(c[kWeight]);
      for (std::size_t v = 0; v < V; ++v) {
        const auto& x = vertex_box[k][v];
        std::array<Interval, 3>& out = im.box[k][l * V + v];
        for (int i = 0; i < 3; ++i) {
          const std::size_t r = 12 * k + 4 * i;
          out[i] = c[r] * x[0] + c[r + 1] * x[1] + c[r + 2] * x[2] + c[r + 3];
          im.point[k][l * V + v][i] = CGAL::to_double(out[i]) / w;
        }
      }
    }
  }
  return im;
}

// True when, at every control point, n separates the group of body 1
// (above) from the group of body 2 (below), certified by intervals.
bool Prover::certify(const PieceImages& im, const std::array<double, 3>& n, int g, int h) const {
  RoundingGuard guard;
  const Interval n0(n[0]), n1(n[1]), n2(n[2]);
  for (int l = 0; l < im.count; ++l) {
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (std::uint32_t v : groups[0]->vertices[g]) {
      const auto& b = im.box[0][l * im.size[0] + v];
      low = std::min(low, (n0 * b[0] + n1 * b[1] + n2 * b[2]).inf());
    }
    for (std::uint32_t v : groups[1]->vertices[h]) {
      const auto& b = im.box[1][l * im.size[1] + v];
      high = std::max(high, (n0 * b[0] + n1 * b[1] + n2 * b[2]).sup());
    }
    if (!(low > high)) return false;  // also false on NaN
    if (im.margins()) {
      const Interval gap = Interval(low) - Interval(high);
      const Interval need = im.weight[l] * CGAL::sqrt(n0 * n0 + n1 * n1 + n2 * n2) * Interval(im.margin) +
                            CGAL::abs(n0) * im.penalty[0] + CGAL::abs(n1) * im.penalty[1] + CGAL::abs(n2) * im.penalty[2];
      if (!(gap.inf() > need.sup())) return false;
    }
  }
  return true;
}

double Prover::dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// A direction separating the swept control points of groups g and h, by
// GJK toward the point of least norm in the hull of the differences (any
// direction would do: the certification decides).
std::optional<std::array<double, 3>> Prover::separate(const PieceImages& im, int g, int h) const {
  const auto& va = groups[0]->vertices[g];
  const auto& vb = groups[1]->vertices[h];
  std::array<double, 3> z{0, 0, 0};
  for (int l = 0; l < im.count; ++l) {
    for (std::uint32_t v : va)
      for (int i = 0; i < 3; ++i) z[i] += im.point[0][l * im.size[0] + v][i] / (va.size() * im.count);
    for (std::uint32_t v : vb)
      for (int i = 0; i < 3; ++i) z[i] -= im.point[1][l * im.size[1] + v][i] / (vb.size() * im.count);
  }
  const int iterations = va.size() + vb.size() > kLargeGroup ? kDirectionIterationsLarge : kDirectionIterations;
  hull_detail::Simplex3 simplex;
  for (int iter = 0; iter < iterations; ++iter) {
    if (!(dot(z, z) > 0) || !std::isfinite(dot(z, z))) return std::nullopt;
    double best = HUGE_VAL;
    std::array<double, 3> s{};
    for (int l = 0; l < im.count; ++l) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      const std::array<double, 3>*pa = nullptr, *pb = nullptr;
      for (std::uint32_t v : va) {
        const auto& p = im.point[0][l * im.size[0] + v];
        if (const double d = dot(z, p); d < lo) lo = d, pa = &p;
      }
      for (std::uint32_t v : vb) {
        const auto& p = im.point[1][l * im.size[1] + v];
        if (const double d = dot(z, p); d > hi) hi = d, pb = &p;
      }
      if (lo - hi < best) {
        best = lo - hi;
        for (int i = 0; i < 3; ++i) s[i] = (*pa)[i] - (*pb)[i];
      }
    }
    if (best > 0) {
      if (const std::array<double, 3> r = rounded(z); certify(im, r, g, h)) return r;
      if (certify(im, z, g, h)) return z;
      // Positive in double but not certified: push a little further.
    }
    // GJK's step (Johnson's sub-algorithm, kernels/separation.h): z becomes
    // the point of least norm of the simplex grown by s.
    const double z2 = dot(z, z);
    if (z2 - dot(z, s) <= 1e-12 * z2) return std::nullopt;  // converged without separating
    simplex.p[simplex.n++] = s;
    if (!hull_detail::closest(simplex, z)) return std::nullopt;  // the origin is in the hull
  }
  return std::nullopt;
}

// For two elements whose clearance is below what intervals resolve:
// exact images of their vertices under the exact control points, tried
// with exact candidate directions (the double one, normals of the placed
// polygons, cross products of placed edges).
std::optional<Vec3E> Prover::separate_exactly(const CurveE& piece, int g, int h,
                                      const std::optional<std::array<double, 3>>& hint) const {
  std::array<std::vector<std::vector<Vec3E>>, 2> image;  // [body][l][vertex]
  const int elements[2] = {groups[0]->element[g], groups[1]->element[h]};
  for (int k = 0; k < 2; ++k) {
    const std::vector<Vec3E>& vertices = groups[k]->elements[elements[k]];
    for (const auto& c : piece) {
      std::vector<Vec3E> placed;
      for (const Vec3E& x : vertices) {
        Vec3E y;
        for (int i = 0; i < 3; ++i) {
          const std::size_t r = 12 * k + 4 * i;
          y[i] = c[r] * x[0] + c[r + 1] * x[1] + c[r + 2] * x[2] + c[r + 3];
        }
        placed.push_back(y);
      }
      image[k].push_back(std::move(placed));
    }
  }
  auto holds = [&](const Vec3E& n) {
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) return false;
    for (std::size_t l = 0; l < piece.size(); ++l) {
      std::optional<Exact> low, high;
      for (const Vec3E& p : image[0][l]) {
        const Exact d = n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
        if (!low || d < *low) low = d;
      }
      for (const Vec3E& p : image[1][l]) {
        const Exact d = n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
        if (!high || d > *high) high = d;
      }
      if (!(*low > *high)) return false;
    }
    return true;
  };
  auto sub = [](const Vec3E& a, const Vec3E& b) { return Vec3E{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto cross = [](const Vec3E& a, const Vec3E& b) {
    return Vec3E{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  std::vector<Vec3E> candidates;
  if (hint) candidates.push_back({Exact((*hint)[0]), Exact((*hint)[1]), Exact((*hint)[2])});
  for (std::size_t l = 0; l < piece.size(); ++l) {
    std::array<std::vector<Vec3E>, 2> edges;
    for (int k = 0; k < 2; ++k) {
      const std::vector<Vec3E>& p = image[k][l];
      if (p.size() >= 3) candidates.push_back(cross(sub(p[1], p[0]), sub(p[2], p[0])));
      for (std::size_t i = 0; i + 1 < p.size() || (p.size() > 2 && i + 1 == p.size()); ++i)
        edges[k].push_back(sub(p[(i + 1) % p.size()], p[i]));
    }
    for (const Vec3E& e : edges[0])
      for (const Vec3E& f : edges[1]) candidates.push_back(cross(e, f));
    // In the plane of a polygon (coplanar elements): normal x edge.
    for (int k = 0; k < 2; ++k) {
      const std::vector<Vec3E>& p = image[k][l];
      if (p.size() < 3) continue;
      const Vec3E normal = cross(sub(p[1], p[0]), sub(p[2], p[0]));
      for (int j = 0; j < 2; ++j)
        for (const Vec3E& e : edges[j]) candidates.push_back(cross(normal, e));
    }
    // Point to point, and the part of each such difference perpendicular
    // to an edge (segments in a common plane, a point beside a segment).
    for (const Vec3E& x : image[0][l])
      for (const Vec3E& y : image[1][l]) {
        const Vec3E w = sub(x, y);
        candidates.push_back(w);
        for (int k = 0; k < 2; ++k)
          for (const Vec3E& e : edges[k]) candidates.push_back(cross(cross(e, w), e));
      }
  }
  for (const Vec3E& n : candidates)
    for (const Vec3E& m : {n, Vec3E{-n[0], -n[1], -n[2]}})
      if (holds(m)) return m;
  return std::nullopt;
}

namespace {

template <class T>
void append_bytes(std::string& key, const T& x) {
  key.append(reinterpret_cast<const char*>(&x), sizeof x);
}

}  // namespace

int ProofNodes::separation(const std::array<double, 3>& n) {
  std::string key = "d";
  for (double x : n) append_bytes(key, x + 0.0);  // -0 as 0
  auto [it, fresh] = index.emplace(std::move(key), static_cast<int>(nodes.size()));
  if (fresh) {
    nodes.push_back({{"sep", integer_direction({Exact(n[0]), Exact(n[1]), Exact(n[2])})}});
    reusable.push_back({Reusable::kSeparation, 0, n, {}});
  }
  return it->second;
}

int ProofNodes::separation(const Vec3E& n) {
  json node{{"sep", integer_direction(n)}};
  auto [it, fresh] = index.emplace("q" + node.dump(), static_cast<int>(nodes.size()));
  if (fresh) {
    nodes.push_back(std::move(node));
    reusable.emplace_back();
  }
  return it->second;
}

int ProofNodes::exact_claim() {
  auto [it, fresh] = index.emplace("e", static_cast<int>(nodes.size()));
  if (fresh) {
    nodes.push_back({{"exact", "no_contact"}});
    reusable.emplace_back();
  }
  return it->second;
}

int ProofNodes::split(int side, const std::vector<int>& parts) {
  std::string key = "s";
  append_bytes(key, side);
  for (int p : parts) append_bytes(key, p);
  auto [it, fresh] = index.emplace(std::move(key), static_cast<int>(nodes.size()));
  if (fresh) {
    json node = json::array({side});
    for (int p : parts) node.push_back(p);
    nodes.push_back(std::move(node));
    reusable.push_back({Reusable::kSplit, side, {}, parts});
  }
  return it->second;
}

json ProofNodes::expand(int k) const {
  const json& n = nodes.at(static_cast<std::size_t>(k));
  if (!n.is_array()) return n;
  json parts = json::array();
  for (std::size_t i = 1; i < n.size(); ++i) parts.push_back(expand(n[i].get<int>()));
  return {{"split", n[0]}, {"parts", std::move(parts)}};
}

json ProofNodes::compact(const std::vector<json*>& roots) const {
  std::vector<char> used(nodes.size(), 0);
  std::vector<int> todo;
  for (const json* r : roots) todo.push_back(r->get<int>());
  while (!todo.empty()) {
    const int k = todo.back();
    todo.pop_back();
    if (used[k]) continue;
    used[k] = 1;
    if (nodes[k].is_array())
      for (std::size_t i = 1; i < nodes[k].size(); ++i) todo.push_back(nodes[k][i].get<int>());
  }
  std::vector<int> renumber(nodes.size(), -1);
  json out = json::array();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (!used[k]) continue;
    renumber[k] = static_cast<int>(out.size());
    json n = nodes[k];
    if (n.is_array())
      for (std::size_t i = 1; i < n.size(); ++i) n[i] = renumber[n[i].get<int>()];  // parts are earlier
    out.push_back(std::move(n));
  }
  for (json* r : roots) *r = renumber[r->get<int>()];
  return out;
}

json integer_direction(const Vec3E& n) {
  CGAL::Gmpz l(1), g(0), z[3];
  for (const Exact& x : n) mpz_lcm(l.mpz(), l.mpz(), x.denominator().mpz());
  for (int i = 0; i < 3; ++i) {
    z[i] = n[i].numerator() * (l / n[i].denominator());
    mpz_gcd(g.mpz(), g.mpz(), z[i].mpz());
  }
  json out = json::array();
  for (int i = 0; i < 3; ++i) {
    if (g > 1) z[i] /= g;
    if (mpz_fits_slong_p(z[i].mpz()) && sizeof(long) == 8) out.push_back(static_cast<std::int64_t>(mpz_get_si(z[i].mpz())));
    else out.push_back(to_string(Exact(z[i])));
  }
  return out;
}

std::optional<int> Prover::prove(const PieceImages& im, const std::function<const CurveE&()>& exact, int g, int h) const {
  const std::uint64_t key = static_cast<std::uint64_t>(g) << 32 | static_cast<std::uint32_t>(h);
  if (g == 0 && h == 0) ++proofs;
  const BodyGroups& A = *groups[0];
  const BodyGroups& B = *groups[1];
  path.push_back(key);
  struct Pop {
    std::vector<std::uint64_t>& path;
    ~Pop() { path.pop_back(); }
  } pop{path};
  // The parts of a split on `side`: the child on the path of the last
  // failure first.
  auto split = [&](int side, int old = -1) -> std::optional<int> {
    const std::array<int, 2>& c = side == 0 ? A.children[g] : B.children[h];
    auto pair = [&](int i) {
      return side == 0 ? std::pair{c[i], h} : std::pair{g, c[i]};
    };
    auto key_of = [](std::pair<int, int> p) {
      return static_cast<std::uint64_t>(p.first) << 32 | static_cast<std::uint32_t>(p.second);
    };
    const int first = hard.size() > path.size() && hard[path.size()] == key_of(pair(1)) ? 1 : 0;
    std::vector<int> parts(2);
    for (int i : {first, 1 - first}) {
      const auto [cg, ch] = pair(i);
      const std::optional<int> p = prove(im, exact, cg, ch);
      if (!p) return std::nullopt;
      parts[i] = *p;
    }
    if (old >= 0 && nodes.reusable[old].parts == parts) return old;
    return nodes.split(side, parts);
  };
  // The neighbouring piece's proof of this pair first.
  std::optional<int> follow;  // the side of a remembered split
  if (const auto was = last.find(key); was != last.end()) {
    const ProofNodes::Reusable& r = nodes.reusable[was->second];
    if (r.kind == ProofNodes::Reusable::kSeparation && certify(im, r.direction, g, h)) {
      ++stats.separations;
      return was->second;
    }
    if (r.kind == ProofNodes::Reusable::kSplit) {
      follow = r.side;
      if (proofs % kRetry != 0) {
        const std::optional<int> k = split(*follow, was->second);
        if (k) last[key] = *k;
        return k;
      }
    }
  }
  const auto remembered = memory.find(key);
  std::optional<std::array<double, 3>> n;
  if (remembered != memory.end() && remembered->second && certify(im, *remembered->second, g, h))
    n = remembered->second;
  else
    n = separate(im, g, h);
  if (n) memory[key] = n;
  if (n) {
    ++stats.separations;
    const int k = nodes.separation(*n);
    last[key] = k;
    return k;
  }
  const bool leaf_a = A.element[g] >= 0, leaf_b = B.element[h] >= 0;
  if (leaf_a && leaf_b) {
    // (The exact fallback knows no margins: general checks bisect instead.)
    if (auto n = im.margins() || !exact ? std::nullopt : separate_exactly(exact(), g, h, std::nullopt)) {
      ++stats.separations;
      ++stats.exact_separations;
      return nodes.separation(*n);
    }
    if (no_contact && no_contact(A.element[g], B.element[h])) {
      ++stats.exact_claims;
      return nodes.exact_claim();
    }
    failed = {A.element[g], B.element[h]};
    hard = path;
    return std::nullopt;
  }
  const int side = leaf_a ? 1 : leaf_b ? 0 : (A.vertices[g].size() >= B.vertices[h].size() ? 0 : 1);
  const std::optional<int> k = split(side);
  if (k) last[key] = *k;
  return k;
}

}  // namespace tmcert::certificate::writer_internal
