// The certificate checker's separation test (docs/certificate-format.md
// "Separations", proofs/certificates.md): a piece's joint control points,
// a body's vertices and a direction brought to integers over common positive
// denominators, and the linear forms over a group's vertices evaluated in
// integers: a fixed-size multi-limb evaluation with 128-bit accumulators
// when the numbers fit (60-bit limbs, coordinates below 2^62), GMP integers
// otherwise.  Also the bodies' element data and the groups of a check.
#pragma once

#include "src/certificate/check_bernstein.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace tmcert::certificate::check_internal {

constexpr int kMaxLimbs = 8;  // 60-bit limbs of a linear form in the fast path

// Points as integers over one positive common denominator D: X = x D.
struct Coords {
  Z D{1};
  std::vector<Z> X;                 // 3 per point
  bool fits64 = false;              // every |X| < 2^62
  std::vector<std::int64_t> X64;    // 3 per point, when fits64
};

Coords make_coords(const std::vector<Vec3E>& points);

// min over the listed points (ids into c) of alpha . X, exactly, into out.
// path: 0 automatic, 1 limbs only (must fit; else std::logic_error), 2 GMP
// only.
void min_dot(const Z* alpha, const Coords& c, const std::uint32_t* ids, std::size_t count, mpz_t out,
             int path = 0);

// ---------------------------------------------------------------- bodies

struct BodyData {
  const Body* body = nullptr;
  std::vector<std::vector<Vec3E>> elems;
  std::vector<std::vector<std::uint32_t>> elem_ids;  // distinct-vertex ids per element
  std::vector<Vec3E> vertices;                       // distinct vertices
  Coords coords;
  std::vector<std::size_t> component;  // per element: smallest element of its component (lazy)
};

std::unique_ptr<BodyData> make_body_data(const Body& b);

// Components of a body: elements linked by shared (exactly equal) vertices;
// per element the smallest element of its component.
const std::vector<std::size_t>& components(BodyData& d);

// ---------------------------------------------------------------- groups

struct GroupSet {
  BodyData* body = nullptr;
  std::vector<char> leaf;                          // per group
  std::vector<std::vector<std::uint32_t>> items;   // elements or children
  std::vector<std::vector<std::uint32_t>> cache;   // distinct vertex ids (when cached)
  std::vector<char> cached;
  std::vector<std::uint32_t> group_stamp, vertex_stamp;
  std::uint32_t stamp = 0;

  // Distinct vertex ids of every element reachable from group g.
  const std::vector<std::uint32_t>& vertices(std::uint32_t g, std::vector<std::uint32_t>& scratch,
                                             std::size_t& budget) {
    if (cached[g]) return cache[g];
    if (++stamp == 0) {  // wrapped: reset the stamps
      std::fill(group_stamp.begin(), group_stamp.end(), 0);
      std::fill(vertex_stamp.begin(), vertex_stamp.end(), 0);
      stamp = 1;
    }
    scratch.clear();
    std::vector<std::uint32_t> stack{g};
    group_stamp[g] = stamp;
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      if (leaf[k]) {
        for (std::uint32_t e : items[k])
          for (std::uint32_t v : body->elem_ids[e])
            if (vertex_stamp[v] != stamp) {
              vertex_stamp[v] = stamp;
              scratch.push_back(v);
            }
      } else {
        for (std::uint32_t c : items[k])
          if (group_stamp[c] != stamp) {
            group_stamp[c] = stamp;
            stack.push_back(c);
          }
      }
    }
    if (scratch.size() <= budget) {
      budget -= scratch.size();
      cache[g] = scratch;
      cached[g] = 1;
      return cache[g];
    }
    return scratch;
  }
};

// ---------------------------------------------------------------- pieces

// A piece's restricted joint control points as integers: for each control
// point l, 24 integers Ñ = Q_l N (Q_l > 0, one per control point), the two
// 3x4 blocks row-major.
struct PieceInts {
  std::vector<Z> v;  // 24 per control point
  std::size_t count = 0;
  std::vector<Exact> q, w;  // Q_l and W_l per control point
  std::vector<Z> qz;        // Q_l as integers
};

// W_l > 0 is required (else std::logic_error): the separation argument
// needs positive weights.
PieceInts integer_control_points(const std::vector<CP>& c);

// What a separation claim is checked against on one piece: the integer
// control points, and for a general check the margins (docs "Planner
// motions, tolerances and clearances").
struct SeparationPiece {
  PieceInts ints;
  // A general check: every separation holds with W_l |n| margin +
  // sum_i |n_i| penalty_i to spare (penalty: the pose boxes' radii).
  bool margins = false;
  std::array<Exact, 3> penalty{Exact(0), Exact(0), Exact(0)};
  // The penalty as integers over one positive denominator (the integer
  // path when there is no margin).
  std::array<Z, 3> penalty_num;
  Z penalty_den{1};
};

// Scratch integers of the separation test (reused between claims).
struct SeparationScratch {
  Z L, f, nn[3], alpha[4], beta[4], mina, minb, lhs, t;
};

// The first control point of the piece at which the claim "direction n
// separates the vertices va of body a (coordinates ca) from the vertices vb
// of body b (cb)" fails, or nothing when it holds at every control point.
// dadb = D_a D_b; margin as in SeparationPiece.
std::optional<std::size_t> separation_fails_at(const Vec3E& n, const std::vector<std::uint32_t>& va, const Coords& ca,
                        const std::vector<std::uint32_t>& vb, const Coords& cb, const SeparationPiece& pc,
                        const Z& dadb, const Exact& margin, SeparationScratch& z);

}  // namespace tmcert::certificate::check_internal
