#include "src/report/report.h"

#include "kernels/decimal.h"
#include "kernels/real_roots.h"
#include "src/motion/segment.h"

#include <Eigen/Dense>
#include <cmath>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace tmcert {

namespace {

// Writes JSON text laid out exactly as nlohmann's dump(2): every member and
// element on a line of its own, indented by two spaces per level, "key": value,
// and empty containers as {} or [].  A result of many checks as an
// nlohmann::ordered_json tree cost more than verifying them; this writes the
// same bytes directly.
class JsonWriter {
 public:
  std::string take() && { return std::move(out_); }

  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }

  // A member's key: its value follows with the next call.
  void key(std::string_view name) {
    next_item();
    string_text(name);
    out_ += ": ";
    after_key_ = true;
  }

  void value(std::string_view s) {
    next_item();
    string_text(s);
  }
  // Without it a string literal would convert to bool.
  void value(const char* s) { value(std::string_view(s)); }
  void value(bool b) {
    next_item();
    out_ += b ? "true" : "false";
  }
  void value(std::uint64_t n) { integer(n); }
  void value(int n) { integer(n); }
  void value(double x) {
    next_item();
    // nlohmann's own shortest round-trip form (e.g. 0.0012, 1e-05, 2.0).
    out_ += nlohmann::json(x).dump();
  }

  // A JSON number for people beside an exact one (tmcert-result/1's
  // "<field>_approx" members): the nearest double, or beyond the double
  // range a string holding the 17-significant-digit decimal with exponent
  // (a JSON number there would read back as infinity or 0).
  void approx(const Exact& q) {
    if (const std::optional<double> x = nearest_double(q)) value(*x);
    else value(scientific(q, 17));
  }
  // The same for an algebraic number, from its printed approximation
  // (real_roots.h's approximate(): the shortest decimal of its nearest
  // double, which reads back as that double, or the 17-digit decimal).
  void approx_text(const std::string& text) {
    const double x = std::strtod(text.c_str(), nullptr);
    if (std::isfinite(x) && x != 0) value(x);
    else value(text);
  }

  template <typename T>
  void member(std::string_view name, const T& v) {
    key(name);
    value(v);
  }

 private:
  template <typename Int>
  void integer(Int n) {
    next_item();
    char digits[24];
    const auto end = std::to_chars(digits, digits + sizeof digits, n).ptr;
    out_.append(digits, end);
  }

  // A string literal.  Printable ASCII without quote or backslash is written
  // as it is; anything else goes through nlohmann's escaping (control
  // characters, and its check of the UTF-8), so every string comes out as
  // dump() writes it.
  void string_text(std::string_view s) {
    const bool plain = std::all_of(s.begin(), s.end(), [](char c) {
      return c >= 0x20 && c < 0x7f && c != '"' && c != '\\';
    });
    if (plain) {
      out_ += '"';
      out_ += s;
      out_ += '"';
    } else {
      out_ += nlohmann::json(std::string(s)).dump();
    }
  }

  void open(char bracket) {
    next_item();
    out_ += bracket;
    empty_.push_back(true);
  }

  void close(char bracket) {
    const bool was_empty = empty_.back();
    empty_.pop_back();
    if (!was_empty) {
      out_ += '\n';
      indent();
    }
    out_ += bracket;
  }

  // Before a value or key: nothing after a key; otherwise the separator
  // from the previous item, a line break and the indentation.
  void next_item() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (empty_.empty()) return;  // the document's top-level value
    if (!empty_.back()) out_ += ',';
    empty_.back() = false;
    out_ += '\n';
    indent();
  }

  void indent() { out_.append(2 * empty_.size(), ' '); }

  std::string out_;
  std::vector<bool> empty_;  // per open container: nothing written into it yet
  bool after_key_ = false;
};

// A parameter: a rational string, or an irrational root as
// {"root_of", "interval", "approx"} (SCENE_FORMAT.md, "Exact contact times").
void write_root(JsonWriter& w, const AlgebraicTime& a) {
  w.begin_object();
  w.key("root_of");
  w.begin_array();
  for (const CGAL::Gmpz& c : a.root_of) w.value(to_string(Exact(c)));
  w.end_array();
  w.key("interval");
  w.begin_array();
  w.value(to_string(a.lo));
  w.value(to_string(a.hi));
  w.end_array();
  w.member("approx", a.approx);
  w.end_object();
}

