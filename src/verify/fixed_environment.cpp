#include "src/verify/fixed_environment.h"

#include "src/verify/prepared.h"
#include "src/verify/prepared_pair.h"
#include "src/verify/search.h"

#include <string>

namespace tmcert {

namespace {

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// A mover is prepared as a moving body (body frame, metric), which needs a
// motion at construction: the identity held over [0, 1].  Nothing
// prepared depends on which motion it is; check() replaces it.
Trajectory standing_still() {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  Motion still;
  still.t0 = 0;
  still.t1 = 1;
  still.control_points = {kIdentity, kIdentity};
  still.weights = {Exact(1), Exact(1)};
  seg.rational = still;
  return Trajectory{{seg}};
}

void require_usable(const Body& b, const char* role) {
  const std::string name = std::string(role) + " \"" + b.name + "\"";
  if (b.solid) throw InputError(name + ": solid bodies are not supported here (a body is its surface)");
  if (b.tolerance != 0) throw InputError(name + ": tolerances are not supported here");
}

}  // namespace

FixedEnvironment::FixedEnvironment(Body environment, std::vector<Body> movers,
                                   std::vector<std::pair<int, int>> mover_pairs, const VerifyOptions& options)
    : options_(options) {
  if (!(options.epsilon > 0)) throw InputError("epsilon: must be > 0");
  require_usable(environment, "environment");
  if (environment.moves()) throw InputError("environment \"" + environment.name + "\": must not move");
  if (movers.empty()) throw InputError("movers: at least one body must move");
  bodies_.reserve(movers.size() + 1);
  bodies_.push_back(std::move(environment));
  for (Body& m : movers) {
    require_usable(m, "mover");
    m.motion.reset();
    m.trajectory = standing_still();
    bodies_.push_back(std::move(m));
  }
  const int n = static_cast<int>(bodies_.size()) - 1;
  for (const auto& [i, j] : mover_pairs) {
    if (i < 0 || j < 0 || i >= n || j >= n || i == j)
      throw InputError("mover_pairs: [" + std::to_string(i) + ", " + std::to_string(j) + "]: not two movers");
    pairs_.push_back({1 + i, 1 + j});
  }
  // bodies_ is not resized from here on: PreparedBody keeps a pointer to
  // its Body.
  for (const Body& b : bodies_) prepared_.push_back(std::make_unique<PreparedBody>(b));
}

FixedEnvironment::~FixedEnvironment() = default;

MotionCheck FixedEnvironment::check(const std::vector<Trajectory>& motions) const {
  if (motions.size() + 1 != bodies_.size())
    throw InputError("motions: " + std::to_string(motions.size()) + " given for " + std::to_string(bodies_.size() - 1) +
                     " movers");
  for (const Trajectory& t : motions) {
    if (t.segments.empty()) throw InputError("motions: a motion has no segment");
    if (t.t0() != motions.front().t0() || t.t1() != motions.front().t1())
      throw InputError("motions: the movers' motions must share their parameter interval");
  }
  std::lock_guard<std::mutex> lock(mutex_);
  // The movers' Body objects are ours; only their motion changes.
  for (std::size_t k = 0; k < motions.size(); ++k) bodies_[k + 1].trajectory = motions[k];

  MotionCheck out;
  std::vector<std::array<int, 2>> pairs;
  for (std::size_t k = 1; k < bodies_.size(); ++k) pairs.push_back({static_cast<int>(k), 0});
  for (const auto& [i, j] : pairs_) pairs.push_back({i, j});
  const Exact t0 = motions.front().t0();
  std::size_t decided = pairs.size();
  for (const auto& [a, b] : pairs) {
    out.checks.push_back(detail::check_prepared_pair(*prepared_[a], *prepared_[b], {a, b}, Exact(0), options_));
    const CheckResult& r = out.checks.back();
    if (r.verdict == Verdict::Safe) continue;
    // A check that is not safe always has its bracket; without one nothing
    // after the start would count as certified.
    const Exact lo = r.first_contact ? r.first_contact->first : t0;
    if (!out.safe_until || lo < *out.safe_until) out.safe_until = lo;
    if (r.verdict == Verdict::Collision && out.verdict != Verdict::Collision) {
      out.verdict = Verdict::Collision;
      decided = out.checks.size() - 1;
    } else if (out.verdict == Verdict::Safe) {
      out.verdict = Verdict::Undecided;
      decided = out.checks.size() - 1;
    }
  }
  if (decided < out.checks.size()) {
    out.witness = out.checks[decided].witness;
    out.first_contact = out.checks[decided].first_contact;
  }
  return out;
}

std::optional<Witness> FixedEnvironment::static_contact(const std::vector<Mat34E>& poses) const {
  if (poses.size() + 1 != bodies_.size())
    throw InputError("poses: " + std::to_string(poses.size()) + " given for " + std::to_string(bodies_.size() - 1) +
                     " movers");
  std::vector<std::vector<StaticPart>> placed;
  for (std::size_t k = 0; k < poses.size(); ++k) placed.push_back(transformed_parts(*prepared_[k + 1], poses[k]));
  auto test = [&](int a, const std::vector<StaticPart>& pa, int b,
                  const std::vector<StaticPart>& pb) -> std::optional<Witness> {
    CheckStats stats;
    const auto hit = detail::first_hit(pa, pb, nullptr, stats);
    if (!hit) return std::nullopt;
    return Witness{Exact(0),
                   {bodies_[a].name + " " + pa[hit->part_moving].name, bodies_[b].name + " " + pb[hit->part_other].name},
                   hit->point};
  };
  for (std::size_t k = 0; k < placed.size(); ++k)
    if (auto w = test(static_cast<int>(k) + 1, placed[k], 0, prepared_[0]->parts)) return w;
  for (const auto& [i, j] : pairs_)
    if (auto w = test(i, placed[i - 1], j, placed[j - 1])) return w;
  return std::nullopt;
}

}  // namespace tmcert
