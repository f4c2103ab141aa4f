// Exact point-in-solid (kernels/containment.h, proofs/containment.md):
// convex and non-convex solids, points on faces, edges and vertices, points
// 1e-30 off the surface, rays that hit an edge, a vertex or run in a
// triangle's plane (forcing the next direction), and a brute-force
// reference (inside iff on the inner side of every face plane) on random
// rational points for convex polytopes.
#include "kernels/containment.h"

#include <boost/test/unit_test.hpp>

#include <chrono>
#include <random>
#include <vector>

using tmcert::ClosedSurface;
using tmcert::Exact;
using tmcert::Vec3E;

namespace {

using Tri = std::array<Vec3E, 3>;

Exact q(const char* text) {
  Exact value;
  BOOST_REQUIRE(tmcert::parse_exact(text, value));
  return value;
}
// A coordinate written as an integer or as text ("1/3", "1e-30").
struct N {
  Exact value;
  N(int x) : value(x) {}
  N(long x) : value(x) {}
  N(const char* text) : value(q(text)) {}
};
Vec3E v(const N& x, const N& y, const N& z) { return {x.value, y.value, z.value}; }

Vec3E add(const Vec3E& a, const Vec3E& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3E mul(const Exact& s, const Vec3E& a) { return {s * a[0], s * a[1], s * a[2]}; }
Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// A closed surface from polygons given as vertex loops (fan triangulation:
// each loop must be convex or star-shaped from its first vertex).
std::vector<Tri> fan(const std::vector<std::vector<Vec3E>>& polygons) {
  std::vector<Tri> out;
  for (const auto& p : polygons)
    for (std::size_t j = 1; j + 1 < p.size(); ++j) out.push_back({p[0], p[j], p[j + 1]});
  return out;
}

// The box [lo, hi] (corners given), as 12 triangles.
std::vector<Tri> box(const Vec3E& lo, const Vec3E& hi) {
  auto c = [&](int x, int y, int z) { return Vec3E{x ? hi[0] : lo[0], y ? hi[1] : lo[1], z ? hi[2] : lo[2]}; };
  return fan({{c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)},
              {c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)},
              {c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)},
              {c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)},
              {c(1, 1, 0), c(0, 1, 0), c(0, 1, 1), c(1, 1, 1)},
              {c(0, 1, 0), c(0, 0, 0), c(0, 0, 1), c(0, 1, 1)}});
}

// A prism over a planar loop (x, y) between z = 0 and z = h; the loop is
// fanned from its first vertex for the caps.
std::vector<Tri> prism(const std::vector<std::array<long, 2>>& loop, long h) {
  std::vector<Vec3E> bottom, top;
  for (const auto& p : loop) {
    bottom.push_back(v(p[0], p[1], 0));
    top.push_back(v(p[0], p[1], h));
  }
  std::vector<std::vector<Vec3E>> polygons{bottom, top};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::size_t j = (i + 1) % loop.size();
    polygons.push_back({bottom[i], bottom[j], top[j], top[i]});
  }
  return fan(polygons);
}

