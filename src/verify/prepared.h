// A body prepared for one check: its contact features in the three number
// types, its metric, and its parts for exact static tests.
#pragma once

#include "kernels/contact.h"
#include "kernels/static_intersection.h"
#include "src/metric/metric.h"
#include "src/motion/bezier.h"
#include "src/scene/model.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tmcert {

// One kind of contact feature (vertices, edges or faces) of a body, the same
// geometry held exactly, as enclosing intervals and as doubles.
struct FeatureTable {
  std::vector<FeatureGeometry<Exact>> exact;
  std::vector<FeatureGeometry<Interval>> interval;
  std::vector<FeatureGeometry<double>> approx;
  std::vector<int> part;  // index into PreparedBody::parts
  std::size_t size() const { return exact.size(); }
};

// A polygon, segment or point as written, as simplices (a polygon's convex
// pieces fanned into triangles) for the exact static test.
struct StaticPart {
  std::string name;  // e.g. "polygon 2", "segment 0", "point 1"
  std::vector<Simplex> simplices;
};

struct PreparedBody {
  const Body* body = nullptr;
  bool moving = false;  // has a motion of degree >= 1
  // Fixed bodies: their pose (identity, or a one-point motion) is applied
  // exactly and all geometry below is in world coordinates.  Moving bodies:
  // the body frame.
  std::vector<StaticPart> parts;
  FeatureTable vertices, edges, faces;
  // Moving bodies only.
  // Heap-held so that MetricData may point at it while PreparedBody moves.
  std::unique_ptr<const Metric> metric;
  std::unique_ptr<MetricData> metric_data;
  HomogeneousCurve<Exact> curve;
  double max_rho2 = 0;  // upper bound of max rho^2 over the body (at a vertex: rho^2 is convex)
};

PreparedBody prepare_body(const Body& body);

// A box that certainly contains every point of the body at every parameter
// of its motion: the hull of all vertices under all affine control points
// (convex hull property), computed with outward rounding.  `valid` is false
// when a bound is not finite.
struct SweptBox {
  std::array<double, 3> lo{}, hi{};
  bool valid = false;
};

SweptBox swept_box(const Body& body);

// True when the boxes are certainly disjoint: the bodies never touch.
bool disjoint(const SweptBox& a, const SweptBox& b);

// The static parts transformed exactly by an affine map.
std::vector<StaticPart> transformed_parts(const PreparedBody& body, const Mat34E& map);

}  // namespace tmcert