// The approximation of a parameter: the algebraic number's own decimal, or
// the rational's.
void write_time_approx(JsonWriter& w, const Exact& t, const AlgebraicTime* root) {
  if (root) w.approx_text(root->approx);
  else w.approx(t);
}

void write_point_approx(JsonWriter& w, const Vec3E& p) {
  w.begin_array();
  for (const Exact& x : p) w.approx(x);
  w.end_array();
}

void write_check(JsonWriter& w, const Scene& scene, const CheckResult& c) {
  w.begin_object();
  w.key("bodies");
  w.begin_array();
  w.value(scene.bodies[c.bodies[0]].name);
  w.value(scene.bodies[c.bodies[1]].name);
  w.end_array();
  w.member("verdict", to_string(c.verdict));
  w.member("epsilon", to_string(c.epsilon));
  w.key("epsilon_approx");
  w.approx(c.epsilon);
  w.member("refined", c.refined);
  if (!scene.bodies[c.bodies[0]].enlarged.empty() || !scene.bodies[c.bodies[1]].enlarged.empty())
    w.member("enlarged_model", true);
  if (c.clearance > 0) {
    w.member("clearance", to_string(c.clearance));
    w.key("clearance_approx");
    w.approx(c.clearance);
    w.member("clearance_violated", c.verdict == Verdict::Collision);
  }
  if (c.first_contact) {
    w.key("first_contact");
    w.begin_object();
    w.key("t");
    w.begin_array();
    const AlgebraicTime* root = c.witness && c.witness->root ? &*c.witness->root : nullptr;
    if (root && c.first_contact_exact) write_root(w, *root);
    else w.value(to_string(c.first_contact->first));
    if (root) write_root(w, *root);  // a witness's bracket ends at its time
    else w.value(to_string(c.first_contact->second));
    w.end_array();
    w.key("t_approx");
    w.begin_array();
    write_time_approx(w, c.first_contact->first, root && c.first_contact_exact ? root : nullptr);
    write_time_approx(w, c.first_contact->second, root);
    w.end_array();
    w.end_object();
  }
  if (c.witness) {
    const Witness& wit = *c.witness;
    w.key("witness");
    w.begin_object();
    if (wit.root) {
      w.key("t");
      write_root(w, *wit.root);
    } else {
      w.member("t", to_string(wit.t));
    }
    w.key("t_approx");
    write_time_approx(w, wit.t, wit.root ? &*wit.root : nullptr);
    w.key("features");
    w.begin_array();
    w.value(wit.features[0]);
    w.value(wit.features[1]);
    w.end_array();
    if (wit.point_box) {
      // A rational box holding the common point: an enclosed pose, or an
      // algebraic time (exact resolution).
      w.key("point_box");
      w.begin_array();
      for (const auto& range : *wit.point_box) {
        w.begin_array();
        w.value(to_string(range[0]));
        w.value(to_string(range[1]));
        w.end_array();
      }
      w.end_array();
      w.key("point_box_approx");
      w.begin_array();
      for (const auto& range : *wit.point_box) {
        w.begin_array();
        w.approx(range[0]);
        w.approx(range[1]);
        w.end_array();
      }
      w.end_array();
    } else {
      w.key("point");
      w.begin_array();
      for (const Exact& x : wit.point) w.value(to_string(x));
      w.end_array();
      w.key("point_approx");
      write_point_approx(w, wit.point);
    }
    if (wit.points) {
      w.key("points");
      w.begin_array();
      for (const Vec3E& p : *wit.points) {
        w.begin_array();
        for (const Exact& x : p) w.value(to_string(x));
        w.end_array();
      }
      w.end_array();
      w.key("points_approx");
      w.begin_array();
      for (const Vec3E& p : *wit.points) write_point_approx(w, p);
      w.end_array();
    }
    if (wit.points_box) {
      // Clearance at an enclosed pose: a box per body holding its point.
      w.key("points_box");
      w.begin_array();
      for (const auto& box : *wit.points_box) {
        w.begin_array();
        for (const auto& range : box) {
          w.begin_array();
          w.value(to_string(range[0]));
          w.value(to_string(range[1]));
          w.end_array();
        }
        w.end_array();
      }
      w.end_array();
      w.key("points_box_approx");
      w.begin_array();
      for (const auto& box : *wit.points_box) {
        w.begin_array();
        for (const auto& range : box) {
          w.begin_array();
          w.approx(range[0]);
          w.approx(range[1]);
          w.end_array();
        }
        w.end_array();
      }
      w.end_array();
    }
    // A body's translation: exact, approximate, and the body's name.
    auto displacement = [&](const std::string& key, const Vec3E& v, const std::string& body_key, int body) {
      w.key(key);
      w.begin_array();
      for (const Exact& x : v) w.value(to_string(x));
      w.end_array();
      w.key(key + "_approx");
      write_point_approx(w, v);
      w.member(body_key, scene.bodies[c.bodies[body]].name);
    };
    if (wit.displacement) displacement("displacement", *wit.displacement, "displaced", wit.displaced);
    if (wit.displacement_other)  // both bodies translated, each within its own tolerance
      displacement("displacement_other", *wit.displacement_other, "displaced_other", 1 - wit.displaced);
    w.end_object();
  }
  w.key("undecided");
  w.begin_array();
  for (const UndecidedInterval& u : c.undecided) {
    w.begin_object();
    w.key("t");
    w.begin_array();
    w.value(to_string(u.t0));
    w.value(to_string(u.t1));
    w.end_array();
    w.key("t_approx");
    w.begin_array();
    w.approx(u.t0);
    w.approx(u.t1);
    w.end_array();
    w.member("reason", to_string(u.reason));
    w.end_object();
  }
  w.end_array();
  if (c.witness) {
    // The witness ends the claims: from its time to the end of the check's
    // interval nothing was searched (SCENE_FORMAT.md, "Every interval
    // claim holds").
    const AlgebraicTime* root = c.witness->root ? &*c.witness->root : nullptr;
    w.key("not_searched");
    w.begin_array();
    if (root) write_root(w, *root);
    else w.value(to_string(c.witness->t));
    w.value(to_string(c.interval.second));
    w.end_array();
    w.key("not_searched_approx");
    w.begin_array();
    write_time_approx(w, c.witness->t, root);
    w.approx(c.interval.second);
    w.end_array();
  }
  const CheckStats& s = c.stats;
  w.key("stats");
  w.begin_object();
  w.member("nodes", s.nodes);
  w.member("max_depth", s.max_depth);
  w.member("predicate_calls", s.contact.calls);
  w.member("exact_fallbacks", s.contact.exact_fallbacks);
  w.member("vertex_face_calls", s.by_kind[0].calls);
  w.member("vertex_face_exact", s.by_kind[0].exact_fallbacks);
  w.member("edge_edge_calls", s.by_kind[1].calls);
  w.member("edge_edge_exact", s.by_kind[1].exact_fallbacks);
  w.member("face_vertex_calls", s.by_kind[2].calls);
  w.member("face_vertex_exact", s.by_kind[2].exact_fallbacks);
  w.member("exact_static_tests", s.static_tests);
  w.member("static_configurations", s.static_configurations);
  w.member("static_filter_pairs", s.static_filter_pairs);
  w.member("static_filter_exact", s.static_filter_exact);
  w.member("sphere_tests", s.sphere_tests);
  w.member("slab_clears", s.slab_clears);
  w.member("swept_clears", s.swept_clears);
  w.member("hull_clears", s.hull_clears);
  w.member("axis_clears", s.axis_clears);
  w.member("stops", s.stops);
  w.member("exact_pieces", s.exact_pieces);
  w.member("exact_undecided", s.exact_unknown);
  w.member("prefiltered", s.prefiltered);
  w.member("seconds", s.seconds);
  w.end_object();
  w.end_object();
}