// Octahedron with vertices (a,0,0), (-b,0,0), (0,c,0), (0,-d,0), (0,0,e),
// (0,0,-f) (all positive): convex, the origin inside.  Each face is
// subdivided `levels` times into 4 (midpoints), which keeps the shape.
std::vector<Tri> octahedron(const std::array<Exact, 6>& r, int levels = 0) {
  const Vec3E px{r[0], 0, 0}, nx{-r[1], 0, 0}, py{0, r[2], 0}, ny{0, -r[3], 0}, pz{0, 0, r[4]}, nz{0, 0, -r[5]};
  std::vector<Tri> faces;
  for (const Vec3E& x : {px, nx})
    for (const Vec3E& y : {py, ny})
      for (const Vec3E& z : {pz, nz}) faces.push_back({x, y, z});
  for (int l = 0; l < levels; ++l) {
    std::vector<Tri> finer;
    const Exact half(1, 2);
    for (const Tri& t : faces) {
      const Vec3E ab = mul(half, add(t[0], t[1])), bc = mul(half, add(t[1], t[2])), ca = mul(half, add(t[2], t[0]));
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({ca, bc, t[2]});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  return faces;
}

// Reference for a convex polytope given by its (unsubdivided) faces and an
// interior point: p is in the closed solid iff it is on the inner side of
// (or on) every face plane.
bool convex_reference(const std::vector<Tri>& faces, const Vec3E& interior, const Vec3E& p) {
  for (const Tri& t : faces) {
    const Vec3E n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    const Exact side_in = dot(n, sub(interior, t[0])), side_p = dot(n, sub(p, t[0]));
    if (side_p != 0 && (side_p > 0) != (side_in > 0)) return false;
  }
  return true;
}

Exact random_rational(std::mt19937& rng, long lo, long hi, long den) {
  std::uniform_int_distribution<long> pick(lo * den, hi * den);
  return Exact(pick(rng), den);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(containment)

BOOST_AUTO_TEST_CASE(unit_cube) {
  const ClosedSurface cube(box(v(0, 0, 0), v(1, 1, 1)));
  BOOST_TEST(cube.size() == 12u);
  int tried = -1;
  BOOST_TEST(cube.contains(v("1/2", "1/2", "1/2"), tried));
  BOOST_TEST(tried == 1);  // a generic point: the first direction serves
  BOOST_TEST(cube.contains(v("0.999", "0.001", "0.5")));
  BOOST_TEST(!cube.contains(v(2, 0, 0)));
  BOOST_TEST(!cube.contains(v(-1, "1/2", "1/2")));
  BOOST_TEST(!cube.contains(v("1/2", "1/2", 7)));
  // On the surface: faces, edges, vertices (closed solid).
  BOOST_TEST(cube.contains(v(1, "1/2", "1/2"), tried));
  BOOST_TEST(tried == 0);
  BOOST_TEST(cube.contains(v("1/3", "1/7", 0)));
  BOOST_TEST(cube.contains(v(1, 1, "1/2")));
  BOOST_TEST(cube.contains(v(0, "1/2", 0)));
  BOOST_TEST(cube.contains(v(0, 0, 0)));
  BOOST_TEST(cube.contains(v(1, 1, 1)));
  // On a diagonal of the fan triangulation.
  BOOST_TEST(cube.contains(v("1/2", "1/2", 0)));
  // 1e-30 off the surface, both ways, on faces, edges and vertices.
  BOOST_TEST(!cube.contains(v("1.000000000000000000000000000001", "1/2", "1/2")));
  BOOST_TEST(cube.contains(v("0.999999999999999999999999999999", "1/2", "1/2")));
  BOOST_TEST(!cube.contains(v("-1e-30", "1/2", "1/2")));
  BOOST_TEST(cube.contains(v("1e-30", "1/2", "1/2")));
  BOOST_TEST(!cube.contains(v("1/2", "1/2", "-1e-30")));
  BOOST_TEST(!cube.contains(v("1.000000000000000000000000000001", "1", "1")));
  BOOST_TEST(!cube.contains(v("-1e-30", "-1e-30", "-1e-30")));
  BOOST_TEST(cube.contains(v("1e-30", "1e-30", "1e-30")));
  BOOST_TEST(!cube.contains(v("1e-30", "1/2", "1.000000000000000000000000000001")));
}

BOOST_AUTO_TEST_CASE(tetrahedron) {
  const Vec3E o = v(0, 0, 0), x = v(1, 0, 0), y = v(0, 1, 0), z = v(0, 0, 1);
  const ClosedSurface t(std::vector<Tri>{{o, y, x}, {o, x, z}, {o, z, y}, {x, y, z}});
  BOOST_TEST(t.contains(v("1/4", "1/4", "1/4")));
  BOOST_TEST(t.contains(v("1/3", "1/3", "1/3")));  // on the slanted face
  BOOST_TEST(!t.contains(v("1/3", "1/3", "0.333333333333333333333333333334")));
  BOOST_TEST(t.contains(v("1/3", "1/3", "0.333333333333333333333333333333")));
  BOOST_TEST(t.contains(v("1/2", "1/2", 0)));  // on an edge
  BOOST_TEST(t.contains(v(0, 0, 1)));          // a vertex
  BOOST_TEST(!t.contains(v("1/2", "1/2", "1/2")));
  BOOST_TEST(!t.contains(v("-1/4", "1/4", "1/4")));
  BOOST_TEST(!t.contains(v(2, "1e-9", "1e-9")));
}

BOOST_AUTO_TEST_CASE(non_convex_l_shape) {
  // The L (0,0)-(2,0)-(2,1)-(1,1)-(1,2)-(0,2), 1 high, fanned from the
  // reflex corner (1,1).
  const ClosedSurface l(prism({{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}}, 1));
  BOOST_TEST(l.contains(v("1/2", "1/2", "1/2")));
  BOOST_TEST(l.contains(v("3/2", "1/2", "1/2")));
  BOOST_TEST(l.contains(v("1/2", "3/2", "1/2")));
  BOOST_TEST(!l.contains(v("3/2", "3/2", "1/2")));  // in the notch
  BOOST_TEST(l.contains(v("3/2", 1, "1/2")));       // on the notch's faces
  BOOST_TEST(l.contains(v(1, "3/2", "1/2")));
  BOOST_TEST(l.contains(v(1, 1, "1/2")));           // on the reflex edge
  BOOST_TEST(!l.contains(v("1.000000000000000000000000000001", "1.000000000000000000000000000001", "1/2")));
  BOOST_TEST(l.contains(v("0.999999999999999999999999999999", "1.000000000000000000000000000001", "1/2")));
  // Reference on a grid of quarters (many points on faces, edges and
  // vertices, many rays along grid lines) and random sevenths.
  auto reference = [](const Vec3E& p) {
    if (p[2] < 0 || p[2] > 1) return false;
    const bool low = p[0] >= 0 && p[0] <= 2 && p[1] >= 0 && p[1] <= 1;
    const bool left = p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 2;
    return low || left;
  };
  int checked = 0;
  for (int i = -1; i <= 9; ++i)
    for (int j = -1; j <= 9; ++j)
      for (int k = -1; k <= 5; ++k) {
        const Vec3E p{Exact(i, 4), Exact(j, 4), Exact(k, 4)};
        BOOST_TEST_CONTEXT("p = (" << i << ", " << j << ", " << k << ")/4") {
          BOOST_TEST(l.contains(p) == reference(p));
        }
        ++checked;
      }
  std::mt19937 rng(7);
  for (int n = 0; n < 500; ++n) {
    const Vec3E p{random_rational(rng, -1, 3, 7), random_rational(rng, -1, 3, 7), random_rational(rng, -1, 2, 7)};
    BOOST_TEST(l.contains(p) == reference(p));
  }
  BOOST_TEST(checked == 11 * 11 * 7);
}

BOOST_AUTO_TEST_CASE(rays_through_vertices_and_edges_force_the_next_direction) {
  const ClosedSurface cube(box(v(0, 0, 0), v(1, 1, 1)));
  const Vec3E d0 = ClosedSurface::ray_direction(0);
  BOOST_TEST(d0[0] == 1);
  BOOST_TEST(d0[1] == Exact(1, 1031));
  const Exact half(1, 2);
  int tried = 0;
  // Inside; the first ray runs exactly through the vertex (1,1,1).
  BOOST_TEST(cube.contains(sub(v(1, 1, 1), mul(half, d0)), tried));
  BOOST_TEST(tried >= 2);
  // Inside; the first ray runs through the edge x = y = 1.
  BOOST_TEST(cube.contains(sub(v(1, 1, "1/2"), mul(half, d0)), tried));
  BOOST_TEST(tried >= 2);
  // Inside; the first ray runs through a fan diagonal of the face x = 1
  // (an edge of the triangulation inside a face).
  BOOST_TEST(cube.contains(sub(v(1, "1/2", "1/2"), mul(half, d0)), tried));
  BOOST_TEST(tried >= 2);
  // Outside; the first ray enters through the vertex (0,0,0) and leaves
  // through the face x = 1: parity would be fooled by counting it once.
  BOOST_TEST(!cube.contains(sub(v(0, 0, 0), d0), tried));
  BOOST_TEST(tried >= 2);
  // Outside, grazing the edge y = z = 0 from below.
  BOOST_TEST(!cube.contains(sub(v("1/2", 0, 0), mul(Exact(3), d0)), tried));
  BOOST_TEST(tried >= 2);

  // The first ray lies in the plane of a triangle it meets (a doubly
  // covered triangle: closed, encloses nothing).
  const Vec3E p = v("1/3", "1/5", "1/7"), w = v(0, 1, 0);
  const Vec3E a = add(p, sub(d0, w)), b = add(p, add(d0, w)), c = add(p, add(mul(Exact(3), d0), mul(half, w)));
  const ClosedSurface sheet(std::vector<Tri>{{a, b, c}, {a, c, b}});
  BOOST_TEST(!sheet.contains(p, tried));
  BOOST_TEST(tried >= 2);
  BOOST_TEST(sheet.contains(mul(Exact(1, 3), add(a, add(b, c)))));  // on it
  // Same with the directions 0 and 1 both spoilt: direction 2 serves.
  const Vec3E d1 = ClosedSurface::ray_direction(1);
  std::vector<Tri> two = box(v(0, 0, 0), v(1, 1, 1));
  const Vec3E inside = v("1/2", "1/2", "1/2");
  // A vertex on ray 0 and one on ray 1, as an extra closed sheet pair each.
  for (const Vec3E& d : {d0, d1}) {
    const Vec3E hit = add(inside, mul(Exact(1, 4), d));
    const Vec3E e = add(hit, v(0, 0, "1/10")), f = add(hit, v(0, "1/10", 0));
    two.push_back({hit, e, f});
    two.push_back({hit, f, e});
  }
  const ClosedSurface spoilt(two);
  BOOST_TEST(spoilt.contains(inside, tried));
  BOOST_TEST(tried == 3);
}

BOOST_AUTO_TEST_CASE(flat_triangles_and_empty_surfaces) {
  // A doubly covered flat triangle (collinear vertices) added to a cube
  // changes nothing; the first ray from p runs along it and is retried.
  std::vector<Tri> cube = box(v(0, 0, 0), v(1, 1, 1));
  const Vec3E d0 = ClosedSurface::ray_direction(0);
  const Vec3E a = v("1/2", "1/2", "1/2"), b = add(a, mul(Exact(1, 4), d0)), m = add(a, mul(Exact(1, 8), d0));
  cube.push_back({a, b, m});
  cube.push_back({a, m, b});
  const ClosedSurface s(cube);
  int tried = 0;
  BOOST_TEST(s.contains(sub(a, mul(Exact(1, 8), d0)), tried));
  BOOST_TEST(tried >= 2);
  BOOST_TEST(s.contains(m, tried));  // on it
  BOOST_TEST(tried == 0);
  BOOST_TEST(s.contains(v("1/8", "1/8", "1/8")));
  BOOST_TEST(!s.contains(v(-1, "1/2", "1/2")));
  const ClosedSurface nothing(std::vector<Tri>{});
  BOOST_TEST(!nothing.contains(v(0, 0, 0)));
}

BOOST_AUTO_TEST_CASE(coordinates_beyond_double_range) {
  // Enclosures become infinite or zero-width around 0: the filters must
  // still only skip what they prove.
  const ClosedSurface huge(box(v(0, 0, 0), v("1e400", "1e400", "1e400")));
  BOOST_TEST(huge.contains(v("5e399", "5e399", "5e399")));
  BOOST_TEST(huge.contains(v("1e-400", "1e399", "3e399")));
  BOOST_TEST(!huge.contains(v("2e400", "5e399", "5e399")));
  BOOST_TEST(!huge.contains(v("-1e-400", "5e399", "5e399")));
  BOOST_TEST(huge.contains(v("1e400", "5e399", "1e400")));
  const ClosedSurface tiny(box(v("1e-400", "1e-400", "1e-400"), v("3e-400", "3e-400", "3e-400")));
  BOOST_TEST(tiny.contains(v("2e-400", "2e-400", "2e-400")));
  BOOST_TEST(!tiny.contains(v("0.5e-400", "2e-400", "2e-400")));
  BOOST_TEST(!tiny.contains(v(0, 0, 0)));
  BOOST_TEST(tiny.contains(v("3e-400", "2e-400", "3e-400")));
}

BOOST_AUTO_TEST_CASE(nested_shells_alternate_within_one_shell_index) {
  // Parity within one shell index: a box inside a box, given as one shell,
  // encloses the space between them.
  std::vector<Tri> shells = box(v(0, 0, 0), v(3, 3, 3));
  const std::vector<Tri> inner = box(v(1, 1, 1), v(2, 2, 2));
  shells.insert(shells.end(), inner.begin(), inner.end());
  const ClosedSurface s(shells);
  BOOST_TEST(s.contains(v("1/2", "1/2", "1/2")));
  BOOST_TEST(!s.contains(v("3/2", "3/2", "3/2")));
  BOOST_TEST(s.contains(v(2, "3/2", "3/2")));  // on the inner shell
}

// Several shells: the inside is the union of their insides (SCENE_FORMAT.md
// "Solids"), however they overlap or nest.
std::vector<int> shell_ids(std::size_t first, std::size_t second) {
  std::vector<int> out(first, 0);
  out.insert(out.end(), second, 1);
  return out;
}

BOOST_AUTO_TEST_CASE(nested_shells_form_a_union) {
  std::vector<Tri> tris = box(v(0, 0, 0), v(3, 3, 3));
  const std::vector<Tri> inner = box(v(1, 1, 1), v(2, 2, 2));
  const std::vector<int> ids = shell_ids(tris.size(), inner.size());
  tris.insert(tris.end(), inner.begin(), inner.end());
  const ClosedSurface s(tris, ids);
  BOOST_TEST(s.contains(v("1/2", "1/2", "1/2")));
  BOOST_TEST(s.contains(v("3/2", "3/2", "3/2")));  // inside both
  BOOST_TEST(s.contains(v(2, "3/2", "3/2")));      // on the inner shell
  BOOST_TEST(!s.contains(v(4, "3/2", "3/2")));
}

BOOST_AUTO_TEST_CASE(overlapping_shells_form_a_union) {
  std::vector<Tri> tris = box(v(0, 0, 0), v(2, 2, 2));
  const std::vector<Tri> other = box(v(1, 1, 1), v(3, 3, 3));
  const std::vector<int> ids = shell_ids(tris.size(), other.size());
  tris.insert(tris.end(), other.begin(), other.end());
  const ClosedSurface s(tris, ids);
  BOOST_TEST(s.contains(v("3/2", "3/2", "3/2")));  // inside both: even in total
  BOOST_TEST(s.contains(v("1/2", "1/2", "1/2")));  // inside the first only
  BOOST_TEST(s.contains(v("5/2", "5/2", "5/2")));  // inside the second only
  BOOST_TEST(s.contains(v("1/2", "1/2", 2)));      // on the first, inside neither other
  BOOST_TEST(!s.contains(v("1/2", "5/2", "1/2")));
  BOOST_TEST(!s.contains(v(-1, -1, -1)));
}

BOOST_AUTO_TEST_CASE(convex_polytopes_against_brute_force) {
  const std::array<Exact, 6> radii{q("1.5"), q("0.7"), q("2"), q("1/3"), q("1.1"), q("0.9")};
  const std::vector<Tri> faces = octahedron(radii);
  const Vec3E origin = v(0, 0, 0);
  std::mt19937 rng(20261123);
  for (int level : {0, 2}) {
    const ClosedSurface solid(octahedron(radii, level));
    int inside = 0, outside = 0;
    for (int n = 0; n < 1500; ++n) {
      const Vec3E p{random_rational(rng, -2, 2, 8), random_rational(rng, -2, 2, 8), random_rational(rng, -2, 2, 8)};
      const bool expected = convex_reference(faces, origin, p);
      BOOST_TEST(solid.contains(p) == expected);
      (expected ? inside : outside)++;
    }
    BOOST_TEST(inside > 20);
    BOOST_TEST(outside > 100);
    // Points on faces (random rational barycentric combinations), and
    // pushed off them by 1e-30 along the outward direction of the origin ray.
    for (int n = 0; n < 200; ++n) {
      const Tri& t = faces[static_cast<std::size_t>(n) % faces.size()];
      const Exact u = random_rational(rng, 0, 1, 16), w = random_rational(rng, 0, 1, 16);
      const Exact s = u + w > 1 ? Exact(0) : u, r = u + w > 1 ? Exact(0) : w;
      const Vec3E p = add(t[0], add(mul(s, sub(t[1], t[0])), mul(r, sub(t[2], t[0]))));
      BOOST_TEST(solid.contains(p));
      const Vec3E out = mul(1 + q("1e-30"), p), in = mul(1 - q("1e-30"), p);
      BOOST_TEST(!solid.contains(out));
      BOOST_TEST(solid.contains(in));
    }
  }
}

BOOST_AUTO_TEST_CASE(many_points_against_many_triangles) {
  // 8192 triangles, 2000 points: the box filter keeps this fast.
  const std::array<Exact, 6> radii{q("1.25"), q("0.75"), q("1"), q("1.5"), q("0.5"), q("1")};
  const std::vector<Tri> faces = octahedron(radii);
  const ClosedSurface solid(octahedron(radii, 5));
  BOOST_TEST(solid.size() == 8192u);
  std::mt19937 rng(5);
  const auto start = std::chrono::steady_clock::now();
  int mismatches = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3E p{random_rational(rng, -2, 2, 1000), random_rational(rng, -2, 2, 1000),
                  random_rational(rng, -2, 2, 1000)};
    if (solid.contains(p) != convex_reference(faces, v(0, 0, 0), p)) ++mismatches;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BOOST_TEST_MESSAGE("containment: 2000 points x 8192 triangles in " << seconds << " s");
  BOOST_TEST(mismatches == 0);
}

BOOST_AUTO_TEST_SUITE_END()
