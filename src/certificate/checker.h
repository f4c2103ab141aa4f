// The certificate checker's claims (docs/certificate-format.md,
// proofs/certificates.md): one check of a certificate read and validated
// (CheckContext) and the Checker that reads (check.cpp), judges
// (check_judge.cpp) and proves (check_proof.cpp) each check of a document.
// Internal to the checker's files.
#pragma once

#include "src/certificate/algebraic_witness.h"
#include "src/certificate/check.h"
#include "src/certificate/check_document.h"
#include "src/certificate/check_separation.h"
#include "src/certificate/motions.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::certificate::check_internal {

// Vertex ids cached for groups, over a whole certificate; beyond it group
// vertex lists are recomputed on each use (slower, bounded memory).
constexpr std::size_t kGroupCacheBudget = 50'000'000;

// Saturation of the expanded sizes of proofs (shared nodes counted per use).
constexpr std::uint64_t kMaxExpanded = std::uint64_t{1} << 62;

struct WitnessSide {
  bool interior = false;
  std::size_t element = 0;
  std::vector<Exact> weights;
  Vec3E ray;
  std::vector<std::size_t> vertices;  // an algebraic witness: the sub-feature's vertices
  bool true_shape = false;  // {"true_shape": true}: the point is in the body's URDF cylinder or sphere (check_primitive.h)
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
  // Shared proof nodes ("nodes", empty when absent) and each entry's
  // expanded size (nodes judged per use, saturated at kMaxExpanded) and
  // depth in splits.
  const json* nodes = nullptr;
  std::vector<std::uint64_t> expanded;
  std::vector<int> node_depth;
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
  // Both bodies translated: the other body (1 - displaced) by this, within
  // its own tolerance ("displacement_other").
  std::optional<Vec3E> displacement_other;
  // The translation of side s that the witness states, if any.
  const Vec3E* displacement_of(int s) const {
    if (!displacement) return nullptr;
    if (displaced == s) return &*displacement;
    return displacement_other ? &*displacement_other : nullptr;
  }
  std::optional<std::array<Vec3E, 2>> points;
  bool enclosed_witness = false;
  // A clearance violation at an enclosed pose ("points_box" in place of
  // "point"): a weighted point of each side's element, within the
  // clearance of each other for every pose of the two pose boxes at t.
  bool enclosed_clearance = false;
  // A witness with a {"true_shape": true} side (check_primitive.h); without
  // `has_point`, the point is the other side's element point.
  bool true_shape_witness = false;
  bool has_point = false;
  std::size_t exact_claims = 0;
  std::unique_ptr<CheckMotions> motions;  // for exact claims, built when first needed
  // A collision's "before_witness": the part of the witness's piece before
  // the witness time, from `before_from` (exact_claims.h).
  const json* before_witness = nullptr;
  Exact before_from;
};

// Reads, validates and judges the checks of one certificate against one
// scene (docs/certificate-format.md, proofs/certificates.md).
class Checker {
 public:
  Checker(const Scene& scene, std::string source) : scene_(scene), in_(std::move(source)) {}

  CheckOutcome run(const json& doc);

 private:
  const Scene& scene_;
  Reader in_;
  std::vector<std::unique_ptr<BodyData>> bodies_;
  // Bodies whose URDF cylinder or sphere polyhedron a check names at a
  // finer level ("levels"), by scene index and level (check_primitive.cpp).
  std::map<std::pair<std::size_t, int>, std::unique_ptr<Body>> refined_;
  std::map<std::pair<std::size_t, int>, std::unique_ptr<BodyData>> refined_data_;
  std::size_t cache_budget_ = kGroupCacheBudget;
  std::vector<std::uint32_t> scratch_a_, scratch_b_;
  SeparationScratch z_;

  [[noreturn]] static void reject(const std::string& message) { throw Rejected{message}; }

  BodyData& body_data(std::size_t i);

  static std::size_t element_count(const Body& b) { return b.pieces.size() + b.segments.size() + b.points.size(); }

  void check_document(const json& doc, CheckOutcome& outcome);

  std::pair<Exact, Exact> check_interval(const Body& a, const Body& b, const std::string& label) const;

  // ------------------------------------------------------------ phase 1 (check.cpp)

  std::unique_ptr<CheckContext> bind_check(const json& c, std::size_t ci);

  // A check's "levels": its bodies' URDF cylinders and spheres at a finer
  // polyhedron (check_primitive.cpp).
  void bind_levels(const json& c, CheckContext& ctx, std::size_t ia, std::size_t ib);

