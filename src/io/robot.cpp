#include "src/io/robot.h"

#include "kernels/decimal.h"
#include "kernels/real_roots.h"

#include "src/io/parse.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace tmcert {

int RobotModel::link_index(const std::string& link) const {
  for (std::size_t i = 0; i < links.size(); ++i)
    if (links[i].name == link) return static_cast<int>(i);
  return -1;
}

int RobotModel::joint_index(const std::string& joint) const {
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == joint) return static_cast<int>(i);
  return -1;
}

PlacedRobot::PlacedRobot(std::shared_ptr<const RobotModel> model, std::string name, Pose base)
    : model_(std::move(model)), name_(std::move(name)), base_(std::move(base)) {
  const RobotModel& m = *model_;
  chain_joints_.resize(m.links.size());
  chains_.resize(m.links.size());
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    // The joints from the root to the link (URDF guarantees a tree).
    std::vector<int> path;
    for (int j = m.links[l].parent_joint; j >= 0; j = m.links[m.joints[j].parent].parent_joint) {
      path.push_back(j);
      if (path.size() > m.joints.size()) throw InputError(m.source + ": the joints form a cycle");
    }
    std::reverse(path.begin(), path.end());
    std::vector<std::vector<Pose>> constants(1, std::vector<Pose>{base_});
    std::vector<ChainJoint> joints;
    for (int j : path) {
      const RobotJoint& joint = m.joints[j];
      constants.back().push_back(joint.origin);
      if (!joint.moves()) continue;
      chain_joints_[l].push_back(j);
      ChainJoint cj;
      cj.kind = joint.type == RobotJoint::Type::Prismatic ? ChainJoint::Kind::Prismatic : ChainJoint::Kind::Revolute;
      cj.axis = joint.axis;
      joints.push_back(cj);
      constants.emplace_back();
    }
    // One chain per part: the part's frame is the last constant factor.
    for (const LinkPart& part : m.links[l].parts) {
      std::vector<std::vector<Pose>> c = constants;
      for (const Pose& p : part.frame) c.back().push_back(p);
      chains_[l].push_back(std::make_shared<const ChainDescription>(std::move(c), joints));
    }
  }
}

namespace {

std::string quoted(const std::string& s) { return quote_text(s); }

}  // namespace

namespace {

// The named joint whose value drives joint j (j itself unless a mimic joint).
int driver(const RobotModel& model, int j) {
  for (std::size_t n = 0; model.joints[j].mimic && n <= model.joints.size(); ++n) j = model.joints[j].mimic->joint;
  return j;
}

std::string mimic_text(const RobotModel& model, const RobotJoint& joint) {
  const RobotJoint::Mimic& m = *joint.mimic;
  return "mimic of " + quoted(model.joints[m.joint].name) + ": " + decimal_text(m.multiplier) + " q + " + decimal_text(m.offset);
}

}  // namespace

namespace {

// The value of every joint from the named columns (joint_values), or with
// `rates` their derivatives (a mimic joint's is m times its joint's: the
// offset drops).
std::vector<Exact> all_joints(const RobotModel& model, const std::vector<int>& columns, const std::vector<Exact>& row,
                              bool rates);

}  // namespace

std::vector<Exact> joint_values(const RobotModel& model, const std::vector<int>& columns, const std::vector<Exact>& row) {
  return all_joints(model, columns, row, false);
}

const char* interpolation_name(JointInterpolation how) {
  switch (how) {
    case JointInterpolation::Linear: return "linear";
    case JointInterpolation::Cubic: return "cubic";
    case JointInterpolation::Quintic: return "quintic";
  }
  return "linear";
}

namespace {

std::vector<Exact> all_joints(const RobotModel& model, const std::vector<int>& columns, const std::vector<Exact>& row,
                              bool rates) {
  std::vector<std::optional<Exact>> value(model.joints.size());
  for (std::size_t c = 0; c < columns.size(); ++c) value[columns[c]] = row[c];
  // Mimic joints follow their joint, which may follow another (no cycles:
  // the reader refuses them), so at most joints.size() rounds.
  for (std::size_t round = 0; round <= model.joints.size(); ++round) {
    bool open = false;
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const RobotJoint& joint = model.joints[j];
      if (value[j] || !joint.moves() || !joint.mimic) continue;
      if (const std::optional<Exact>& q = value[joint.mimic->joint])
        value[j] = joint.mimic->multiplier * *q + (rates ? Exact(0) : joint.mimic->offset);
      else open = true;
    }
    if (!open) break;
  }
  std::vector<Exact> out(model.joints.size(), Exact(0));
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    if (!model.joints[j].moves()) continue;
    if (!value[j]) throw InputError(model.source + ": joint " + quoted(model.joints[j].name) + " has no value");
    out[j] = *value[j];
  }
  return out;
}

