#include "src/verify/fixed_environment.h"

#include "kernels/robust_crossing.h"
#include "src/verify/edge_slices.h"
#include "src/motion/segment.h"
#include "src/verify/prepared.h"
#include "src/verify/prepared_pair.h"
#include "src/verify/refine.h"
#include "src/verify/sample_first.h"
#include "src/verify/search.h"
#include "src/verify/true_shape.h"
#include "src/verify/solid_contact.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <tuple>

namespace tmcert {

// ---------------------------------------------------------------- the index

// The environment's simplices (world coordinates), each with its interval
// enclosure and a box holding it, in a tree of boxes (median splits along
// the longest side; every node's box holds its simplices' boxes).
struct EnvironmentIndex {
  struct Item {
    int part, index;
    SimplexI s;
    std::array<double, 3> lo, hi;
  };
  struct Node {
    std::array<double, 3> lo, hi;
    std::uint32_t first, count;  // a leaf: items order_[first, first + count)
    std::int32_t left = -1, right = -1;
  };
  std::vector<Item> items;
  std::vector<std::uint32_t> order;
  std::vector<Node> nodes;

  static constexpr std::uint32_t kLeaf = 8;

  std::int32_t build(std::uint32_t first, std::uint32_t count) {
    Node n;
    n.first = first;
    n.count = count;
    n.lo.fill(std::numeric_limits<double>::infinity());
    n.hi.fill(-std::numeric_limits<double>::infinity());
    for (std::uint32_t k = first; k < first + count; ++k)
      for (int c = 0; c < 3; ++c) {
        n.lo[c] = std::min(n.lo[c], items[order[k]].lo[c]);
        n.hi[c] = std::max(n.hi[c], items[order[k]].hi[c]);
      }
    const auto id = static_cast<std::int32_t>(nodes.size());
    nodes.push_back(n);
    if (count <= kLeaf) return id;
    int axis = 0;
    double best = -1;
    for (int c = 0; c < 3; ++c) {
      const double w = n.hi[c] - n.lo[c];  // infinite boxes: any axis
      if (w > best) best = w, axis = c;
    }
    const std::uint32_t half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                     [&](std::uint32_t x, std::uint32_t y) {
                       return items[x].lo[axis] + items[x].hi[axis] < items[y].lo[axis] + items[y].hi[axis];
                     });
    const std::int32_t l = build(first, half);
    const std::int32_t r = build(first + half, count - half);
    nodes[id].left = l;
    nodes[id].right = r;
    return id;
  }

  explicit EnvironmentIndex(const std::vector<StaticPart>& parts) {
    RoundingGuard guard;
    for (std::size_t i = 0; i < parts.size(); ++i)
      for (std::size_t k = 0; k < parts[i].simplices.size(); ++k) {
        const Simplex& x = parts[i].simplices[k];
        Item it{static_cast<int>(i), static_cast<int>(k), {}, {}, {}};
        it.s.count = x.count;
        for (int v = 0; v < x.count; ++v)
          for (int c = 0; c < 3; ++c) it.s.p[v][c] = to_interval(x.p[v][c]);
        box(it);
        items.push_back(it);
      }
    order.resize(items.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
    if (!items.empty()) build(0, static_cast<std::uint32_t>(items.size()));
  }

  // The box of an enclosure; NaN: unbounded (never separates).
  static void box(Item& it) {
    for (int c = 0; c < 3; ++c) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int v = 0; v < it.s.count; ++v) {
        const Interval& x = it.s.p[v][c];
        if (std::isnan(x.inf()) || std::isnan(x.sup())) {
          lo = -std::numeric_limits<double>::infinity();
          hi = -lo;
          break;
        }
        lo = std::min(lo, x.inf());
        hi = std::max(hi, x.sup());
      }
      it.lo[c] = lo;
      it.hi[c] = hi;
    }
  }

  static bool overlap(const std::array<double, 3>& alo, const std::array<double, 3>& ahi,
                      const std::array<double, 3>& blo, const std::array<double, 3>& bhi) {
    for (int c = 0; c < 3; ++c)
      if (ahi[c] < blo[c] || bhi[c] < alo[c]) return false;
    return true;
  }

  // Some item's box overlaps [lo, hi].
  bool any(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const {
    if (nodes.empty()) return false;
    std::int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes[stack[--top]];
      if (!overlap(lo, hi, n.lo, n.hi)) continue;
      if (n.left < 0) {
        for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
          if (overlap(lo, hi, items[order[k]].lo, items[order[k]].hi)) return true;
        continue;
      }
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
    return false;
  }

  // Items whose boxes overlap [lo, hi] (a strict gap between boxes that
  // hold the simplices proves them disjoint).
  template <class F>
  void query(const std::array<double, 3>& lo, const std::array<double, 3>& hi, F&& f) const {
    if (nodes.empty()) return;
    std::int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes[stack[--top]];
      if (!overlap(lo, hi, n.lo, n.hi)) continue;
      if (n.left < 0) {
        for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
          const Item& it = items[order[k]];
          if (overlap(lo, hi, it.lo, it.hi)) f(it);
        }
        continue;
      }
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
};