  // ------------------------------------------------------------ phase 2 (check.cpp)

  void read_check(CheckContext& ctx);

  std::pair<std::uint64_t, int> validate_proof(const json& root, const std::string& root_path, std::size_t bound,
                               const CheckContext& ctx);

  void validate_root(const json& root, const std::string& path, const CheckContext& ctx);

  void read_groups(const json& c, CheckContext& ctx);

  void read_witness(const json& w, CheckContext& ctx);

  void read_start(const json& c, CheckContext& ctx);

  // The two point-witness sides both witness readers accept: "interior"
  // (a ray from the point out of the solid) and "element" with "weights"
  // (the point as a weighted sum of the element's vertices).
  void read_interior_side(const json& interior, const std::string& sp, WitnessSide& side);
  void read_weighted_side(const json& x, const std::string& sp, const BodyData& bd, WitnessSide& side);

  // ------------------------------------------------------------ phase 3 (check_judge.cpp)

  std::string judge_check(CheckContext& ctx);

  void check_coverage(const CheckContext& ctx);

  // ------------------------------------------------------------ witness

  void check_algebraic_witness(const CheckContext& ctx);

  void check_enclosed_witness(const CheckContext& ctx);
  void check_enclosed_clearance(const CheckContext& ctx);
  void check_displacement(const CheckContext& ctx);

  void check_witness(const CheckContext& ctx);

  // One side of a point witness at an exact pose: the element's weighted
  // point placed at `point`, or `point` inside the solid by the ray.
  void check_side_at(const CheckContext& ctx, int s, const Mat34E& pose, const Vec3E& point);
  // The point Σ wᵢ vᵢ of a witness side's element (its vertices vᵢ, the
  // side's weights wᵢ), rejected unless every wᵢ >= 0 and Σ wᵢ = 1 (a point
  // of the element); `where`: the side's path in the certificate.
  static Vec3E weighted_point(const std::vector<Vec3E>& verts, const WitnessSide& side, const std::string& where);

  // Witnesses on the true shape of a URDF cylinder or sphere (check_primitive.cpp).
  static bool has_true_shape_side(const json& w);

  void read_true_shape_witness(const json& w, CheckContext& ctx);

  void check_true_shape_witness(const CheckContext& ctx);

  // A side of a witness whose body is a URDF cylinder or sphere must be a
  // "true_shape" side (a point of the polyhedron is not one of the link).
  void require_true_shape_sides(const CheckContext& ctx);

  static std::vector<std::vector<Vec3E>> placed(const BodyData& d, const Mat34E& pose);

  // ------------------------------------------------------------ start claims

  std::optional<Mat34E> claim_pose(const CheckContext& ctx, int s, const Exact& t) const;

  static std::string at_text(const CheckContext& ctx, const Exact& t);

  std::size_t check_start(CheckContext& ctx, const std::vector<Exact>& runs);

  // ------------------------------------------------------------ proofs (check_proof.cpp)

  // A piece (or before_witness) being proven: what its separations are
  // checked against (check_separation.h), and where it is.
  struct PieceContext : SeparationPiece {
    std::size_t index;
    std::string path;   // "checks[0].pieces[17]"
    std::string label;  // "checks[0] (..): pieces[17] [3/16, 7/32]"
    Exact ua, ub;                     // the piece in curve parameters
    const RealRoot* before = nullptr;  // before_witness: the claims hold before this time only
  };

  void check_piece(const json& piece, std::size_t k, const std::pair<Exact, Exact>& t, CheckContext& ctx);

  void general_piece(const std::pair<Exact, Exact>& t, PieceContext& pc, const CheckContext& ctx);

  // ------------------------------------------------------------ exact claims

  void validate_exact_leaf(const json& node, const json& exact, bool other_keys, const std::string& path);

  static std::vector<std::uint32_t> group_elements(const GroupSet& gs, std::uint32_t g);

  std::string exact_leaf_error(std::uint32_t g, std::uint32_t h, const PieceContext& pc, CheckContext& ctx);

  void check_before_witness(CheckContext& ctx);

  static std::string trail_path(const std::vector<int>& trail);

  void prove(const json& node, std::uint32_t g, std::uint32_t h, std::vector<int>& trail, const PieceContext& pc,
             CheckContext& ctx);

  // The first control point at which the separation claim fails, or nothing.
  std::optional<std::size_t> separation_fails_at(const Vec3E& n, std::uint32_t g, std::uint32_t h, const PieceContext& pc,
                          CheckContext& ctx);
};

}  // namespace tmcert::certificate::check_internal
