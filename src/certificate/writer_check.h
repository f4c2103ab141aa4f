// The certificate writer's checks (writer.cpp: pieces and proofs;
// writer_claims.cpp: witnesses and start claims, with their helpers).
#pragma once

#include "src/certificate/exact_claims.h"
#include "src/certificate/motions.h"
#include "src/certificate/writer_prover.h"
#include "kernels/real_roots.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::certificate::writer_internal {

// The body with its URDF cylinder or sphere polyhedron at `level`
// (writer_primitive.cpp); nullopt at level 0 (the scene's body).
std::optional<Body> at_level(const Body& body, int level);

// ---------------------------------------------------------------- witness helpers (writer_claims.cpp)

// Weights (one per vertex, >= 0, sum 1) placing the element's vertices
// under `m` exactly at p, if there are any among the vertices, pairs and fan
// triangles of the element.
std::optional<std::vector<Exact>> weights_at(const std::vector<Vec3E>& element, const Mat34E& m, const Vec3E& p);

// The elements a witness feature name ("<body> polygon 2", "<body> segment
// 0 end 1", "<body> point 3") can stand for.
std::vector<int> named_elements(const Body& body, const std::string& feature);

// The convex pieces of `solid` placed by m.
std::vector<std::vector<Vec3E>> placed_pieces(const Body& solid, const Mat34E& m);

// A ray direction from p whose crossings with the placed pieces of `solid`
// are well defined, from a fixed sequence of directions, and whether p is
// inside (an odd count for some shell: the inside is the union of the
// shells' insides).
std::optional<std::pair<Vec3E, bool>> ray_from(const Body& solid, const std::vector<std::vector<Vec3E>>& polygons,
                                               const Vec3E& p);

// det of m's linear part is 0.
bool singular(const Mat34E& m);

// Per element the root of its component (elements linked by exactly equal
// vertices), the first element of each component its own root.
std::vector<std::size_t> component_roots(const std::vector<std::vector<Vec3E>>& el);

// ---------------------------------------------------------------- one check

struct CheckWriter {
  const Scene& scene;
  const CheckResult& r;
  const Body& a;
  const Body& b;
  WriteStats& stats;
  std::pair<Exact, Exact> interval;
  CurveE joint;

  Exact scene_t(std::uint64_t index, int depth) const;

  Exact curve_u(std::uint64_t index, int depth) const;

  // Exact claims for the piece [u0, u1] of the curve (before `before` when
  // given): the scene's motions as polynomials, built once per check.
  mutable std::unique_ptr<CheckMotions> motions;
  void set_no_contact(const Prover& prover, const Exact& u0, const Exact& u1, const RealRoot* before) const;

  [[noreturn]] void fail(const std::string& what) const;

  std::vector<CoverPiece> cover() const;

  bool general() const { return general_check(a, b, r.clearance); }

  std::pair<Exact, Exact> piece_times(const CoverPiece& c) const;

  std::vector<std::pair<Exact, Exact>> general_cover() const;

  bool prove_general(const Prover& prover, const Exact& ta, const Exact& tb, int extra, const Exact& margin,
                     const std::array<Exact, 4> (&bounds)[2], bool partial, json& pieces);

  CurveE exact_piece(std::uint64_t index, int depth) const;

  void prove_piece(const Prover& prover, const CurveI& piece, std::uint64_t index, int depth, int extra,
                   json& pieces);

  json enclosed_witness(const Witness& w) const;
  json enclosed_clearance_witness(const Witness& w) const;

  json witness() const;

  // A witness proven on the true shape of a URDF cylinder or sphere
  // (writer_primitive.cpp, check_primitive.h).
  json true_shape_witness(const Witness& w) const;

  json algebraic_witness(const Witness& w) const;

  void before_witness(const Prover& prover, const Exact& from, json& out) const;

  void start(const Exact& at, json& out) const;

  // The pose start claims place a body by when it is exact (a rational
  // motion anywhere; a planner motion where its pose is exact), else none.
  std::optional<Mat34E> exact_start_pose(const Body& body, const Exact& at) const;

  // The start claim of solid k (0: a, 1: b) where a pose at `at` is not
  // exact: the other body's vertices enclosed in the solid's frame
  // (check_enclosed.h), one per component, each box clear of the solid's
  // polygons and its centre outside by a ray.
  void enclosed_start(int k, const Exact& at, json& out) const;

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

  json write();
};

}  // namespace tmcert::certificate::writer_internal
