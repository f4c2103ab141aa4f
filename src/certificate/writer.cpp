#include "src/certificate/writer.h"

#include "src/certificate/algebraic_witness.h"
#include "src/certificate/check.h"
#include "src/certificate/motions.h"
#include "src/certificate/exact_claims.h"
#include "src/model/solid.h"
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
#include <set>
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

Motion motion_or_identity(const Body& b) {
  if (b.motion) return *b.motion;
  Motion m;
  m.control_points = {kIdentity};
  m.weights = {Exact(1)};
  return m;
}

// A check the plain format does not describe: a keyframe or piecewise
// motion, a tolerance or a clearance (docs/certificate-format.md, "Planner
// motions, tolerances and clearances").
bool general_check(const Body& a, const Body& b, const Exact& clearance) {
  return a.trajectory || b.trajectory || a.tolerance > 0 || b.tolerance > 0 || clearance > 0;
}

Vec3E apply(const Mat34E& m, const Vec3E& x) {
  Vec3E y;
  for (int i = 0; i < 3; ++i) y[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return y;
}

Mat34E pose(const Body& b, const Exact& t) {
  if (b.trajectory) {
    const std::optional<Mat34E> m = exact_pose_at(b, t);
    if (!m) throw ResourceLimit("certificate: the pose of " + b.name + " at t = " + to_string(t) + " is not exact");
    return *m;
  }
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
  // A general check (checker: general_piece): each separation must hold
  // with W_l |n| margin + sum_i |n_i| penalty_i to spare (upper bounds).
  std::vector<Interval> weight;  // W_l
  double margin = 0;
  std::array<double, 3> penalty{0, 0, 0};
  bool margins() const { return margin > 0 || penalty[0] > 0 || penalty[1] > 0 || penalty[2] > 0; }
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
      if (im.margins()) {
        const Interval gap = Interval(low) - Interval(high);
        const Interval need = im.weight[l] * CGAL::sqrt(n0 * n0 + n1 * n1 + n2 * n2) * Interval(im.margin) +
                              CGAL::abs(n0) * im.penalty[0] + CGAL::abs(n1) * im.penalty[1] + CGAL::abs(n2) * im.penalty[2];
        if (!(gap.inf() > need.sup())) return false;
      }
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
      // (The exact fallback knows no margins: general checks bisect instead.)
      if (auto n = im.margins() || !exact ? std::nullopt : separate_exactly(exact(), g, h, std::nullopt)) {
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
  } else if ((kind == "cylinder" || kind == "sphere") && body.primitive) {
    // A contact proven on a URDF cylinder or sphere (its true shape, inside
    // the body's polyhedron): any element of the polyhedron.
    for (int e = 0; e < P; ++e) out.push_back(e);
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

  bool general() const { return general_check(a, b, r.clearance); }

  // The scene interval of a cleared piece.
  std::pair<Exact, Exact> piece_times(const CoverPiece& c) const {
    if (c.timed) return {c.t0, c.t1};
    return {scene_t(c.index, c.depth), scene_t(c.index + 1, c.depth)};
  }

  // A general check's cover as scene intervals in order, cut at every join
  // of either body's motion (the checker wants each piece inside one
  // segment of each motion).
  std::vector<std::pair<Exact, Exact>> general_cover() const {
    std::vector<std::pair<Exact, Exact>> times;
    if (r.verdict == Verdict::Safe && r.cleared.empty()) times.push_back(interval);
    for (const CoverPiece& c : r.cleared) {
      const auto t = piece_times(c);
      if (r.verdict != Verdict::Collision || t.second <= r.first_contact->first) times.push_back(t);
    }
    std::sort(times.begin(), times.end());
    std::vector<Exact> joins;
    for (const Body* body : {&a, &b})
      if (body->trajectory)
        for (const MotionSegment& seg : body->trajectory->segments) joins.push_back(seg.t1);
    std::sort(joins.begin(), joins.end());
    std::vector<std::pair<Exact, Exact>> out;
    for (auto [lo, hi] : times) {
      for (const Exact& j : joins)
        if (lo < j && j < hi) {
          out.push_back({lo, j});
          lo = j;
        }
      out.push_back({lo, hi});
    }
    return out;
  }

  // A piece of a general check (the checker's general_piece): the joint
  // curve of the two exact restrictions, or one control point at the pose
  // boxes' centres with their radii as a penalty; bisected (the boxes
  // recomputed on each half) when no proof is found.
  // Returns false (having written the pieces before it) when a piece
  // cannot be proven and `partial` allows stopping there: a collision's
  // certificate may prove less of the time before its witness than the
  // verifier did (a tolerance's plane margin is coarser than the search's
  // metric balls); its first-contact bracket then starts earlier.
  bool prove_general(const Prover& prover, const Exact& ta, const Exact& tb, int extra, const Exact& margin,
                     const std::array<Exact, 4> (&bounds)[2], bool partial, json& pieces) {
    std::optional<PieceMotion> m[2];
    const Body* bodies[2] = {&a, &b};
    std::string why;
    for (int k = 0; k < 2 && why.empty(); ++k) m[k] = piece_motion(*bodies[k], ta, tb, why);
    auto bisect = [&](const std::string& what) {
      if (extra == 0) ++stats.bisections;
      if (extra >= kMaxExtraDepth) {
        if (partial) return false;
        fail(what + " after " + std::to_string(extra) + " bisections");
      }
      const Exact mid = (ta + tb) / 2;
      return prove_general(prover, ta, mid, extra + 1, margin, bounds, partial, pieces) &&
             prove_general(prover, mid, tb, extra + 1, margin, bounds, partial, pieces);
    };
    if (!why.empty()) {
      if (why.find("inside one segment") != std::string::npos) fail(why);
      return bisect(why);  // an enclosure too wide to be finite: smaller pieces
    }
    CurveE exact_curve;
    CurveI curve;
    std::array<double, 3> penalty{0, 0, 0};
    const bool exact = m[0]->exact && m[1]->exact;
    if (exact) {
      exact_curve = joint_curve(*m[0]->exact, *m[1]->exact);
      curve = enclose(exact_curve);
    } else {
      std::array<Interval, 25> c;
      std::array<Exact, 3> pen{Exact(0), Exact(0), Exact(0)};
      for (int k = 0; k < 2; ++k) {
        const PoseBox box = m[k]->exact ? control_box(*m[k]->exact) : m[k]->box;
        for (int e = 0; e < 12; ++e) c[12 * k + e] = to_interval(box.center[e]);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 4; ++j) pen[i] += box.radius[4 * i + j] * bounds[k][j];
      }
      c[kWeight] = Interval(1);
      curve = {c};
      for (int i = 0; i < 3; ++i) penalty[i] = to_interval(pen[i]).sup();
    }
    PieceImages im = prover.images(curve);
    im.margin = to_interval(margin).sup();
    im.penalty = penalty;
    const std::function<const CurveE&()> exact_of =
        exact ? std::function<const CurveE&()>([&]() -> const CurveE& { return exact_curve; }) : nullptr;
    if (std::optional<json> proof = prover.prove(im, exact_of, 0, 0)) {
      ++stats.pieces;
      pieces.push_back({{"t", json::array({rational(ta), rational(tb)})}, {"proof", std::move(*proof)}});
      return true;
    }
    return bisect("no separation proof for the cleared piece [" + to_string(ta) + ", " + to_string(tb) + "] (elements " +
                  std::to_string(prover.failed[0]) + " and " + std::to_string(prover.failed[1]) + ")");
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

  // A witness at an enclosed pose (a transcendental motion): an edge of one
  // named element crossing a triangle of the other, certain over the
  // checker's own pose boxes at t (motions.h).
  json enclosed_witness(const Witness& w) const {
    const Body* bodies[2] = {&a, &b};
    std::optional<PoseBox> box[2];
    for (int k = 0; k < 2; ++k) {
      box[k] = pose_box_at(*bodies[k], w.t);
      if (!box[k]) fail("the pose of " + bodies[k]->name + " at the witness's t = " + to_string(w.t) + " has no finite enclosure");
    }
    const std::vector<std::vector<Vec3E>> el[2] = {elements(a), elements(b)};
    for (int ea : named_elements(a, w.features[0]))
      for (int eb : named_elements(b, w.features[1])) {
        if (ea < 0 || eb < 0 || ea >= static_cast<int>(el[0].size()) || eb >= static_cast<int>(el[1].size())) continue;
        const int e[2] = {ea, eb};
        std::vector<RBox> placed[2];
        for (int k = 0; k < 2; ++k)
          for (const Vec3E& v : el[k][e[k]]) placed[k].push_back(place_box(*box[k], v));
        for (int edge_side = 0; edge_side < 2; ++edge_side) {
          const std::vector<RBox>& P = placed[edge_side];
          const std::vector<RBox>& T = placed[1 - edge_side];
          if (P.size() < 2 || T.size() < 3) continue;
          for (std::size_t i = 0; i < P.size(); ++i)
            for (std::size_t j = i + 1; j < P.size(); ++j)
              for (std::size_t x = 0; x < T.size(); ++x)
                for (std::size_t y = x + 1; y < T.size(); ++y)
                  for (std::size_t z = y + 1; z < T.size(); ++z) {
                    if (!certain_crossing(P[i], P[j], T[x], T[y], T[z])) continue;
                    json box_json = json::array();
                    for (const auto& range : *w.point_box)
                      box_json.push_back(json::array({rational(range[0]), rational(range[1])}));
                    json sides[2];
                    sides[edge_side] = {{"element", e[edge_side]}, {"vertices", json::array({i, j})}};
                    sides[1 - edge_side] = {{"element", e[1 - edge_side]}, {"vertices", json::array({x, y, z})}};
                    return json{{"t", rational(w.t)}, {"point_box", box_json}, {"a", sides[0]}, {"b", sides[1]}};
                  }
        }
      }
    fail("the enclosed witness at t = " + to_string(w.t) + " is not a certain edge-triangle crossing over the checker's pose boxes");
  }

  json witness() const {
    const Witness& w = *r.witness;
    if (w.root) return algebraic_witness(w);
    if (w.point_box) return enclosed_witness(w);
    json out{{"t", rational(w.t)}, {"point", vec(w.point)}};
    if (w.displacement) {
      out["displacement"] = vec(*w.displacement);
      out["displaced"] = w.displaced == 0 ? "a" : "b";
    }
    if (w.points) out["points"] = json::array({vec((*w.points)[0]), vec((*w.points)[1])});
    const Body* bodies[2] = {&a, &b};
    const char* keys[2] = {"a", "b"};
    for (int k = 0; k < 2; ++k) {
      const Body& body = *bodies[k];
      const std::string& feature = w.features[k];
      Mat34E m = pose(body, w.t);
      if (w.displacement && w.displaced == k)
        for (int i = 0; i < 3; ++i) m[4 * i + 3] += (*w.displacement)[i];
      const Vec3E& target = w.points ? (*w.points)[k] : w.point;
      // A point proven in a URDF cylinder or sphere lies in its body, the
      // solid polyhedron around it: an interior claim.
      const bool in_primitive = w.true_shape && body.primitive && feature.rfind(body.name + " ", 0) == 0 &&
                                (feature.find(" cylinder", body.name.size()) != std::string::npos ||
                                 feature.find(" sphere", body.name.size()) != std::string::npos);
      if (feature == body.name + " interior" || in_primitive) {
        auto ray = ray_from(body, placed_pieces(body, m), target);
        if (!ray || !ray->second) fail("the interior witness could not be confirmed by a ray");
        out[keys[k]] = {{"interior", {{"ray", vec(ray->first)}}}};
        continue;
      }
      const std::vector<std::vector<Vec3E>> el = elements(body);
      bool found = false;
      for (int e : named_elements(body, feature)) {
        if (e < 0 || e >= static_cast<int>(el.size())) continue;
        if (auto weights = weights_at(el[e], m, target)) {
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
    RealRoot root;
    std::optional<CheckMotions> general_motions;
    if (general()) {  // on the rational segment of each motion around the root
      const auto span = rational_span(a, b, at.lo, at.hi, interval.first, interval.second);
      if (!span) fail("the witness time is not inside one rational segment of both motions");
      std::string why;
      const auto ma = piece_motion(a, span->first, span->second, why);
      const auto mb = piece_motion(b, span->first, span->second, why);
      if (!ma || !mb || !ma->exact || !mb->exact) fail("the witness's segment is not rational: " + why);
      general_motions.emplace(*ma->exact, *mb->exact);
      root = check_parameter_root(claim, span->first, span->second);
    } else {
      root = check_parameter_root(claim, interval.first, interval.second);
    }
    const CheckMotions motions = general_motions ? *general_motions : CheckMotions(a, b);
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
  // each solid body with a regular pose at `at` (t0, or the start of a run
  // of pieces after an undecided interval: then with "t").
  void start(const Exact& at, json& out) const {
    const Body* bodies[2] = {&a, &b};
    for (int k = 0; k < 2; ++k) {
      const Body& solid = *bodies[k];
      const Body& other = *bodies[1 - k];
      if (!solid.solid) continue;
      const Mat34E ms = pose(solid, at);
      if (singular(ms)) continue;
      const auto polygons = placed_pieces(solid, ms);
      const Mat34E mo = pose(other, at);
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
      json entry{{"solid", k == 0 ? "a" : "b"}};
      if (at != interval.first) entry["t"] = rational(at);
      entry["points"] = std::move(points);
      out.push_back(std::move(entry));
    }
  }

  // Runs of pieces (in order) of an undecided check with a solid body that
  // start after an undecided interval where a body's pose is not exact:
  // start claims cannot be written there, so those pieces are not claimed
  // (they join the undecided intervals; proofs/partition.md §5).  `starts`
  // gets every run start (t0 included) whose pieces stay.
  template <class Piece, class Times>
  std::vector<Piece> claimable(const std::vector<Piece>& pieces, Times times, std::vector<Exact>& starts,
                               std::vector<std::pair<Exact, Exact>>& undecided) const {
    for (const UndecidedInterval& u : r.undecided) undecided.push_back({u.t0, u.t1});
    if (r.verdict != Verdict::Undecided) {
      if (!pieces.empty()) starts.push_back(interval.first);
      return pieces;
    }
    std::set<Exact> ends;
    for (const UndecidedInterval& u : r.undecided) ends.insert(u.t1);
    std::vector<Piece> out;
    bool dropping = false;
    std::optional<Exact> prev_end;
    for (const Piece& p : pieces) {
      const auto [ta, tb] = times(p);
      const bool run_start = !prev_end || *prev_end != ta || ends.count(ta);
      prev_end = tb;
      if (run_start) {
        dropping = (a.solid || b.solid) && ta != interval.first && (!exact_pose_at(a, ta) || !exact_pose_at(b, ta));
        if (!dropping) starts.push_back(ta);
      }
      if (!dropping) {
        out.push_back(p);
        continue;
      }
      undecided.push_back({ta, tb});
    }
    // In order, abutting ones joined.
    std::sort(undecided.begin(), undecided.end());
    std::vector<std::pair<Exact, Exact>> joined;
    for (const auto& u : undecided) {
      if (!joined.empty() && joined.back().second == u.first) joined.back().second = u.second;
      else joined.push_back(u);
    }
    undecided = std::move(joined);
    return out;
  }

  json write() {
    json out{{"bodies", json::array({a.name, b.name})},
             {"verdict", to_string(r.verdict)},
             {"interval", json::array({rational(interval.first), rational(interval.second)})}};
    const BodyGroups ga(a), gb(b);
    out["groups"] = json::array({ga.to_json(), gb.to_json()});
    json pieces = json::array();
    const bool gen = general();
    // The runs' starts (for start claims) and the undecided intervals, with
    // the runs no start claim can be written for.
    std::vector<Exact> starts;
    std::vector<std::pair<Exact, Exact>> undecided_times;
    const std::vector<CoverPiece> cover_pieces =
        gen ? std::vector<CoverPiece>{}
            : claimable(cover(), [&](const CoverPiece& c) { return piece_times(c); }, starts, undecided_times);
    const std::vector<std::pair<Exact, Exact>> general_pieces =
        gen ? claimable(general_cover(), [](const std::pair<Exact, Exact>& p) { return p; }, starts, undecided_times)
            : std::vector<std::pair<Exact, Exact>>{};
    if (!gen) joint = joint_curve(motion_or_identity(a), motion_or_identity(b));
    const Prover prover(ga, gb, stats);
    if (gen) {
      // Margins: the clearance, and each tolerance times how far a point of
      // its body can move per unit of metric (motions.h).  (No exact
      // no-contact claims: they decide the check's one rational curve.)
      Exact margin = r.clearance;
      std::array<Exact, 4> bounds[2];
      const Body* bodies[2] = {&a, &b};
      for (int k = 0; k < 2; ++k) {
        bounds[k] = coordinate_bounds(elements(*bodies[k]));
        if (bodies[k]->tolerance > 0)
          margin += bodies[k]->tolerance * displacement_bound(*bodies[k], elements(*bodies[k]));
      }
      const bool partial = r.verdict == Verdict::Collision;
      for (const auto& [ta, tb] : general_pieces)
        if (!prove_general(prover, ta, tb, 0, margin, bounds, partial, pieces)) break;
    } else if (!cover_pieces.empty()) {
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
      if (gen) {
        for (const json& p : out["pieces"]) {
          const std::string& lo = p["t"][0].get_ref<const std::string&>();
          if (Exact(lo) == clear_until) clear_until = Exact(p["t"][1].get<std::string>());
        }
      }
      for (const CoverPiece& c : cover_pieces)
        if (scene_t(c.index, c.depth) == clear_until) clear_until = scene_t(c.index + 1, c.depth);
      if (clear_until > r.first_contact->first) clear_until = r.first_contact->first;
      out["first_contact"] = json::array({rational(clear_until), rational(r.first_contact->second)});
      if (r.first_contact_exact && !gen) before_witness(prover, clear_until, out);
    }
    json start_claims = json::array();
    if (!out["pieces"].empty() || out.contains("before_witness")) {
      if (starts.empty() || starts.front() != interval.first) {
        if (r.verdict != Verdict::Undecided) start(interval.first, start_claims);  // before_witness alone
      }
      for (const Exact& at : starts) start(at, start_claims);
    }
    out["start"] = std::move(start_claims);
    json undecided = json::array();
    for (const auto& [lo, hi] : undecided_times) undecided.push_back(json::array({rational(lo), rational(hi)}));
    out["undecided"] = r.verdict == Verdict::Undecided ? std::move(undecided) : json::array();
    return out;
  }
};

}  // namespace

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
