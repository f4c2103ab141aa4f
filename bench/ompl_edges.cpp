// The certified OMPL motion validator against OMPL's DiscreteMotionValidator
// (issue 13, item 5), on the same planner edges.
//
// SE(3) case: the gripper (examples/gripper/gripper.off, 438 triangles)
// among its fixture (fixture.off, 5294 triangles).  The edges are those an
// RRT extension makes: from a start state free of contact (FCL says so and
// tmcert certifies it) towards a uniformly sampled state, cut at the range
// RRTConnect uses by default (0.2 x the space's maximum extent); seeded.
//
//  - certified: tmcert::CertifiedMotionValidator (src/ompl/): the bodies
//    prepared once, then each edge decided as checkMotion(s1, s2) does
//    (`decide`: filtered kernel, one thread, the gripper scene's epsilon
//    1/2000, stopping at the first proof of contact); the full search with
//    the first-contact bracket (`certify`, what checkMotion with lastValid
//    and certify_edge run) is timed too, for colliding edges.
//  - discrete: ompl::base::DiscreteMotionValidator at OMPL's default
//    resolution (longest valid segment 1% of the maximum extent) with FCL
//    0.7 (OBBRSS models built once; a yes/no collide per state) as the
//    state validity checker: what a planner runs today.
//
// Arm case: the 6-joint arm of examples/ompl/arm6.urdf (7 box links) with
// its base at (0.32, 0.06, 0) beside the same fixture, planned in joint
// space (RealVectorStateSpace with the URDF limits): the certified
// validator (tmcert::use_certified_arm, linear joint motion, epsilon 1/2000)
// against DiscreteMotionValidator with FCL (every link's OBBRSS model
// placed by forward kinematics in doubles); the same RRT extension edges.
// Links against the fixture only (no self-collision), for both.
//
// Each edge is timed once per method (one run), in thread CPU time.  The table gives medians and
// maxima per edge, and their ratios; then the edges the discrete validator
// accepted that tmcert proves colliding, with their witnesses.
//
// Usage: tmcert_ompl_bench [--edges N] [--seed S] [--root DIR] [--verbose] [--no-full]
//                          [--se3-only] [--repeat K]
// --verbose prints the search statistics of every edge; --no-full skips the
// full search (certify) of every edge (for profiling checkMotion alone);
// --se3-only skips the arm (its edges depend on the SE(3) case's random
// draws, so the arm cannot run alone); --repeat K runs checkMotion's
// decide K - 1 more times per edge, untimed (profiling: the edges then
// outweigh the one-time preparation).
// Exit status 0; 3 on bad usage.
#include "src/ompl/certified_arm.h"
#include "src/io/parse.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#ifndef TMCERT_SOURCE_DIR
#define TMCERT_SOURCE_DIR "."
#endif

namespace ob = ompl::base;
using namespace tmcert;

namespace {

// Thread CPU time: the machine may be shared; both validators run on this
// one thread.
struct Clock {
  using time_point = double;
  static double now() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
  }
};
double since(double start) { return Clock::now() - start; }

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * (v.size() - 1) + 0.5)];
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    std::exit(3);
  }
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ------------------------------------------------------------------ FCL

using Model = fcl::BVHModel<fcl::OBBRSSd>;

// A body's polygons as triangles in doubles (fans of its convex pieces),
// for FCL only.
std::shared_ptr<Model> fcl_model(const Body& b) {
  std::vector<fcl::Vector3d> verts;
  std::vector<fcl::Triangle> tris;
  for (const ConvexPiece& piece : b.pieces) {
    const std::size_t first = verts.size();
    for (const Vec3E& v : piece.vertices)
      verts.emplace_back(CGAL::to_double(v[0]), CGAL::to_double(v[1]), CGAL::to_double(v[2]));
    for (std::size_t k = 1; k + 1 < piece.vertices.size(); ++k) tris.emplace_back(first, first + k, first + k + 1);
  }
  auto model = std::make_shared<Model>();
  model->beginModel(static_cast<int>(tris.size()), static_cast<int>(verts.size()));
  model->addSubModel(verts, tris);
  model->endModel();
  return model;
}

std::size_t triangles(const Body& b) {
  std::size_t n = 0;
  for (const ConvexPiece& piece : b.pieces) n += piece.vertices.size() - 2;
  return n;
}

