// The scene reader's poses and motions (src/io/scene_reader.h): rigid
// poses (SCENE_FORMAT.md "Rigid poses"), rational Bezier motions, keyframes
// (slerp, screw, nlerp) and piecewise motions, with their messages.
#include "src/io/scene_reader.h"

#include "kernels/decimal.h"

#include "src/model/segment_kind.h"
#include "src/model/pose_algebra.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace tmcert::reader {

namespace {

// A rational above 2 pi (2 pi < 6.283185307179587): an rpy angle beyond
// it is most likely in degrees.
const Exact& two_pi_above() {
  static const Exact bound = [] {
    Exact e;
    parse_exact("6.283185307179587", e);
    return e;
  }();
  return bound;
}

// "; the nearest rotation is the unit quaternion ...: write ... instead"
// with its components as decimals, which the reader takes exactly (a
// quaternion of any norm is a rotation): the rotation factor of the
// matrix's polar decomposition, in double precision.  When the matrix is
// not a rotation up to float noise (singular values off 1 by more than
// 1e-3: a scaling, a shear), the hint says so.  Empty when no rotation
// is near (a polar factor with determinant -1: a reflection) or the
// matrix is beyond the doubles.
std::string nearest_quaternion_hint(const std::array<Exact, 9>& m) {
  Eigen::Matrix3d a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      a(r, c) = CGAL::to_double(m[3 * r + c]);
      if (!std::isfinite(a(r, c))) return {};
    }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d sigma = svd.singularValues();
  const Eigen::Matrix3d nearest = svd.matrixU() * svd.matrixV().transpose();
  if (!(nearest.determinant() > 0)) return {};
  Eigen::Quaterniond q(nearest);
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  std::string list;
  for (const double x : {q.w(), q.x(), q.y(), q.z()}) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, x == 0 ? 0.0 : x);
    list += (list.empty() ? "" : ", ") + std::string(buffer, r.ptr);
  }
  std::string far;
  if ((sigma.array() - 1).abs().maxCoeff() > 1e-3) {
    std::ostringstream values;
    values.precision(6);
    values << sigma(0) << ", " << sigma(1) << ", " << sigma(2);
    far = " (but the matrix is not a rotation up to rounding: it scales by " + values.str() + ")";
  }
  return "; the nearest rotation is the unit quaternion [w, x, y, z] = [" + list + "]" + far + ": write " +
         "\"rotation\": {\"quaternion\": [" + list + "]} instead (its decimals are read exactly; a quaternion " +
         "of any norm is a rotation)";
}

bool same_pose(const Pose& a, const Pose& b) {
  if (a.translation != b.translation || a.rotation.kind != b.rotation.kind) return false;
  return a.rotation.kind != Rotation::Kind::Rpy || a.rotation.rpy == b.rotation.rpy;
}

}  // namespace

std::string SceneReader::rpy_warning(const Path& path, const Exact& angle) const {
  const double degrees = CGAL::to_double(angle);
  char radians[64];
  const auto r = std::to_chars(radians, radians + sizeof radians, degrees * 3.141592653589793 / 180);
  return located(source_, path.str(), "the angle " + to_decimal(angle).text + " is more than 2 pi: it is read as " +
                                          "radians; if it is in degrees, write " + std::string(radians, r.ptr) +
                                          " (its radians) instead");
}

// A body's motion: one rational Bezier curve stays `Body::motion` (also
// when keyframes or pieces reduce to one exactly), anything else becomes
// a trajectory of segments.
void SceneReader::motion(Body& b, const Node& node, const Path& path) const {
  std::vector<MotionSegment> segments;
  std::optional<Motion> single = motion_segments(node, path, segments);
  if (single) {
    b.motion = std::move(single);
    return;
  }
  if (segments.size() == 1 && segments[0].rational) {
    b.motion = segments[0].rational;
    return;
  }
  b.trajectory = Trajectory{std::move(segments)};
}

// Appends the segments of a motion; returns a motionless or one-curve
// rational_bezier motion instead, as it is.
std::optional<Motion> SceneReader::motion_segments(const Node& node, const Path& path, std::vector<MotionSegment>& out) const {
  const Members obj = object(node, path);
  const Path type_path = path.member("type");
  const Node* type = find(obj, "type");
  if (!type) fail(type_path, "missing required field (e.g. \"rational_bezier\")");
  const std::string kind = type->kind == Node::Kind::String ? std::string(text(*type)) : std::string();
  std::string supported;
  for (const MotionType& t : motion_types()) {
    if (kind == t.name) return (this->*t.read)(obj, path, out);
    supported += std::string(supported.empty() ? "" : ", ") + "\"" + t.name + "\"";
  }
  fail(type_path, "unknown motion type " + describe(*type) + " (supported: " + supported + ")");
}

// The motion types, in the order the message lists them: a new type is a
// reader here, its segment kind (src/model/segment_kind.h) and the
// checker's enclosure of that kind (README "Architecture").
const std::vector<SceneReader::MotionType>& SceneReader::motion_types() {
  static const std::vector<MotionType> types = {
      {"rational_bezier", &SceneReader::rational_bezier},
      {"keyframes", &SceneReader::keyframes},
      {"piecewise", &SceneReader::piecewise},
  };
  return types;
}

