#include "src/io/primitives.h"

#include "src/io/parse.h"

#include <array>
#include <cmath>

namespace tmcert {

namespace {

using Vec2E = std::array<Exact, 2>;

// Rational points of the unit circle in the first octant from angle 0 to
// 45 degrees.  Level 0: (1, 0), (12/13, 5/13) (22.62 deg), (697/985,
// 696/985) (44.96 deg); x^2 + y^2 = 1 exactly for each (169 = 144 + 25,
// 985^2 = 697^2 + 696^2).  Level k >= 1: 2 * 4^k + 1 points
// ((1 - t^2)/(1 + t^2), 2t/(1 + t^2)) (unit for every rational t) with t
// the multiple of 2^-20 nearest tan(theta/2) for theta from 0 to 45 degrees
// in equal steps: consecutive ones at most 45/(2 * 4^k) + 0.001 degrees
// apart.
std::vector<Vec2E> octant(int level = 0) {
  if (level <= 0) return {{Exact(1), Exact(0)}, {Exact(12, 13), Exact(5, 13)}, {Exact(697, 985), Exact(696, 985)}};
  const int m = 2 << (2 * level);
  std::vector<Vec2E> out;
  for (int i = 0; i <= m; ++i) {
    const double theta = std::atan(1.0) * i / m;  // pi/4 * i/m (any approximation will do: the points are exact)
    const Exact t(static_cast<long>(std::llround(std::tan(theta / 2) * 1048576.0)), 1048576L);
    const Exact d = 1 + t * t;
    out.push_back({(1 - t * t) / d, 2 * t / d});
  }
  return out;
}

// 16 (level 0; 16 m at level k) rational unit vectors counterclockwise
// around the circle: the octant points, their reflections in the diagonal
// (but the one nearest 45 degrees), and the images of these under
// rotations by 90 degrees (which keep coordinates rational and lengths 1).
std::vector<Vec2E> azimuths(int level = 0) {
  const std::vector<Vec2E> oct = octant(level);
  std::vector<Vec2E> q1;  // first quadrant, from 0 to 90 degrees exclusive
  for (const Vec2E& p : oct) q1.push_back(p);
  for (std::size_t i = oct.size() - 1; i-- > 1;) q1.push_back({oct[i][1], oct[i][0]});  // reflections, counterclockwise
  std::vector<Vec2E> out;
  for (int quadrant = 0; quadrant < 4; ++quadrant)
    for (Vec2E p : q1) {
      for (int r = 0; r < quadrant; ++r) p = {-p[1], p[0]};  // rotation by 90 degrees
      out.push_back(p);
    }
  return out;
}

// The vertex where the tangent lines m . v = 1 and n . v = 1 meet
// (m, n unit, counterclockwise, less than 180 degrees apart).
Vec2E meet(const Vec2E& m, const Vec2E& n) {
  const Exact det = m[0] * n[1] - m[1] * n[0];
  return {(n[1] - m[1]) / det, (m[0] - n[0]) / det};
}

// The polygon circumscribing the unit circle with tangent lines at the
// azimuths: vertex i is where lines i and i+1 meet.
std::vector<Vec2E> azimuth_polygon(int level) {
  const std::vector<Vec2E> p = azimuths(level);
  std::vector<Vec2E> out;
  for (std::size_t i = 0; i < p.size(); ++i) out.push_back(meet(p[i], p[(i + 1) % p.size()]));
  return out;
}

// The solid of revolution-like polyhedron {(y, z) : (g(y), z) in Q}, with
// g the gauge of the azimuth polygon scaled by `scale` in y, and Q the
// profile polygon given by its vertices (r_k, z_k) from bottom to top (r >= 0;
// an r = 0 vertex is a pole).  Faces: one quadrilateral (a triangle at a
// pole) per azimuth edge and profile edge, and a cap polygon at a first or
// last vertex with r > 0.  Faces are oriented outward.
PolygonList revolve(const std::vector<Vec2E>& profile, int level) {
  const std::vector<Vec2E> a = azimuth_polygon(level);
  const std::size_t n = a.size();
  auto at = [&](const Vec2E& rz, std::size_t i) {
    return Vec3E{rz[0] * a[i % n][0], rz[0] * a[i % n][1], rz[1]};
  };
  PolygonList out;
  if (profile.front()[0] != 0) {  // bottom cap, seen from below: clockwise
    std::vector<Vec3E> cap;
    for (std::size_t i = n; i-- > 0;) cap.push_back(at(profile.front(), i));
    out.push_back(cap);
  }
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const Vec2E &lo = profile[k], &hi = profile[k + 1];
    for (std::size_t i = 0; i < n; ++i) {
      // The face on azimuth line i+1 (between vertices i and i+1 of the polygon).
      std::vector<Vec3E> f;
      f.push_back(at(lo, i));
      if (lo[0] != 0) f.push_back(at(lo, i + 1));
      f.push_back(at(hi, i + 1));
      if (hi[0] != 0) f.push_back(at(hi, i));
      out.push_back(f);
    }
  }
  if (profile.back()[0] != 0) {
    std::vector<Vec3E> cap;
    for (std::size_t i = 0; i < n; ++i) cap.push_back(at(profile.back(), i));
    out.push_back(cap);
  }
  return out;
}

// Latitude normals (c, s) from -90 to 90 degrees, with c >= 0: the octant
// points, their reflections and the pole, and the mirror images below.
std::vector<Vec2E> latitudes(int level = 0) {
  const std::vector<Vec2E> oct = octant(level);
  std::vector<Vec2E> up;  // 0 .. 90 degrees
  for (const Vec2E& p : oct) up.push_back(p);
  for (std::size_t i = oct.size() - 1; i-- > 1;) up.push_back({oct[i][1], oct[i][0]});
  up.push_back({Exact(0), Exact(1)});
  std::vector<Vec2E> out;
  for (std::size_t k = up.size(); k-- > 1;) out.push_back({up[k][0], -up[k][1]});
  for (const Vec2E& p : up) out.push_back(p);
  return out;
}

Vec3E scaled(const Vec3E& v, const Exact& f) { return {v[0] * f, v[1] * f, v[2] * f}; }

}  // namespace