// FCL as an OMPL state validity checker for one rigid body in SE(3).
class FclSE3Checker final : public ob::StateValidityChecker {
 public:
  FclSE3Checker(const ob::SpaceInformationPtr& si, std::shared_ptr<Model> robot, std::shared_ptr<Model> obstacles)
      : ob::StateValidityChecker(si), robot_(robot, fcl::Transform3d::Identity()),
        obstacles_(obstacles, fcl::Transform3d::Identity()) {}
  bool isValid(const ob::State* s) const override {
    const auto* x = s->as<ob::SE3StateSpace::StateType>();
    const auto& q = x->rotation();
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
    tf.translation() = fcl::Vector3d(x->getX(), x->getY(), x->getZ());
    robot_.setTransform(tf);
    robot_.computeAABB();
    fcl::CollisionRequestd request;  // yes/no
    fcl::CollisionResultd result;
    fcl::collide(&robot_, &obstacles_, request, result);
    return !result.isCollision();
  }

 private:
  mutable fcl::CollisionObjectd robot_;
  fcl::CollisionObjectd obstacles_;
};

// ------------------------------------------------------------------ the comparison

struct Row {
  double certified = 0, discrete = 0;
  double full = 0;  // certify(): the whole search, with the first-contact bracket
  Verdict verdict = Verdict::Undecided;
  Verdict full_verdict = Verdict::Undecided;
  bool discrete_ok = false;
  bool prefiltered = false;  // every check cleared by the swept-box prefilter alone
  std::optional<Witness> witness;
};

std::string point_text(const Witness& w) {
  if (w.point_box) {
    std::ostringstream o;
    o << "box [";
    for (int i = 0; i < 3; ++i)
      o << (i ? ", " : "") << CGAL::to_double((*w.point_box)[i][0]) << ".." << CGAL::to_double((*w.point_box)[i][1]);
    return o.str() + "]";
  }
  char text[128];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", CGAL::to_double(w.point[0]), CGAL::to_double(w.point[1]),
                CGAL::to_double(w.point[2]));
  return text;
}

void report(const char* name, const std::vector<Row>& rows, std::size_t print_limit, bool full) {
  std::vector<double> cert_safe, cert_all, disc_all, disc_safe, cert_coll, disc_coll, full_coll, cert_searched,
      disc_searched;
  std::size_t safe = 0, collision = 0, undecided = 0, disc_ok = 0, missed = 0, disc_only_reject = 0, disagree = 0;
  for (const Row& r : rows) {
    cert_all.push_back(r.certified);
    disc_all.push_back(r.discrete);
    if (r.verdict == Verdict::Safe) {
      ++safe;
      cert_safe.push_back(r.certified);
      disc_safe.push_back(r.discrete);
      if (!r.prefiltered) {
        cert_searched.push_back(r.certified);
        disc_searched.push_back(r.discrete);
      }
    } else if (r.verdict == Verdict::Collision) {
      ++collision;
      cert_coll.push_back(r.certified);
      disc_coll.push_back(r.discrete);
      full_coll.push_back(r.full);
    } else {
      ++undecided;
    }
    if (r.discrete_ok) ++disc_ok;
    if (r.discrete_ok && r.verdict == Verdict::Collision) ++missed;
    if (!r.discrete_ok && r.verdict == Verdict::Safe) ++disc_only_reject;
    // checkMotion's answer and the full search's must agree on "safe"; a
    // collision of one is never the other's safe.
    if ((r.verdict == Verdict::Safe) != (r.full_verdict == Verdict::Safe)) ++disagree;
  }
  const double ms = 1e3;
  std::printf("\n== %s: %zu edges ==\n", name, rows.size());
  std::printf("tmcert: %zu safe, %zu collision, %zu undecided; discrete+FCL accepted %zu\n", safe, collision,
              undecided, disc_ok);
  std::printf("| edges | certified median | certified max | discrete median | discrete max | median ratio |\n");
  std::printf("|---|---|---|---|---|---|\n");
  auto line = [&](const char* which, const std::vector<double>& c, const std::vector<double>& d) {
    if (c.empty()) return;
    const double cm = quantile(c, 0.5), dm = quantile(d, 0.5);
    std::printf("| %s (%zu) | %.3f ms | %.3f ms | %.3f ms | %.3f ms | %.1fx |\n", which, c.size(), cm * ms,
                quantile(c, 1.0) * ms, dm * ms, quantile(d, 1.0) * ms, dm > 0 ? cm / dm : 0.0);
  };
  line("all", cert_all, disc_all);
  line("certified safe", cert_safe, disc_safe);
  line("certified safe, searched", cert_searched, disc_searched);
  line("certified collision", cert_coll, disc_coll);
  if (full && !full_coll.empty())
    std::printf("certified collision edges (%zu), full search with the first-contact bracket (certify): median %.3f "
                "ms, max %.3f ms\n",
                full_coll.size(), quantile(full_coll, 0.5) * ms, quantile(full_coll, 1.0) * ms);
  if (full) std::printf("edges where checkMotion and the full search disagree on safe: %zu\n", disagree);
  std::printf("edges the discrete validator accepted that tmcert proves colliding: %zu\n", missed);
  std::printf("edges tmcert certifies safe that the discrete validator rejected: %zu\n", disc_only_reject);
  std::size_t printed = 0;
  for (std::size_t k = 0; k < rows.size() && printed < print_limit; ++k) {
    const Row& r = rows[k];
    if (!(r.discrete_ok && r.verdict == Verdict::Collision) || !r.witness) continue;
    ++printed;
    std::printf("  edge %zu: t = %.9g, %s x %s at %s\n", k, CGAL::to_double(r.witness->t),
                r.witness->features[0].c_str(), r.witness->features[1].c_str(), point_text(*r.witness).c_str());
  }
}