// {"translation": [x, y, z], "rotation": {...}} (SCENE_FORMAT.md "Rigid poses").
Pose SceneReader::pose(const Node& node, const Path& path) const {
  const Members obj = object(node, path);
  reject_unknown_keys(obj, path, {"translation", "rotation"});
  Pose p;
  if (const Node* t = find(obj, "translation")) p.translation = point(*t, path.member("translation"));
  if (const Node* r = find(obj, "rotation")) {
    const Path rpath = path.member("rotation");
    const Members rot = object(*r, rpath);
    reject_unknown_keys(rot, rpath, {"quaternion", "rpy", "matrix"});
    const Node* q = find(rot, "quaternion");
    const Node* e = find(rot, "rpy");
    const Node* m = find(rot, "matrix");
    if ((q ? 1 : 0) + (e ? 1 : 0) + (m ? 1 : 0) != 1)
      fail(rpath, "a rotation is exactly one of \"quaternion\", \"rpy\" or \"matrix\"");
    if (q) {
      const Path qpath = rpath.member("quaternion");
      const std::span<const Node> items = array(*q, qpath);
      if (items.size() != 4) fail(qpath, "a quaternion is [w, x, y, z]: expected 4 numbers, got " + std::to_string(items.size()));
      p.rotation.kind = Rotation::Kind::Quaternion;
      for (int i = 0; i < 4; ++i) p.rotation.quaternion[i] = number(items[i], qpath.index(i));
      if (std::all_of(p.rotation.quaternion.begin(), p.rotation.quaternion.end(), [](const Exact& x) { return x == 0; }))
        fail(qpath, "the quaternion is zero (it has no rotation)");
    } else if (e) {
      const Path epath = rpath.member("rpy");
      const std::span<const Node> items = array(*e, epath);
      if (items.size() != 3) fail(epath, "rpy is [roll, pitch, yaw] in radians: expected 3 numbers, got " + std::to_string(items.size()));
      p.rotation.kind = Rotation::Kind::Rpy;
      for (int i = 0; i < 3; ++i) {
        p.rotation.rpy[i] = number(items[i], epath.index(i));
        // Far beyond any angle: the enclosures of sin and cos would be [-1, 1].
        if (CGAL::abs(p.rotation.rpy[i]) > 1000000) fail(epath.index(i), "angle out of range (at most 10^6 radians)");
        // Above 2 pi: likely degrees.  Read as radians, as documented, and said.
        if (CGAL::abs(p.rotation.rpy[i]) > two_pi_above()) warnings_.push_back(rpy_warning(epath.index(i), p.rotation.rpy[i]));
      }
    } else {
      const Path mpath = rpath.member("matrix");
      const std::span<const Node> rows = array(*m, mpath);
      if (rows.size() != 3) fail(mpath, "a rotation matrix has 3 rows, got " + std::to_string(rows.size()));
      p.rotation.kind = Rotation::Kind::Matrix;
      for (std::size_t r = 0; r < 3; ++r) {
        const Path row_path = mpath.index(r);
        const std::span<const Node> row = array(rows[r], row_path);
        if (row.size() != 3) fail(row_path, "a rotation matrix row has 3 numbers, got " + std::to_string(row.size()));
        for (std::size_t c = 0; c < 3; ++c) p.rotation.matrix[3 * r + c] = number(row[c], row_path.index(c));
      }
      if (const std::string problem = rotation_matrix_problem(p.rotation.matrix); !problem.empty())
        fail(mpath, "not a rotation: " + problem + nearest_quaternion_hint(p.rotation.matrix));
    }
  }
  return p;
}

// Strictly increasing parameter values, `count` of them.
std::vector<Exact> SceneReader::times(const Node& node, const Path& path, std::size_t count, const std::string& per) const {
  const std::span<const Node> list = array(node, path);
  if (list.size() != count)
    fail(path, "expected " + std::to_string(count) + " times (one per " + per + "), got " + std::to_string(list.size()));
  std::vector<Exact> out;
  for (std::size_t i = 0; i < count; ++i) {
    out.push_back(number(list[i], path.index(i)));
    if (i > 0 && !(out[i - 1] < out[i])) fail(path.index(i), "times must be strictly increasing");
  }
  return out;
}