namespace {

// The outcome of the static test of one mover's configuration against the
// environment.
struct StaticOutcome {
  enum class Kind { Free, Hit, Unknown } kind = Kind::Free;
  int part_mover = 0, part_environment = 0;
  Vec3E point;  // a Hit at an exact configuration
  std::optional<std::array<Interval, 3>> box;  // a Hit at an enclosed one: a box holding the crossing point
};

// The mover's parts placed by the interval map `map` (enclosing the pose),
// against the index: candidates from the box tree, the separating-axis
// filter, then the exact test on simplices placed by `exact` (the exact
// pose) in the order of parts and simplices, as filtered_first_hit does
// (src/verify/search.h; proofs/static-test.md).  Without an exact pose a
// hit must be a certain transversal crossing; a pair neither separated nor
// crossing leaves the outcome Unknown.  `crossing_first`: each candidate
// pair is tested for a certain crossing of the enclosures as it is found
// (with an exact pose too), and the first one ends the test with its box
// (no exact point); only without one, the exact tests in order
// (proofs/sample-first.md section 2: a hit either way, the interval test
// much cheaper, and the rest of the mover is not placed).
StaticOutcome static_test(const std::vector<StaticPart>& parts, const std::array<Interval, 12>& map,
                          const std::optional<Mat34E>& exact, const EnvironmentIndex& index,
                          const std::vector<StaticPart>& environment,
                          const std::vector<std::vector<SimplexI>>* local = nullptr, bool crossing_first = false,
                          const LocalVertices* shared = nullptr,
                          std::vector<std::array<Interval, 3>>* preplaced = nullptr,
                          const std::function<std::optional<Mat34E>()>* exact_later = nullptr) {
  struct Candidate {
    int pi, pj, si, sj;
    SimplexI x, y;
  };
  std::vector<Candidate> candidates;
  StaticOutcome out;
  // With `shared` (the same enclosures as `local`, one per distinct
  // vertex): each vertex placed once, when a simplex first needs it; the
  // same interval operations on the same intervals, so the same placed
  // simplices (proofs/sample-first.md section 2b).
  std::vector<std::array<Interval, 3>> placed;
  std::vector<char> done;
  if (shared && local && preplaced && preplaced->size() == shared->vertices.size()) {
    // Every vertex already placed by the caller, by the same operations.
    placed = std::move(*preplaced);
    done.assign(shared->vertices.size(), 1);
  } else if (shared && local) {
    placed.resize(shared->vertices.size());
    done.assign(shared->vertices.size(), 0);
  } else {
    shared = nullptr;
  }
  {
    RoundingGuard guard;
    for (std::size_t i = 0; i < parts.size() && out.kind == StaticOutcome::Kind::Free; ++i)
      for (std::size_t k = 0; k < parts[i].simplices.size() && out.kind == StaticOutcome::Kind::Free; ++k) {
        const Simplex& x = parts[i].simplices[k];
        EnvironmentIndex::Item it{static_cast<int>(i), static_cast<int>(k), {}, {}, {}};
        it.s.count = x.count;
        for (int v = 0; v < x.count; ++v) {
          if (shared) {
            const std::uint32_t id = shared->index[i][k][v];
            if (!done[id]) {
              const std::array<Interval, 3>& p = shared->vertices[id];
              for (int c = 0; c < 3; ++c)
                placed[id][c] = map[4 * c] * p[0] + map[4 * c + 1] * p[1] + map[4 * c + 2] * p[2] + map[4 * c + 3];
              done[id] = 1;
            }
            it.s.p[v] = placed[id];
            continue;
          }
          // The simplex's own coordinates enclosed (once per body when
          // `local` holds them: the same intervals).
          const std::array<Interval, 3> p =
              local ? (*local)[i][k].p[v]
                    : std::array<Interval, 3>{to_interval(x.p[v][0]), to_interval(x.p[v][1]), to_interval(x.p[v][2])};
          for (int c = 0; c < 3; ++c)
            it.s.p[v][c] = map[4 * c] * p[0] + map[4 * c + 1] * p[1] + map[4 * c + 2] * p[2] + map[4 * c + 3];
        }
        EnvironmentIndex::box(it);
        index.query(it.lo, it.hi, [&](const EnvironmentIndex::Item& e) {
          if (out.kind != StaticOutcome::Kind::Free || certainly_disjoint(it.s, e.s)) return;
          if (crossing_first)
            if (const auto box = certain_crossing(it.s, e.s)) {
              out.kind = StaticOutcome::Kind::Hit;
              out.part_mover = it.part;
              out.part_environment = e.part;
              out.box = box;  // no exact point: the box of the certain crossing
              return;
            }
          candidates.push_back({it.part, e.part, it.index, e.index, it.s, e.s});
        });
      }
  }
  if (out.kind == StaticOutcome::Kind::Hit) return out;
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.pi, x.pj, x.si, x.sj) < std::tie(y.pi, y.pj, y.si, y.sj);
  });
  if (candidates.empty()) return out;
  // Without `exact`, the exact pose from `exact_later` (when the caller
  // can give one): asked only now, with candidate pairs left that the
  // enclosures did not decide (proofs/sample-first.md section 2c: `map`
  // encloses that pose, so its candidates are the pairs to test exactly).
  std::optional<Mat34E> later;
  if (!exact && exact_later) later = (*exact_later)();
  const std::optional<Mat34E>& exact_pose = exact ? exact : later;
  if (!exact_pose && crossing_first) {
    out.kind = StaticOutcome::Kind::Unknown;  // every candidate tested above
    return out;
  }
  if (!exact_pose) {
    RoundingGuard guard;
    for (const Candidate& c : candidates)
      if (const auto box = certain_crossing(c.x, c.y)) {
        out.kind = StaticOutcome::Kind::Hit;
        out.part_mover = c.pi;
        out.part_environment = c.pj;
        out.box = box;  // no exact point: the box of the certain crossing
        return out;
      }
    out.kind = StaticOutcome::Kind::Unknown;
    return out;
  }
  for (const Candidate& c : candidates) {
    Simplex x = parts[c.pi].simplices[c.si];
    for (int k = 0; k < x.count; ++k) {
      Vec3E r;
      for (int i = 0; i < 3; ++i)
        r[i] = (*exact_pose)[4 * i] * x.p[k][0] + (*exact_pose)[4 * i + 1] * x.p[k][1] +
               (*exact_pose)[4 * i + 2] * x.p[k][2] + (*exact_pose)[4 * i + 3];
      x.p[k] = r;
    }
    if (auto p = common_point(x, environment[c.pj].simplices[c.sj])) {
      out.kind = StaticOutcome::Kind::Hit;
      out.part_mover = c.pi;
      out.part_environment = c.pj;
      out.point = *p;
      return out;
    }
  }
  return out;
}

