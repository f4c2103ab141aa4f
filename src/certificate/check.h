// The independent certificate checker (docs/certificate-format.md,
// proofs/certificates.md): re-verifies every claim of a
// tmcert-certificate/2 document in exact rational arithmetic.
//
// Independence: this code shares the scene reader (src/io, src/model) and the exact
// number type (kernels/number_types.h) with the verifier and nothing else:
// its Bernstein products, degree elevation, de Casteljau restriction, pose
// evaluation and ray test are its own, so a bug in src/motion, src/metric or
// src/verify cannot make a false certificate pass.
#pragma once

#include "kernels/number_types.h"
#include "src/model/model.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tmcert::certificate {

// Limits on hostile input (docs/certificate-format.md, "Limits").  A
// certificate beyond them is bad input (InputError, exit 3).
inline constexpr std::size_t kMaxNumberChars = 100'000;   // characters of one rational (above any scene number's p/q)
inline constexpr long kMaxDecimalExponent = 10'000;       // |exponent| of a decimal, and its scale
inline constexpr int kMaxProofDepth = 256;                // nested splits in one proof tree
inline constexpr std::size_t kMaxJsonNesting = 2 * kMaxProofDepth + 32;  // JSON levels of a file
inline constexpr std::uintmax_t kMaxFileBytes = 1ull << 31;

struct CheckOutcome {
  bool ok = false;
  // When !ok: one line naming the failing claim (docs "Failure messages").
  std::string message;
  // Per check of the scene, what was proven, e.g.
  // "gripper x table: safe proven (412 pieces, 9120 separations)".
  std::vector<std::string> proven;
};

// Checks `certificate` against `scene`.  Throws tmcert::InputError for a
// malformed certificate (the message names `source` and the JSON path).
// Returns ok = false, with the first failing claim, when a well-formed claim
// does not hold or the certificate belongs to another scene; may throw
// InputError naming the scene when the scene itself cannot be certified
// (two moving bodies of a check with different intervals).
CheckOutcome check_certificate(const Scene& scene, const nlohmann::json& certificate, const std::string& source);

// Reads a certificate file as JSON (size and nesting limits).  Throws
// InputError naming `path` when it cannot be read or is not JSON.
nlohmann::json read_certificate_file(const std::string& path);
// The same for a text held in memory; `source` names it in messages.
nlohmann::json parse_certificate_text(const std::string& text, const std::string& source);

// The elements of a body in the documented order (convex pieces, segments,
// points), each with its vertices in the body's frame.
std::vector<std::vector<Vec3E>> elements(const Body& body);

// The ray test of the start claims and of interior witnesses: the convex
// polygons `placed_polygons` (vertices in order, world coordinates), point
// p, direction d.  nullopt when the test is degenerate: d = 0, p on a
// polygon, the ray {p + s d : s > 0} through a vertex or an edge of a
// polygon, or lying in the plane of a polygon it meets (a polygon placed
// flat onto a line or point counts as degenerate when the ray meets it).
// Otherwise the number of polygons whose relative interior the ray crosses.
std::optional<int> ray_crossings(const std::vector<std::vector<Vec3E>>& placed_polygons, const Vec3E& p,
                                 const Vec3E& d);
// The same, counted per shell: `shell[i]` (>= 0) is the shell of polygon i
// (SCENE_FORMAT.md "Solids": the inside of a solid is the union of its
// shells' insides, so p is outside iff every count is even).
std::optional<std::vector<int>> ray_crossings(const std::vector<std::vector<Vec3E>>& placed_polygons,
                                              const std::vector<int>& shell, const Vec3E& p, const Vec3E& d);

// The exact pose of `body` at scene parameter t: its motion
// sum B_k(u) w_k A_k / sum B_k(u) w_k at u = (t - t0) / (t1 - t0) of the
// motion's own interval (meant for t in that interval), or the identity
// when the body has no motion.  Throws std::domain_error if the weight
// vanishes at t (impossible inside the interval).
Mat34E pose_at(const Body& body, const Exact& t);

namespace detail {
// For tests: min over `points` of alpha . x, by the separation test's
// integer evaluation (path 0: automatic, 1: multi-limb only, 2: GMP only).
Exact min_dot_for_testing(const std::array<Exact, 3>& alpha, const std::vector<Vec3E>& points, int path);
// For tests: the joint curve of bodies a and b (docs "The curve of a
// check") restricted to curve parameters [ua, ub] (0 <= ua < ub <= 1):
// per control point N_a (12, row-major), N_b (12), W.
std::vector<std::array<Exact, 25>> joint_control_points(const Body& a, const Body& b, const Exact& ua,
                                                        const Exact& ub);
}  // namespace detail

}  // namespace tmcert::certificate
