// Internal to src/verify: the search of one check: start check, pruned depth-first subdivision in
// parameter order, stop rules, witnesses (DESIGN.md sections 4-6,
// proofs/search-and-pruning.md, proofs/witness.md).
// The steps are split by topic (search_check.h); this header includes them
// all, with the start check and the partition.
#pragma once

#include "src/verify/search_check.h"
#include "src/verify/witness_search.h"
#include "src/verify/pair_pruning.h"
#include "src/verify/ordered_tasks.h"

#include <optional>
#include <vector>

namespace tmcert::detail {

// The start check (DESIGN.md section 4: the contact tests are complete
// only after a contact-free start), then the search.
template <int B>
void Check<B>::run() {
  bool uncertain = false;
  if (extras.start_proven_free) {
    // nothing to test at the start
  } else if (enlarged_pair(*moving.body, *other.body)) {
    // The polyhedra at the start: a contact there is proven on the true
    // shapes or leaves the whole part undecided (the contact tests are
    // complete only after a start free of contact of the polyhedra).
    bool touch = false;
    {
      CheckResult probe;
      Check sub = fork(probe);
      touch = sub.static_test(Exact(0), nullptr, &uncertain).has_value();
    }
    if (touch || uncertain) {
      if (true_witness(Exact(0), {})) {
        result.first_contact = std::pair{motion.t0, motion.t0};
        result.first_contact_exact = true;
        return;
      }
      if (true_witness_later(Exact(0), Exact(1, 1 << 20))) return;
      record(Node{0, 0, {}}, StopReason::EnlargedModel);
      ++result.stats.stops;
      return;
    }
  } else if (auto hit = static_test(Exact(0), nullptr, &uncertain)) {
    set_witness(Exact(0), *hit);
    result.first_contact = std::pair{motion.t0, motion.t0};
    result.first_contact_exact = true;
    return;
  }
  if (uncertain) {
    // An enclosed start configuration within rounding of contact: the
    // contact tests are complete only after a start proven free, so
    // nothing in this range can be cleared.
    record(Node{0, 0, {}}, StopReason::Epsilon);
    ++result.stats.stops;
    return;
  }
  if (!extras.start_proven_free && !extras.start_solids_proven) {
    // A join after a part that was not cleared entirely: a solid's
    // inside is contact there too (proofs/partition.md §3).
    const Apartness inside = containment_at(Exact(0));
    if (inside == Apartness::Contact) {
      result.first_contact = std::pair{motion.t0, motion.t0};
      result.first_contact_exact = true;
      return;
    }
    start_unproven = inside == Apartness::Unknown;
  }
  if (!extras.start_proven_free && enlarged_pair(*moving.body, *other.body) && extras.distance_witness()) {
    CheckResult probe;
    Check sub = fork(probe);
    if (sub.distance_witness(Exact(0), nullptr)) {  // within the clearance or tolerance on the polyhedra
      record(Node{0, 0, {}}, StopReason::EnlargedModel);
      ++result.stats.stops;
      return;
    }
  } else if (!extras.start_proven_free && distance_witness(Exact(0), nullptr)) {
    result.first_contact = std::pair{motion.t0, motion.t0};
    return;
  }
  if (extras.enclosed) {
    search(EnclosedPolicy<B>{FilteredPolicy<B>{moving, other, curve, 0, extras.clear}, *extras.enclosed});
  } else {
    switch (options.kernel) {
      case KernelKind::Filtered: search(FilteredPolicy<B>{moving, other, curve, extras.tube, extras.clear}); break;
      case KernelKind::Exact: search(ExactPolicy<B>{moving, other, curve, extras.tube, extras.clear}); break;
      case KernelKind::Fast: search(FastPolicy<B>{moving, other, curve, extras.tube, extras.clear}); break;
    }
  }
  secure_partition();
}

// Drops the cleared pieces (certificates' cover) inside [s, e] (scene
// parameters; without e: from s on).
template <int B>
void Check<B>::drop_cover(const Exact& s, const std::optional<Exact>& e) {
  if (result.cleared.empty()) return;
  const Exact us = curve_u(s);
  const std::optional<Exact> ue = e ? std::optional<Exact>(curve_u(*e)) : std::nullopt;
  std::erase_if(result.cleared, [&](const CoverPiece& c) {
    const Node n{c.index, c.depth, {}};
    return n.u0() >= us && (!ue || n.u1() <= *ue);
  });
}

// The partition's claims after the search (SCENE_FORMAT.md, "Every
// interval claim holds"; proofs/partition.md).  The contact tests clear a
// piece of contact that begins in it; a run of cleared pieces is free of
// contact when the bodies are apart at its start.  In parameter order:
// the bodies are apart at the range's start (its start check), and stay
// so over a cleared run that starts apart; after an undecided interval
// nothing is known (a stop's witness candidates test only the parts that
// own its live pairs, which need not hold a contact that began in the
// stop: an edge is listed with one of the faces that share it).  So a run
// that follows an undecided interval gets the test of the whole
// configuration at its start: free, the run stands; contact, that
// instant is the witness and nothing after it is claimed; neither, the
// run is undecided "after_undecided", and the next run is tested in turn.
template <int B>
void Check<B>::secure_partition() {
  std::vector<UndecidedInterval>& list = result.undecided;
  // The end of the claims: the witness's time, else the range's end.
  const Exact end = !result.witness ? motion.t1 : result.witness->root ? result.witness->root->hi : result.witness->t;
  bool apart = !start_unproven;
  Exact cursor = motion.t0;
  for (std::size_t k = 0; k <= list.size(); ++k) {
    const Exact run_end = k < list.size() ? list[k].t0 : end;
    if (cursor < run_end && !apart) {
      // At the range's start the test was just made (start_unproven).
      const Apartness at = cursor == motion.t0 ? Apartness::Unknown : free_at(curve_u(cursor));
      if (at == Apartness::Contact) {
        // The witness at `cursor`: nothing after it is claimed.
        list.resize(k);
        drop_cover(cursor, std::nullopt);
        const Exact lo = result.first_contact ? result.first_contact->first : cursor;
        result.first_contact = std::pair{std::min(lo, cursor), cursor};
        result.first_contact_exact = false;
        return;
      }
      if (at == Apartness::Free) {
        apart = true;
      } else {
        list.insert(list.begin() + static_cast<std::ptrdiff_t>(k),
                    UndecidedInterval{cursor, run_end, StopReason::AfterUndecided});
        drop_cover(cursor, run_end);
        if (!result.first_contact) result.first_contact = std::pair{cursor, run_end};
        else if (cursor < result.first_contact->first) result.first_contact->first = cursor;
        result.first_contact_exact = false;
        ++k;
      }
    }
    if (k >= list.size()) break;
    apart = false;  // after an undecided interval
    cursor = list[k].t1;
  }
}

}  // namespace tmcert::detail