// The edges of RRT extensions: from a start that both checkers call free,
// towards a uniform sample, at most `range` long.
template <class StartFree>
std::vector<std::pair<ob::State*, ob::State*>> planner_edges(const ob::SpaceInformationPtr& si, std::size_t n,
                                                             double range, StartFree&& start_free) {
  std::vector<std::pair<ob::State*, ob::State*>> edges;
  ob::StateSamplerPtr sampler = si->allocStateSampler();
  ob::State* target = si->allocState();
  while (edges.size() < n) {
    ob::State* a = si->allocState();
    do sampler->sampleUniform(a);
    while (!start_free(a));
    sampler->sampleUniform(target);
    ob::State* b = si->allocState();
    const double d = si->distance(a, target);
    if (d > range) si->getStateSpace()->interpolate(a, target, range / d, b);
    else si->copyState(b, target);
    edges.push_back({a, b});
  }
  si->freeState(target);
  return edges;
}


// ------------------------------------------------------------------ the arm (doubles, for FCL)

Eigen::Isometry3d to_double(const Pose& p) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(CGAL::to_double(p.translation[0]), CGAL::to_double(p.translation[1]),
                                      CGAL::to_double(p.translation[2]));
  const Rotation& r = p.rotation;
  switch (r.kind) {
    case Rotation::Kind::Identity: break;
    case Rotation::Kind::Quaternion:
      out.linear() = Eigen::Quaterniond(CGAL::to_double(r.quaternion[0]), CGAL::to_double(r.quaternion[1]),
                                        CGAL::to_double(r.quaternion[2]), CGAL::to_double(r.quaternion[3]))
                         .normalized()
                         .toRotationMatrix();
      break;
    case Rotation::Kind::Rpy:  // R = Rz(yaw) Ry(pitch) Rx(roll)
      out.linear() = (Eigen::AngleAxisd(CGAL::to_double(r.rpy[2]), Eigen::Vector3d::UnitZ()) *
                      Eigen::AngleAxisd(CGAL::to_double(r.rpy[1]), Eigen::Vector3d::UnitY()) *
                      Eigen::AngleAxisd(CGAL::to_double(r.rpy[0]), Eigen::Vector3d::UnitX()))
                         .toRotationMatrix();
      break;
    case Rotation::Kind::Matrix:
      for (int i = 0; i < 9; ++i) out.linear()(i / 3, i % 3) = CGAL::to_double(r.matrix[i]);
      break;
  }
  return out;
}