std::array<Interval, 12> enclose_map(const Mat34E& m) {
  std::array<Interval, 12> out;
  for (int e = 0; e < 12; ++e) out[e] = to_interval(m[e]);
  return out;
}

}  // namespace

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
  if (b.tolerance != 0) throw InputError(name + ": tolerances are not supported here");
}

}  // namespace

namespace {

// `models`: the motion's segment models, built when absent (shared with its
// slices and sampled poses).
StartPose start_pose_of(const Trajectory& t, std::vector<std::unique_ptr<SegmentModel>>& models) {
  if (models.size() != t.segments.size()) models.resize(t.segments.size());
  if (!models.front()) models.front() = make_segment_model(t.segments.front());
  const SegmentModel* model = models.front().get();
  StartPose out;
  out.exact = model->exact_pose(Exact(0));
  if (out.exact) {
    out.map = enclose_map(*out.exact);
  } else {
    RoundingGuard guard;
    out.map = model->pose_values(Interval(0));
  }
  return out;
}

StartPose fixed_start(const Body& b) {
  StartPose out;
  out.exact = fixed_pose(b);
  out.map = enclose_map(*out.exact);
  return out;
}

}  // namespace

namespace {

// The check searched only on `windows` (in order, inside [t0, t1]): the
// parts between them are slices cleared by boxes (proofs/edge-slices.md).
// A window after a cleared slice starts where the bodies are apart (the
// slice's box covers its closed interval) and, with everything before it
// cleared, neither is inside a solid other: its start is proven free.  The
// first window at t0 has the caller's start test.  After a window that is
// not cleared entirely (undecided), the rest [its end, t1] is searched as
// one window whose start is tested (as a join after a part not cleared,
// proofs/partition.md); a witness ends the search.
CheckResult search_windows(const PreparedBody& pa, const PreparedBody& pb, std::array<int, 2> ids,
                           const std::vector<std::pair<Exact, Exact>>& windows, const Exact& t0, const Exact& t1,
                           const VerifyOptions& options, bool start_free) {
  const auto started = std::chrono::steady_clock::now();
  CheckResult total;
  total.bodies = ids;
  for (const auto& w : windows) {
    const bool free = w.first == t0 ? start_free : true;
    const CheckResult part = detail::check_prepared_pair(pa, pb, ids, Exact(0), options, free, w);
    if (!detail::merge_result(total, part)) break;  // a witness ends the claims
    if (!part.undecided.empty()) {
      if (w.second < t1)
        detail::merge_result(total, detail::check_prepared_pair(pa, pb, ids, Exact(0), options, false, std::pair{w.second, t1}));
      break;
    }
  }
  if (total.verdict != Verdict::Collision) total.verdict = total.undecided.empty() ? Verdict::Safe : Verdict::Undecided;
  if (total.verdict == Verdict::Safe) total.first_contact.reset();
  total.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return total;
}

}  // namespace

