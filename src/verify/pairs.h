// Internal to src/verify: the feature pairs a check carries, and their tables.
#pragma once

#include "src/verify/prepared.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tmcert::detail {

// ------------------------------------------------------------------ pairs

// A feature pair (nodes = false): feature i of the moving body's table of
// `kind` and feature j of the other body's table.  Or a pair of hierarchy
// nodes (nodes = true, kind unused): node i of the moving body's cell tree
// and node j of the other body's, standing for every feature pair of the
// three kinds under them (proofs/hierarchy.md section 4).
struct PairRef {
  ContactKind kind;
  bool nodes;
  // A feature pair: the depth of the piece where the hierarchy made it (0
  // for pairs carried from the root); the pieces above that depth are
  // re-tested at a stop so that the surviving pairs are those of all pairs.
  std::uint8_t born = 0;
  // A node pair carried to the sub-pieces by its slab test: how far its
  // slabs' gap fell short of the fattening when it was carried (a search
  // decision only, proofs/hierarchy.md §1b); 0 when not carried.
  std::uint8_t carried = 0;
  std::uint32_t i;
  std::uint32_t j;
};

static_assert(sizeof(PairRef) == 12, "alive lists hold many pairs: keep them small");

inline PairRef node_pair(std::uint32_t i, std::uint32_t j) { return {ContactKind::VertexFace, true, 0, 0, i, j}; }
inline PairRef feature_pair(ContactKind k, std::uint32_t i, std::uint32_t j, std::uint8_t born = 0) {
  return {k, false, born, 0, i, j};
}

inline const FeatureTable& moving_table(const PreparedBody& b, ContactKind k) {
  return k == ContactKind::VertexFace ? b.vertices : k == ContactKind::EdgeEdge ? b.edges : b.faces;
}
inline const std::vector<FeatureGeometry<Exact>>& moving_exact(const PreparedBody& b, ContactKind k) {
  const ExactFeatures& e = b.exact();
  return k == ContactKind::VertexFace ? e.vertices : k == ContactKind::EdgeEdge ? e.edges : e.faces;
}
inline const std::vector<FeatureGeometry<Exact>>& other_exact(const PreparedBody& b, ContactKind k) {
  const ExactFeatures& e = b.exact();
  return k == ContactKind::VertexFace ? e.faces : k == ContactKind::EdgeEdge ? e.edges : e.vertices;
}
inline const FeatureTable& other_table(const PreparedBody& b, ContactKind k) {
  return k == ContactKind::VertexFace ? b.faces : k == ContactKind::EdgeEdge ? b.edges : b.vertices;
}

// The three contact types over all features: complete for the first contact
// after a contact-free start (proofs/contact-tests.md).
// Without a hierarchy every pair is carried: refuse sizes whose lists could
// not be held (about 1.2 GB at the limit) rather than thrash.
constexpr std::size_t kMaxPairs = 100'000'000;

inline std::vector<PairRef> all_pairs(const PreparedBody& m, const PreparedBody& f) {
  std::size_t total = 0;
  for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex})
    total += moving_table(m, k).size() * other_table(f, k).size();
  if (total > kMaxPairs)
    throw ResourceLimit("check of \"" + m.body->name + "\" and \"" + f.body->name + "\": " + std::to_string(total) +
                        " feature pairs exceed the limit of " + std::to_string(kMaxPairs) +
                        " with --all-pairs (run without it: the hierarchy has no such limit)");
  std::vector<PairRef> pairs;
  pairs.reserve(total);
  for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
    const std::size_t nx = moving_table(m, k).size(), ny = other_table(f, k).size();
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        pairs.push_back(feature_pair(k, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)));
  }
  return pairs;
}


}  // namespace tmcert::detail
