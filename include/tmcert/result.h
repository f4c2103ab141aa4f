// The result of verify(): per check a verdict with its proof data, exact
// values (Rational, Time) for proofs next to doubles for people, and the
// same result as the tmcert-result/1 document the command line prints.
#pragma once

#include "tmcert/export.h"
#include "tmcert/numbers.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tmcert::api {

enum class Verdict {
  Safe,       // certified: the bodies share no point at any parameter (with a clearance: stay farther apart)
  Collision,  // certified by an exact witness: a parameter at which they share a point (come within the clearance)
  Undecided   // neither was proven (a limit was hit); see CheckResult::undecided
};

// How verify() computes (VerifyOptions::kernel).
enum class Kernel {
  Filtered,  // certified: interval filters with exact fallback (default)
  Exact,     // certified: exact arithmetic throughout (slow, the reference)
  Fast       // plain double precision: NOT certified, and the result says so
};

// Why an interval was left undecided.
enum class StopReason {
  Epsilon,         // the bodies come within about epsilon there
  Depth,           // the subdivision depth limit was reached
  Limit,           // a node, stop or time limit
  AfterUndecided,  // cleared only of contact beginning there, after a part not cleared,
                   // and the bodies were not proven apart at its start
  // A URDF cylinder's or sphere's circumscribed polyhedron touches there,
  // and neither a contact of the true shape nor its absence was proven.
  EnlargedModel
};

// "safe", "collision", "undecided"; "filtered", "exact", "fast";
// "epsilon", "depth", "limit", "after_undecided", "enlarged_model" (as in
// tmcert-result/1).
TMCERT_API const char* to_string(Verdict v);
TMCERT_API const char* to_string(Kernel k);
TMCERT_API const char* to_string(StopReason r);

// Where and when two bodies provably touch (or, with a clearance, come
// within it).  Coordinates are world coordinates.
struct Witness {
  Time t;                                // the parameter
  std::array<std::string, 2> features;   // e.g. "gripper polygon 0 vertex 2", "table polygon 0"
  // The common point, exact (absent at an algebraic time or an enclosed
  // pose: then point_box holds it).
  std::optional<std::array<Rational, 3>> point;
  // A rational box [lo, hi] per coordinate holding the common point.
  std::optional<std::array<std::array<Rational, 2>, 3>> point_box;
  // With a clearance: a point of each body (in the check's order) no
  // farther apart than the clearance.
  std::optional<std::array<std::array<Rational, 3>, 2>> points;
  // With a tolerance: body `displaced` translated by `displacement` (within
  // its tolerance) touches at the point.
  std::optional<std::array<Rational, 3>> displacement;
  std::string displaced;  // a body name, when displacement is set
  // Both bodies toleranced, where neither translation alone suffices: the
  // other body `displaced_other` translated too, by `displacement_other`
  // (within its own tolerance).
  std::optional<std::array<Rational, 3>> displacement_other;
  std::string displaced_other;  // a body name, when displacement_other is set
  // The point (or the centre of point_box) as doubles, for people.
  std::array<double, 3> point_approx{0, 0, 0};
};

struct UndecidedInterval {
  Rational t0, t1;
  StopReason reason = StopReason::Epsilon;
};

// The work a check took (for people and tuning; keys of the JSON "stats").
struct CheckStats {
  std::uint64_t nodes = 0;            // search nodes
  int max_depth = 0;                  // deepest subdivision reached
  std::uint64_t predicate_calls = 0;  // contact tests
  std::uint64_t exact_fallbacks = 0;  // of them decided in exact arithmetic
  std::uint64_t stops = 0;            // undecided stops
  std::uint64_t exact_pieces = 0;     // pieces decided from the contact polynomials' roots
  std::uint64_t exact_undecided = 0;  // pieces that could not be decided so
  bool prefiltered = false;           // cleared by the swept-box prefilter alone
  double seconds = 0;                 // wall time (not deterministic)
};

struct CheckResult {
  std::array<std::string, 2> bodies;  // names, in the check's order
  Verdict verdict = Verdict::Undecided;
  // The termination tolerance this check ran with: the given one, or the
  // check's default (1/1000 of the box of its two bodies' motion); when
  // refined, the smallest one used.
  Rational epsilon;
  // Its undecided parts were searched again at smaller epsilons
  // (refinement: no epsilon given, or "auto"; VerifyOptions::epsilon).
  bool refined = false;
  Rational clearance;                 // 0: plain contact
  bool clearance_violated = false;    // clearance > 0 and verdict Collision
  bool enlarged_model = false;        // a body is a circumscribed model of its URDF shapes
  // Brackets the earliest possible contact: everything before its lower
  // end is certified free of contact.  Absent when the check is safe.
  std::optional<std::array<Time, 2>> first_contact;
  bool first_contact_exact = false;   // the witness's time is the first contact
  std::optional<Witness> witness;     // present iff verdict is Collision
  // The check's interval is partitioned into the parts certified safe (no
  // contact; everything below not listed), `undecided`, and with a witness
  // its time and after it `not_searched`, nothing else (SCENE_FORMAT.md,
  // "Every interval claim holds").
  std::vector<UndecidedInterval> undecided;
  std::array<Rational, 2> interval;   // the check's parameter interval
  // With a witness: [its time, the interval's end], where nothing was
  // searched (the witness ends the claims).
  std::optional<std::array<Time, 2>> not_searched;
  CheckStats stats;
};

class TMCERT_API Result {
 public:
  // Collision if any check is, else Undecided if any check is, else Safe.
  Verdict verdict() const;
  Kernel kernel() const;
  bool certified() const;  // false only for the fast kernel
  // The epsilon given (options or scene), or else the largest of the
  // checks' own (CheckResult::epsilon: their defaults, or with refinement
  // the smallest each used), as the JSON's "epsilon".
  const Rational& epsilon() const;
  const std::vector<CheckResult>& checks() const;
  // The scene's notes and warnings (Scene::notes(), Scene::warnings()), as
  // the result document's "notes" and "warnings".
  const std::vector<std::string>& notes() const;
  const std::vector<std::string>& warnings() const;

  // The tmcert-result/1 document, byte for byte what `tmcert verify --json`
  // prints for the same scene and options (up to the "seconds").
  std::string to_json() const;
  // The human summary `tmcert verify` prints.
  std::string summary() const;

  // The tmcert-certificate/1 document of this result (docs/
  // certificate-format.md), for `tmcert check` or check_certificate().
  // Needs VerifyOptions::certificate; throws InputError otherwise.
  std::string certificate() const;
  // Writes certificate() to `path`.  Throws InputError, before anything is
  // written, when the path is empty, a directory, cannot be written, or is
  // one of the files the scene was read from; ResourceLimit when the write
  // fails (a full disk), leaving no partial file (docs/scene-format.md
  // "Output paths").
  void write_certificate(const std::string& path) const;

  // The visual report (`tmcert verify --report`): one self-contained HTML
  // page showing the scene, the motion and this result.
  std::string report_html() const;
  // Writes report_html() to `path`, with the rules of write_certificate().
  void write_report(const std::string& path) const;

  // Internal (src/api/).
  struct Impl;
  explicit Result(std::shared_ptr<const Impl> impl);

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
