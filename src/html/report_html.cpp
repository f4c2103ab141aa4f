#include "src/html/report_html.h"

#include "kernels/real_roots.h"
#include "src/report/report.h"
#include "src/html/assets.h"
#include "src/model/segment_kind.h"
#include "src/motion/enclosure.h"
#include "src/motion/segment.h"

#include <nlohmann/json.hpp>


#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tmcert {

namespace {

using nlohmann::json;

// Parameter samples of the slider: this many equal steps over the scene's
// range, plus the times of every first contact and witness, so that the
// page shows the pose exactly there.  Between samples the page interpolates
// the sampled matrices linearly (display only).
constexpr int kSliderSteps = 240;

double to_display(const Exact& x) { return CGAL::to_double(x); }

// ---------------------------------------------------------------- poses

const Mat34E kIdentityPose{Exact(1), Exact(0), Exact(0), Exact(0), Exact(0), Exact(1),
                           Exact(0), Exact(0), Exact(0), Exact(0), Exact(1), Exact(0)};

std::array<double, 12> to_display(const Mat34E& m) {
  std::array<double, 12> out;
  for (int i = 0; i < 12; ++i) out[i] = to_display(m[i]);
  return out;
}

// A body's pose at scene parameter t, for display: exact where the motion
// is rational (or a keyframe pose), else the midpoint of the motion's
// rigorous enclosure (src/motion/enclosure.h).  Outside the motion's
// interval, the pose at its nearer end.
class DisplayPose {
 public:
  explicit DisplayPose(const Body& body) : body_(body) {
    if (body.trajectory) models_.resize(body.trajectory->segments.size());
  }

  std::array<double, 12> at(const Exact& t) {
    if (body_.motion) {
      const Motion& m = *body_.motion;
      return to_display(motion_pose(m, std::clamp(t, m.t0, m.t1)));
    }
    if (!body_.trajectory) return to_display(kIdentityPose);
    const auto& segments = body_.trajectory->segments;
    const Exact tc = std::clamp(t, body_.trajectory->t0(), body_.trajectory->t1());
    std::size_t k = 0;
    while (k + 1 < segments.size() && segments[k].t1 < tc) ++k;
    const MotionSegment& seg = segments[k];
    if (const Motion* rational = kind_of(seg).rational(seg)) return to_display(motion_pose(*rational, tc));
    if (!models_[k]) models_[k] = make_segment_model(seg);
    const Exact s = (tc - seg.t0) / (seg.t1 - seg.t0);
    if (const std::optional<Mat34E> exact = models_[k]->exact_pose(s)) return to_display(*exact);
    const PoseInterval box = enclose_pose(*models_[k], s);
    std::array<double, 12> mid;
    for (int i = 0; i < 12; ++i) mid[i] = 0.5 * box[i].inf() + 0.5 * box[i].sup();
    return mid;
  }

 private:
  const Body& body_;
  std::vector<std::unique_ptr<SegmentModel>> models_;
};

// ---------------------------------------------------------------- numbers as text

// A coordinate or pose entry beyond single precision: the scene is then
// not drawn (the page says so; the timeline is complete).
struct DisplayOverflow {};

// Floats in their shortest round-trip form: the page's geometry is for
// display, and float precision keeps a mesh of thousands of triangles small.
class FloatArray {
 public:
  void add(double x) {
    const float f = static_cast<float>(x);
    if (!std::isfinite(f)) throw DisplayOverflow{};
    out_ += first_ ? '[' : ',';
    first_ = false;
    char digits[32];
    const auto end = std::to_chars(digits, digits + sizeof digits, f).ptr;
    out_.append(digits, end);
  }
  void add(const Vec3E& p) {
    for (const Exact& x : p) add(to_display(x));
  }
  std::string take() && { return first_ ? std::string("[]") : std::move(out_) + ']'; }

