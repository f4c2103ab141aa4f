// Exact first contact of two moving features over a parameter interval,
// for motions whose points are polynomial up to one common positive weight
// (rational motions): the contact polynomial's real roots, isolated
// exactly, and the signs of the containment predicates at each root; the
// cases where a contact polynomial vanishes identically reduce to
// lower-dimensional ones (proofs/exact-resolution.md).
#pragma once

#include "kernels/real_roots.h"

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace tmcert {

// A moving point: x(u) / w(u) in world coordinates, stored as its
// numerator x(u) (three polynomials in u).  All points handled together
// share the same w(u) > 0, so every predicate below (built from
// differences of points, homogeneous in them) has the sign of the true one.
struct MovingPoint {
  std::array<PolyQ, 3> x;
};

// Where a contact happens: at a vertex (one point, exactly on the other
// feature), or where two edges' lines meet (four points a0 a1 b0 b1).
struct ContactPoint {
  std::vector<MovingPoint> points;  // size 1 or 4
};

struct Contact {
  RealRoot t;          // the contact's parameter u
  ContactPoint where;
};

// Earliest contacts in the closed interval [u0, u1], or nothing when the
// features never touch there.  Throws ExactLimit (never a wrong answer)
// when a loop passes its cap.  One solver remembers the roots it isolated
// (and refined) per contact polynomial: features sharing a polynomial
// (a vertex against coplanar faces) isolate its roots once.  Not for use
// by several threads at once.
class ContactSolver {
 public:
  ContactSolver(Exact u0, Exact u1) : u0_(std::move(u0)), u1_(std::move(u1)) {}
  // `positive`: a polynomial the caller knows to be positive on [u0, u1]
  // (the points' common weight w(u)).  Contact polynomials are divided by
  // it as often as it divides them exactly: the same roots and signs on the
  // piece, and a lower degree (a fixed body's points are w(u) y, so a
  // moving vertex against a fixed face gives w(u)^2 times the polynomial
  // that matters).
  ContactSolver(Exact u0, Exact u1, PolyZ positive)
      : u0_(std::move(u0)), u1_(std::move(u1)), positive_(std::move(positive)) {}

  std::optional<Contact> vertex_vertex(const MovingPoint& a, const MovingPoint& b) const;
  std::optional<Contact> vertex_edge(const MovingPoint& v, const MovingPoint& e0, const MovingPoint& e1) const;
  // `polygon`: a convex polygon's vertices in order (at least 3).
  std::optional<Contact> vertex_face(const MovingPoint& v, const std::vector<MovingPoint>& polygon) const;
  std::optional<Contact> edge_edge(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                                   const MovingPoint& b1) const;

  // Contacts after `bound` are of no interest from now on: a method may
  // then report nothing for features whose earliest contact is later (the
  // caller keeps the earliest over many pairs).  Roots are still isolated
  // on the whole [u0, u1].
  void set_bound(const RealRoot& bound) const { bound_ = bound; }

  // The same predicates at one parameter (rational or an isolated root),
  // exactly: does the vertex lie on the closed segment, the coplanar vertex
  // in the closed polygon, do the coplanar segments meet?
  static bool on_segment(const MovingPoint& v, const MovingPoint& e0, const MovingPoint& e1, RealRoot& r);
  static bool in_polygon(const MovingPoint& v, const std::vector<MovingPoint>& polygon, RealRoot& r);
  static bool segments_meet(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                            const MovingPoint& b1, RealRoot& r);
  // Two features (a point, a segment, or a convex polygon's vertices in
  // order) share a point at r, exactly; pairs of these kinds only: point
  // and anything, segment and segment (polygon pairs: false).
  static bool touch(const std::vector<MovingPoint>& a, const std::vector<MovingPoint>& b, RealRoot& r);

 private:
  Exact u0_, u1_;
  PolyZ positive_;  // empty: none known
  mutable std::map<PolyZ, std::vector<RealRoot>> roots_;  // square-free polynomial -> its roots in [u0, u1]
  mutable std::optional<RealRoot> bound_;
};

// The earlier of two optional contacts (the first on a tie).
std::optional<Contact> earlier(std::optional<Contact> a, std::optional<Contact> b);

// A rational box holding the exact point of a contact: refines the time
// as needed; `weight` is the points' common denominator polynomial w(u).
std::array<std::array<Exact, 2>, 3> point_box(Contact& c, const PolyQ& weight);

}  // namespace tmcert