// The degree of a path's joint polynomials: 1, 3 or 5.
int path_degree(const JointPath& path) {
  return path.interpolation == JointInterpolation::Quintic ? 5 : path.interpolation == JointInterpolation::Cubic ? 3 : 1;
}

// Every joint's values, rates and accelerations at waypoint k (zero where
// the path has none).
struct Waypoint {
  std::vector<Exact> value, rate, accel;
};

Waypoint waypoint(const RobotModel& model, const std::vector<int>& columns, const JointPath& path, std::size_t k) {
  Waypoint w;
  w.value = all_joints(model, columns, path.positions[k], false);
  const std::vector<Exact> zero(columns.size(), Exact(0));
  w.rate = all_joints(model, columns, path.velocities.empty() ? zero : path.velocities[k], true);
  w.accel = all_joints(model, columns, path.accelerations.empty() ? zero : path.accelerations[k], true);
  return w;
}

// A rational s in [0, 1] with p(s) > 0, or nullopt when p <= 0 on all of
// [0, 1], decided exactly (proofs/trajectories.md section 2): p has one
// sign between consecutive distinct real roots, so the ends 0 and 1 and a
// point between each two consecutive roots of p in [0, 1] (isolated
// exactly on its square-free part) meet every part of [0, 1] where p is
// not zero.  Throws ExactLimit when the isolation does not finish.
std::optional<Exact> positive_point(PolyQ p) {
  trim(p);
  if (p.empty()) return std::nullopt;  // p = 0
  const PolyZ z = primitive(p);        // a positive multiple: the same signs
  std::vector<Exact> samples = {Exact(0), Exact(1)};
  if (z.size() > 1) {
    const std::vector<RealRoot> roots = real_roots(square_free(z), Exact(0), Exact(1));
    for (std::size_t i = 0; i + 1 < roots.size(); ++i) samples.push_back((roots[i].hi + roots[i + 1].lo) / 2);
  }
  for (const Exact& x : samples)
    if (sign_at(z, x) == CGAL::POSITIVE) return x;
  return std::nullopt;
}

// A link segment with its joints linear between two waypoint values.
std::shared_ptr<const LinkMotion> linear_link(std::shared_ptr<const ChainDescription> chain, std::vector<Exact> from,
                                              std::vector<Exact> to) {
  auto m = std::make_shared<LinkMotion>();
  m->chain = std::move(chain);
  m->from = std::move(from);
  m->to = std::move(to);
  return m;
}

// An exact rational as a short text: its decimal when it has one, else p/q.
std::string exact_text(const Exact& q) {
  const std::string d = decimal_text(q);
  return d.rfind("about ", 0) == 0 || d.find("(a double)") != std::string::npos ? to_string(q) : d;
}

}  // namespace