// For a rational Bezier motion whose poses are not rigid: how much the body
// is stretched or shrunk, at worst over the control points and 33 sampled
// parameters (for people: the check is exact for the affine motion as
// written, but a user who interpolated rotation matrices linearly shrank
// the body without meaning to).  Empty for rigid motions.
std::string rigidity_note(const Body& b) {
  if (!b.motion || b.motion->degree() < 1) return {};
  // A body of points only has no shape to deform (continuous-collision
  // queries encode moving points by singular maps on purpose).
  if (b.polygons.empty() && b.segments.empty()) return {};
  const Motion& m = *b.motion;
  auto linear_equal = [](const Mat34E& x, const Mat34E& y) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (x[4 * r + c] != y[4 * r + c]) return false;
    return true;
  };
  auto orthonormal = [](const Mat34E& p) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (p[r] * p[c] + p[4 + r] * p[4 + c] + p[8 + r] * p[8 + c] != (r == c ? 1 : 0)) return false;
    return true;
  };
  // One linear part throughout (translations, such as continuous-collision
  // queries): rigid exactly when it is orthonormal.  No sampling needed.
  if (std::all_of(m.control_points.begin(), m.control_points.end(),
                  [&](const Mat34E& p) { return linear_equal(p, m.control_points[0]); }) &&
      orthonormal(m.control_points[0]))
    return {};
  double worst_lo = 1, worst_hi = 1;
  Exact worst_t = m.t0;
  bool rigid = true;
  for (int k = 0; k <= 32; ++k) {
    const Exact t = m.t0 + (m.t1 - m.t0) * Exact(k, 32);
    const Mat34E p = motion_pose(m, t);
    Eigen::Matrix3d a;
    bool exact_rotation = true;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        a(r, c) = CGAL::to_double(p[4 * r + c]);
        Exact dot = p[4 * 0 + r] * p[4 * 0 + c] + p[4 * 1 + r] * p[4 * 1 + c] + p[4 * 2 + r] * p[4 * 2 + c];
        if (dot != (r == c ? 1 : 0)) exact_rotation = false;
      }
    if (exact_rotation) continue;
    rigid = false;
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a);
    const double lo = svd.singularValues().minCoeff(), hi = svd.singularValues().maxCoeff();
    if (std::max(hi - 1, 1 - lo) > std::max(worst_hi - 1, 1 - worst_lo)) {
      worst_lo = lo;
      worst_hi = hi;
      worst_t = t;
    }
  }
  if (rigid) return {};
  std::ostringstream out;
  out.precision(4);
  out << "the motion of " << b.name << " is not rigid (an affine motion, checked as written): at t = "
      << to_decimal(worst_t).text << " lengths are scaled by " << worst_lo << " to " << worst_hi;
  if (std::abs(worst_hi - 1) < 1e-12 && std::abs(worst_lo - 1) < 1e-12) out << " (within rounding of rigid)";
  return out.str();
}

}  // namespace