std::optional<Motion> SceneReader::keyframes(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const {
  reject_unknown_keys(obj, path, {"type", "interpolation", "times", "poses"});
  Interpolation how = Interpolation::Slerp;
  if (const Node* i = find(obj, "interpolation")) {
    const Path ipath = path.member("interpolation");
    const std::string name = i->kind == Node::Kind::String ? std::string(text(*i)) : std::string();
    if (name == "slerp") how = Interpolation::Slerp;
    else if (name == "screw") how = Interpolation::Screw;
    else if (name == "nlerp") how = Interpolation::Nlerp;
    else fail(ipath, "unknown interpolation " + describe(*i) + " (supported: \"slerp\", \"screw\", \"nlerp\")");
  }
  const Path ppath = path.member("poses");
  const Node* poses_node = find(obj, "poses");
  if (!poses_node) fail(ppath, "missing required field");
  const std::span<const Node> list = array(*poses_node, ppath);
  if (list.size() < 2) fail(ppath, "keyframes need at least 2 poses, got " + std::to_string(list.size()));
  std::vector<Pose> poses;
  for (std::size_t k = 0; k < list.size(); ++k) poses.push_back(pose(list[k], ppath.index(k)));
  std::vector<Exact> t;
  if (const Node* tn = find(obj, "times")) {
    t = times(*tn, path.member("times"), poses.size(), "pose");
  } else {
    for (std::size_t k = 0; k < poses.size(); ++k) t.push_back(Exact(static_cast<long>(k)) / Exact(static_cast<long>(poses.size() - 1)));
  }
  for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
    try {
      require_interpolable(poses[k], poses[k + 1], how);
    } catch (const InputError& e) {
      fail(ppath.index(k + 1), std::string(e.what()) + " (from poses[" + std::to_string(k) + "])");
    }
    MotionSegment seg;
    seg.t0 = t[k];
    seg.t1 = t[k + 1];
    seg.from = poses[k];
    seg.to = poses[k + 1];
    seg.interpolation = how;
    seg.rational = rational_keyframe_segment(poses[k], poses[k + 1], how, t[k], t[k + 1]);
    out.push_back(std::move(seg));
  }
  return std::nullopt;
}

std::optional<Motion> SceneReader::piecewise(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const {
  reject_unknown_keys(obj, path, {"type", "pieces"});
  const Path ppath = path.member("pieces");
  const Node* pieces = find(obj, "pieces");
  if (!pieces) fail(ppath, "missing required field");
  const std::span<const Node> list = array(*pieces, ppath);
  if (list.empty()) fail(ppath, "at least one piece is required");
  for (std::size_t k = 0; k < list.size(); ++k) {
    const Path piece_path = ppath.index(k);
    std::vector<MotionSegment> segs;
    const std::optional<Motion> still = motion_segments(list[k], piece_path, segs);
    if (segs.empty()) fail(piece_path, "a piece must move over an interval (one control point is a pose, not a motion)");
    (void)still;
    if (!out.empty()) {
      const MotionSegment& prev = out.back();
      const MotionSegment& next = segs.front();
      const std::string join = "join with pieces[" + std::to_string(k - 1) + "]";
      if (prev.t1 != next.t0)
        fail(piece_path, join + ": the intervals do not abut (the previous piece ends at " + to_string(prev.t1) +
                             ", this one starts at " + to_string(next.t0) + ")");
      const std::optional<Mat34E> end = kind_of(prev).exact_end(prev, true), start = kind_of(next).exact_end(next, false);
      if (end && start) {
        if (*end != *start) fail(piece_path, join + ": the poses differ at t = " + to_string(next.t0) + " (a jump)");
      } else if (const Pose *a = kind_of(prev).written_end(prev, true), *b = kind_of(next).written_end(next, false);
                 !(a && b && same_pose(*a, *b))) {
        fail(piece_path, join + ": the poses at t = " + to_string(next.t0) +
                             " cannot be proven equal (an rpy pose must be written the same way on both sides)");
      }
    }
    for (MotionSegment& seg : segs) out.push_back(std::move(seg));
  }
  return std::nullopt;
}

std::optional<Motion> SceneReader::rational_bezier(const Members& obj, const Path& path,
                                                   std::vector<MotionSegment>& out) const {
  reject_unknown_keys(obj, path, {"type", "interval", "control_points", "weights"});

  Motion m;
  if (const Node* interval = find(obj, "interval")) {
    const Path interval_path = path.member("interval");
    const std::span<const Node> ends = array(*interval, interval_path);
    if (ends.size() != 2)
      fail(interval_path, "expected [t0, t1], got " + std::to_string(ends.size()) + " values");
    m.t0 = number(ends[0], interval_path.index(0));
    m.t1 = number(ends[1], interval_path.index(1));
    if (!(m.t0 < m.t1)) fail(interval_path, "interval start must be less than its end");
  }
  const Path cp_path = path.member("control_points");
  const Node* cps = find(obj, "control_points");
  if (!cps) fail(cp_path, "missing required field");
  const std::span<const Node> list = array(*cps, cp_path);
  if (list.empty()) fail(cp_path, "at least one control point is required");
  m.control_points.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k)
    m.control_points.push_back(affine(list[k], cp_path.index(k)));
  if (const Node* weights = find(obj, "weights"))
    m.weights = positive_weights(*weights, path.member("weights"), list.size(), "control point");
  else
    m.weights.assign(list.size(), Exact(1));
  normalise_weights(m);  // the same curve; weights of 1e400 would overflow every enclosure
  if (m.degree() >= 1) {
    MotionSegment seg;
    seg.t0 = m.t0;
    seg.t1 = m.t1;
    seg.rational = m;
    out.push_back(std::move(seg));
  }
  return m;
}

}  // namespace tmcert::reader