void validate_joint_path(const RobotModel& model, const JointPath& path) {
  std::map<std::string, std::size_t> columns;
  for (std::size_t c = 0; c < path.joints.size(); ++c) {
    const std::string& name = path.joints[c];
    const int j = model.joint_index(name);
    if (j < 0) throw JointPathError("joints", {c}, "unknown joint " + quoted(name) + " (not in " + model.source + ")");
    if (!model.joints[j].moves()) throw JointPathError("joints", {c}, "joint " + quoted(name) + " is fixed (name only moving joints)");
    if (model.joints[j].mimic)
      throw JointPathError("joints", {c}, "joint " + quoted(name) + " is a " + mimic_text(model, model.joints[j]) +
                                              " (do not name it: it follows that joint)");
    if (auto [it, fresh] = columns.emplace(name, c); !fresh)
      throw JointPathError("joints", {c}, "joint " + quoted(name) + " named twice (also joints[" + std::to_string(it->second) + "])");
  }
  for (const RobotJoint& joint : model.joints)
    if (joint.moves() && !joint.mimic && !columns.count(joint.name))
      throw JointPathError("joints", {}, "the moving joint " + quoted(joint.name) + " is missing (every moving joint must be named)");
  if (path.times.size() < 2)
    throw JointPathError("times", {}, "at least 2 times are required, got " + std::to_string(path.times.size()));
  for (std::size_t k = 1; k < path.times.size(); ++k)
    if (!(path.times[k - 1] < path.times[k])) throw JointPathError("times", {k}, "times must be strictly increasing");
  if (path.positions.size() != path.times.size())
    throw JointPathError("positions", {}, "expected " + std::to_string(path.times.size()) + " waypoints (one per time), got " +
                                              std::to_string(path.positions.size()));
  std::vector<int> index;
  for (const std::string& name : path.joints) index.push_back(model.joint_index(name));
  for (std::size_t k = 0; k < path.positions.size(); ++k) {
    const std::vector<Exact>& row = path.positions[k];
    if (row.size() != path.joints.size())
      throw JointPathError("positions", {k}, "waypoint " + std::to_string(k) + ": expected " + std::to_string(path.joints.size()) +
                                                 " values (one per joint), got " + std::to_string(row.size()));
    for (std::size_t c = 0; c < row.size(); ++c) {
      const RobotJoint& joint = model.joints[index[c]];
      if (joint.type != RobotJoint::Type::Revolute && joint.type != RobotJoint::Type::Prismatic) continue;
      if (row[c] < *joint.lower || row[c] > *joint.upper)
        throw JointPathError("positions", {k, c}, "waypoint " + std::to_string(k) + ": joint " + quoted(joint.name) + " at " +
                                                      decimal_text(row[c]) + " is outside its limits [" +
                                                      decimal_text(*joint.lower) + ", " + decimal_text(*joint.upper) + "]");
    }
    // Mimic joints: their values at the waypoint, within their limits.
    const std::vector<Exact> all = joint_values(model, index, row);
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const RobotJoint& joint = model.joints[j];
      if (!joint.mimic || (joint.type != RobotJoint::Type::Revolute && joint.type != RobotJoint::Type::Prismatic)) continue;
      if (all[j] >= *joint.lower && all[j] <= *joint.upper) continue;
      const int d = driver(model, static_cast<int>(j));
      const std::size_t c = static_cast<std::size_t>(std::find(index.begin(), index.end(), d) - index.begin());
      throw JointPathError("positions", {k, c}, "waypoint " + std::to_string(k) + ": joint " + quoted(joint.name) + " (" +
                                                    mimic_text(model, joint) + ") at " + decimal_text(all[j]) +
                                                    " is outside its limits [" + decimal_text(*joint.lower) + ", " +
                                                    decimal_text(*joint.upper) + "]");
    }
  }
  // Rates and accelerations: of the shape of positions where the
  // interpolation uses them, absent elsewhere.
  const char* how = interpolation_name(path.interpolation);
  auto shape = [&](const std::vector<std::vector<Exact>>& rows, const char* field, bool used) {
    if (!used) {
      if (!rows.empty())
        throw JointPathError(field, {}, std::string(field) + " are not used by " + how +
                                            " interpolation (velocities: cubic or quintic; accelerations: quintic)");
      return;
    }
    if (rows.size() != path.times.size())
      throw JointPathError(field, {}, "expected " + std::to_string(path.times.size()) + " rows (one per time), got " +
                                          std::to_string(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k)
      if (rows[k].size() != path.joints.size())
        throw JointPathError(field, {k}, "waypoint " + std::to_string(k) + ": expected " +
                                             std::to_string(path.joints.size()) + " values (one per joint), got " +
                                             std::to_string(rows[k].size()));
  };
  const int degree = path_degree(path);
  shape(path.velocities, "velocities", degree > 1);
  shape(path.accelerations, "accelerations", degree > 3);
  if (degree == 1) return;
  // Cubic and quintic: every joint with limits (mimic joints too) within
  // them on the whole polynomial of every segment, decided exactly.
  Waypoint a = waypoint(model, index, path, 0);
  for (std::size_t k = 0; k + 1 < path.times.size(); ++k) {
    Waypoint b = waypoint(model, index, path, k + 1);
    const Exact T = path.times[k + 1] - path.times[k];
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const RobotJoint& joint = model.joints[j];
      if (!joint.moves() || (joint.type != RobotJoint::Type::Revolute && joint.type != RobotJoint::Type::Prismatic)) continue;
      const PolyQ q = hermite_coefficients(degree, a.value[j], b.value[j], a.rate[j], b.rate[j], a.accel[j], b.accel[j], T);
      for (const bool upper : {true, false}) {
        PolyQ p = q;
        if (upper) p[0] -= *joint.upper;
        else {
          for (Exact& c : p) c = -c;
          p[0] += *joint.lower;
        }
        std::optional<Exact> s;
        try {
          s = positive_point(p);
        } catch (const ExactLimit&) {
          throw JointPathError("path", {}, "segment from waypoint " + std::to_string(k) + " to " + std::to_string(k + 1) +
                                               ": could not decide whether joint " + quoted(joint.name) +
                                               " stays within its limits (exact root isolation did not finish)");
        }
        if (!s) continue;
        Exact value = q.back();
        for (std::size_t c = q.size() - 1; c-- > 0;) value = value * *s + q[c];
        const std::string what = joint.mimic ? " (" + mimic_text(model, joint) + ")" : "";
        throw JointPathError("path", {}, "segment from waypoint " + std::to_string(k) + " to " + std::to_string(k + 1) +
                                             " (" + how + "): joint " + quoted(joint.name) + what + " at t = " +
                                             exact_text(path.times[k] + *s * T) + " is at " + exact_text(value) +
                                             ", outside its limits [" + decimal_text(*joint.lower) + ", " +
                                             decimal_text(*joint.upper) + "]");
      }
    }
    a = std::move(b);
  }
}