FixedEnvironment::FixedEnvironment(Body environment, std::vector<Body> movers,
                                   std::vector<std::pair<int, int>> mover_pairs, const VerifyOptions& options)
    : options_(options) {
  // No per-check default here: the environment's box is the whole scene's.
  if (!options.epsilon) throw InputError("epsilon: must be given (an environment has no per-check default)");
  if (!(*options.epsilon > 0)) throw InputError("epsilon: must be > 0");
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
  index_ = std::make_unique<EnvironmentIndex>(prepared_[0]->parts);
  // For the containment of solids: every body's vertices and one vertex per
  // connected component, in its own frame (the environment's: the frame
  // its fixed pose applies to).
  const Mat34E identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  for (const Body& b : bodies_) {
    vertices_.push_back(every_vertex(b));
    enclosed_.push_back(enclosed_vertices(b));
    bounds_.push_back(enclosed_bounds(enclosed_.back()));
    representatives_.push_back(component_representatives(b, identity));
  }
  for (const auto& p : prepared_) {
    std::vector<std::vector<SimplexI>> parts;
    for (const StaticPart& part : p->parts) {
      std::vector<SimplexI> list;
      for (const Simplex& x : part.simplices) {
        SimplexI e;
        e.count = x.count;
        for (int v = 0; v < x.count; ++v)
          for (int c = 0; c < 3; ++c) e.p[v][c] = to_interval(x.p[v][c]);
        list.push_back(e);
      }
      parts.push_back(std::move(list));
    }
    local_.push_back(std::move(parts));
    // The distinct vertices of its simplices, and each simplex corner's
    // index among them (static_test places each vertex once).
    LocalVertices shared;
    std::map<Vec3E, std::uint32_t> ids;
    for (const StaticPart& part : p->parts) {
      std::vector<std::array<std::uint32_t, 3>> list;
      for (const Simplex& x : part.simplices) {
        std::array<std::uint32_t, 3> corner{0, 0, 0};
        for (int v = 0; v < x.count; ++v) {
          const auto [at, fresh] = ids.emplace(x.p[v], static_cast<std::uint32_t>(shared.vertices.size()));
          if (fresh)
            shared.vertices.push_back({to_interval(x.p[v][0]), to_interval(x.p[v][1]), to_interval(x.p[v][2])});
          corner[v] = at->second;
        }
        list.push_back(corner);
      }
      shared.index.push_back(std::move(list));
    }
    shared_.push_back(std::move(shared));
  }
}

FixedEnvironment::~FixedEnvironment() = default;

MotionCheck FixedEnvironment::check(const std::vector<Trajectory>& motions) const { return run(motions, false); }

MotionCheck FixedEnvironment::decide(const std::vector<Trajectory>& motions) const { return run(motions, true); }