// Forward kinematics in doubles: the world pose of every link's frame at
// joint values `q` (column k: joint `joints[k]`).
std::vector<Eigen::Isometry3d> link_poses(const PlacedRobot& robot, const std::vector<std::string>& joints,
                                          const double* q) {
  const RobotModel& m = robot.model();
  std::vector<Eigen::Isometry3d> out(m.links.size());
  std::vector<char> done(m.links.size(), 0);
  std::function<const Eigen::Isometry3d&(int)> pose = [&](int l) -> const Eigen::Isometry3d& {
    if (done[l]) return out[l];
    const int j = m.links[l].parent_joint;
    if (j < 0) {
      out[l] = to_double(robot.base());
    } else {
      const RobotJoint& joint = m.joints[j];
      Eigen::Isometry3d t = pose(joint.parent) * to_double(joint.origin);
      if (joint.moves()) {
        const double v = q[std::find(joints.begin(), joints.end(), joint.name) - joints.begin()];
        const Eigen::Vector3d axis = Eigen::Vector3d(CGAL::to_double(joint.axis[0]), CGAL::to_double(joint.axis[1]),
                                                     CGAL::to_double(joint.axis[2]))
                                         .normalized();
        if (joint.type == RobotJoint::Type::Prismatic) t.translate(v * axis);
        else t.rotate(Eigen::AngleAxisd(v, axis));
      }
      out[l] = t;
    }
    done[l] = 1;
    return out[l];
  };
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    pose(static_cast<int>(l));
  }
  return out;
}

// FCL as an OMPL state validity checker for an arm in joint space: every
// link with geometry against the obstacles (no self-collision).
class FclArmChecker final : public ob::StateValidityChecker {
 public:
  FclArmChecker(const ob::SpaceInformationPtr& si, std::shared_ptr<const PlacedRobot> robot,
                std::vector<std::string> joints, std::shared_ptr<Model> obstacles)
      : ob::StateValidityChecker(si), robot_(std::move(robot)), joints_(std::move(joints)),
        obstacles_(obstacles, fcl::Transform3d::Identity()) {
    const RobotModel& m = robot_->model();
    // One object per part of a link (its collision elements in the part's
    // frame within the link frame).
    for (std::size_t l = 0; l < m.links.size(); ++l)
      for (const LinkPart& part : m.links[l].parts) {
        links_.push_back(static_cast<int>(l));
        Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
        for (const Pose& p : part.frame) frame = frame * to_double(p);
        frames_.push_back(frame);
        objects_.push_back(std::make_unique<fcl::CollisionObjectd>(fcl_model(part.geometry),
                                                                   fcl::Transform3d::Identity()));
      }
  }
  bool isValid(const ob::State* s) const override {
    const auto poses = link_poses(*robot_, joints_, s->as<ob::RealVectorStateSpace::StateType>()->values);
    for (std::size_t k = 0; k < links_.size(); ++k) {
      fcl::Transform3d tf = fcl::Transform3d::Identity();
      const Eigen::Isometry3d placed = poses[links_[k]] * frames_[k];
      tf.linear() = placed.linear();
      tf.translation() = placed.translation();
      objects_[k]->setTransform(tf);
      objects_[k]->computeAABB();
      fcl::CollisionRequestd request;
      fcl::CollisionResultd result;
      fcl::collide(objects_[k].get(), &obstacles_, request, result);
      if (result.isCollision()) return false;
    }
    return true;
  }

 private:
  std::shared_ptr<const PlacedRobot> robot_;
  std::vector<std::string> joints_;
  fcl::CollisionObjectd obstacles_;
  std::vector<int> links_;
  std::vector<Eigen::Isometry3d> frames_;  // each part's frame in its link's frame
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects_;
};

}  // namespace