RobotBodies add_robot(Scene& scene, const PlacedRobot& robot, const JointPath& path) {
  const RobotModel& model = robot.model();
  validate_joint_path(model, path);
  std::vector<int> index;
  for (const std::string& name : path.joints) index.push_back(model.joint_index(name));
  std::vector<std::vector<Exact>> all;  // every joint's value at every waypoint (mimic joints included)
  for (const std::vector<Exact>& row : path.positions) all.push_back(joint_values(model, index, row));
  const int degree = path_degree(path);
  std::vector<Waypoint> ends;  // cubic and quintic: every joint's value, rate and acceleration at every waypoint
  if (degree > 1)
    for (std::size_t k = 0; k < path.times.size(); ++k) ends.push_back(waypoint(model, index, path, k));
  const Exact t_first = path.times.front(), t_last = path.times.back();
  RobotBodies out;
  out.body.assign(model.links.size(), -1);
  out.parts.resize(model.links.size());
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    const RobotLink& link = model.links[l];
    const std::vector<int>& js = robot.chain_joints(static_cast<int>(l));
    auto values = [&](std::size_t k) {
      std::vector<Exact> q;
      q.reserve(js.size());
      for (int j : js) q.push_back(all[k][j]);
      return q;
    };
    // Cubic and quintic: segment k's motion of this link, when its joints'
    // polynomials are not all of degree <= 1 (then it is the linear motion
    // between its waypoint values, exactly); null otherwise.
    auto hermite = [&](std::size_t k, const std::shared_ptr<const ChainDescription>& chain) -> std::shared_ptr<const LinkMotion> {
      if (degree == 1) return nullptr;
      const Exact T = path.times[k + 1] - path.times[k];
      bool linear = true;
      for (std::size_t c = 0; c < js.size() && linear; ++c) {
        const int j = js[c];
        const std::vector<Exact> q = hermite_coefficients(degree, ends[k].value[j], ends[k + 1].value[j], ends[k].rate[j],
                                                          ends[k + 1].rate[j], ends[k].accel[j], ends[k + 1].accel[j], T);
        for (std::size_t e = 2; e < q.size(); ++e) linear = linear && q[e] == 0;
      }
      if (linear) return nullptr;
      auto m = std::make_shared<LinkMotion>();
      m->chain = chain;
      m->from = values(k);
      m->to = values(k + 1);
      m->duration = T;
      for (int j : js) {
        m->from_rate.push_back(ends[k].rate[j]);
        m->to_rate.push_back(ends[k + 1].rate[j]);
        if (degree == 5) {
          m->from_accel.push_back(ends[k].accel[j]);
          m->to_accel.push_back(ends[k + 1].accel[j]);
        }
      }
      return m;
    };
    bool still = true;
    const std::vector<Exact> first = values(0);
    for (std::size_t k = 1; k < path.times.size() && still; ++k) still = values(k) == first;
    for (std::size_t k = 0; k + 1 < path.times.size() && still && degree > 1; ++k) still = !hermite(k, nullptr);
    for (std::size_t p = 0; p < link.parts.size(); ++p) {
      const std::shared_ptr<const ChainDescription>& chain = robot.chain(static_cast<int>(l), p);
      Body b = link.parts[p].geometry;
      b.name = robot.name() + "/" + link.name + link.parts[p].suffix;
      if (still) {
        if (const std::optional<Mat34E> pose = chain->exact_pose(first)) {
          Motion m;  // one pose: motionless
          m.t0 = t_first;
          m.t1 = t_last;
          m.control_points = {*pose};
          m.weights = {1};
          b.motion = std::move(m);
        } else {
          MotionSegment seg;
          seg.t0 = t_first;
          seg.t1 = t_last;
          seg.link = linear_link(chain, first, first);
          b.trajectory = Trajectory{{std::move(seg)}};
        }
      } else {
        Trajectory traj;
        for (std::size_t k = 0; k + 1 < path.times.size(); ++k) {
          MotionSegment seg;
          seg.t0 = path.times[k];
          seg.t1 = path.times[k + 1];
          if (std::shared_ptr<const LinkMotion> polynomial = hermite(k, chain)) {
            seg.link = std::move(polynomial);  // never rational: a joint moves along a polynomial of degree >= 2
            traj.segments.push_back(std::move(seg));
            continue;
          }
          std::vector<Exact> from = values(k), to = values(k + 1);
          if (chain->rational_between(from, to)) {
            Motion m;
            m.t0 = seg.t0;
            m.t1 = seg.t1;
            m.control_points = {*chain->exact_pose(from), *chain->exact_pose(to)};
            m.weights = {1, 1};
            seg.rational = std::move(m);
          }
          // Also beside a rational curve: the segment is known as a link's.
          seg.link = linear_link(chain, std::move(from), std::move(to));
          traj.segments.push_back(std::move(seg));
        }
        if (traj.segments.size() == 1 && traj.segments[0].rational) b.motion = traj.segments[0].rational;
        else b.trajectory = std::move(traj);
      }
      out.parts[l].push_back(static_cast<int>(scene.bodies.size()));
      scene.bodies.push_back(std::move(b));
    }
    if (!out.parts[l].empty()) out.body[l] = out.parts[l].front();
  }
  return out;
}