std::string check_json(const Scene& scene, const CheckResult& check) {
  JsonWriter w;
  write_check(w, scene, check);
  return std::move(w).take();
}

std::string result_json(const Scene& scene, const SceneResult& r) {
  JsonWriter w;
  w.begin_object();
  w.member("format", "tmcert-result/1");
  w.member("verdict", to_string(r.verdict));
  w.member("kernel", to_string(r.kernel));
  w.member("certified", r.certified);
  w.member("epsilon", to_string(r.epsilon));
  w.key("epsilon_approx");
  w.approx(r.epsilon);
  w.member("epsilon_per_check", r.epsilon_per_check);
  // Bodies that are enlarged models of their input (robot links' URDF
  // cylinders and spheres as circumscribed polyhedra): present only then.
  bool any_enlarged = false;
  for (const Body& b : scene.bodies) any_enlarged = any_enlarged || !b.enlarged.empty();
  if (any_enlarged) {
    w.key("enlarged");
    w.begin_array();
    for (const Body& b : scene.bodies) {
      if (b.enlarged.empty()) continue;
      w.begin_object();
      w.member("body", b.name);
      w.key("shapes");
      w.begin_array();
      for (const std::string& shape : b.enlarged) w.value(shape);
      w.end_array();
      w.end_object();
    }
    w.end_array();
  }
  // What the reader did to the input (docs/scene-format.md, "Data from
  // real pipelines"): present only when there is something to say.
  for (const auto& [key, list] : {std::pair{"notes", &scene.notes}, std::pair{"warnings", &scene.warnings}}) {
    if (list->empty()) continue;
    w.key(key);
    w.begin_array();
    for (const std::string& note : *list) w.value(note);
    w.end_array();
  }
  w.key("checks");
  w.begin_array();
  for (const CheckResult& c : r.checks) write_check(w, scene, c);
  w.end_array();
  w.end_object();
  return std::move(w).take() + "\n";
}