 private:
  std::string out_;
  bool first_ = true;
};

std::string html_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

// JSON text safe inside <script type="application/json">: "</" cannot end
// the element when written "<\/" (the same string to JSON).  Invalid UTF-8
// in names is replaced rather than refused: the page is for display.
std::string script_json(const json& doc) {
  std::string text = doc.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int shift = 18; shift >= 0; shift -= 6) out += kDigits[(v >> shift) & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += rest == 2 ? kDigits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string module_url(std::string_view source) { return "data:text/javascript;base64," + base64(source); }

// ---------------------------------------------------------------- times

// A parameter as the result prints it: a rational string, or an algebraic
// number {root_of, interval, approx}.
json time_json(const Exact& t, const AlgebraicTime* root) {
  if (!root) return to_string(t);
  json coefficients = json::array();
  for (const CGAL::Gmpz& c : root->root_of) coefficients.push_back(to_string(Exact(c)));
  return json{{"root_of", coefficients}, {"interval", {to_string(root->lo), to_string(root->hi)}}, {"approx", root->approx}};
}

// A witness time as a rational for display: itself, or the decimal
// approximation of its root (clamped into the root's interval).
Exact display_time(const Witness& w) {
  if (!w.root) return w.t;
  Exact approx;
  if (!parse_exact(w.root->approx, approx)) approx = (w.root->lo + w.root->hi) / 2;
  return std::clamp(approx, w.root->lo, w.root->hi);
}

// The scene's parameter range: the union of the moving bodies' intervals
// ([0, 1] when nothing moves).
std::pair<Exact, Exact> scene_range(const Scene& scene) {
  std::optional<std::pair<Exact, Exact>> range;
  for (const Body& b : scene.bodies) {
    if (!b.moves()) continue;
    const auto iv = *b.interval();
    if (!range) range = iv;
    range->first = std::min(range->first, iv.first);
    range->second = std::max(range->second, iv.second);
  }
  return range ? *range : std::pair<Exact, Exact>{Exact(0), Exact(1)};
}

// The parameter interval of a check: its moving body's (two moving bodies
// of a check share it), or the scene's range.
std::pair<Exact, Exact> check_interval(const Scene& scene, const CheckResult& c) {
  for (int side = 0; side < 2; ++side) {
    const Body& b = scene.bodies[c.bodies[side]];
    if (b.moves()) return *b.interval();
  }
  return scene_range(scene);
}

// ---------------------------------------------------------------- timeline

struct Span {
  const char* kind;  // "safe", "undecided", "witness", "not-searched"
  Exact t0, t1;
  const char* reason = nullptr;  // undecided only
};

// The witness's time with rational ends narrow enough to draw: [t, t] for
// a rational time; for an algebraic one its isolating interval (which may
// be as wide as the whole motion) refined exactly (Sturm bisection,
// kernels/real_roots.h) to 2^-24 of the check's interval.
std::pair<Exact, Exact> witness_bracket(const Witness& w, const std::pair<Exact, Exact>& interval) {
  if (!w.root) return {w.t, w.t};
  const AlgebraicTime& at = *w.root;
  RealRoot r{PolyZ(at.root_of.begin(), at.root_of.end()), at.lo, at.hi};
  try {
    refine_to(r, (interval.second - interval.first) / Exact(1 << 24));
  } catch (const ExactLimit&) {
    return {at.lo, at.hi};  // the result's own interval, wide but right
  }
  return {r.lo, r.hi};
}

// The check's interval cut into spans, in parameter order, exactly as the
// result partitions it (SCENE_FORMAT.md, "Every interval claim holds"):
// each undecided interval as the result lists it; between them, certified
// safe; with a collision, the witness's time ends the claims and from it
// on the interval is "not-searched" (an algebraic witness time: the narrow
// bracket around it is a "witness" span, the parts before it safe or
// undecided as the result says, clipped there).
std::vector<Span> timeline(const CheckResult& c, const Exact& t0, const Exact& t1) {
  std::vector<Span> spans;
  std::optional<std::pair<Exact, Exact>> witness;
  if (c.verdict == Verdict::Collision && c.witness) witness = witness_bracket(*c.witness, {t0, t1});
  const Exact claims_end = witness ? std::min(std::max(witness->first, t0), t1) : t1;
  auto clip = [&](const char* kind, const Exact& a, const Exact& b, const char* reason = nullptr) {
    const Exact& hi = std::min(b, claims_end);
    if (a < hi) spans.push_back(Span{kind, a, hi, reason});
  };
  std::vector<UndecidedInterval> undecided = c.undecided;
  std::stable_sort(undecided.begin(), undecided.end(),
                   [](const UndecidedInterval& x, const UndecidedInterval& y) { return x.t0 < y.t0; });
  Exact cursor = t0;
  for (const UndecidedInterval& u : undecided) {
    clip("safe", cursor, u.t0);
    clip("undecided", std::max(cursor, u.t0), u.t1, to_string(u.reason));
    cursor = std::max(cursor, u.t1);
  }
  clip("safe", cursor, t1);
  if (witness) {
    const Exact hi = std::min(std::max(witness->second, claims_end), t1);
    if (claims_end < hi) spans.push_back(Span{"witness", claims_end, hi});
    if (hi < t1) spans.push_back(Span{"not-searched", hi, t1});
  }
  return spans;
}

// For people: what a span says (the page's tooltips).  With a clearance,
// "contact" is coming within it.
std::string span_title(const Span& s, bool certified, bool clearance) {
  const std::string_view kind(s.kind);
  if (kind == "safe") {
    const char* what = clearance ? "farther apart than the clearance" : "no contact";
    return std::string(certified ? "certified safe: " : "safe by the fast kernel (NOT CERTIFIED): ") + what;
  }
  if (kind == "witness")
    return clearance ? "the witness's time (clearance violated) lies here" : "the witness's time (contact) lies here";
  if (kind == "not-searched") return "not searched: the witness ends the search";
  return "undecided";
}

// ---------------------------------------------------------------- features

// A witness feature ("<body> polygon 3 vertex 1", "<body> segment 0 end 1",
// "<body> point 2", "<body> interior") as geometry in the body's frame, for
// highlighting: triangles, line segments and points.  Names of another form
// are shown as text only.
json feature_geometry(const Body& body, int body_index, const std::string& feature) {
  json out{{"body", body_index}, {"name", feature}};
  const std::string prefix = body.name + " ";
  if (feature.rfind(prefix, 0) != 0) return out;
  const std::string part = feature.substr(prefix.size());
  FloatArray triangles, lines, points;
  auto add_polygon = [&](std::size_t k) {
    for (const ConvexPiece& piece : body.pieces) {
      if (piece.polygon != static_cast<int>(k)) continue;
      for (std::size_t i = 1; i + 1 < piece.vertices.size(); ++i) {
        triangles.add(piece.vertices[0]);
        triangles.add(piece.vertices[i]);
        triangles.add(piece.vertices[i + 1]);
      }
    }
    const auto& poly = body.polygons[k];
    for (std::size_t i = 0; i < poly.size(); ++i) {
      lines.add(poly[i]);
      lines.add(poly[(i + 1) % poly.size()]);
    }
  };
  // "<kind> <n>" optionally followed by "<sub> <m>".
  char kind[16] = {}, sub[16] = {};
  long n = -1, m = -1;
  int consumed = 0;
  const int fields = std::sscanf(part.c_str(), "%15s %ld %15s %ld%n", kind, &n, sub, &m, &consumed);
  const std::string_view k(kind), s(sub);
  const bool whole = fields == 2 && part.find(' ', part.find(' ') + 1) == std::string::npos;
  const bool with_sub = fields == 4 && consumed == static_cast<int>(part.size());
  if (part == "interior") {
    for (std::size_t i = 0; i < body.polygons.size(); ++i) add_polygon(i);
  } else if (k == "polygon" && n >= 0 && static_cast<std::size_t>(n) < body.polygons.size() && (whole || with_sub)) {
    add_polygon(static_cast<std::size_t>(n));
    const auto& poly = body.polygons[n];
    if (with_sub && s == "vertex" && m >= 0 && static_cast<std::size_t>(m) < poly.size()) points.add(poly[m]);
  } else if (k == "segment" && n >= 0 && static_cast<std::size_t>(n) < body.segments.size() && (whole || with_sub)) {
    lines.add(body.segments[n][0]);
    lines.add(body.segments[n][1]);
    if (with_sub && s == "end" && (m == 0 || m == 1)) points.add(body.segments[n][m]);
  } else if (k == "point" && n >= 0 && static_cast<std::size_t>(n) < body.points.size() && whole) {
    points.add(body.points[n]);
  }
  out["triangles"] = json::parse(std::move(triangles).take());
  out["lines"] = json::parse(std::move(lines).take());
  out["points"] = json::parse(std::move(points).take());
  return out;
}

// ---------------------------------------------------------------- page parts

json witness_json(const Scene& scene, const CheckResult& c) {
  const Witness& w = *c.witness;
  json out;
  out["t"] = time_json(w.t, w.root ? &*w.root : nullptr);
  out["t_display"] = to_display(display_time(w));
  out["features"] = {w.features[0], w.features[1]};
  json highlight = json::array();
  for (int side = 0; side < 2; ++side)
    highlight.push_back(feature_geometry(scene.bodies[c.bodies[side]], c.bodies[side], w.features[side]));
  out["highlight"] = std::move(highlight);
  // The marker: the exact point, or the centre of the box that holds it.
  std::array<double, 3> marker;
  if (w.point_box) {
    json box = json::array();
    for (int i = 0; i < 3; ++i) {
      const auto& range = (*w.point_box)[i];
      box.push_back({to_string(range[0]), to_string(range[1])});
      marker[i] = to_display((range[0] + range[1]) / 2);
    }
    out["point_box"] = std::move(box);
  } else {
    json point = json::array();
    for (int i = 0; i < 3; ++i) {
      point.push_back(to_string(w.point[i]));
      marker[i] = to_display(w.point[i]);
    }
    out["point"] = std::move(point);
  }
  for (double x : marker)
    if (!std::isfinite(static_cast<float>(x))) throw DisplayOverflow{};
  out["marker"] = marker;
  if (w.points) {
    json pts = json::array();
    for (const Vec3E& p : *w.points) pts.push_back({to_display(p[0]), to_display(p[1]), to_display(p[2])});
    out["points"] = std::move(pts);
  }
  if (w.displacement) {
    out["displacement"] = {to_display((*w.displacement)[0]), to_display((*w.displacement)[1]),
                           to_display((*w.displacement)[2])};
    out["displaced"] = c.bodies[w.displaced];
  }
  if (w.displacement_other) {
    out["displacement_other"] = {to_display((*w.displacement_other)[0]), to_display((*w.displacement_other)[1]),
                                 to_display((*w.displacement_other)[2])};
    out["displaced_other"] = c.bodies[1 - w.displaced];
  }
  return out;
}

double percent(const Exact& t, const std::pair<Exact, Exact>& range) {
  return 100 * to_display((t - range.first) / (range.second - range.first));
}

std::string shortest(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

std::string fixed(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", x);
  return buf;
}

// One check's timeline bar: spans with their exact ends as data
// attributes, the witness mark, and the playhead (moved by the page).
std::string timeline_html(const Scene& scene, const CheckResult& c, int index, bool certified) {
  const auto interval = check_interval(scene, c);
  const std::string& a = scene.bodies[c.bodies[0]].name;
  const std::string& b = scene.bodies[c.bodies[1]].name;
  std::string out = "<div class=\"check\" data-check=\"" + std::to_string(index) + "\" data-verdict=\"" +
                    to_string(c.verdict) + "\" data-body-a=\"" + html_escape(a) + "\" data-body-b=\"" +
                    html_escape(b) + "\">\n";
  out += "<div class=\"check-head\"><span class=\"badge " + std::string(to_string(c.verdict)) + "\">" +
         to_string(c.verdict) + "</span> <b>" + html_escape(a) + "</b> &times; <b>" + html_escape(b) + "</b>";
  if (c.witness) {
    const Witness& w = *c.witness;
    out += ": " + html_escape(w.features[0]) + (w.points || w.points_box ? " comes within the clearance of " : " meets ") +
           html_escape(w.features[1]) + " at t = " +
           html_escape(w.root ? "~" + w.root->approx : to_string(w.t));
    if (w.displacement)
      out += " when " + html_escape(scene.bodies[c.bodies[w.displaced]].name) +
             (w.displacement_other ? " and " + html_escape(scene.bodies[c.bodies[1 - w.displaced]].name) + " are"
                                   : std::string(" is")) +
             " displaced within " + (w.displacement_other ? "their tolerances" : "its tolerance") +
             " (drawn at " + (w.displacement_other ? "their nominal poses)" : "its nominal pose)");
  } else if (!c.undecided.empty()) {
    out += ": " + std::to_string(c.undecided.size()) + " undecided interval(s)";
  }
  out += "</div>\n<div class=\"bar\" data-t0=\"" + to_string(interval.first) + "\" data-t1=\"" +
         to_string(interval.second) + "\">";
  for (const Span& s : timeline(c, interval.first, interval.second)) {
    const double left = percent(s.t0, interval), width = percent(s.t1, interval) - left;
    std::string title = span_title(s, certified, c.clearance > 0) + ", t in [" + to_string(s.t0) + ", " + to_string(s.t1) + "]";
    if (s.reason) title += ", reason: " + std::string(s.reason);
    out += "<div class=\"span " + std::string(s.kind) + "\" data-kind=\"" + s.kind + "\" data-t0=\"" +
           to_string(s.t0) + "\" data-t1=\"" + to_string(s.t1) + "\"";
    if (s.reason) out += " data-reason=\"" + std::string(s.reason) + "\"";
    out += " style=\"left:" + fixed(left) + "%;width:" + fixed(width) + "%\" title=\"" + html_escape(title) +
           "\"></div>";
  }
  if (c.witness) {
    const Witness& w = *c.witness;
    out += "<div class=\"witness-mark\" data-t-display=\"" + shortest(to_display(display_time(w))) + "\"";
    if (w.root)
      out += " data-t-lo=\"" + to_string(w.root->lo) + "\" data-t-hi=\"" + to_string(w.root->hi) + "\"";
    else
      out += " data-t=\"" + to_string(w.t) + "\"";
    out += " style=\"left:" + fixed(percent(display_time(w), interval)) + "%\" title=\"witness at t = " +
           html_escape(w.root ? "~" + w.root->approx : to_string(w.t)) + " (click to go there)\"></div>";
  }
  out += "<div class=\"playhead\"></div></div>\n<div class=\"axis\"><span>" + html_escape(to_string(interval.first)) +
         "</span><span>" + html_escape(to_string(interval.second)) + "</span></div>\n</div>\n";
  return out;
}

// Bodies: triangles of the convex pieces, polygon outlines, segments and
// points in the body's frame, and the poses at the slider's samples.
std::string geometry_json(const Scene& scene, const std::vector<Exact>& times) {
  std::string out = "{\"bodies\":[";
  for (std::size_t bi = 0; bi < scene.bodies.size(); ++bi) {
    const Body& body = scene.bodies[bi];
    FloatArray triangles, outlines, segments, points, poses;
    for (const ConvexPiece& piece : body.pieces)
      for (std::size_t i = 1; i + 1 < piece.vertices.size(); ++i) {
        triangles.add(piece.vertices[0]);
        triangles.add(piece.vertices[i]);
        triangles.add(piece.vertices[i + 1]);
      }
    for (const auto& poly : body.polygons)
      for (std::size_t i = 0; i < poly.size(); ++i) {
        outlines.add(poly[i]);
        outlines.add(poly[(i + 1) % poly.size()]);
      }
    for (const auto& seg : body.segments) {
      segments.add(seg[0]);
      segments.add(seg[1]);
    }
    for (const Vec3E& p : body.points) points.add(p);
    DisplayPose pose(body);
    if (body.moves()) {
      for (const Exact& t : times)
        for (double x : pose.at(t)) poses.add(x);
    } else {
      for (double x : pose.at(times.front())) poses.add(x);
    }
    json head{{"name", body.name}, {"moving", body.moves()}, {"solid", body.solid}};
    std::string text = head.dump(-1, ' ', false, json::error_handler_t::replace);
    text.pop_back();  // '}'
    out += (bi ? "," : "") + text + ",\"triangles\":" + std::move(triangles).take() +
           ",\"outlines\":" + std::move(outlines).take() + ",\"segments\":" + std::move(segments).take() +
           ",\"points\":" + std::move(points).take() + ",\"poses\":" + std::move(poses).take() + "}";
  }
  return out + "]}";
}

std::string three_version() {
  // VERSION's first line: "three <version>".
  const std::string_view v = html::kThreeVersion;
  const std::string_view line = v.substr(0, v.find('\n'));
  return std::string(line.substr(line.find(' ') + 1));
}

}  // namespace

std::string report_html(const Scene& scene, const SceneResult& result) {
  const auto range = scene_range(scene);
  // Slider samples: equal steps, and the exact first-contact and witness times.
  std::vector<Exact> times;
  for (int k = 0; k <= kSliderSteps; ++k) times.push_back(range.first + (range.second - range.first) * Exact(k, kSliderSteps));
  for (const CheckResult& c : result.checks) {
    if (c.witness) times.push_back(display_time(*c.witness));
    if (c.first_contact) {
      times.push_back(c.first_contact->first);
      times.push_back(c.first_contact->second);
    }
  }
  times.erase(std::remove_if(times.begin(), times.end(),
                             [&](const Exact& t) { return t < range.first || range.second < t; }),
              times.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());

  json data;
  data["scene"] = scene.source;
  data["verdict"] = to_string(result.verdict);
  data["kernel"] = to_string(result.kernel);
  data["certified"] = result.certified;
  data["epsilon"] = to_string(result.epsilon);
  data["range"] = {to_display(range.first), to_display(range.second)};
  data["range_exact"] = {to_string(range.first), to_string(range.second)};
  json t_display = json::array();
  for (const Exact& t : times) t_display.push_back(to_display(t));
  data["times"] = std::move(t_display);
  json checks = json::array();
  for (const CheckResult& c : result.checks) {
    checks.push_back(json{{"bodies", {c.bodies[0], c.bodies[1]}}, {"verdict", to_string(c.verdict)}});
  }
  data["checks"] = std::move(checks);
  std::string geometry;
  try {
    geometry = geometry_json(scene, times);
    for (std::size_t i = 0; i < result.checks.size(); ++i)
      if (result.checks[i].witness) data["checks"][i]["witness"] = witness_json(scene, result.checks[i]);
  } catch (const DisplayOverflow&) {
    // Nothing is drawn: bodies without geometry, witnesses as text.
    data["undrawable"] = "coordinates of this scene exceed single precision: the bodies are not drawn";
    json bodies = json::array();
    for (const Body& b : scene.bodies)
      bodies.push_back({{"name", b.name}, {"moving", false}, {"solid", b.solid}, {"triangles", json::array()},
                        {"outlines", json::array()}, {"segments", json::array()}, {"points", json::array()},
                        {"poses", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}});
    geometry = script_json(json{{"bodies", bodies}});
  }

  std::string title = "tmcert report: " + scene.source;
  std::string page;
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<title>" + html_escape(title) + "</title>\n";
  // First: record every error and console.error, before any module runs.
  page += "<script>\n"
          "window.tmcertErrors = [];\n"
          "window.tmcertRecordError = function (message) {\n"
          "  window.tmcertErrors.push(String(message));\n"
          "  document.documentElement.dataset.errors = String(window.tmcertErrors.length);\n"
          "  var box = document.getElementById('errors');\n"
          "  if (box) { box.hidden = false; box.textContent = window.tmcertErrors.join('\\n'); }\n"
          "};\n"
          "window.addEventListener('error', function (e) {\n"
          "  window.tmcertRecordError(e.message || ('cannot load ' + ((e.target && e.target.tagName) || 'a resource')));\n"
          "}, true);\n"
          "window.addEventListener('unhandledrejection', function (e) {\n"
          "  window.tmcertRecordError('unhandled rejection: ' + ((e.reason && e.reason.message) || e.reason));\n"
          "});\n"
          "(function () { var original = console.error; console.error = function () {\n"
          "  window.tmcertRecordError(Array.prototype.join.call(arguments, ' ')); original.apply(console, arguments); }; })();\n"
          "</script>\n";
  page += "<style>\n" + std::string(html::kReportStyle) + "</style>\n";
  json imports{{"three/core", module_url(html::kThreeCore)},
               {"three", module_url(html::kThreeModule)},
               {"three/addons/controls/OrbitControls.js", module_url(html::kOrbitControls)}};
  page += "<script type=\"importmap\">\n" + json{{"imports", imports}}.dump() + "\n</script>\n";
  page += "</head>\n<body>\n<header>\n<h1>tmcert report</h1>\n<span class=\"badge " +
          std::string(to_string(result.verdict)) + "\" id=\"verdict\">" + to_string(result.verdict) + "</span>\n";
  page += "<span class=\"meta\">" + html_escape(scene.source) + " &middot; kernel " + to_string(result.kernel) +
          (result.certified ? " (certified)" : " (NOT CERTIFIED: plain double precision)") + " &middot; epsilon " +
          html_escape(to_string(result.epsilon)) + "</span>\n</header>\n";
  page += "<main>\n<div id=\"view\"><canvas id=\"scene-canvas\"></canvas>"
          "<div id=\"bodies-legend\"></div><div id=\"view-message\" hidden></div></div>\n";
  page += "<section id=\"panel\">\n<div id=\"player\"><button id=\"play\" type=\"button\">Play</button>"
          "<input id=\"time\" type=\"range\" min=\"" + fixed(to_display(range.first)) + "\" max=\"" +
          fixed(to_display(range.second)) + "\" step=\"any\" value=\"" + fixed(to_display(range.first)) +
          "\" aria-label=\"motion parameter t\"><output id=\"time-label\"></output>";
  const bool any_witness = std::any_of(result.checks.begin(), result.checks.end(),
                                       [](const CheckResult& c) { return c.witness.has_value(); });
  if (any_witness) page += "<button id=\"to-witness\" type=\"button\">Go to witness</button>";
  page += "</div>\n<div id=\"timelines\">\n";
  for (std::size_t i = 0; i < result.checks.size(); ++i) page += timeline_html(scene, result.checks[i], static_cast<int>(i), result.certified);
  page += std::string("</div>\n<div class=\"legend\"><span class=\"key safe\"></span>") +
          (result.certified ? "certified safe " : "safe (NOT CERTIFIED: fast kernel) ") +
          "<span class=\"key undecided\"></span>undecided (hover: reason) "
          "<span class=\"key witness\"></span>witness (exact contact) "
          "<span class=\"key not-searched\"></span>not searched (after the witness)</div>\n";
  // The result document itself, as `--json` prints it.
  page += "<details id=\"result\"><summary>The result document (<code>tmcert-result/1</code>, as "
          "<code>--json</code> prints it)</summary><pre id=\"tmcert-result\">" +
          html_escape(result_json(scene, result)) + "</pre></details>\n";
  page += "<p class=\"note\">Drawn in single precision for display; the verdicts and the interval ends "
          "(hover a span) are the exact results of <code>tmcert verify --json</code>. three.js " +
          html_escape(three_version()) + " (MIT licence).</p>\n</section>\n</main>\n<pre id=\"errors\" hidden></pre>\n";
  page += "<script type=\"application/json\" id=\"tmcert-data\">" + script_json(data) + "</script>\n";
  page += "<script type=\"application/json\" id=\"tmcert-geometry\">" + geometry + "</script>\n";
  page += "<script type=\"module\">\n" + std::string(html::kReportApp) + "</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace tmcert
