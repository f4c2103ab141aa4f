// Checks beyond one rational Bezier motion per body: keyframe and piecewise
// motions, tolerances and clearances (SCENE_FORMAT.md, final section).  The
// check's parameter interval is cut at every join of either body's
// segments; each part is searched in parameter order with its own start
// check (a join is a start like any other: the contact tests are complete
// after a configuration proven free, proofs/enclosures.md section 7; a join
// that the part before cleared needs none), and
// the parts' results are merged as the search merges its tasks (on several
// threads the parts run at once and the merge replays the sequential
// order: proofs/enclosures.md section 7).  A part
// where every moving body is rational runs the rational search on the
// exact restriction of the curves; a part with an enclosed (transcendental)
// motion runs the Taylor-enclosure search.
#include "src/verify/verify.h"

#include "src/model/segment_kind.h"
#include "src/motion/segment.h"
#include "src/verify/prepared.h"
#include "src/verify/prepared_pair.h"
#include "src/verify/search.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <thread>
#include <vector>

namespace tmcert {

namespace {

using detail::Check;
using detail::CheckExtras;
using detail::EnclosedSource;

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// One body's motion on a part [t0, t1] of the check's interval.
struct PartMotion {
  std::optional<Motion> rational;           // exact, over [t0, t1]
  const MotionSegment* segment = nullptr;   // else: this enclosed segment ...
  Exact s0, s1;                             // ... over these segment parameters
};

PartMotion part_motion(const Body& b, const Exact& t0, const Exact& t1) {
  PartMotion out;
  if (b.trajectory) {
    for (const MotionSegment& seg : b.trajectory->segments) {
      if (!(seg.t0 <= t0 && t1 <= seg.t1)) continue;
      if (const Motion* rational = kind_of(seg).rational(seg)) {
        out.rational = restrict_motion(*rational, t0, t1);
      } else {
        out.segment = &seg;
        out.s0 = (t0 - seg.t0) / (seg.t1 - seg.t0);
        out.s1 = (t1 - seg.t0) / (seg.t1 - seg.t0);
      }
      return out;
    }
  }
  if (b.motion && b.motion->degree() >= 1) {
    out.rational = restrict_motion(*b.motion, t0, t1);
    return out;
  }
  Motion still;  // a body standing still (moved only within its tolerance)
  still.t0 = t0;
  still.t1 = t1;
  still.control_points = {b.motion ? b.motion->control_points[0] : kIdentity};
  still.weights = {Exact(1)};
  out.rational = still;
  return out;
}

Exact mass_sum(const Body& b) {
  Exact w = 0;
  for (const Exact& x : b.mass.weights) w += x;
  return w;
}

template <int B>
void run_part(const PreparedBody& m, const PreparedBody& o, bool swapped, const PartMotion& pm, const PartMotion& po,
              const Exact& t0, const Exact& t1, const VerifyOptions& options, const std::array<double, 2>& tube,
              const CheckExtras<B>& base, CheckResult& part) {
  const double eps = CGAL::to_double(*options.epsilon);
  const double rho2 = m.max_rho2 + (B == 2 ? o.max_rho2 : 0.0);
  CheckExtras<B> extras = base;
  const bool rational = pm.rational && (B == 1 || po.rational);
  if (rational) {
    HomogeneousCurve<Exact, B> curve;
    if constexpr (B == 1) curve = homogeneous_curve(*pm.rational);
    else curve = joint_curve(*pm.rational, *po.rational);
    {
      RoundingGuard guard;
      const Interval t = B == 1 ? Interval(tube[0]) : CGAL::sqrt(CGAL::square(Interval(tube[0])) + CGAL::square(Interval(tube[1])));
      extras.tube = t.sup();
    }
    Check<B> check{m, o, swapped, curve, enclose(curve), *pm.rational, eps * eps, rho2, options, part, extras};
    check.run();
    return;
  }
  std::array<std::unique_ptr<SegmentModel>, B> models;
  EnclosedSource<B> source;
  const PartMotion* pms[2] = {&pm, &po};
  const PreparedBody* bodies[2] = {&m, &o};
  for (int b = 0; b < B; ++b) {
    const PartMotion& p = *pms[b];
    if (p.rational) {
      models[b] = make_bezier_model(*p.rational);
      source.s0[b] = 0;
      source.s1[b] = 1;
    } else {
      models[b] = make_segment_model(*p.segment);
      source.s0[b] = p.s0;
      source.s1[b] = p.s1;
    }
    source.models[b] = models[b].get();
    source.metrics[b] = &bodies[b]->metric_data;
    source.tube[b] = tube[b];
  }
  extras.enclosed = &source;
  Motion span;
  span.t0 = t0;
  span.t1 = t1;
  const HomogeneousCurve<Exact, B> none;
  Check<B> check{m, o, swapped, none, {}, span, eps * eps, rho2, options, part, extras};
  check.run();
}

}  // namespace

CheckResult Verifier::check_general(int a, int b, const Exact& clearance, const VerifyOptions& options) const {
  return detail::check_prepared_pair(prepared(a), prepared(b), {a, b}, clearance, options);
}

CheckResult detail::check_prepared_pair(const PreparedBody& pa, const PreparedBody& pb, std::array<int, 2> ids,
                                        const Exact& clearance, const VerifyOptions& options,
                                        bool start_proven_free,
                                        const std::optional<std::pair<Exact, Exact>>& window) {
  const auto started = std::chrono::steady_clock::now();
  CheckResult result;
  result.bodies = ids;
  result.clearance = clearance;
  result.interval = parameter_interval(*pa.body, *pb.body);
  const bool swapped = !pa.moving && pb.moving;
  const PreparedBody& m = swapped ? pb : pa;
  const PreparedBody& o = swapped ? pa : pb;
  const Body& mb = *m.body;
  const Body& ob = *o.body;

  auto finish = [&] {
    for (const FilterCounters& c : result.stats.by_kind) result.stats.contact += c;
    if (result.verdict != Verdict::Collision)
      result.verdict = result.undecided.empty() ? Verdict::Safe : Verdict::Undecided;
    if (result.verdict == Verdict::Safe) result.first_contact.reset();
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
  };

  if (!m.moving) {
    // Two bodies standing still, only a clearance: one exact static test,
    // then the exact distance.
    const Exact t0 = mb.motion ? mb.motion->t0 : ob.motion ? ob.motion->t0 : Exact(0);
    CheckStats& stats = result.stats;
    std::optional<std::pair<std::string, std::string>> names;
    if (auto hit = detail::first_hit(m.parts, o.parts, nullptr, stats)) {
      Witness w{t0, {mb.name + " " + m.parts[hit->part_moving].name, ob.name + " " + o.parts[hit->part_other].name}, hit->point};
      if (swapped) std::swap(w.features[0], w.features[1]);
      result.witness = w;
    } else if (auto near = detail::closest_within(m.parts, nullptr, o.parts, nullptr, clearance * clearance, nullptr, stats)) {
      Witness w{t0, {mb.name + " " + m.parts[near->part_a].name, ob.name + " " + o.parts[near->part_b].name}, near->points.a};
      w.points = std::array{near->points.a, near->points.b};
      if (swapped) {
        std::swap(w.features[0], w.features[1]);
        std::swap((*w.points)[0], (*w.points)[1]);
        w.point = (*w.points)[0];
      }
      result.witness = w;
    }
    if (result.witness) {
      result.verdict = Verdict::Collision;
      result.first_contact = std::pair{t0, t0};
    }
    return finish();
  }

  // The check's interval and its joins.
  const auto interval = window                     ? *window
                        : mb.moves()               ? *mb.interval()
                        : ob.moves()               ? *ob.interval()
                        : mb.motion                ? *mb.interval()
                                                   : std::pair{Exact(0), Exact(1)};
  std::vector<Exact> cuts = {interval.first, interval.second};
  for (const Body* body : {&mb, &ob})
    if (body->trajectory)
      for (const MotionSegment& seg : body->trajectory->segments)
        for (const Exact& t : {seg.t0, seg.t1})
          if (interval.first < t && t < interval.second) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  // Tubes: each body's tolerance (proofs/enclosures.md section 6).  The
  // clearance is no tube: every test asks for a distance above it instead
  // (proofs/clearance.md).  The mass sums only where a tolerance needs them
  // (a sum over every mass point: noticeable per check for a large fixed
  // body).
  const Exact wm = mb.tolerance > 0 ? mass_sum(mb) : Exact(1);
  const Exact wo = ob.tolerance > 0 ? mass_sum(ob) : Exact(1);
  std::array<double, 2> tube = {to_interval(mb.tolerance).sup(), o.moving ? to_interval(ob.tolerance).sup() : 0.0};
  const bool two = o.moving;
  CheckExtras<1> e1;
  CheckExtras<2> e2;
  e1.clearance2 = e2.clearance2 = clearance * clearance;
  e1.clear = e2.clear = to_interval(clearance).sup();
  e1.reach2 = e2.reach2 = {mb.tolerance * mb.tolerance / wm, ob.tolerance * ob.tolerance / wo};
  // The first part's start: proven free by the caller, or tested by the search.
  e1.start_proven_free = e2.start_proven_free = start_proven_free;

  // Part k of the check, searched with `start_free` (its start proven free:
  // by the caller for the first part, by the part before it otherwise) on
  // `threads` threads (the result does not depend on them).
  const std::size_t parts = cuts.size() - 1;
  auto run_one = [&](std::size_t k, bool start_free, int threads, CheckResult& part) {
    const Exact &t0 = cuts[k], &t1 = cuts[k + 1];
    const PartMotion pm = part_motion(mb, t0, t1);
    const PartMotion po = two ? part_motion(ob, t0, t1) : PartMotion{};
    // The part's share of the check's progress (src/verify/progress.h).
    VerifyOptions part_options = options;
    part_options.threads = threads;
    if (options.slot)
      part_options.slot_span = static_cast<std::uint64_t>(static_cast<double>(options.slot_span) *
                                                          CGAL::to_double((t1 - t0) / (interval.second - interval.first)));
    CheckExtras<1> x1 = e1;
    CheckExtras<2> x2 = e2;
    x1.start_proven_free = x2.start_proven_free = start_free;
    // Only the first part's start containment of solids is the caller's,
    // and only at the check's own start: a window of a refinement
    // (src/verify/refine.h) starts inside the check, where a start test
    // must test the containment too (proofs/partition.md section 3).
    x1.start_solids_proven = x2.start_solids_proven = k == 0 && !window;
    if (two) run_part<2>(m, o, false, pm, po, t0, t1, part_options, tube, x2, part);
    else run_part<1>(m, o, swapped, pm, po, t0, t1, part_options, tube, x1, part);
    if (options.record_cover)  // the part's pieces as scene intervals, for certificates
      for (CoverPiece& c : part.cleared)
        if (!c.timed) {
          CGAL::Gmpz pieces;  // 2^depth
          mpz_setbit(pieces.mpz(), static_cast<mp_bitcnt_t>(c.depth));
          const Exact unit = (t1 - t0) / Exact(pieces);
          c.t0 = t0 + unit * Exact(CGAL::Gmpz(static_cast<unsigned long>(c.index)));
          c.t1 = c.t0 + unit;
          c.timed = true;
        }
  };

  // Several parts and threads: the parts run at once, each as if the part
  // before it were cleared entirely (the common case: its start then needs
  // no test), the threads left over spread over each part's pieces.  Then,
  // at once again, the parts after a part whose run was not cleared
  // entirely, with their start tests (a run with the start test is never
  // more cleared than one without: the search after the test is the same,
  // so the sequential search tests these starts whatever the part before
  // assumed).  The merge below replays the sequential search: a part whose
  // assumption turns out false, or that was not run (after a witness, past
  // the time limit), is searched again there, alone, as the sequential
  // search would have.  So the result is the sequential one for every
  // thread count (proofs/enclosures.md section 7).
  // A part's run is kept per start assumption: `ahead[k]` as first
  // scheduled (start free, the first part as the caller says), `tested[k]`
  // with its start test.  The worker that finishes a part not cleared
  // entirely runs the next part with its start test at once, before any
  // part further ahead: that is the run the merge will need there, and
  // leaving it to a second round left it to be run after every part ahead,
  // so that past a time limit the merge stopped at it and dropped the
  // valid runs after it (escape, OMPL.app: stuck at t = 8 with two threads).
  struct Speculative {
    CheckResult part;
    bool done = false;
    bool start_free = false;  // what the run assumed
    std::exception_ptr error;
  };
  std::vector<Speculative> ahead, tested;
  // One worker per slot: the first to claim it runs it (two runs of part
  // k, with and without its start test, may both end not cleared and both
  // reach for part k + 1 with its start test).
  std::unique_ptr<std::atomic<bool>[]> claimed;
  if (options.threads > 1 && parts > 1) {
    ahead.resize(parts);
    tested.resize(parts);
    claimed.reset(new std::atomic<bool>[2 * parts]);
    for (std::size_t i = 0; i < 2 * parts; ++i) claimed[i].store(false);
    std::atomic<std::size_t> first_witness{parts};
    // Runs the parts `jobs` (in parameter order) with the given start
    // assumptions on up to options.threads threads.
    auto round = [&](const std::vector<std::pair<std::size_t, bool>>& jobs) {
      const int workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(options.threads), jobs.size()));
      const int per_part = std::max(1, options.threads / std::max(1, static_cast<int>(jobs.size())));
      std::atomic<std::size_t> next{0};
      // Runs part k with the start assumption into its slot; true when
      // the run ended not cleared entirely (an undecided piece or a
      // witness).  Skipped after a witness (one that a later run may take
      // back: the parts after it are then left to the merge), or past the
      // time limit.
      auto run_into = [&](std::size_t k, bool start_free) {
        if (k > first_witness.load() || past_deadline(options)) return false;
        const bool first_slot = start_free || k == 0;
        if (claimed[2 * k + (first_slot ? 0 : 1)].exchange(true)) return false;  // another worker runs it
        Speculative& s = first_slot ? ahead[k] : tested[k];
        s = Speculative{};
        s.start_free = start_free;
        try {
          run_one(k, start_free, per_part, s.part);
          s.done = true;
          if (s.part.witness) {
            std::size_t w = first_witness.load();
            while (k < w && !first_witness.compare_exchange_weak(w, k)) {}
          }
          return !s.part.undecided.empty() || s.part.witness.has_value();
        } catch (...) {
          s.error = std::current_exception();
          return false;
        }
      };
      auto worker = [&] {
        for (std::size_t j = next++; j < jobs.size(); j = next++) {
          auto [k, start_free] = jobs[j];
          // Not cleared: the next part with its start test, at once (and
          // so on while those are not cleared either).
          while (run_into(k, start_free) && k + 1 < parts) {
            ++k;
            start_free = false;
          }
        }
      };
      std::vector<std::thread> pool;
      for (int t = 1; t < workers; ++t) pool.emplace_back(worker);
      worker();
      for (std::thread& t : pool) t.join();
    };
    std::vector<std::pair<std::size_t, bool>> jobs;
    for (std::size_t k = 0; k < parts; ++k) jobs.push_back({k, k == 0 ? start_proven_free : true});
    round(jobs);
  }

  // The merge, in parameter order: each part's start is proven free by the
  // caller (the first) or by the part before it cleared entirely.
  bool start_free = start_proven_free;
  for (std::size_t k = 0; k < parts; ++k) {
    const Exact& t0 = cuts[k];
    CheckResult part;
    Speculative* run = nullptr;  // a run with the sequential assumption, if any
    if (!ahead.empty())
      for (Speculative* s : {&ahead[k], &tested[k]})
        if (s->start_free == start_free && (s->done || s->error)) run = s;
    if (run) {
      if (run->error) std::rethrow_exception(run->error);
      part = std::move(run->part);
    } else if (past_deadline(options)) {
      // Time limit: the parts not yet searched are undecided, not cleared.
      part.undecided.push_back({t0, interval.second, StopReason::Limit});
      part.first_contact = std::pair{t0, interval.second};
      detail::merge_result(result, part);
      break;
    } else {
      run_one(k, start_free, options.threads, part);
    }
    // A part cleared entirely proves the join after it free: the next part
    // needs no start check there.
    start_free = part.undecided.empty() && !part.witness;
    if (!detail::merge_result(result, part)) break;
  }
  return finish();
}

}  // namespace tmcert
