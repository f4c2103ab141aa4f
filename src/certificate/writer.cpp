#include "src/certificate/writer.h"

#include "src/certificate/algebraic_witness.h"
#include "src/certificate/check.h"
#include "src/certificate/exact_claims.h"
#include "src/scene/solid.h"
#include "kernels/separation.h"
#include "src/motion/bezier.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <functional>
#include <iterator>
#include <random>
#include <sstream>
#include <unordered_map>

namespace tmcert::certificate {

namespace {

using json = nlohmann::json;
using CurveE = HomogeneousCurve<Exact, 2>;
using CurveI = HomogeneousCurve<Interval, 2>;
constexpr std::size_t kWeight = 24;  // index of the weight in a joint control point

// Bisections of a cleared piece before giving up (each halves the piece).
constexpr int kMaxExtraDepth = 24;
// Iterations of the direction search for one group pair: many for small
// groups, few for large ones (a large pair that does not separate quickly
// is cheaper to split).
constexpr int kDirectionIterations = 48;
constexpr int kDirectionIterationsLarge = 6;
constexpr std::size_t kLargeGroup = 64;  // vertices of both groups together

// A direction rounded to about 20 significant bits: shorter numbers in the
// certificate and faster exact checks; the certification decides either way.
std::array<double, 3> rounded(const std::array<double, 3>& n) {
  const double m = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
  if (!(m > 0) || !std::isfinite(m)) return n;
  const double unit = std::ldexp(1.0, std::ilogb(m) - 20);
  return {std::nearbyint(n[0] / unit) * unit, std::nearbyint(n[1] / unit) * unit, std::nearbyint(n[2] / unit) * unit};
}

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

bool moves(const Body& b) { return b.motion && b.motion->degree() >= 1; }

Motion motion_or_identity(const Body& b) {
  if (b.motion) return *b.motion;
  Motion m;
  m.control_points = {kIdentity};
  m.weights = {Exact(1)};
  return m;
}

// The check's parameter interval (docs/certificate-format.md).
std::pair<Exact, Exact> check_interval(const Body& a, const Body& b) {
  if (moves(a)) return {a.motion->t0, a.motion->t1};
  if (moves(b)) return {b.motion->t0, b.motion->t1};
  if (a.motion) return {a.motion->t0, a.motion->t1};
  return {Exact(0), Exact(1)};
}

Vec3E apply(const Mat34E& m, const Vec3E& x) {
  Vec3E y;
  for (int i = 0; i < 3; ++i) y[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return y;
}

Mat34E pose(const Body& b, const Exact& t) {
  if (!b.motion) return kIdentity;
  const Motion& m = *b.motion;
  return evaluate<1>(homogeneous_curve(m), (t - m.t0) / (m.t1 - m.t0));
}

json rational(const Exact& q) { return to_string(q); }

json vec(const Vec3E& v) { return json::array({rational(v[0]), rational(v[1]), rational(v[2])}); }

// ------------------------------------------------------------------ groups

// A body's elements, their vertices numbered once, and a binary tree of
// groups over them (median splits of the element centroids, preorder
// numbering: children after their parent).
struct BodyGroups {
  std::vector<std::vector<Vec3E>> elements;
  PointIds ids;
  std::vector<std::vector<std::uint32_t>> element_vertices;
  std::vector<std::array<int, 2>> children;          // {-1, -1} for a leaf
  std::vector<int> element;                          // a leaf's element, else -1
  std::vector<std::vector<std::uint32_t>> vertices;  // sorted vertex ids under the group

  explicit BodyGroups(const Body& body) : elements(certificate::elements(body)) {
    element_vertices.resize(elements.size());
    std::vector<std::array<double, 3>> centroid(elements.size());
    for (std::size_t e = 0; e < elements.size(); ++e) {
      std::array<double, 3> c{0, 0, 0};
      for (const Vec3E& v : elements[e]) {
        element_vertices[e].push_back(ids.id(v));
        for (int i = 0; i < 3; ++i) c[i] += CGAL::to_double(v[i]) / elements[e].size();
      }
      centroid[e] = c;
    }
    std::vector<int> order(elements.size());
    std::iota(order.begin(), order.end(), 0);
    if (!order.empty()) build(order, 0, order.size(), centroid);
  }

  int build(std::vector<int>& order, std::size_t lo, std::size_t hi, const std::vector<std::array<double, 3>>& c) {
    const int g = static_cast<int>(children.size());
    children.push_back({-1, -1});
    element.push_back(-1);
    vertices.emplace_back();
    if (hi - lo == 1) {
      element[g] = order[lo];
      std::vector<std::uint32_t> v = element_vertices[order[lo]];
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
      vertices[g] = std::move(v);
      return g;
    }
    std::array<double, 3> mn{HUGE_VAL, HUGE_VAL, HUGE_VAL}, mx{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::size_t k = lo; k < hi; ++k)
      for (int i = 0; i < 3; ++i) {
        mn[i] = std::min(mn[i], c[order[k]][i]);
        mx[i] = std::max(mx[i], c[order[k]][i]);
      }
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (mx[i] - mn[i] > mx[axis] - mn[axis]) axis = i;
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(order.begin() + lo, order.begin() + mid, order.begin() + hi,
                     [&](int x, int y) { return c[x][axis] < c[y][axis] || (c[x][axis] == c[y][axis] && x < y); });
    const int left = build(order, lo, mid, c);
    const int right = build(order, mid, hi, c);
    children[g] = {left, right};
    std::vector<std::uint32_t> v;
    std::set_union(vertices[left].begin(), vertices[left].end(), vertices[right].begin(), vertices[right].end(),
                   std::back_inserter(v));
    vertices[g] = std::move(v);
    return g;
  }

  json to_json() const {
    json out = json::array();
    for (std::size_t g = 0; g < children.size(); ++g) {
      if (element[g] >= 0) out.push_back({{"elements", json::array({element[g]})}});
      else out.push_back({{"children", json::array({children[g][0], children[g][1]})}});
    }
    return out;
  }
};

// ------------------------------------------------------------------ proofs

// The two bodies' vertices under the control points of one piece: interval
// enclosures of the homogeneous images (N_l x^, not divided by the weight)
// for the certification, and doubles of the placed points for the search of
// a direction.
struct PieceImages {
  int count = 0;
  std::array<std::vector<std::array<Interval, 3>>, 2> box;   // [body][l * V + v]
  std::array<std::vector<std::array<double, 3>>, 2> point;   // same layout
  std::array<std::size_t, 2> size{};
};

struct Prover {
  const std::array<const BodyGroups*, 2> groups;
  std::array<std::vector<std::array<Interval, 3>>, 2> vertex_box;  // enclosures of the exact vertices
  WriteStats& stats;
  mutable std::array<int, 2> failed{-1, -1};  // the last two elements found inseparable
  // For the current piece: does the exact "no contact" claim hold for two
  // elements (exact_claims.h)?  Tried where no separating plane is found.
  mutable std::function<bool(int, int)> no_contact;

  Prover(const BodyGroups& a, const BodyGroups& b, WriteStats& s) : groups{&a, &b}, stats(s) {
    for (int k = 0; k < 2; ++k) {
      const PointIds& ids = groups[k]->ids;
      for (std::size_t v = 0; v < ids.size(); ++v) {
        const Vec3E& p = ids.point(static_cast<std::uint32_t>(v));
        vertex_box[k].push_back({to_interval(p[0]), to_interval(p[1]), to_interval(p[2])});
      }
    }
  }

  PieceImages images(const CurveI& piece) const {
    PieceImages im;
    im.count = static_cast<int>(piece.size());
    RoundingGuard guard;
    for (int k = 0; k < 2; ++k) {
      const std::size_t V = vertex_box[k].size();
      im.size[k] = V;
      im.box[k].resize(piece.size() * V);
      im.point[k].resize(piece.size() * V);
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
  bool certify(const PieceImages& im, const std::array<double, 3>& n, int g, int h) const {
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
    }
    return true;
  }

  static double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  // A direction separating the swept control points of groups g and h, by
  // GJK toward the point of least norm in the hull of the differences (any
  // direction would do: the certification decides).
  std::optional<std::array<double, 3>> separate(const PieceImages& im, int g, int h) const {
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
  std::optional<Vec3E> separate_exactly(const CurveE& piece, int g, int h,
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

  // The proof of the pair (g, h) on the piece, or nothing.
  // The direction an earlier piece found for a pair of groups (neighbouring
  // pieces mostly share them).
  mutable std::unordered_map<std::uint64_t, std::optional<std::array<double, 3>>> memory;

  std::optional<json> prove(const PieceImages& im, const std::function<const CurveE&()>& exact, int g, int h) const {
    const std::uint64_t key = static_cast<std::uint64_t>(g) << 32 | static_cast<std::uint32_t>(h);
    const auto remembered = memory.find(key);
    std::optional<std::array<double, 3>> n;
    if (remembered != memory.end() && remembered->second && certify(im, *remembered->second, g, h))
      n = remembered->second;
    else
      n = separate(im, g, h);
    if (n) memory[key] = n;
    if (n) {
      ++stats.separations;
      return json{{"sep", vec({Exact((*n)[0]), Exact((*n)[1]), Exact((*n)[2])})}};
    }
    const BodyGroups& A = *groups[0];
    const BodyGroups& B = *groups[1];
    const bool leaf_a = A.element[g] >= 0, leaf_b = B.element[h] >= 0;
    if (leaf_a && leaf_b) {
      if (auto n = separate_exactly(exact(), g, h, std::nullopt)) {
        ++stats.separations;
        ++stats.exact_separations;
        return json{{"sep", vec(*n)}};
      }
      if (no_contact && no_contact(A.element[g], B.element[h])) {
        ++stats.exact_claims;
        return json{{"exact", "no_contact"}};
      }
      failed = {A.element[g], B.element[h]};
      return std::nullopt;
    }
    const int side = leaf_a ? 1 : leaf_b ? 0 : (A.vertices[g].size() >= B.vertices[h].size() ? 0 : 1);
    json parts = json::array();
    for (int c : side == 0 ? A.children[g] : B.children[h]) {
      std::optional<json> p = side == 0 ? prove(im, exact, c, h) : prove(im, exact, g, c);
      if (!p) return std::nullopt;
      parts.push_back(std::move(*p));
    }
    return json{{"split", side}, {"parts", std::move(parts)}};
  }
};

// ------------------------------------------------------------------ witness

// Weights (one per vertex, >= 0, sum 1) placing the element's vertices
// under `m` exactly at p, if there are any among the vertices, pairs and fan
// triangles of the element.
std::optional<std::vector<Exact>> weights_at(const std::vector<Vec3E>& element, const Mat34E& m, const Vec3E& p) {
  std::vector<Vec3E> P;
  for (const Vec3E& v : element) P.push_back(apply(m, v));
  const std::size_t n = P.size();
  auto sub = [](const Vec3E& a, const Vec3E& b) { return Vec3E{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto dotE = [](const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto valid = [&](const std::vector<Exact>& w) {
    Vec3E s{0, 0, 0};
    Exact total(0);
    for (std::size_t i = 0; i < n; ++i) {
      if (w[i] < 0) return false;
      total += w[i];
      for (int k = 0; k < 3; ++k) s[k] += w[i] * P[i][k];
    }
    return total == 1 && s == p;
  };
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Exact> w(n, Exact(0));
    w[i] = 1;
    if (valid(w)) return w;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3E d = sub(P[j], P[i]);
      const Exact dd = dotE(d, d);
      if (dd == 0) continue;
      const Exact s = dotE(sub(p, P[i]), d) / dd;
      std::vector<Exact> w(n, Exact(0));
      w[i] = 1 - s;
      w[j] = s;
      if (valid(w)) return w;
    }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec3E e1 = sub(P[i], P[0]), e2 = sub(P[i + 1], P[0]), r = sub(p, P[0]);
    const Exact a11 = dotE(e1, e1), a12 = dotE(e1, e2), a22 = dotE(e2, e2);
    const Exact det = a11 * a22 - a12 * a12;
    if (det == 0) continue;
    const Exact b1 = dotE(r, e1), b2 = dotE(r, e2);
    const Exact x = (b1 * a22 - b2 * a12) / det, y = (a11 * b2 - a12 * b1) / det;
    std::vector<Exact> w(n, Exact(0));
    w[0] = 1 - x - y;
    w[i] = x;
    w[i + 1] = y;
    if (valid(w)) return w;
  }
  return std::nullopt;
}

// The elements a witness feature name ("<body> polygon 2", "<body> segment
// 0 end 1", "<body> point 3") can stand for.
std::vector<int> named_elements(const Body& body, const std::string& feature) {
  std::string rest = feature.substr(std::min(feature.size(), body.name.size() + 1));
  std::istringstream in(rest);
  std::string kind;
  int index = -1;
  in >> kind >> index;
  std::vector<int> out;
  const int P = static_cast<int>(body.pieces.size()), S = static_cast<int>(body.segments.size());
  if (kind == "polygon") {
    for (int e = 0; e < P; ++e)
      if (body.pieces[e].polygon == index) out.push_back(e);
  } else if (kind == "segment") {
    out.push_back(P + index);
  } else if (kind == "point") {
    out.push_back(P + S + index);
  }
  return out;
}

std::vector<std::vector<Vec3E>> placed_pieces(const Body& solid, const Mat34E& m) {
  std::vector<std::vector<Vec3E>> out;
  for (const ConvexPiece& piece : solid.pieces) {
    std::vector<Vec3E> poly;
    for (const Vec3E& v : piece.vertices) poly.push_back(apply(m, v));
    out.push_back(std::move(poly));
  }
  return out;
}

// A ray direction from p whose crossings with the placed pieces of `solid`
// are well defined, from a fixed sequence of directions, and whether p is
// inside (an odd count for some shell: the inside is the union of the
// shells' insides).
std::optional<std::pair<Vec3E, bool>> ray_from(const Body& solid, const std::vector<std::vector<Vec3E>>& polygons,
                                               const Vec3E& p) {
  const std::vector<int> polygon_shell = polygon_shells(solid);
  std::vector<int> shell;
  for (const ConvexPiece& piece : solid.pieces) shell.push_back(polygon_shell[piece.polygon]);
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> coordinate(-97, 97);
  for (int attempt = 0; attempt < 200; ++attempt) {
    Vec3E d;
    if (attempt == 0) d = {Exact(1), Exact(1, 3), Exact(1, 7)};
    else d = {Exact(coordinate(rng), 89), Exact(coordinate(rng), 83), Exact(coordinate(rng), 79)};
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
    if (auto count = ray_crossings(polygons, shell, p, d))
      return std::pair{d, std::any_of(count->begin(), count->end(), [](int c) { return c % 2 != 0; })};
  }
  return std::nullopt;
}

bool singular(const Mat34E& m) {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
             m[2] * (m[4] * m[9] - m[5] * m[8]) == 0;
}

// ------------------------------------------------------------------ one check

struct CheckWriter {
  const Scene& scene;
  const CheckResult& r;
  const Body& a;
  const Body& b;
  WriteStats& stats;
  std::pair<Exact, Exact> interval;
  CurveE joint;

  Exact scene_t(std::uint64_t index, int depth) const {
    CGAL::Gmpz den;
    mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
    const Exact u(CGAL::Gmpz(static_cast<unsigned long>(index)), den);
    return interval.first + u * (interval.second - interval.first);
  }

  Exact curve_u(std::uint64_t index, int depth) const {
    CGAL::Gmpz den;
    mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
    return Exact(CGAL::Gmpz(static_cast<unsigned long>(index)), den);
  }

  // Exact claims for the piece [u0, u1] of the curve (before `before` when
  // given): the scene's motions as polynomials, built once per check.
  mutable std::unique_ptr<CheckMotions> motions;
  void set_no_contact(const Prover& prover, const Exact& u0, const Exact& u1, const RealRoot* before) const {
    if (!motions) motions = std::make_unique<CheckMotions>(a, b);
    prover.no_contact = [this, &prover, u0, u1, before](int ea, int eb) {
      try {
        return no_contact_error(*motions, prover.groups[0]->elements[ea], prover.groups[1]->elements[eb], u0, u1,
                                before)
            .empty();
      } catch (const ResourceLimit&) {
        return false;  // not proven: the writer bisects or fails as without the claim
      }
    };
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw ResourceLimit("certificate: " + a.name + " x " + b.name + ": " + what);
  }

  // Pieces covering the cleared part of the parameter interval: the
  // search's pieces, or the whole interval for a check decided without a
  // search.
  // (The search reports its pieces in the order its tasks finish; they are
  // disjoint, so sorting puts them in parameter order.)
  std::vector<CoverPiece> cover() const {
    if (r.verdict == Verdict::Safe && r.cleared.empty()) return {CoverPiece{0, 0}};
    std::vector<std::pair<Exact, CoverPiece>> sorted;
    for (const CoverPiece& c : r.cleared)
      if (r.verdict != Verdict::Collision || scene_t(c.index + 1, c.depth) <= r.first_contact->first)
        sorted.emplace_back(scene_t(c.index, c.depth), c);
    std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<CoverPiece> out;
    for (const auto& [t, c] : sorted) out.push_back(c);
    return out;
  }

  // The exact control points of piece [index, index + 1] / 2^depth.
  CurveE exact_piece(std::uint64_t index, int depth) const {
    CurveE piece = joint, left, right;
    for (int level = depth - 1; level >= 0; --level) {
      split_half(piece, left, right);
      piece = (index >> level) & 1 ? std::move(right) : std::move(left);
    }
    return piece;
  }

  void prove_piece(const Prover& prover, const CurveI& piece, std::uint64_t index, int depth, int extra,
                   json& pieces) {
    const PieceImages im = prover.images(piece);
    std::optional<CurveE> exact;
    const std::function<const CurveE&()> exact_of = [&]() -> const CurveE& {
      if (!exact) exact = exact_piece(index, depth);
      return *exact;
    };
    set_no_contact(prover, curve_u(index, depth), curve_u(index + 1, depth), nullptr);
    if (std::optional<json> proof = prover.prove(im, exact_of, 0, 0)) {
      ++stats.pieces;
      pieces.push_back({{"t", json::array({rational(scene_t(index, depth)), rational(scene_t(index + 1, depth))})},
                        {"proof", std::move(*proof)}});
      return;
    }
    if (extra == 0) ++stats.bisections;
    if (extra >= kMaxExtraDepth || depth >= 62)
      fail("no separation proof for the cleared piece [" + to_string(scene_t(index, depth)) + ", " +
           to_string(scene_t(index + 1, depth)) + "] after " + std::to_string(extra) + " bisections (elements " +
           std::to_string(prover.failed[0]) + " and " + std::to_string(prover.failed[1]) + ")");
    CurveI left, right;
    {
      RoundingGuard guard;
      split_half(piece, left, right);
    }
    prove_piece(prover, left, 2 * index, depth + 1, extra + 1, pieces);
    prove_piece(prover, right, 2 * index + 1, depth + 1, extra + 1, pieces);
  }

  json witness() const {
    const Witness& w = *r.witness;
    if (w.root) return algebraic_witness(w);
    json out{{"t", rational(w.t)}, {"point", vec(w.point)}};
    const Body* bodies[2] = {&a, &b};
    const char* keys[2] = {"a", "b"};
    for (int k = 0; k < 2; ++k) {
      const Body& body = *bodies[k];
      const std::string& feature = w.features[k];
      const Mat34E m = pose(body, w.t);
      if (feature == body.name + " interior") {
        auto ray = ray_from(body, placed_pieces(body, m), w.point);
        if (!ray || !ray->second) fail("the interior witness could not be confirmed by a ray");
        out[keys[k]] = {{"interior", {{"ray", vec(ray->first)}}}};
        continue;
      }
      const std::vector<std::vector<Vec3E>> el = elements(body);
      bool found = false;
      for (int e : named_elements(body, feature)) {
        if (e < 0 || e >= static_cast<int>(el.size())) continue;
        if (auto weights = weights_at(el[e], m, w.point)) {
          json ws = json::array();
          for (const Exact& x : *weights) ws.push_back(rational(x));
          out[keys[k]] = {{"element", e}, {"weights", std::move(ws)}};
          found = true;
          break;
        }
      }
      if (!found) fail("the witness point was not found on " + feature);
    }
    return out;
  }

  // A witness at an irrational time: the root as the result gives it, and
  // on each side an element and the vertices of a sub-feature of it (a
  // vertex, an edge or the whole element) such that the two sub-features
  // provably share a point at the root (algebraic_witness.h).
  json algebraic_witness(const Witness& w) const {
    const AlgebraicTime& at = *w.root;
    const ClaimedRoot claim{at.root_of, at.lo, at.hi};
    if (const std::string error = root_claim_error(claim, interval.first, interval.second); !error.empty())
      fail("the witness time is not a valid root claim: " + error);
    RealRoot root = check_parameter_root(claim, interval.first, interval.second);
    const CheckMotions motions(a, b);
    const std::vector<std::vector<Vec3E>> el[2] = {elements(a), elements(b)};
    const std::vector<int> named[2] = {named_elements(a, w.features[0]), named_elements(b, w.features[1])};
    for (int ea : named[0])
      for (int eb : named[1]) {
        if (ea < 0 || eb < 0 || ea >= static_cast<int>(el[0].size()) || eb >= static_cast<int>(el[1].size())) continue;
        const std::vector<Vec3E>& va = el[0][ea];
        const std::vector<Vec3E>& vb = el[1][eb];
        for (const std::vector<int>& sa : sub_features(va.size()))
          for (const std::vector<int>& sb : sub_features(vb.size())) {
            std::vector<MovingPoint> pa, pb;
            for (int i : sa) pa.push_back(motions.place(0, va[i]));
            for (int j : sb) pb.push_back(motions.place(1, vb[j]));
            if (!ContactSolver::touch(pa, pb, root)) continue;
            json coefficients = json::array();
            for (const CGAL::Gmpz& c : at.root_of) coefficients.push_back(rational(Exact(c)));
            json box = json::array();
            for (const auto& range : *w.point_box) box.push_back(json::array({rational(range[0]), rational(range[1])}));
            return json{{"t", {{"root_of", coefficients}, {"interval", json::array({rational(at.lo), rational(at.hi)})}}},
                        {"point_box", box},
                        {"a", {{"element", ea}, {"vertices", sa}}},
                        {"b", {{"element", eb}, {"vertices", sb}}}};
          }
      }
    fail("no two sub-features of the witness's elements meet at its time " + at.approx);
  }

  // The part [from, T) before the witness time T of an exact first contact:
  // a proof tree (separations on [from, T] or [from, hi], exact claims
  // before T); on success, before_witness is set and the bracket becomes
  // [T, T] (rational T) or the witness's interval, narrowed.
  void before_witness(const Prover& prover, const Exact& from, json& out) const {
    const Witness& w = *r.witness;
    const Exact length = interval.second - interval.first;
    const Exact u0 = (from - interval.first) / length;
    RealRoot root;
    Exact u1;
    try {
      if (w.root) {
        root = check_parameter_root(ClaimedRoot{w.root->root_of, w.root->lo, w.root->hi}, interval.first,
                                    interval.second);
        RealRoot start = rational_root(u0);
        if (compare(start, root) != CGAL::SMALLER) return;
        // Narrow the root's interval to a small fraction of [from, root).
        for (int k = 0; k < 200 && !root.is_rational() && (root.lo <= u0 || (root.hi - root.lo) * 64 > root.lo - u0);
             ++k)
          refine(root);
        if (root.is_rational() || root.lo <= u0) return;
        u1 = root.hi;
      } else {
        u1 = (w.t - interval.first) / length;
        if (!(u0 < u1)) return;
        root = rational_root(u1);
      }
    } catch (const ExactLimit&) {
      return;
    }
    // The exact control points on [u0, u1] (de Casteljau at u1, then at
    // u0 / u1 on the left part).
    auto split_at = [](const CurveE& c, const Exact& s, bool keep_left) {
      CurveE p = c, left;
      const std::size_t n = p.size();
      left.reserve(n);
      CurveE right(n);
      for (std::size_t j = 0; j < n; ++j) {
        left.push_back(p[0]);
        right[n - 1 - j] = p[n - 1 - j];
        for (std::size_t i = 0; i + 1 < n - j; ++i)
          for (std::size_t e = 0; e < p[i].size(); ++e) p[i][e] = (1 - s) * p[i][e] + s * p[i + 1][e];
      }
      return keep_left ? left : right;
    };
    const CurveE piece = split_at(u1 == 1 ? joint : split_at(joint, u1, true), u0 / u1, false);
    const PieceImages im = prover.images(enclose(piece));
    const std::function<const CurveE&()> exact_of = [&]() -> const CurveE& { return piece; };
    set_no_contact(prover, u0, u1, &root);
    std::optional<json> proof = prover.prove(im, exact_of, 0, 0);
    prover.no_contact = nullptr;
    if (!proof) return;
    out["before_witness"] = {{"from", rational(from)}, {"proof", std::move(*proof)}};
    if (w.root) {
      const Exact lo = interval.first + root.lo * length, hi = interval.first + root.hi * length;
      out["witness"]["t"]["interval"] = json::array({rational(lo), rational(hi)});
      out["first_contact"] = json::array({rational(lo), rational(hi)});
    } else {
      out["first_contact"] = json::array({rational(w.t), rational(w.t)});
    }
  }

  // Start claims: one outside point per component of the other body for
  // each solid body with a regular pose at t0.
  json start() const {
    json out = json::array();
    const Body* bodies[2] = {&a, &b};
    for (int k = 0; k < 2; ++k) {
      const Body& solid = *bodies[k];
      const Body& other = *bodies[1 - k];
      if (!solid.solid) continue;
      const Mat34E ms = pose(solid, interval.first);
      if (singular(ms)) continue;
      const auto polygons = placed_pieces(solid, ms);
      const Mat34E mo = pose(other, interval.first);
      const auto el = elements(other);
      std::vector<std::size_t> parent(el.size());
      std::iota(parent.begin(), parent.end(), 0);
      auto find = [&](std::size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
      };
      std::map<Vec3E, std::size_t> owner;
      for (std::size_t e = 0; e < el.size(); ++e)
        for (const Vec3E& v : el[e]) {
          auto [it, fresh] = owner.emplace(v, e);
          if (!fresh) parent[find(e)] = find(it->second);
        }
      json points = json::array();
      for (std::size_t e = 0; e < el.size(); ++e) {
        if (find(e) != e) continue;
        const Vec3E p = apply(mo, el[e][0]);
        auto ray = ray_from(solid, polygons, p);
        if (!ray || ray->second)
          fail("no outside ray for element " + std::to_string(e) + " of " + other.name + " against solid " + solid.name);
        points.push_back({{"element", e}, {"vertex", 0}, {"ray", vec(ray->first)}});
      }
      out.push_back({{"solid", k == 0 ? "a" : "b"}, {"points", std::move(points)}});
    }
    return out;
  }

  json write() {
    json out{{"bodies", json::array({a.name, b.name})},
             {"verdict", to_string(r.verdict)},
             {"interval", json::array({rational(interval.first), rational(interval.second)})}};
    const BodyGroups ga(a), gb(b);
    out["groups"] = json::array({ga.to_json(), gb.to_json()});
    json pieces = json::array();
    const std::vector<CoverPiece> cover_pieces = cover();
    joint = joint_curve(motion_or_identity(a), motion_or_identity(b));
    const Prover prover(ga, gb, stats);
    if (!cover_pieces.empty()) {
      const CurveI root = enclose(joint);
      for (const CoverPiece& c : cover_pieces) {
        CurveI piece = root, left, right;
        {
          RoundingGuard guard;
          for (int level = c.depth - 1; level >= 0; --level) {
            split_half(piece, left, right);
            piece = (c.index >> level) & 1 ? std::move(right) : std::move(left);
          }
        }
        prove_piece(prover, piece, c.index, c.depth, 0, pieces);
      }
    }
    out["pieces"] = std::move(pieces);
    if (r.verdict == Verdict::Collision) {
      out["witness"] = witness();
      // The bracket the certificate proves: from the end of its pieces
      // (contiguous from t0).  An exact first contact (exact resolution)
      // also rests on "no contact between the piece's start and the
      // witness": carried as before_witness when its proof is found, and
      // then the bracket is the witness time itself.
      Exact clear_until = interval.first;
      for (const CoverPiece& c : cover_pieces)
        if (scene_t(c.index, c.depth) == clear_until) clear_until = scene_t(c.index + 1, c.depth);
      if (clear_until > r.first_contact->first) clear_until = r.first_contact->first;
      out["first_contact"] = json::array({rational(clear_until), rational(r.first_contact->second)});
      if (r.first_contact_exact) before_witness(prover, clear_until, out);
    }
    out["start"] = out["pieces"].empty() && !out.contains("before_witness") ? json::array() : start();
    json undecided = json::array();
    for (const UndecidedInterval& u : r.undecided) undecided.push_back(json::array({rational(u.t0), rational(u.t1)}));
    out["undecided"] = r.verdict == Verdict::Undecided ? std::move(undecided) : json::array();
    return out;
  }
};

}  // namespace

std::string uncertifiable(const Scene& scene) {
  for (const Body& b : scene.bodies) {
    if (b.trajectory)
      return "body \"" + b.name + "\" has a keyframe or piecewise motion that is not one rational Bezier curve";
    if (b.tolerance > 0) return "body \"" + b.name + "\" has a tolerance";
  }
  for (std::size_t k = 0; k < scene.checks.size(); ++k)
    if (scene.clearance_of(k) > 0) return "check " + std::to_string(k) + " has a clearance";
  return {};
}

std::string certificate_json(const Scene& scene, const SceneResult& result, WriteStats* stats) {
  if (!result.certified) throw InputError("--certificate: the fast kernel is not certified; use filtered or exact");
  if (const std::string why = uncertifiable(scene); !why.empty())
    throw InputError("--certificate: certificates do not cover this scene: " + why);
  const auto started = std::chrono::steady_clock::now();
  WriteStats local;
  WriteStats& s = stats ? *stats : local;
  json doc{{"format", "tmcert-certificate/1"}};
  json bodies = json::array();
  for (const Body& body : scene.bodies)
    bodies.push_back({{"name", body.name}, {"elements", elements(body).size()}});
  doc["scene_bodies"] = std::move(bodies);
  json checks = json::array();
  for (const CheckResult& r : result.checks) {
    const Body& a = scene.bodies[r.bodies[0]];
    const Body& b = scene.bodies[r.bodies[1]];
    CheckWriter w{scene, r, a, b, s, check_interval(a, b), {}};
    checks.push_back(w.write());
  }
  doc["checks"] = std::move(checks);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return doc.dump() + "\n";
}

}  // namespace tmcert::certificate
