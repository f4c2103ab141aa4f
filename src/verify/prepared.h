// A body prepared for verification: its contact features enclosed by
// intervals (and rounded to doubles for the fast kernel), its metric, its
// parts for exact static tests, and - built only when first needed - the
// same features and metric in exact rationals.
#pragma once

#include "kernels/contact.h"
#include "kernels/static_intersection.h"
#include "src/metric/metric.h"
#include "src/motion/bezier.h"
#include "src/verify/hierarchy.h"
#include "src/model/model.h"

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace tmcert {

// One kind of contact feature (vertices, edges or faces) of a body.
struct FeatureTable {
  std::vector<FeatureGeometry<Interval>> interval;  // enclose the exact features
  std::vector<FeatureGeometry<double>> approx;      // for the fast kernel only
  std::vector<int> part;                            // index into PreparedBody::parts
  std::vector<BvNode> spheres;                      // one per feature, certainly holding it
  // Fixed bodies only: enclosures of each feature's vertices in the world
  // (detail::vertex_images, for the axis test), feature k's `image_count[k]`
  // of them from `images[image_first[k]]`; they do not change with the piece.
  std::vector<std::uint32_t> image_first;
  std::vector<std::uint8_t> image_count;
  std::vector<Vec3<Interval>> images;
  std::size_t size() const { return interval.size(); }
  std::pair<const Vec3<Interval>*, std::size_t> fixed_images(std::size_t k) const {
    return {images.data() + image_first[k], image_count[k]};
  }
};

// The exact features, in the same order as the tables.
struct ExactFeatures {
  std::vector<FeatureGeometry<Exact>> vertices, edges, faces;
};

// The exact vertices of the features (a vertex, an edge's two ends, a
// convex face's vertices in order), in the same order as the tables, in the
// frame of ExactFeatures; no metric needed (exact resolution).
struct ExactFeatureVertices {
  std::vector<std::vector<Vec3E>> vertices, edges, faces;
};

// A polygon, segment or point as written, as simplices (a polygon's convex
// pieces fanned into triangles) for the exact static test.
struct StaticPart {
  std::string name;  // e.g. "polygon 2", "segment 0", "point 1"
  std::vector<Simplex> simplices;
};

class PreparedBody {
 public:
  explicit PreparedBody(const Body& body);
  PreparedBody(const PreparedBody&) = delete;
  PreparedBody& operator=(const PreparedBody&) = delete;

  const Body* body = nullptr;
  bool moving = false;  // has a motion of degree >= 1
  // Fixed bodies: their pose (identity, or a one-point motion) is applied
  // exactly and all geometry is in world coordinates.  Moving bodies: the
  // body frame.
  std::vector<StaticPart> parts;
  FeatureTable vertices, edges, faces;
  // The body's hierarchy: cells (a convex piece with the edges and vertices
  // it owns; segments, points) over the three tables (proofs/hierarchy.md).
  CellTree cells;
  // Moving bodies only.
  MetricData metric_data;
  HomogeneousCurve<Exact> curve;
  double max_rho2 = 0;  // about max rho^2 over the body (a tolerance, not a bound)

  // Exact metric and features; thread-safe, computed once on first call.
  const Metric& exact_metric() const;
  const ExactFeatures& exact() const;
  const ExactFeatureVertices& exact_vertices() const;

 private:
  std::vector<Vec3E> placed(const std::vector<Vec3E>& points) const;

  Mat34E pose_;
  mutable std::once_flag metric_once_, exact_once_, vertices_once_;
  mutable std::unique_ptr<const ExactFeatureVertices> vertices_;
  mutable std::unique_ptr<const Metric> metric_;
  mutable std::unique_ptr<const ExactFeatures> exact_;
};

// A box that certainly contains every point of the body at every parameter
// of its motion: the hull of all vertices under all affine control points
// (convex hull property), computed with outward rounding.  `valid` is false
// when a bound is not finite.
// For small bodies (at most kSweptPointsMax vertices, such as the points,
// segments and triangles of continuous-collision queries) the images of the
// vertices under every control point are kept too: their convex hull holds
// everything the body sweeps, and a separating axis between two such hulls
// clears a check without any further work.
struct SweptBox {
  std::array<double, 3> lo{}, hi{};
  bool valid = false;
  int vertices = 0;                                  // per pose, 0 when not kept
  std::vector<std::array<Interval, 3>> points;       // pose-major: points[k * vertices + v]
};

constexpr int kSweptPointsMax = 4;

SweptBox swept_box(const Body& body);

// True when the bodies certainly never touch: their boxes are disjoint, or
// (for small bodies) a plane separates the hulls of their swept points.
bool disjoint(const SweptBox& a, const SweptBox& b);

// The static parts transformed exactly by an affine map.
std::vector<StaticPart> transformed_parts(const PreparedBody& body, const Mat34E& map);

}  // namespace tmcert
