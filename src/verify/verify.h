// Certified verification of body pairs over their motion (paper Algorithms
// 1 and 2 as amended by DESIGN.md sections 4-6).
#pragma once

#include "kernels/filtered.h"
#include "src/model/model.h"
#include "src/verify/progress.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <ostream>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert {

enum class Verdict { Safe, Collision, Undecided };
enum class KernelKind { Filtered, Exact, Fast };
// Why a part of a check's interval was not cleared (SCENE_FORMAT.md, "Every
// interval claim holds"): the search stopped there (epsilon, depth), a
// budget ended the search (limit), or the part was cleared by contact tests
// that detect only the onset of contact, after a part that was not cleared,
// and the bodies could not be proven apart at its start (after_undecided;
// proofs/partition.md); enlarged_model: a URDF cylinder's or sphere's circumscribed polyhedron
// touches there, and neither a contact of the true shape nor its absence
// was proven (proofs/robot-links.md section 6).
enum class StopReason { Epsilon, Depth, Limit, AfterUndecided, EnlargedModel };

const char* to_string(Verdict v);
const char* to_string(KernelKind k);
const char* to_string(StopReason r);

inline std::ostream& operator<<(std::ostream& out, Verdict v) { return out << to_string(v); }

struct VerifyOptions {
  KernelKind kernel = KernelKind::Filtered;
  // The termination tolerance, > 0, a length in scene units.  Absent: each
  // check uses default_epsilon of its own two bodies (a scene's "epsilon"
  // or `--epsilon` sets it for every check).
  std::optional<Exact> epsilon;
  // Refinement (SCENE_FORMAT.md "Decisive by default", src/verify/refine.h):
  // a check that ends undecided has its undecided intervals searched again
  // at epsilon / 10, ..., down to epsilon / 10^6, within its time limit
  // (time_limit, else 30 s).  The command line, batch, the library and the
  // OMPL adapter set it when no epsilon is given (or `--epsilon auto`).
  bool refine = false;
  int max_depth = 40;
  std::uint64_t max_nodes = 2'000'000;  // per check; beyond it: undecided "limit"
  // Per check: after this many undecided stops (pieces that came within
  // epsilon, or reached the depth limit, without a witness), the rest of the
  // interval is undecided "limit" without being searched.  A motion that
  // stays within epsilon of contact along the whole interval (bodies
  // resting on each other) would otherwise be subdivided to epsilon
  // everywhere; the verdict is undecided from the first stop on anyway, and
  // the first-contact bracket comes from the first stop.
  std::uint64_t max_stops = 256;
  // Per check, in seconds (0: none given; `--time-limit`; with refinement
  // then 30 s: detail::check_time_limit).  When a check runs past it, the
  // pieces not yet searched are undecided "limit", never cleared: the search
  // looks at the clock where it counts its node budget (results then vary).
  double time_limit = 0;
  // The running check's deadline (set by Verifier from time_limit when the
  // check starts; max(): none).
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Bounding-volume hierarchies over the features (false: every feature pair
  // is carried from the root, the reference the hierarchy is checked against).
  bool hierarchy = true;
  // Threads for the pieces of one check (the result does not depend on it).
  int threads = 1;
  // Progress and cancellation (src/verify/progress.h): the run's shared
  // state (null: none; its cancel() stops every check as a time limit
  // does), and, set per check by Verifier::check, the check's share and
  // how many of its units the searched curve's parameter interval is worth
  // (a part of a keyframe check is worth its share of the check).
  RunProgress* run = nullptr;
  RunProgress::Slot* slot = nullptr;
  std::uint64_t slot_span = 0;
  // Decide the feature pairs alive on a piece exactly from the roots of
  // their contact polynomials (certified kernels; proofs/exact-resolution.md):
  // at a stop, and at once when few pairs are left.  false: the ball search
  // alone (as before exact resolution; for tests of its budgets and stops).
  bool exact_resolution = true;
  // Keep the pieces the search cleared (CheckResult::cleared), for
  // certificates.
  bool record_cover = false;
};

// An irrational parameter: the only root of `root_of` (integer
// coefficients, constant term first, square-free) in the open interval
// (lo, hi) (SCENE_FORMAT.md, "Exact contact times").
struct AlgebraicTime {
  std::vector<CGAL::Gmpz> root_of;
  Exact lo, hi;
  std::string approx;  // decimal, for people
};

// The check's deadline has passed (VerifyOptions::time_limit), or its run
// was cancelled.
inline bool past_deadline(const VerifyOptions& options) {
  if (options.run && options.run->cancelled()) return true;
  return options.deadline != std::chrono::steady_clock::time_point::max() &&
         std::chrono::steady_clock::now() >= options.deadline;
}

struct Witness {
  Exact t;                                  // scene parameter (with `root`: the lower end of its interval)
  std::array<std::string, 2> features;      // as the check names its bodies
  Vec3E point;                              // world coordinates, shared by both (when exact; unset with `root`)
  // A contact at an irrational parameter (exact resolution,
  // proofs/exact-resolution.md): its exact time.
  std::optional<AlgebraicTime> root{};
  // A rational box [lo, hi] per coordinate holding the common point, in
  // place of `point`: at an algebraic time (with `root`), or at a pose that
  // is only enclosed (a transcendental motion).
  std::optional<std::array<std::array<Exact, 2>, 3>> point_box;
  // Tolerance: the nominal poses do not touch, but translating body
  // `displaced` (0 or 1, in the check's order) by `displacement`, within its
  // tolerance, makes them touch at `point`.
  std::optional<Vec3E> displacement;
  int displaced = 0;
  // Both bodies toleranced: the other body (1 - displaced) translated too,
  // by `displacement_other`, within its own tolerance (only where neither
  // translation alone suffices; proofs/witness.md, two displacements).
  std::optional<Vec3E> displacement_other;
  // Clearance: a point of each body (in the check's order) no farther apart
  // than the clearance; `point` is the first of them.
  std::optional<std::array<Vec3E, 2>> points;
  // Clearance at a pose that is only enclosed (a transcendental motion), in
  // place of `points`: a rational box per body (in the check's order)
  // holding its point for every pose of the enclosure at `t`, the two
  // points no farther apart than the clearance for every such pose;
  // `point_box` is the first box.  `local_points`: the two points in their
  // bodies' own frames, exact (the certificate writer's witness).
  std::optional<std::array<std::array<std::array<Exact, 2>, 3>, 2>> points_box;
  std::optional<std::array<Vec3E, 2>> local_points;
  // Proven on the true shape of a URDF cylinder or sphere (a body of the
  // check has Body::primitive; src/verify/true_shape.h).
  bool true_shape = false;
  // With `true_shape` and `point_box` (the other body's pose only
  // enclosed): the proven point in the frame of side `local_side` (the body
  // that is not the primitive), exact; the certificate writer's witness.
  std::optional<Vec3E> local_point;
  int local_side = 1;
};

struct UndecidedInterval {
  Exact t0, t1;
  StopReason reason;
};

struct CheckStats {
  std::uint64_t nodes = 0;
  std::uint64_t stops = 0;       // undecided stops (epsilon or depth), at most VerifyOptions::max_stops
  int max_depth = 0;
  FilterCounters contact;        // all contact tests
  std::array<FilterCounters, 3> by_kind;  // vertex-face, edge-edge, face-vertex
  std::uint64_t static_tests = 0;
  // The interval filter in front of the exact static tests (start check and
  // witness candidates): configurations tested, simplex pairs it looked at
  // (interval boxes overlapping along x), and those it could not separate,
  // left to exact arithmetic (static_tests counts the exact tests run: fewer
  // when a hit ends the configuration early).
  std::uint64_t static_configurations = 0;
  std::uint64_t static_filter_pairs = 0;
  std::uint64_t static_filter_exact = 0;
  std::uint64_t sphere_tests = 0;  // hierarchy node pairs tested
  std::uint64_t slab_clears = 0;   // node pairs cleared by their slabs
  std::uint64_t swept_clears = 0;  // node and feature pairs cleared by the swept-sphere test (enclosed motions)
  std::uint64_t hull_clears = 0;   // feature pairs cleared by the hull test (contact test failed)
  std::uint64_t axis_clears = 0;   // contact tests settled by the axis test alone (not counted in `contact`)
  // Exact resolution (proofs/exact-resolution.md): pieces decided by the
  // contact polynomials' roots, and those it could not decide (a node pair
  // alive, or an iteration cap).
  std::uint64_t exact_pieces = 0;
  std::uint64_t exact_unknown = 0;
  bool prefiltered = false;      // cleared by the swept-box prefilter alone
  double seconds = 0;
};

// The piece [index, index + 1] / 2^depth of a check's curve parameter.
struct CoverPiece {
  std::uint64_t index = 0;
  int depth = 0;
  // The piece's scene interval, when it was searched on a part of the
  // check's interval (keyframe and piecewise motions, tolerances,
  // clearances: src/verify/general.cpp) rather than on the whole of it.
  bool timed = false;
  Exact t0 = 0, t1 = 0;
};

struct CheckResult {
  std::array<int, 2> bodies;  // indices into Scene::bodies, in the order of the check
  // The check's parameter interval (parameter_interval).  With a witness, the
  // part after the witness's time up to its end was not searched
  // ("not_searched" in tmcert-result/1).
  std::pair<Exact, Exact> interval{Exact(0), Exact(1)};
  // The refinement level of each body's URDF cylinder or sphere polyhedron
  // the result was found on (src/io/primitives.h; 0: the scene's, and for
  // every other body).  A certificate records it ("levels").
  std::array<int, 2> levels{0, 0};
  // The check's clearance (0: plain contact).  With clearance > 0 a
  // "collision" means the bodies come within it (clearance violated).
  Exact clearance = 0;
  Verdict verdict = Verdict::Undecided;
  // The termination tolerance this check ran with (VerifyOptions::epsilon,
  // or the check's default); after refinement the smallest one used.
  Exact epsilon = 0;
  // Its undecided parts were searched again with a smaller epsilon
  // (VerifyOptions::refine).
  bool refined = false;
  // Refinement ended undecided: at its floor (or with only parts no epsilon
  // changes: a start that no subdivision can decide) ...
  bool refine_exhausted = false;
  // ... or when the check's time limit (VerifyOptions::time_limit, else 30 s)
  // ran out.
  bool refine_out_of_time = false;
  std::optional<std::pair<Exact, Exact>> first_contact;
  // The first contact's time is known exactly: it is the witness's time
  // (first_contact then holds it, or with an algebraic witness the
  // rational bounds of its interval).
  bool first_contact_exact = false;
  std::optional<Witness> witness;
  std::vector<UndecidedInterval> undecided;
  // With VerifyOptions::record_cover: the pieces the search cleared,
  // disjoint, in the order the search's tasks were merged (sort them by
  // their start for parameter order); empty for a check decided without a
  // search (prefiltered, motionless, or a collision at the start).
  std::vector<CoverPiece> cleared;
  CheckStats stats;
};

// The parameter interval of a check of bodies a and b: the motion interval
// of a if a moves, else of b if b moves, else of a if a has a motion, else
// of b if b has one, else [0, 1] (docs/certificate-format.md).
std::pair<Exact, Exact> parameter_interval(const Body& a, const Body& b);

struct SceneResult {
  Verdict verdict = Verdict::Safe;
  KernelKind kernel = KernelKind::Filtered;
  bool certified = true;
  // VerifyOptions::epsilon when given; otherwise (epsilon_per_check) the
  // largest of the checks' default tolerances, each in CheckResult::epsilon.
  Exact epsilon;
  bool epsilon_per_check = false;
  // VerifyOptions::refine: the checks refined their undecided parts (each
  // check's epsilon is then the smallest it used).
  bool refine = false;
  // The limits the checks ran under (VerifyOptions), for reports that say
  // what to change when a check stops undecided.
  int max_depth = 40;
  std::uint64_t max_nodes = 0;
  std::uint64_t max_stops = 0;
  double time_limit = 0;
  std::vector<CheckResult> checks;
};

// 1/1000 of the scene's box diagonal (rounded up), as a decimal with six
// significant digits (a tolerance, not a bound: no guarantee depends on it).
// The box holds each body's local bounding box placed by every pose of its
// motion (control points of rational motions, keyframe poses, a link's
// poses at its waypoints), computed in interval arithmetic.
Exact default_epsilon(const Scene& scene);
// The same for one check: 1/1000 of the diagonal of the box of its two
// bodies over their whole motion (what a check uses when neither the scene
// nor VerifyOptions gives an epsilon), so that bodies far away elsewhere in
// the scene do not coarsen it.
Exact default_epsilon(const Body& a, const Body& b);

// Throws InputError when the scene cannot be verified as built in code (a
// solid that is not closed shells, nothing to check).  Called before any
// verdict is printed.
void require_supported(const Scene& scene);

class PreparedBody;
struct SweptBox;
class ClosedSurface;

// Verifies checks of one scene.  Bodies are prepared lazily, once, on first
// use, and only when the cheap certified prefilter (disjoint boxes around
// everything each body sweeps) cannot clear a check; so a scene with
// thousands of small bodies costs little per check.  check() is thread-safe.
class Verifier {
 public:
  Verifier(const Scene& scene, const VerifyOptions& options);
  ~Verifier();
  Verifier(const Verifier&) = delete;
  Verifier& operator=(const Verifier&) = delete;