MotionCheck FixedEnvironment::run(const std::vector<Trajectory>& motions, bool decide) const {
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
  // Adds check k's verdict to the motion's.
  auto record = [&](std::size_t k) {
    const CheckResult& r = out.checks[k];
    if (r.verdict == Verdict::Safe) return;
    // A check that is not safe always has its bracket; without one nothing
    // after the start would count as certified.
    const Exact lo = r.first_contact ? r.first_contact->first : t0;
    if (!out.safe_until || lo < *out.safe_until) out.safe_until = lo;
    if (r.verdict == Verdict::Collision && out.verdict != Verdict::Collision) {
      out.verdict = Verdict::Collision;
      decided = k;
    } else if (out.verdict == Verdict::Safe) {
      out.verdict = Verdict::Undecided;
      decided = k;
    }
  };
  // Certified prefilter (proofs/prefilter.md): a box holding everything a
  // mover sweeps (swept_box: the hull property for rational pieces, interval
  // poses over eighths of an enclosed segment) that overlaps no
  // environment simplex's box, or two movers' disjoint swept boxes, clear
  // the check without a search.
  // The boxes are those of the motion's slices (edge_slices.h): every
  // pose of a slice enclosed, the mover's vertices enclosed once; their
  // union holds everything the mover sweeps (proofs/edge-slices.md).
  std::vector<SweptBox> swept(bodies_.size());
  std::vector<EdgeSlices> slices(bodies_.size());
  std::vector<StartPose> start(bodies_.size());
  start[0] = fixed_start(bodies_[0]);
  // A mover in no mover pair, neither it nor the environment solid: a
  // slice whose coarse box (its map applied to the box of the mover's
  // vertices) meets no environment simplex's box keeps that box, the box of
  // its vertices is not computed (proofs/edge-slices.md section 1b: the
  // slices' windows, and every check's result, are those of the vertex
  // boxes).  Otherwise every slice gets its vertex box (the whole box then
  // also orders the solids' start containment as before).
  std::vector<char> in_pair(bodies_.size(), 0);
  for (const auto& [i, j] : pairs_) in_pair[i] = in_pair[j] = 1;
  SliceFilter filter;
  filter.clears = [&](const std::array<double, 3>& lo, const std::array<double, 3>& hi) { return !index_->any(lo, hi); };
  // Per mover, its segments' models, built once per motion (the slices,
  // the start pose and the sampled poses).
  std::vector<std::vector<std::unique_ptr<SegmentModel>>> models(bodies_.size());
  const Exact t1 = motions.front().t1();
  // A mover's witness from a hit of the static test at parameter t.
  auto mover_witness = [&](int a, const StaticOutcome& o, const Exact& t) {
    Witness w{t,
              {bodies_[a].name + " " + prepared_[a]->parts[o.part_mover].name,
               bodies_[0].name + " " + prepared_[0]->parts[o.part_environment].name},
              o.point, std::nullopt, std::nullopt, std::nullopt, 0, std::nullopt};
    if (o.box) {
      std::array<std::array<Exact, 2>, 3> box;
      for (int c = 0; c < 3; ++c) box[c] = {Exact((*o.box)[c].inf()), Exact((*o.box)[c].sup())};
      w.point_box = box;
    }
    return w;
  };
  // decide(): the end configuration of every mover against the
  // environment first, before any slice is enclosed (proofs/sample-first.md
  // section 3): t1 is the first sampled parameter, and a mover-environment
  // pair comes before every mover pair, so a hit here is the one the sample
  // pass below would find first.  A mover whose coarse box at t1 (its pose's
  // interval map applied to the box of its vertex enclosures), or else the
  // box of its placed vertex enclosures, meets no environment simplex's box
  // has no candidate pair there (the static test would come out free) and
  // is skipped.
  // Only for one mover (a rigid body, e.g. OMPL's SE(3) states): with
  // several (a robot's links) the pose of each at t1 costs about as much
  // as its slices' first boxes, and an edge rarely ends in contact; the
  // sample pass below then tests t1 where the slices do not clear it.
  std::vector<char> end_tested(bodies_.size(), 0);
  if (decide && bodies_.size() == 2 && kSampledParameters > 0 && t0 < t1) {
    std::uint64_t configurations = 0;
    for (std::size_t k = 1; k < bodies_.size(); ++k) {
      const int a = static_cast<int>(k);
      if (enlarged_pair(bodies_[a], bodies_[0])) continue;
      end_tested[a] = 1;
      // The enclosure of the end pose; its exact pose (GMP) only when the
      // static test is left with candidate pairs (sample-first.md 2c).
      const StartPose p = pose_at(motions[a - 1], t1, &models[a], false);
      const std::function<std::optional<Mat34E>()> exact_end = [&]() {
        return pose_at(motions[a - 1], t1, &models[a]).exact;
      };
      // Two gates, each a box holding every placed simplex's box of the
      // static test: the coarse box (the map applied to the box of the
      // vertex enclosures), then the box of the placed vertex enclosures.
      auto clears = [&](const std::array<Interval, 3>& x, std::array<double, 3>& lo, std::array<double, 3>& hi,
                        bool first) {
        bool finite = true;
        for (int i = 0; i < 3; ++i) {
          const Interval y = p.map[4 * i] * x[0] + p.map[4 * i + 1] * x[1] + p.map[4 * i + 2] * x[2] + p.map[4 * i + 3];
          lo[i] = first ? y.inf() : std::min(lo[i], y.inf());
          hi[i] = first ? y.sup() : std::max(hi[i], y.sup());
          finite = finite && std::isfinite(y.inf()) && std::isfinite(y.sup()) && y.inf() <= y.sup();
        }
        return finite;
      };
      bool gate = false;
      // The vertices placed for the second gate, by static_test's
      // operations: handed to it (section 2b).
      std::vector<std::array<Interval, 3>> placed;
      {
        RoundingGuard guard;
        std::array<double, 3> lo, hi;
        gate = clears(bounds_[a], lo, hi, true) && !index_->any(lo, hi);
        const std::vector<std::array<Interval, 3>>& corners = shared_[a].vertices;
        if (!gate && !corners.empty()) {
          placed.resize(corners.size());
          bool finite = true;
          for (std::size_t v = 0; v < corners.size(); ++v) {
            const std::array<Interval, 3>& x = corners[v];
            for (int i = 0; i < 3; ++i) {
              const Interval y = p.map[4 * i] * x[0] + p.map[4 * i + 1] * x[1] + p.map[4 * i + 2] * x[2] + p.map[4 * i + 3];
              placed[v][i] = y;
              lo[i] = v == 0 ? y.inf() : std::min(lo[i], y.inf());
              hi[i] = v == 0 ? y.sup() : std::max(hi[i], y.sup());
              finite = finite && std::isfinite(y.inf()) && std::isfinite(y.sup()) && y.inf() <= y.sup();
            }
          }
          gate = finite && !index_->any(lo, hi);
        }
      }
      if (gate) continue;
      ++configurations;
      const StaticOutcome o =
          static_test(prepared_[a]->parts, p.map, p.exact, *index_, prepared_[0]->parts, &local_[a], true,
                      &shared_[a], &placed, &exact_end);
      if (o.kind != StaticOutcome::Kind::Hit) continue;
      // As the sample pass's hit below: record(0), then finish().
      out.checks.push_back(sampled_collision({a, 0}, t0, t1, mover_witness(a, o, t1), configurations));
      record(0);
      CheckResult& r = out.checks.back();
      r.epsilon = *options_.epsilon;
      r.interval = {t0, t1};
      out.witness = r.witness;
      out.first_contact = r.first_contact;
      return out;
    }
  }
  for (std::size_t k = 1; k < bodies_.size(); ++k) {
    const bool coarse = !in_pair[k] && !bodies_[k].solid && !bodies_[0].solid;
    if (coarse) filter.bounds = bounds_[k];
    slices[k] = edge_slices(motions[k - 1], enclosed_[k], kSlices, coarse ? &filter : nullptr, &models[k]);
    swept[k] = slices[k].whole;
  }
  // The start poses, computed when first needed (the solids' containment,
  // the start test before a search): a prefiltered edge needs none.
  std::vector<char> has_start(bodies_.size(), 0);
  has_start[0] = 1;
  auto start_of = [&](int k) -> const StartPose& {
    if (!has_start[k]) {
      start[k] = start_pose_of(motions[k - 1], models[k]);
      has_start[k] = 1;
    }
    return start[k];
  };
  // A check cleared by boxes alone, without a search.
  auto prefiltered = [&](int a, int b) {
    CheckResult r;
    r.bodies = {a, b};
    r.verdict = Verdict::Safe;
    r.stats.prefiltered = true;
    out.checks.push_back(r);
  };
  // The end of the result: every check's epsilon and interval, and the
  // motion's witness and bracket from the check that decided it.
  auto finish = [&]() -> MotionCheck& {
    for (CheckResult& r : out.checks) {
      if (!r.refined) r.epsilon = *options_.epsilon;
      r.interval = {t0, t1};
    }
    if (decided < out.checks.size()) {
      out.witness = out.checks[decided].witness;
      out.first_contact = out.checks[decided].first_contact;
    }
    return out;
  };
  // A swept box that misses the environment's root box, or every
  // environment simplex's box (a mover), or the other mover's swept box.
  auto boxes_clear = [&](int a, int b) {
    if (b == 0)
      return swept[a].valid && (index_->nodes.empty() || !index_->any(swept[a].lo, swept[a].hi));
    return disjoint(swept[a], swept[b]);
  };
  // Per pair, the runs of slices its boxes do not clear (computed when
  // first needed).
  std::vector<std::optional<std::vector<std::pair<Exact, Exact>>>> windows_of(pairs.size());
  auto pair_windows = [&](std::size_t k) -> const std::vector<std::pair<Exact, Exact>>& {
    if (windows_of[k]) return *windows_of[k];
    const auto [a, b] = pairs[k];
    const EdgeSlices& sa = slices[a];
    if (b != 0 && !(sa.t == slices[b].t)) return *(windows_of[k] = std::vector<std::pair<Exact, Exact>>{{t0, t1}});
    return *(windows_of[k] = slice_runs(sa, [&](std::size_t i) {
      if (!sa.valid[i]) return true;
      if (b == 0) return index_->any(sa.lo[i], sa.hi[i]);
      const EdgeSlices& sb = slices[b];
      if (!sb.valid[i]) return true;
      for (int c = 0; c < 3; ++c)
        if (sa.hi[i][c] < sb.lo[i][c] || sb.hi[i][c] < sa.lo[i][c]) return false;
      return true;
    }));
  };
  if (decide) {
    // Contacts first where they are cheapest (src/verify/sample_first.h,
    // proofs/sample-first.md): the exact static test of the configuration
    // at a few sampled parameters, for every pair the boxes do not clear.
    // Not for a URDF cylinder or sphere, whose polyhedron's contact proves
    // nothing about the true shape.
    std::vector<std::size_t> sampled;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto [a, b] = pairs[k];
      if (!enlarged_pair(bodies_[a], bodies_[b]) && !boxes_clear(a, b) && !pair_windows(k).empty()) sampled.push_back(k);
    }
    const std::vector<Exact> times = sample_times(t0, t1, kSampledParameters);
    // Per body at the current sampled parameter: the pose's enclosure
    // alone (a mover against the environment: its exact pose only when the
    // static test is left with candidate pairs, sample-first.md 2c), and
    // the pose with its exact form (mover pairs).
    std::vector<std::optional<StartPose>> at(bodies_.size()), at_exact(bodies_.size());
    const Exact* at_time = nullptr;
    std::uint64_t configurations = 0;
    const auto hit = first_sampled_contact(times, sampled.size(), [&](std::size_t i, const Exact& t) -> std::optional<Witness> {
      if (at_time != &t) {
        for (auto& p : at) p.reset();
        for (auto& p : at_exact) p.reset();
        at_time = &t;
      }
      auto enclosed = [&](int body) -> const StartPose& {
        if (!at[body]) at[body] = pose_at(motions[body - 1], t, &models[body], false);
        return *at[body];
      };
      auto pose = [&](int body) -> const StartPose& {
        if (!at_exact[body]) at_exact[body] = pose_at(motions[body - 1], t, &models[body]);
        return *at_exact[body];
      };
      const auto [a, b] = pairs[sampled[i]];
      // A mover's end configuration was tested above.
      if (b == 0 && end_tested[a] && t == t1) return std::nullopt;
      // Only inside the slices the boxes do not clear: elsewhere nothing
      // touches (proofs/edge-slices.md).
      const auto& runs = pair_windows(sampled[i]);
      if (std::none_of(runs.begin(), runs.end(), [&](const auto& r) { return r.first <= t && t <= r.second; }))
        return std::nullopt;
      ++configurations;
      if (b == 0) {
        const StartPose& p = enclosed(a);
        const std::function<std::optional<Mat34E>()> exact_later = [&]() { return pose(a).exact; };
        // A certain crossing of the enclosures first, also where an exact
        // pose exists (cheaper than the exact tests; its witness is a box).
        const StaticOutcome o =
            static_test(prepared_[a]->parts, p.map, p.exact, *index_, prepared_[0]->parts, &local_[a], true,
                      &shared_[a], nullptr, &exact_later);
        if (o.kind != StaticOutcome::Kind::Hit) return std::nullopt;
        return mover_witness(a, o, t);
      }
      // Two movers: the search's filtered static test with both poses.
      const StartPose& pa = pose(a);
      const StartPose& pb = pose(b);
      CheckStats stats;
      const auto h = detail::filtered_first_hit(
          prepared_[a]->parts, &pa.map, prepared_[b]->parts, &pb.map, nullptr,
          [&]() -> std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>> {
            if (!pa.exact || !pb.exact) return std::nullopt;  // enclosed: certain crossings only
            return std::pair{pa.exact, pb.exact};
          },
          stats);
      if (!h) return std::nullopt;
      Witness w{t, {bodies_[a].name + " " + prepared_[a]->parts[h->part_moving].name,
                    bodies_[b].name + " " + prepared_[b]->parts[h->part_other].name},
                h->point, std::nullopt, std::nullopt, std::nullopt, 0, std::nullopt};
      if (h->box) {
        std::array<std::array<Exact, 2>, 3> box;
        for (int c = 0; c < 3; ++c) box[c] = {Exact((*h->box)[c].inf()), Exact((*h->box)[c].sup())};
        w.point_box = box;
      }
      return w;
    });
    if (hit) {
      const auto [a, b] = pairs[sampled[hit->first]];
      out.checks.push_back(sampled_collision({a, b}, t0, t1, hit->second, configurations));
      record(0);
      return finish();
    }
  }
  for (std::size_t k_pair = 0; k_pair < pairs.size(); ++k_pair) {
    const auto [a, b] = pairs[k_pair];
    // decide(): the first check that is not safe decides the motion.
    if (decide && out.verdict != Verdict::Safe) break;
    // A mover whose swept box misses the box of the whole environment never
    // meets it, insides of solids included (every point of a solid lies in
    // the box of its vertices): cleared before any exact test, which for
    // solids places a surface exactly at every check.
    if (b == 0 && swept[a].valid && !index_->nodes.empty() &&
        !EnvironmentIndex::overlap(swept[a].lo, swept[a].hi, index_->nodes[0].lo, index_->nodes[0].hi)) {
      prefiltered(a, b);
      continue;
    }
    // A solid's inside counts as contact: at the start, a component of one
    // body inside the other (solid) body is a collision there; later
    // contacts go through the surfaces (as Verifier::check does).
    if (bodies_[a].solid || bodies_[b].solid) {
      Containment c;
      for (int side = 0; side < 2 && c.kind == Containment::Kind::Free; ++side) {
        const int sb = side == 0 ? a : b, ob = side == 0 ? b : a;
        if (bodies_[sb].solid)
          c = start_containment(bodies_[sb], vertices_[sb], start_of(sb), bodies_[ob], representatives_[ob], start_of(ob),
                                side == 0);
      }
      if (c.kind != Containment::Kind::Free) {
        CheckResult r;
        r.bodies = {a, b};
        if (c.kind == Containment::Kind::Hit) {
          r.verdict = Verdict::Collision;
          r.witness = c.witness;
          r.witness->t = t0;
          r.first_contact = std::pair{t0, t0};
        } else {
          r.verdict = Verdict::Undecided;
          r.undecided.push_back({t0, t1, StopReason::Epsilon});
          r.first_contact = std::pair{t0, t1};
        }
        out.checks.push_back(r);
        settle_enlarged(out.checks.back(), *prepared_[a], *prepared_[b], t1);
        record(out.checks.size() - 1);
        continue;
      }
    }
    // With the start containment settled, a swept box that meets no
    // environment simplex's box, or two movers' disjoint swept boxes, clear
    // the check without a search.
    const bool cleared = b == 0 ? swept[a].valid && !index_->any(swept[a].lo, swept[a].hi)
                                : disjoint(swept[a], swept[b]);
    if (cleared) {
      prefiltered(a, b);
      continue;
    }
    // The slices whose boxes meet an obstacle's box (a mover against the
    // environment) or the other mover's slice box: only those are searched
    // (proofs/edge-slices.md); none left, the check is cleared by boxes.
    const std::vector<std::pair<Exact, Exact>>& windows = pair_windows(k_pair);
    if (windows.empty()) {
      prefiltered(a, b);
      continue;
    }
    // A mover's start against the environment through the index (the
    // search's own start test would enclose every environment simplex
    // again); proven free, the search skips its start test.  A hit or an
    // unknown outcome leaves the start test to the search, which then
    // reports the collision with its witness, or stops undecided.  Only
    // when the first window starts at t0.
    // Without a start pose yet (no solid), the enclosure at t0 first and
    // the exact start pose only for candidate pairs (sample-first.md 2c).
    auto start_test = [&]() {
      if (has_start[a])
        return static_test(prepared_[a]->parts, start[a].map, start[a].exact, *index_, prepared_[0]->parts,
                           &local_[a], false, &shared_[a]);
      const StartPose p = pose_at(motions[a - 1], t0, &models[a], false);
      const std::function<std::optional<Mat34E>()> exact_later = [&]() { return start_of(a).exact; };
      return static_test(prepared_[a]->parts, p.map, std::nullopt, *index_, prepared_[0]->parts, &local_[a], false,
                         &shared_[a], nullptr, &exact_later);
    };
    const bool start_free =
        b == 0 && windows.front().first == t0 && start_test().kind == StaticOutcome::Kind::Free;
    // check_time_limit bounds each check, as in Verifier::check (with
    // refinement and none given: 30 s for the first search and the
    // refinement together).
    VerifyOptions options = options_;
    const auto started = std::chrono::steady_clock::now();
    options.deadline = detail::check_deadline(options, started);
    CheckResult result = windows.size() == 1 && windows.front() == std::pair{t0, t1}
                             ? detail::check_prepared_pair(*prepared_[a], *prepared_[b], {a, b}, Exact(0), options, start_free)
                             : search_windows(*prepared_[a], *prepared_[b], {a, b}, windows, t0, t1, options, start_free);
    // Refinement (src/verify/refine.h), as in Verifier::check: the
    // undecided parts searched again as parts of [t0, t1].
    if (options.refine && result.verdict == Verdict::Undecided)
      detail::refine_check(result, t0, t1, false, options, started,
                           [&](const Exact& w0, const Exact& w1, bool free, const VerifyOptions& o) {
                             return detail::check_prepared_pair(*prepared_[a], *prepared_[b], {a, b}, Exact(0), o,
                                                                free || (w0 == t0 && start_free), std::pair{w0, w1});
                           });
    out.checks.push_back(std::move(result));
    // A URDF cylinder's or sphere's collision only proven on its true shape
    // (true_shape.h); no finer polyhedra here (a planner's edge is then not
    // certified).
    settle_enlarged(out.checks.back(), *prepared_[a], *prepared_[b], t1);
    record(out.checks.size() - 1);
  }
  return finish();
}