PolygonList box_polyhedron(const Vec3E& size) {
  const Exact x = size[0] / 2, y = size[1] / 2, z = size[2] / 2;
  auto v = [&](int i, int j, int k) { return Vec3E{i ? x : -x, j ? y : -y, k ? z : -z}; };
  // Outward: counterclockwise seen from outside.
  return {{v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)},   // z = -z
          {v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)},   // z = +z
          {v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)},   // y = -y
          {v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)},   // y = +y
          {v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)},   // x = -x
          {v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}};  // x = +x
}

PolygonList cylinder_polyhedron(const Exact& radius, const Exact& length, int level) {
  const Exact h = length / 2;
  PolygonList out = revolve({{radius, -h}, {radius, h}}, level);
  return out;
}

PolygonList sphere_polyhedron(const Exact& radius, int level) {
  const std::vector<Vec2E> lat = latitudes(level);
  // Profile vertices: consecutive latitude lines meet; from the bottom cap
  // line (0, -1) to the top one (0, 1).
  std::vector<Vec2E> profile;
  for (std::size_t k = 0; k + 1 < lat.size(); ++k) profile.push_back(meet(lat[k], lat[k + 1]));
  PolygonList out = revolve(profile, level);
  for (auto& f : out)
    for (Vec3E& v : f) v = scaled(v, radius);
  return out;
}

std::vector<Vec3E> cylinder_tangent_normals(int level) {
  std::vector<Vec3E> out;
  for (const Vec2E& p : azimuths(level)) out.push_back({p[0], p[1], Exact(0)});
  return out;
}

std::vector<Vec3E> sphere_tangent_normals(int level) {
  std::vector<Vec3E> out;
  for (const Vec2E& cs : latitudes(level)) {
    if (cs[0] == 0) {
      out.push_back({Exact(0), Exact(0), cs[1]});
      continue;
    }
    for (const Vec2E& p : azimuths(level)) out.push_back({cs[0] * p[0], cs[0] * p[1], cs[1]});
  }
  return out;
}

bool refine_primitive(Body& body) {
  if (!body.primitive) return false;
  const bool sphere = body.primitive->kind == Body::Primitive::Kind::Sphere;
  if (body.primitive->level >= (sphere ? kMaxSphereLevel : kMaxCylinderLevel)) return false;
  Body::Primitive prim = *body.primitive;
  ++prim.level;
  const PolygonList polygons = prim.kind == Body::Primitive::Kind::Sphere ? sphere_polyhedron(prim.radius, prim.level)
                                                                          : cylinder_polyhedron(prim.radius, prim.length, prim.level);
  body.polygons.clear();
  body.pieces.clear();
  for (const std::vector<Vec3E>& polygon : polygons) {
    auto [clean, pieces] = split_scene_polygon(polygon, static_cast<int>(body.polygons.size()));
    body.polygons.push_back(std::move(clean));
    for (ConvexPiece& p : pieces) body.pieces.push_back(std::move(p));
  }
  body.primitive = prim;
  return true;
}

}  // namespace tmcert
