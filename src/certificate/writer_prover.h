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

// The shared proof nodes of one check (docs/certificate-format.md "Shared
// proof nodes"): each distinct node once, a separation {"sep": [n1, n2,
// n3]} (integers), an exact claim, or a split [s, k1, ..., km] whose parts
// are earlier nodes (children are added before their parent).
struct ProofNodes {
  std::vector<json> nodes;
  std::unordered_map<std::string, int> index;  // keyed by a byte string of the node
  // Per node, what the prover needs to try it again on another piece: a
  // separation found in double precision (its direction), a split (its
  // side and parts), or anything else (an exact direction or claim: found
  // again rather than reused).
  struct Reusable {
    enum Kind : char { kOther, kSeparation, kSplit } kind = kOther;
    int side = 0;
    std::array<double, 3> direction{};
    std::vector<int> parts;
  };
  std::vector<Reusable> reusable;

  // The number of a node (the existing one for an equal node): a
  // separation with direction n (a double direction, or an exact one), an
  // exact claim, a split.
  int separation(const std::array<double, 3>& n);
  int separation(const Vec3E& n);
  int exact_claim();
  int split(int side, const std::vector<int>& parts);

  // Node k written out as a tree (object forms only).
  json expand(int k) const;

  // The nodes reachable from `roots` (node numbers, rewritten in place),
  // renumbered in their order: the check's "nodes".
  json compact(const std::vector<json*>& roots) const;
};

// A direction scaled to coprime integers (a positive multiple: the same
// separation claim), JSON integers where they fit in 64 bits, else strings.
json integer_direction(const Vec3E& n);

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

  // The proof node an earlier piece used for a pair of groups: tried
  // first on the next piece (its separations certified again, its splits
  // followed without searching), so that only what fails is searched
  // again and an unchanged proof is the same node.
  mutable std::unordered_map<std::uint64_t, int> last;

  // The pairs from the root down to the last pair of leaves found
  // inseparable: visited first in a split, so that a piece that fails
  // there (to be bisected) fails before the rest is proven.
  mutable std::vector<std::uint64_t> path, hard;

  // Proofs begun (a split remembered from a neighbour is followed without
  // searching its pair again, except on every kRetry-th piece, where a
  // coarser proof is looked for).
  mutable std::uint64_t proofs = 0;
  static constexpr std::uint64_t kRetry = 8;

  // The check's proof nodes (shared by all its pieces).
  mutable ProofNodes nodes;

  // The proof of the pair (g, h) on the piece (a node of `nodes`), or
  // nothing.
  std::optional<int> prove(const PieceImages& im, const std::function<const CurveE&()>& exact, int g, int h) const;
};

}  // namespace tmcert::certificate::writer_internal