std::optional<Witness> FixedEnvironment::static_contact(const std::vector<Mat34E>& poses) const {
  if (poses.size() + 1 != bodies_.size())
    throw InputError("poses: " + std::to_string(poses.size()) + " given for " + std::to_string(bodies_.size() - 1) +
                     " movers");
  // A solid's inside counts as contact (exact poses: exact ray parity).
  std::vector<StartPose> at(bodies_.size());
  at[0] = fixed_start(bodies_[0]);
  for (std::size_t k = 0; k < poses.size(); ++k) at[k + 1] = StartPose{poses[k], enclose_map(poses[k])};
  std::vector<std::array<int, 2>> pairs;
  for (std::size_t k = 1; k < bodies_.size(); ++k) pairs.push_back({static_cast<int>(k), 0});
  for (const auto& [i, j] : pairs_) pairs.push_back({i, j});
  for (const auto& [a, b] : pairs)
    for (int side = 0; side < 2; ++side) {
      const int sb = side == 0 ? a : b, ob = side == 0 ? b : a;
      if (!bodies_[sb].solid) continue;
      const Containment c = start_containment(bodies_[sb], vertices_[sb], at[sb], bodies_[ob], representatives_[ob],
                                              at[ob], side == 0);
      if (c.kind == Containment::Kind::Hit) return c.witness;
    }
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const StaticOutcome o =
        static_test(prepared_[k + 1]->parts, enclose_map(poses[k]), poses[k], *index_, prepared_[0]->parts,
                    &local_[k + 1], false, &shared_[k + 1]);
    if (o.kind == StaticOutcome::Kind::Hit)
      return Witness{Exact(0),
                     {bodies_[k + 1].name + " " + prepared_[k + 1]->parts[o.part_mover].name,
                      bodies_[0].name + " " + prepared_[0]->parts[o.part_environment].name},
                     o.point, std::nullopt, std::nullopt, std::nullopt, 0, std::nullopt};
  }
  // Mover pairs: both placed exactly, the filtered test of the search.
  for (const auto& [i, j] : pairs_) {
    const std::vector<StaticPart> pi = transformed_parts(*prepared_[i], poses[i - 1]);
    const std::vector<StaticPart> pj = transformed_parts(*prepared_[j], poses[j - 1]);
    CheckStats stats;
    if (const auto hit = detail::first_hit(pi, pj, nullptr, stats))
      return Witness{Exact(0),
                     {bodies_[i].name + " " + pi[hit->part_moving].name, bodies_[j].name + " " + pj[hit->part_other].name},
                     hit->point, std::nullopt, std::nullopt, std::nullopt, 0, std::nullopt};
  }
  return std::nullopt;
}

}  // namespace tmcert