namespace {

// A parameter for people: "2.06812 (8471/4096)", or for an algebraic
// number its decimal and where it is exactly (the polynomial is in --json).
std::string readable_time(const Exact& t, const AlgebraicTime* root) {
  if (!root) return readable(t);
  // Six digits rounded from the root itself (not from its double).
  std::string decimal;
  try {
    decimal = approximate_decimal(RealRoot{root->root_of, root->lo, root->hi});
  } catch (const ExactLimit&) {
    decimal = "~" + root->approx;
  }
  return decimal + " (a root of a degree-" + std::to_string(root->root_of.size() - 1) + " polynomial in (" +
         to_string(root->lo) + ", " + to_string(root->hi) + "))";
}

// "(0.5, 0.333333, 0)", followed by ", exactly (1/2, 1/3, 0)" when a
// decimal is rounded.
std::string readable_point(const Vec3E& p) {
  std::string decimals = "(", exact = "(";
  bool all_exact = true;
  for (int i = 0; i < 3; ++i) {
    const Decimal d = to_decimal(p[i]);
    decimals += (i ? ", " : "") + d.text;
    exact += (i ? ", " : "") + to_string(p[i]);
    all_exact = all_exact && d.exact;
  }
  return decimals + ")" + (all_exact ? "" : ", exactly " + exact + ")");
}

// A rational box holding a point: its centre plus or minus its half-widths.
std::string readable_box(const std::array<std::array<Exact, 2>, 3>& box) {
  std::string centre = "(", half = "(";
  for (int i = 0; i < 3; ++i) {
    centre += (i ? ", " : "") + to_decimal((box[i][0] + box[i][1]) / 2).text;
    half += (i ? ", " : "") + to_decimal((box[i][1] - box[i][0]) / 2).text;
  }
  return centre + ") ± " + half + ")";
}

// The epsilon a hint suggests: a tenth of the check's, not below the
// refinement's floor, unless that is still larger than the check's whole
// box (1000 times its default epsilon, the diagonal of its two bodies'
// box), where no smaller epsilon of that size can help: then the default
// (a given epsilon of 1e16 for bodies of size 1 gets the suggestion
// 0.00173205, not 1e15).  The floor is the check's default epsilon / 10^6
// (1e-9 of the diagonal of its two bodies' box; SCENE_FORMAT.md "Decisive
// by default").  None when the check's epsilon is at or below the floor
// already: the bodies come within 1e-9 of their box there.
Exact epsilon_floor(const Scene& scene, const CheckResult& c) {
  return default_epsilon(scene.bodies[c.bodies[0]], scene.bodies[c.bodies[1]]) / 1000000;
}

std::optional<Exact> smaller_epsilon(const Scene& scene, const CheckResult& c) {
  const Exact fallback = default_epsilon(scene.bodies[c.bodies[0]], scene.bodies[c.bodies[1]]);
  const Exact floor = fallback / 1000000;
  if (c.epsilon <= floor) return std::nullopt;
  const Exact tenth = c.epsilon / 10;
  if (tenth > 1000 * fallback) return fallback;
  return tenth < floor ? floor : tenth;
}

// What to try when a check stops undecided for `reason` (issue 23 item 7:
// hints that lead somewhere).  `smaller`: the epsilon a hint suggests
// (smaller_epsilon; none at or below the floor).  A hint suggests a
// smaller epsilon only where one could decide the part: never for a check
// undecided without a single subdivision node (its start configuration, an
// enclosed pose within rounding of contact or a solid's containment at an
// enclosed start, is what is undecided), after refinement reached its floor
// or could not search its parts again, at a given epsilon already at or
// below the floor, or where the time limit cut the check short (then a
// larger --time-limit is the lever).
// `stuck`: refinement ended because every part left could not be searched
// again (refine_exhausted above the floor: a re-search that visited no node).
std::string undecided_hint(const SceneResult& r, const CheckResult& c, StopReason reason,
                           const std::optional<Exact>& smaller, bool stuck) {
  const std::string epsilon = to_decimal(c.epsilon).text;
  // SceneResult::time_limit: the given one, else with refinement the
  // default (30 s).
  const std::string time_limit = [&] {
    std::ostringstream t;
    t << "the check's time limit (" << r.time_limit << " s)";
    return t.str();
  }();
  // The time limit cut the check short (or its run was cancelled).
  const std::string out_of_time =
      r.time_limit > 0 ? time_limit + " ran out; try a larger --time-limit" : "the run was cancelled";
  const std::string try_smaller =
      smaller ? "try a smaller --epsilon, e.g. --epsilon " + to_decimal(*smaller).text + (r.refine ? "" : ", or --epsilon auto")
              : "";
  const std::string at_floor = "epsilon (" + epsilon +
                               ") is already at or below the refinement's floor (1e-9 of the check's box): the bodies "
                               "touch or nearly touch there";
  switch (reason) {
    case StopReason::Epsilon:
      if (c.stats.nodes == 0)
        return "the start configuration could not be proven free (an enclosed pose within rounding of contact, "
               "or a solid's containment at an enclosed start); no epsilon changes that";
      if (c.refine_out_of_time)
        return c.refined ? "the bodies come within about epsilon (" + epsilon + ") there; refinement stopped at it when " +
                               out_of_time
                         : "the bodies come within about epsilon (" + epsilon +
                               ") there; refinement could not search it again: " + out_of_time;
      if (stuck)
        return "the bodies come within about epsilon (" + epsilon +
               ") there, and searching it again at a smaller epsilon could not begin (its start, an enclosed pose "
               "within rounding of contact, stays undecided); no epsilon changes that";
      if (c.refine_exhausted)
        return "the bodies come within about epsilon (" + epsilon +
               ") there even at the refinement's floor (epsilon/10^6 of the check's default); a smaller epsilon "
               "would not decide it";
      if (!smaller) return "the bodies come within about epsilon there; " + at_floor;
      return "the bodies come within about epsilon (" + epsilon + ") there; " + try_smaller;
    case StopReason::Depth:
      if (r.max_depth < 62)
        return "the subdivision reached its depth limit (" + std::to_string(r.max_depth) + "); try --max-depth " +
               std::to_string(std::min(62, 2 * r.max_depth));
      return "the subdivision reached its finest depth (62): the bodies are within rounding of contact there";
    case StopReason::Limit:
      // A refined check: its time limit ran out during the first search or
      // the refinement (the node and stop budgets count per search there).
      if (c.refine_out_of_time)
        return r.time_limit > 0 ? time_limit + " ran out before this part was searched; try a larger --time-limit"
                                : "the run was cancelled before this part was searched";
      if (r.max_stops > 0 && c.stats.stops >= r.max_stops) {
        const std::string stops = "the stop budget (" + std::to_string(r.max_stops) + " undecided pieces";
        if (c.refine_exhausted)
          return stops + " per search) was used up even at the refinement's floor (epsilon " + epsilon +
                 "): the bodies stay within about epsilon over a long stretch (resting on each other); a smaller "
                 "epsilon would not decide it";
        if (!smaller)
          return stops + ") was used up, so the rest was not searched: the bodies stay within about epsilon over a "
                         "long stretch, and " + at_floor;
        return stops + ") was used up, so the rest was not searched: the bodies stay within about epsilon over a "
                       "long stretch; " + try_smaller;
      }
      if (r.max_nodes > 0 && c.stats.nodes >= r.max_nodes)
        return "the node budget (" + std::to_string(r.max_nodes) +
               " nodes per check) was used up; try a larger --epsilon, or check shorter pieces of the motion";
      if (r.time_limit > 0) return time_limit + " ran out before this part was searched; try a larger --time-limit";
      return "a budget of the check was used up";
    case StopReason::AfterUndecided: {
      const std::string not_claimed =
          "not claimed: the contact tests see only contact that begins here, and after the part not cleared before "
          "it the bodies were not proven apart (a pose only enclosed, or a solid's inside left open)";
      if (c.refine_out_of_time) return not_claimed + "; " + out_of_time;
      if (c.refine_exhausted)
        return not_claimed + "; refinement " +
               (stuck ? "could not search the part before it again" : "reached its floor") +
               " without deciding it, so a smaller epsilon would not decide it";
      if (!smaller) return not_claimed + "; " + at_floor;
      return not_claimed + "; " + try_smaller;
    }
    case StopReason::EnlargedModel:
      return c.verdict == Verdict::Collision
                 ? "a URDF cylinder's or sphere's circumscribed polyhedron touches there; the contact of the true "
                   "shape was proven only at the witness"
                 : "a URDF cylinder's or sphere's circumscribed polyhedron touches there, and no contact of the true "
                   "shape was proven, even on the finest polyhedron (the shapes come within about 0.01% (a cylinder) "
                   "or 0.25% (a sphere) of the radius there, or the poses are enclosed too loosely to decide)";
  }
  return {};
}

// The undecided intervals of a check, adjacent ones with the same reason
// merged (--json lists every one).
std::vector<UndecidedInterval> merged_undecided(const std::vector<UndecidedInterval>& in) {
  std::vector<UndecidedInterval> sorted = in;
  std::sort(sorted.begin(), sorted.end(), [](const UndecidedInterval& x, const UndecidedInterval& y) { return x.t0 < y.t0; });
  std::vector<UndecidedInterval> out;
  for (const UndecidedInterval& u : sorted) {
    if (!out.empty() && out.back().reason == u.reason && out.back().t1 == u.t0) out.back().t1 = u.t1;
    else out.push_back(u);
  }
  return out;
}

constexpr std::size_t kUndecidedShown = 5;

// Seconds for people: two significant digits, whole seconds from 10 on.
std::string seconds_text(double seconds) {
  std::ostringstream out;
  if (seconds >= 10) out << std::fixed << std::setprecision(0);
  else out << std::setprecision(2);
  out << seconds;
  return out.str();
}

}  // namespace

