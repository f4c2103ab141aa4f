// The certificate writer's proofs (docs/certificate-format.md "Proofs"):
// separating planes between the swept control points of groups of
// elements, found in double precision and confirmed with interval
// arithmetic on enclosures of the exact control points, exact directions
// where intervals do not resolve, and exact "no contact" claims for two
// elements no plane separates.
#pragma once

#include "src/certificate/writer_groups.h"

#include <functional>
#include <optional>
#include <unordered_map>

namespace tmcert::certificate::writer_internal {

// The two bodies' vertices under the control points of one piece: interval
// enclosures of the homogeneous images (N_l x^, not divided by the weight)
// for the certification, and doubles of the placed points for the search of
// a direction.
struct PieceImages {
  int count = 0;
  std::array<std::vector<std::array<Interval, 3>>, 2> box;   // [body][l * V + v]
  std::array<std::vector<std::array<double, 3>>, 2> point;   // same layout
  std::array<std::size_t, 2> size{};
  // A general check (checker: general_piece): each separation must hold
  // with W_l |n| margin + sum_i |n_i| penalty_i to spare (upper bounds).
  std::vector<Interval> weight;  // W_l
  double margin = 0;
  std::array<double, 3> penalty{0, 0, 0};
  bool margins() const { return margin > 0 || penalty[0] > 0 || penalty[1] > 0 || penalty[2] > 0; }
};

struct Prover {
  const std::array<const BodyGroups*, 2> groups;
  std::array<std::vector<std::array<Interval, 3>>, 2> vertex_box;  // enclosures of the exact vertices
  WriteStats& stats;
  mutable std::array<int, 2> failed{-1, -1};  // the last two elements found inseparable
  // For the current piece: does the exact "no contact" claim hold for two
  // elements (exact_claims.h)?  Tried where no separating plane is found.
  mutable std::function<bool(int, int)> no_contact;

  Prover(const BodyGroups& a, const BodyGroups& b, WriteStats& s);

  PieceImages images(const CurveI& piece) const;

  bool certify(const PieceImages& im, const std::array<double, 3>& n, int g, int h) const;

  static double dot(const std::array<double, 3>& a, const std::array<double, 3>& b);

  std::optional<std::array<double, 3>> separate(const PieceImages& im, int g, int h) const;

  std::optional<Vec3E> separate_exactly(const CurveE& piece, int g, int h,
                                        const std::optional<std::array<double, 3>>& hint) const;

  // The direction an earlier piece found for a pair of groups (neighbouring
  // pieces mostly share them).
  mutable std::unordered_map<std::uint64_t, std::optional<std::array<double, 3>>> memory;

  // The proof of the pair (g, h) on the piece, or nothing.
  std::optional<json> prove(const PieceImages& im, const std::function<const CurveE&()>& exact, int g, int h) const;
};

}  // namespace tmcert::certificate::writer_internal
