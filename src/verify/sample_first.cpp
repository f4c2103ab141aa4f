#include "src/verify/sample_first.h"

#include "src/motion/segment.h"

#include <memory>

namespace tmcert {

std::vector<Exact> sample_times(const Exact& t0, const Exact& t1, std::size_t count) {
  std::vector<Exact> out;
  if (count == 0 || !(t0 < t1)) return out;
  out.push_back(t1);
  const Exact span = t1 - t0;
  for (long den = 2; out.size() < count; den *= 2)
    for (long num = 1; num < den && out.size() < count; num += 2) out.push_back(t0 + span * Exact(num, den));
  return out;
}

StartPose pose_at(const Trajectory& motion, const Exact& t, std::vector<std::unique_ptr<SegmentModel>>* models,
                  bool with_exact) {
  std::size_t index = motion.segments.size() - 1;
  for (std::size_t k = 0; k < motion.segments.size(); ++k)
    if (motion.segments[k].t0 <= t && t <= motion.segments[k].t1) {
      index = k;
      break;
    }
  const MotionSegment* seg = &motion.segments[index];
  const Exact s = seg->t1 == seg->t0 ? Exact(0) : (t - seg->t0) / (seg->t1 - seg->t0);
  std::unique_ptr<SegmentModel> own;
  if (models && models->size() != motion.segments.size()) models->resize(motion.segments.size());
  std::unique_ptr<SegmentModel>& slot = models ? (*models)[index] : own;
  if (!slot) slot = make_segment_model(*seg);
  const SegmentModel* model = slot.get();
  StartPose out;
  if (with_exact) out.exact = model->exact_pose(s);
  RoundingGuard guard;
  if (out.exact) {
    for (int e = 0; e < 12; ++e) out.map[e] = to_interval((*out.exact)[e]);
  } else {
    out.map = model->pose_values(to_interval(s));
  }
  return out;
}

CheckResult sampled_collision(std::array<int, 2> ids, const Exact& t0, const Exact& t1, Witness witness,
                              std::uint64_t configurations) {
  CheckResult r;
  r.bodies = ids;
  r.interval = {t0, t1};
  r.verdict = Verdict::Collision;
  if (t0 < witness.t) r.undecided.push_back({t0, witness.t, StopReason::Limit});
  r.first_contact = std::pair{t0, witness.t};
  r.first_contact_exact = false;
  r.witness = std::move(witness);
  r.stats.static_configurations = configurations;
  return r;
}

}  // namespace tmcert