  CheckResult check(int body_a, int body_b) const;
  // With a minimum separation: safe means the bodies stay farther apart
  // than `clearance` (SCENE_FORMAT.md "Tolerance and clearance").
  CheckResult check(int body_a, int body_b, const Exact& clearance) const;

 private:
  const PreparedBody& prepared(int body) const;
  // check() with the check's own options (its deadline and epsilon set).
  CheckResult check_with(int body_a, int body_b, const Exact& clearance, const VerifyOptions& options) const;
  // Checks with a keyframe or piecewise motion, a tolerance or a clearance:
  // the parameter interval cut at every segment join, each part searched in
  // order (src/verify/general.cpp).
  CheckResult check_general(int body_a, int body_b, const Exact& clearance, const VerifyOptions& options) const;
  // A solid body's surface at the start parameter (null when its pose there
  // is singular), built once; the start vertices of a body's components.
  const ClosedSurface* start_surface(int body) const;
  std::vector<std::pair<std::string, Vec3E>> start_representatives(const Body& body) const;

  const Scene& scene_;
  VerifyOptions options_;
  std::vector<SweptBox> boxes_;
  // Per body: -1 when it does not move, else an index of its motion
  // interval among the scene's distinct ones (two moving bodies in a check
  // must share it).  Kept here so that a check the boxes clear touches no
  // exact number.
  std::vector<int> interval_;
  // Per body, without a given epsilon: the box of its local bounding box
  // under every pose of its motion (for the check's default epsilon).
  std::vector<std::optional<std::array<std::array<double, 3>, 2>>> reach_;
  std::unique_ptr<std::once_flag[]> once_;
  mutable std::vector<std::unique_ptr<PreparedBody>> prepared_;
  std::unique_ptr<std::once_flag[]> surface_once_;
  mutable std::vector<std::unique_ptr<ClosedSurface>> surfaces_;
};

// Verifies one check (a pair of body indices).
CheckResult verify_check(const Scene& scene, int body_a, int body_b, const VerifyOptions& options);

// Verifies every check of the scene, on up to `threads` threads; the result
// does not depend on `threads`.
SceneResult verify_scene(const Scene& scene, const VerifyOptions& options, int threads = 1);

}  // namespace tmcert