std::string result_summary(const Scene& scene, const SceneResult& r) {
  std::ostringstream out;
  out << "tmcert: " << to_string(r.verdict);
  if (!r.certified) out << " (kernel fast: NOT CERTIFIED)";
  out << "  [kernel " << to_string(r.kernel) << ", epsilon ";
  if (r.epsilon_per_check) out << "per check: 1/1000 of its bodies' box" << (r.refine ? ", refined" : "");
  else out << readable(r.epsilon);
  out << "]\n";
  for (const std::string& note : scene.notes) out << "  note: " << note << "\n";
  for (const std::string& warning : scene.warnings) out << "  warning: " << warning << "\n";
  for (const Body& b : scene.bodies) {
    if (b.enlarged.empty()) continue;
    out << "  note: " << b.name << " is an enlarged model: its ";
    for (std::size_t i = 0; i < b.enlarged.size(); ++i) out << (i ? ", " : "") << b.enlarged[i];
    out << (b.enlarged.size() == 1 ? " is replaced by a circumscribed polyhedron" : " are replaced by circumscribed polyhedra")
        << (b.primitive ? " (safe holds for the true shape; a collision is proven on it)\n"
                        : " (safe holds for the true shapes; a collision is one of the model)\n");
  }
  for (const CheckResult& c : r.checks) {
    const std::string& name_a = scene.bodies[c.bodies[0]].name;
    const std::string& name_b = scene.bodies[c.bodies[1]].name;
    out << "  " << name_a << " x " << name_b << ": " << to_string(c.verdict);
    if (c.clearance > 0) out << " (clearance " << readable(c.clearance) << (c.verdict == Verdict::Collision ? " violated" : "") << ")";
    const Witness* wit = c.witness ? &*c.witness : nullptr;
    const AlgebraicTime* root = wit && wit->root ? &*wit->root : nullptr;
    if (wit) out << " at t = " << readable_time(wit->t, root);
    if (c.first_contact && c.first_contact_exact && wit)
      out << ", the exact first contact";
    else if (c.first_contact)
      out << "; no contact before t = " << readable(c.first_contact->first);
    if (c.stats.prefiltered) {
      out << "  (prefilter: the boxes of what the bodies sweep are apart)\n";
    } else {
      out << "  (";
      if (r.epsilon_per_check || c.refined)
        out << "epsilon " << to_decimal(c.epsilon).text << (c.refined ? " (refined)" : "") << ", ";
      out << c.stats.nodes << " nodes, depth " << c.stats.max_depth << ", " << c.stats.contact.calls << " tests, "
          << c.stats.contact.exact_fallbacks << " exact, " << seconds_text(c.stats.seconds) << " s)\n";
    }
    if (wit) {
      const bool closest = wit->points || wit->points_box;
      out << "    " << (closest ? "closest: " : "contact: ") << wit->features[0]
          << (closest ? " comes within the clearance of " : " meets ") << wit->features[1];
      if (wit->points) {
        out << ": " << readable_point((*wit->points)[0]) << " and " << readable_point((*wit->points)[1]);
      } else if (wit->points_box) {
        out << ": " << readable_box((*wit->points_box)[0]) << " and " << readable_box((*wit->points_box)[1]);
      } else if (wit->point_box) {
        out << " at " << readable_box(*wit->point_box);
      } else {
        out << " at " << readable_point(wit->point);
      }
      if (wit->displacement)
        out << " when " << scene.bodies[c.bodies[wit->displaced]].name << " is displaced by "
            << readable_point(*wit->displacement) << " (within its tolerance)";
      if (wit->displacement && wit->displacement_other)
        out << " and " << scene.bodies[c.bodies[1 - wit->displaced]].name << " by "
            << readable_point(*wit->displacement_other) << " (within its own)";
      out << "\n";
    }
    const std::vector<UndecidedInterval> undecided = merged_undecided(c.undecided);
    // The epsilon hints suggest, computed for the first hint that needs it.
    std::optional<std::optional<Exact>> smaller;
    bool stuck = false;
    for (std::size_t k = 0; k < undecided.size() && k < kUndecidedShown; ++k) {
      const UndecidedInterval& u = undecided[k];
      // The stopped piece a witness was found in, up to the witness.
      const bool before_witness =
          wit && !root && u.t1 == wit->t && (u.reason == StopReason::Epsilon || u.reason == StopReason::Depth);
      if (!before_witness && !smaller && u.reason != StopReason::Depth && u.reason != StopReason::EnlargedModel) {
        smaller = smaller_epsilon(scene, c);
        stuck = c.refine_exhausted && c.epsilon > epsilon_floor(scene, c);
      }
      out << "    undecided t in [" << to_decimal(u.t0).text << ", " << to_decimal(u.t1).text << "] ("
          << to_string(u.reason) << "): "
          << (before_witness ? "the bodies come within about epsilon there; the first contact lies in here or at the witness"
                             : undecided_hint(r, c, u.reason, smaller ? *smaller : std::nullopt, stuck))
          << "\n";
    }
    if (undecided.size() > kUndecidedShown)
      out << "    ... and " << undecided.size() - kUndecidedShown << " more undecided intervals (--json lists them all)\n";
    // A toleranced check left undecided: the one lever no hint can name
    // (issue 23 item 7).  A collision's displacement is a translation, so
    // where only an admissible affine map beyond a translation's reach could
    // touch, no witness exists at any epsilon or time limit
    // (docs/scene-format.md, "Tolerance and clearance").
    if (c.verdict == Verdict::Undecided)
      for (int side = 0; side < 2; ++side)
        if (const Body& body = scene.bodies[c.bodies[side]]; body.tolerance > 0)
          out << "    note: " << body.name
              << " has a tolerance: a part where only an admissible affine deviation beyond the reach of a "
                 "translation could touch stays undecided at every epsilon and time limit (a collision's "
                 "displacement is a translation)\n";
    if (wit && wit->t < c.interval.second)
      out << "    not searched after the witness: t in [" << (root ? root->approx : to_decimal(wit->t).text) << ", "
          << to_decimal(c.interval.second).text << "]\n";
    for (int side = 0; side < 2; ++side)
      if (const std::string note = rigidity_note(scene.bodies[c.bodies[side]]); !note.empty())
        out << "    note: " << note << "\n";
  }
  return out.str();
}

}  // namespace tmcert