std::vector<std::pair<int, int>> robot_default_checks(const PlacedRobot& robot, const RobotBodies& bodies,
                                                      const std::vector<int>& environment, bool self_collision,
                                                      const std::vector<std::pair<std::string, std::string>>& allowed_pairs) {
  const RobotModel& model = robot.model();
  std::set<std::pair<int, int>> allowed;  // link indices, ordered
  for (const auto& [a, b] : allowed_pairs) {
    const int la = model.link_index(a), lb = model.link_index(b);
    if (la < 0) throw InputError("allowed pair: unknown link " + quote_text(a));
    if (lb < 0) throw InputError("allowed pair: unknown link " + quote_text(b));
    allowed.insert(std::minmax(la, lb));
  }
  // A link's bodies: its parts, or (bodies built by hand) its one body.
  auto of = [&](std::size_t l) -> std::vector<int> {
    if (l < bodies.parts.size() && !bodies.parts[l].empty()) return bodies.parts[l];
    if (l < bodies.body.size() && bodies.body[l] >= 0) return {bodies.body[l]};
    return {};
  };
  std::vector<std::pair<int, int>> out;
  const int n = static_cast<int>(model.links.size());
  for (int l = 0; l < n; ++l)
    for (int part : of(l))
      for (int e : environment) out.emplace_back(part, e);
  if (self_collision) {
    auto adjacent = [&](int a, int b) {
      const int pa = model.links[a].parent_joint, pb = model.links[b].parent_joint;
      return (pa >= 0 && model.joints[pa].parent == b) || (pb >= 0 && model.joints[pb].parent == a);
    };
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        if (adjacent(a, b) || allowed.count({a, b})) continue;
        for (int x : of(a))
          for (int y : of(b)) out.emplace_back(x, y);
      }
  }
  return out;
}

}  // namespace tmcert
