// Steps of the ordered search that are not templates: a node's parameter and
// the merge of results in parameter order (search_check.h).
#include "src/verify/search_check.h"

#include <algorithm>

namespace tmcert::detail {

Exact Node::at(std::uint64_t k) const {
  CGAL::Gmpz den;
  mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
  return Exact(CGAL::Gmpz(static_cast<unsigned long>(k)), den);
}

// Adds `part`, the result of the parameter range right after everything in
// `total`, to `total`: statistics, cleared pieces, undecided intervals
// (joined where they abut with the same reason), the first-contact bracket
// and the witness.  False once a witness ends the search.
bool merge_result(CheckResult& total, const CheckResult& part) {
  CheckStats& s = total.stats;
  const CheckStats& p = part.stats;
  s.nodes += p.nodes;
  s.stops += p.stops;
  s.max_depth = std::max(s.max_depth, p.max_depth);
  s.contact += p.contact;
  for (int k = 0; k < 3; ++k) s.by_kind[k] += p.by_kind[k];
  s.static_tests += p.static_tests;
  s.static_configurations += p.static_configurations;
  s.static_filter_pairs += p.static_filter_pairs;
  s.static_filter_exact += p.static_filter_exact;
  s.sphere_tests += p.sphere_tests;
  s.slab_clears += p.slab_clears;
  s.swept_clears += p.swept_clears;
  s.hull_clears += p.hull_clears;
  s.axis_clears += p.axis_clears;
  s.exact_pieces += p.exact_pieces;
  s.exact_unknown += p.exact_unknown;
  total.cleared.insert(total.cleared.end(), part.cleared.begin(), part.cleared.end());
  for (const UndecidedInterval& u : part.undecided) {
    if (!total.undecided.empty() && total.undecided.back().t1 == u.t0 && total.undecided.back().reason == u.reason) {
      total.undecided.back().t1 = u.t1;
    } else {
      total.undecided.push_back(u);
    }
  }
  if (part.witness) {
    total.witness = part.witness;
    total.verdict = Verdict::Collision;
    total.first_contact_exact = part.first_contact_exact && !total.first_contact;
    const Exact lo = total.first_contact ? total.first_contact->first : part.first_contact->first;
    total.first_contact = std::pair{lo, part.first_contact->second};
    return false;
  }
  if (!total.first_contact && part.first_contact) total.first_contact = part.first_contact;
  return true;
}

}  // namespace tmcert::detail