int main(int argc, char** argv) {
  std::size_t n_edges = 300;
  std::uint32_t seed = 20261125;
  std::string root = TMCERT_SOURCE_DIR;
  bool verbose = false;
  bool full = true;
  bool se3_only = false;
  unsigned repeat = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--edges" && i + 1 < argc) n_edges = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--seed" && i + 1 < argc) seed = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 10));
    else if (a == "--root" && i + 1 < argc) root = argv[++i];
    else if (a == "--verbose") verbose = true;
    else if (a == "--no-full") full = false;
    else if (a == "--se3-only") se3_only = true;
    else if (a == "--repeat" && i + 1 < argc) repeat = std::max(1ul, std::strtoul(argv[++i], nullptr, 10));
    else {
      std::fprintf(stderr, "usage: tmcert_ompl_bench [--edges N] [--seed S] [--root DIR] [--verbose] [--no-full] [--se3-only] [--repeat K]\n");
      return 3;
    }
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(seed);

  // ---------------------------------------------------------------- SE(3)
  const Scene scene = parse_scene_file(root + "/examples/gripper/gripper-safe.json");
  const Body* gripper = nullptr;
  const Body* fixture = nullptr;
  for (const Body& b : scene.bodies) (b.name == "gripper" ? gripper : fixture) = &b;
  std::printf("SE(3): gripper %zu triangles, fixture %zu triangles, epsilon %g\n", triangles(*gripper),
              triangles(*fixture), scene.epsilon ? CGAL::to_double(*scene.epsilon) : 0.0);

  // Bounds: the fixture's box, grown by the gripper's size on each side.
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  double size = 0;
  for (const ConvexPiece& p : fixture->pieces)
    for (const Vec3E& v : p.vertices)
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], CGAL::to_double(v[i]));
        hi[i] = std::max(hi[i], CGAL::to_double(v[i]));
      }
  for (const ConvexPiece& p : gripper->pieces)
    for (const Vec3E& v : p.vertices)
      for (int i = 0; i < 3; ++i) size = std::max(size, std::abs(CGAL::to_double(v[i])));
  auto space = std::make_shared<ob::SE3StateSpace>();
  ob::RealVectorBounds bounds(3);
  for (int i = 0; i < 3; ++i) {
    bounds.setLow(i, lo[i] - size);
    bounds.setHigh(i, hi[i] + size);
  }
  space->setBounds(bounds);

  auto si_discrete = std::make_shared<ob::SpaceInformation>(space);
  si_discrete->setStateValidityChecker(std::make_shared<FclSE3Checker>(si_discrete, fcl_model(*gripper), fcl_model(*fixture)));
  si_discrete->setup();  // DiscreteMotionValidator, resolution 0.01 of the extent
  auto si_certified = std::make_shared<ob::SpaceInformation>(space);
  VerifyOptions options;
  options.epsilon = scene.epsilon ? *scene.epsilon : default_epsilon(scene);
  const auto started = Clock::now();
  const auto validator = use_certified_se3(si_certified, *gripper, *fixture, options);
  const double prepare = since(started);
  si_certified->setup();
  std::printf("preparing both bodies once: %.1f ms; OMPL resolution %.3g of the extent %.4g\n", prepare * 1e3,
              si_discrete->getStateValidityCheckingResolution(), space->getMaximumExtent());

  const double range = 0.2 * space->getMaximumExtent();
  const auto edges = planner_edges(si_discrete, n_edges, range, [&](const ob::State* s) {
    return si_discrete->isValid(s) && si_certified->isValid(s);
  });
  ob::DiscreteMotionValidator discrete(si_discrete);
  std::vector<Row> rows;
  for (const auto& [a, b] : edges) {
    Row r;
    auto t = Clock::now();
    r.discrete_ok = discrete.checkMotion(a, b);
    r.discrete = since(t);
    t = Clock::now();
    const EdgeCertificate e = validator->decide(a, b);  // what checkMotion(a, b) runs
    r.certified = since(t);
    r.verdict = e.check.verdict;
    for (unsigned k = 1; k < repeat; ++k) validator->decide(a, b);
    t = Clock::now();
    r.full_verdict = full ? validator->certify(a, b).check.verdict : r.verdict;
    r.full = since(t);
    r.witness = e.check.witness;
    r.prefiltered = !e.check.checks.empty();
    for (const CheckResult& c : e.check.checks) r.prefiltered = r.prefiltered && c.stats.prefiltered;
    if (verbose)
      for (const CheckResult& c : e.check.checks)
        std::printf("edge %zu: %s %.3f ms (discrete %.3f ms): nodes %llu, static configurations %llu, filter pairs %llu, "
                    "exact static %llu, sphere tests %llu, exact pieces %llu, search %.3f ms\n",
                    rows.size(), to_string(c.verdict), r.certified * 1e3, r.discrete * 1e3,
                    (unsigned long long)c.stats.nodes, (unsigned long long)c.stats.static_configurations,
                    (unsigned long long)c.stats.static_filter_pairs, (unsigned long long)c.stats.static_tests,
                    (unsigned long long)c.stats.sphere_tests, (unsigned long long)c.stats.exact_pieces, c.stats.seconds * 1e3);
    rows.push_back(r);
  }
  report("SE(3) gripper among the fixture, RRT extension edges", rows, 10, full);
  for (const auto& [a, b] : edges) {
    si_discrete->freeState(a);
    si_discrete->freeState(b);
  }

  if (se3_only) return 0;
  // ---------------------------------------------------------------- the arm
  // examples/ompl/arm6.urdf (6 revolute joints, box links) beside the
  // fixture (5294 triangles), base at (0.32, 0.06, 0): its reach covers the
  // fixture.  Joint space with the URDF limits; links against the fixture
  // only (no self-collision, for both validators).
  {
    const auto arm = std::make_shared<const PlacedRobot>(
        load_urdf(root + "/examples/ompl/arm6.urdf"), "arm",
        Pose{{Exact(8, 25), Exact(3, 50), Exact(0)}, Rotation{}});
    const std::vector<std::string> joints = {"j1", "j2", "j3", "j4", "j5", "j6"};
    auto jspace = std::make_shared<ob::RealVectorStateSpace>(joints.size());
    ob::RealVectorBounds jb(joints.size());
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const RobotJoint& j = arm->model().joints[arm->model().joint_index(joints[k])];
      jb.setLow(k, CGAL::to_double(*j.lower));
      jb.setHigh(k, CGAL::to_double(*j.upper));
    }
    jspace->setBounds(jb);
    auto jdiscrete = std::make_shared<ob::SpaceInformation>(jspace);
    jdiscrete->setStateValidityChecker(std::make_shared<FclArmChecker>(jdiscrete, arm, joints, fcl_model(*fixture)));
    jdiscrete->setup();
    auto jcertified = std::make_shared<ob::SpaceInformation>(jspace);
    const auto t = Clock::now();
    const auto arm_validator = use_certified_arm(jcertified, arm, joints, *fixture, false, {}, options);
    const double arm_prepare = since(t);
    jcertified->setup();
    std::printf("\narm: 6 revolute joints, %zu box links; preparing once: %.1f ms; joint-space extent %.4g, OMPL "
                "resolution %.3g\n", arm_validator->pool().labels().size() - 1, arm_prepare * 1e3,
                jspace->getMaximumExtent(), jdiscrete->getStateValidityCheckingResolution());
    const double jrange = 0.2 * jspace->getMaximumExtent();
    const auto jedges = planner_edges(jdiscrete, n_edges, jrange, [&](const ob::State* s) {
      return jdiscrete->isValid(s) && jcertified->isValid(s);
    });
    ob::DiscreteMotionValidator jdiscrete_validator(jdiscrete);
    std::vector<Row> jrows;
    for (const auto& [a, b] : jedges) {
      Row r;
      auto t0 = Clock::now();
      r.discrete_ok = jdiscrete_validator.checkMotion(a, b);
      r.discrete = since(t0);
      t0 = Clock::now();
      const EdgeCertificate e = arm_validator->decide(a, b);  // what checkMotion(a, b) runs
      r.certified = since(t0);
      r.verdict = e.check.verdict;
      for (unsigned k = 1; k < repeat; ++k) arm_validator->decide(a, b);
      t0 = Clock::now();
      r.full_verdict = full ? arm_validator->certify(a, b).check.verdict : r.verdict;
      r.full = since(t0);
      r.witness = e.check.witness;
      r.prefiltered = !e.check.checks.empty();
      for (const CheckResult& c : e.check.checks) r.prefiltered = r.prefiltered && c.stats.prefiltered;
      if (verbose) {
        std::printf("arm edge %zu: %s %.3f ms (discrete %.3f ms)", jrows.size(), to_string(e.check.verdict),
                    r.certified * 1e3, r.discrete * 1e3);
        for (const CheckResult& c : e.check.checks)
          std::printf(" [%s%s %.2f ms %llu nodes]", to_string(c.verdict), c.stats.prefiltered ? " prefiltered" : "",
                      c.stats.seconds * 1e3, (unsigned long long)c.stats.nodes);
        std::printf("\n");
      }
      jrows.push_back(r);
    }
    report("6-joint arm beside the fixture, RRT extension edges in joint space", jrows, 10, full);
    for (const auto& [a, b] : jedges) {
      jdiscrete->freeState(a);
      jdiscrete->freeState(b);
    }
  }
  return 0;
}
