// verify() and Result (include/tmcert/verify.h, result.h): the internal
// verifier with the command line's option rules, and its result seen
// through exact Rationals and Times with doubles next to them.
#include "kernels/decimal.h"
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/report/report.h"
#include "src/html/report_html.h"
#include "src/io/output_file.h"
#include "src/io/parse.h"
#include "src/verify/options.h"
#include "src/verify/verify.h"

#include "src/api/internal.h"
#include "tmcert/certificate.h"
#include "tmcert/verify.h"

#include <cmath>
#include <exception>
#include <cstdlib>
#include <limits>
#include <optional>
#include <fstream>

namespace tmcert::api {

namespace {

// The public enums list the internal ones' values in the same order
// (checked here), so a conversion either way is a cast.
static_assert(static_cast<int>(Verdict::Safe) == static_cast<int>(tmcert::Verdict::Safe) &&
              static_cast<int>(Verdict::Collision) == static_cast<int>(tmcert::Verdict::Collision) &&
              static_cast<int>(Verdict::Undecided) == static_cast<int>(tmcert::Verdict::Undecided));
static_assert(static_cast<int>(Kernel::Filtered) == static_cast<int>(tmcert::KernelKind::Filtered) &&
              static_cast<int>(Kernel::Exact) == static_cast<int>(tmcert::KernelKind::Exact) &&
              static_cast<int>(Kernel::Fast) == static_cast<int>(tmcert::KernelKind::Fast));
static_assert(static_cast<int>(StopReason::Epsilon) == static_cast<int>(tmcert::StopReason::Epsilon) &&
              static_cast<int>(StopReason::Depth) == static_cast<int>(tmcert::StopReason::Depth) &&
              static_cast<int>(StopReason::Limit) == static_cast<int>(tmcert::StopReason::Limit) &&
              static_cast<int>(StopReason::AfterUndecided) == static_cast<int>(tmcert::StopReason::AfterUndecided));
static_assert(static_cast<int>(StopReason::EnlargedModel) == static_cast<int>(tmcert::StopReason::EnlargedModel));

template <typename To, typename From>
To same_enum(From value) {
  return static_cast<To>(static_cast<int>(value));
}

}  // namespace

const char* to_string(Verdict v) { return tmcert::to_string(same_enum<tmcert::Verdict>(v)); }
const char* to_string(Kernel k) { return tmcert::to_string(same_enum<tmcert::KernelKind>(k)); }
const char* to_string(StopReason r) { return tmcert::to_string(same_enum<tmcert::StopReason>(r)); }

namespace {

std::array<Rational, 3> public_point(const tmcert::Vec3E& p) {
  return {to_rational(p[0]), to_rational(p[1]), to_rational(p[2])};
}

AlgebraicNumber public_root(const tmcert::AlgebraicTime& a) {
  AlgebraicNumber out;
  for (const CGAL::Gmpz& c : a.root_of) out.root_of.push_back(tmcert::to_string(tmcert::Exact(c)));
  out.lower = to_rational(a.lo);
  out.upper = to_rational(a.hi);
  out.approx_text = a.approx;  // the shortest decimal of the nearest double, or the 17-digit decimal beyond range
  const double x = std::strtod(a.approx.c_str(), nullptr);
  out.approx = std::isfinite(x) && x != 0 ? x : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace

Witness public_witness(const std::vector<tmcert::Body>& bodies, const tmcert::CheckResult& c, const tmcert::Witness& w) {
  Witness out;
  out.t = w.root ? Time{public_root(*w.root)} : Time{to_rational(w.t)};
  out.features = w.features;
  if (w.point_box) {
    std::array<std::array<Rational, 2>, 3> box;
    for (int k = 0; k < 3; ++k) {
      box[k] = {to_rational((*w.point_box)[k][0]), to_rational((*w.point_box)[k][1])};
      // The exact centre's nearest double (not the mean of two doubles).
      const std::optional<double> c = tmcert::nearest_double(((*w.point_box)[k][0] + (*w.point_box)[k][1]) / 2);
      out.point_approx[k] = c ? *c : std::numeric_limits<double>::quiet_NaN();
    }
    out.point_box = box;
  } else {
    out.point = public_point(w.point);
    for (int k = 0; k < 3; ++k) out.point_approx[k] = (*out.point)[k].approx;
  }
  if (w.points) out.points = std::array{public_point((*w.points)[0]), public_point((*w.points)[1])};
  if (w.displacement) {
    out.displacement = public_point(*w.displacement);
    out.displaced = bodies[c.bodies[w.displaced]].name;
  }
  if (w.displacement_other) {
    out.displacement_other = public_point(*w.displacement_other);
    out.displaced_other = bodies[c.bodies[1 - w.displaced]].name;
  }
  return out;
}

namespace {

// As result_json writes a check (src/report/report.cpp).
CheckResult public_check(const tmcert::Scene& scene, const tmcert::CheckResult& c) {
  CheckResult out;
  const tmcert::Body& a = scene.bodies[c.bodies[0]];
  const tmcert::Body& b = scene.bodies[c.bodies[1]];
  out.bodies = {a.name, b.name};
  out.verdict = same_enum<Verdict>(c.verdict);
  out.epsilon = to_rational(c.epsilon);
  out.refined = c.refined;
  out.clearance = to_rational(c.clearance);
  out.clearance_violated = c.clearance > 0 && c.verdict == tmcert::Verdict::Collision;
  out.enlarged_model = !a.enlarged.empty() || !b.enlarged.empty();
  if (c.witness) out.witness = public_witness(scene.bodies, c, *c.witness);
  if (c.first_contact) {
    // With an algebraic witness the bracket ends at its time, and starts
    // there too when that is the exact first contact.
    const bool root = out.witness && !out.witness->t.is_rational();
    Time lo = root && c.first_contact_exact ? out.witness->t : Time{to_rational(c.first_contact->first)};
    Time hi = root ? out.witness->t : Time{to_rational(c.first_contact->second)};
    out.first_contact = std::array{std::move(lo), std::move(hi)};
  }
  out.first_contact_exact = c.first_contact_exact;
  for (const tmcert::UndecidedInterval& u : c.undecided)
    out.undecided.push_back({to_rational(u.t0), to_rational(u.t1), same_enum<StopReason>(u.reason)});
  out.interval = {to_rational(c.interval.first), to_rational(c.interval.second)};
  if (out.witness) out.not_searched = std::array{out.witness->t, Time{to_rational(c.interval.second)}};
  const tmcert::CheckStats& s = c.stats;
  out.stats.nodes = s.nodes;
  out.stats.max_depth = s.max_depth;
  out.stats.predicate_calls = s.contact.calls;
  out.stats.exact_fallbacks = s.contact.exact_fallbacks;
  out.stats.stops = s.stops;
  out.stats.exact_pieces = s.exact_pieces;
  out.stats.exact_undecided = s.exact_unknown;
  out.stats.prefiltered = s.prefiltered;
  out.stats.seconds = s.seconds;
  return out;
}

}  // namespace

tmcert::WrittenOptions written_options(Kernel kernel, const std::optional<Number>& epsilon,
                                       std::optional<int> max_depth, std::optional<double> time_limit, int threads) {
  tmcert::WrittenOptions w;
  w.kernel = same_enum<tmcert::KernelKind>(kernel);
  if (epsilon) w.epsilon = tmcert::parse_epsilon(epsilon->text(), tmcert::OptionSpelling::Library);
  w.max_depth = max_depth;
  w.time_limit = time_limit;
  w.threads = threads;
  return w;
}

tmcert::VerifyOptions internal_options(const tmcert::Scene& scene, const VerifyOptions& o, tmcert::EpsilonScope scope) {
  tmcert::WrittenOptions w = written_options(o.kernel, o.epsilon, o.max_depth, o.time_limit, o.threads);
  w.all_pairs = o.all_pairs;
  w.certificate = o.certificate;
  return tmcert::build_options(w, scene, scope, tmcert::OptionSpelling::Library);
}

namespace {

Progress public_progress(const tmcert::ProgressReport& r) {
  Progress p;
  p.fraction = r.fraction;
  p.checks_done = r.checks_done;
  p.checks = r.checks;
  p.activity = r.activity;
  p.seconds = r.seconds;
  return p;
}

// verify_scene with the public progress callback on a watcher thread
// (src/verify/progress.h).
tmcert::SceneResult verify_with_progress(const tmcert::Scene& scene, tmcert::VerifyOptions o,
                                         const VerifyOptions& options) {
  if (!options.progress) return tmcert::verify_scene(scene, o, o.threads);
  if (!std::isfinite(options.progress_interval) || !(options.progress_interval > 0) || options.progress_interval > 3600)
    throw InputError("progress_interval: must be a number of seconds, > 0 and at most 3600");
  tmcert::RunProgress run;
  o.run = &run;
  std::exception_ptr callback_error;
  tmcert::SceneResult result;
  try {
    tmcert::ProgressWatcher watcher(
        run,
        [&](const tmcert::ProgressReport& r) {
          try {
            return options.progress(public_progress(r));
          } catch (...) {
            callback_error = std::current_exception();
            return false;
          }
        },
        options.progress_interval);
    result = tmcert::verify_scene(scene, o, o.threads);
  } catch (const tmcert::Cancelled&) {
    if (callback_error) std::rethrow_exception(callback_error);
    throw;
  }
  if (callback_error) std::rethrow_exception(callback_error);
  tmcert::ProgressReport last = run.report();
  last.fraction = 1;
  last.activity = "done";
  options.progress(public_progress(last));  // the run is over: its answer no longer matters
  return result;
}

}  // namespace

Result verify(const Scene& scene, const VerifyOptions& options) {
  return public_errors([&] {
    const std::shared_ptr<const tmcert::Scene>& internal = scene.impl().scene;
    const tmcert::VerifyOptions o = internal_options(*internal, options);
    tmcert::require_supported(*internal);
    if (options.certificate)
      if (const std::string why = tmcert::certificate::uncertifiable(*internal); !why.empty())
        throw InputError("certificate: certificates do not cover this scene: " + why);
    auto impl = std::make_shared<Result::Impl>();
    impl->scene = internal;
    impl->internal = verify_with_progress(*internal, o, options);
    impl->certificate = options.certificate;
    impl->epsilon = to_rational(impl->internal.epsilon);
    impl->checks.reserve(impl->internal.checks.size());
    for (const tmcert::CheckResult& c : impl->internal.checks) impl->checks.push_back(public_check(*internal, c));
    return Result(std::move(impl));
  });
}

Result::Result(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Verdict Result::verdict() const { return same_enum<Verdict>(impl_->internal.verdict); }
Kernel Result::kernel() const { return same_enum<Kernel>(impl_->internal.kernel); }
bool Result::certified() const { return impl_->internal.certified; }
const Rational& Result::epsilon() const { return impl_->epsilon; }
const std::vector<CheckResult>& Result::checks() const { return impl_->checks; }
const std::vector<std::string>& Result::notes() const { return impl_->scene->notes; }
const std::vector<std::string>& Result::warnings() const { return impl_->scene->warnings; }

std::string Result::to_json() const { return tmcert::result_json(*impl_->scene, impl_->internal); }
std::string Result::summary() const { return tmcert::result_summary(*impl_->scene, impl_->internal); }

std::string Result::certificate() const {
  if (!impl_->certificate)
    throw InputError("certificate: the result was verified without VerifyOptions::certificate");
  return public_errors([&] { return tmcert::certificate::certificate_json(*impl_->scene, impl_->internal); });
}

void Result::write_certificate(const std::string& path) const {
  // The command line's rules for output paths (src/io/output_file.h):
  // checked first (InputError: empty, a directory, not writable, or one of
  // the scene's files), written only once the document is whole, a failed
  // write a ResourceLimit naming the path, leaving no partial file.
  public_errors([&] {
    tmcert::OutputFile file("certificate", path);
    tmcert::require_distinct({&file}, impl_->scene->input_files);
    file.write(certificate());
  });
}

std::string Result::report_html() const {
  return public_errors([&] { return tmcert::report_html(*impl_->scene, impl_->internal); });
}

void Result::write_report(const std::string& path) const {
  // The rules of write_certificate.
  public_errors([&] {
    tmcert::OutputFile file("report", path);
    tmcert::require_distinct({&file}, impl_->scene->input_files);
    file.write(report_html());
  });
}

namespace {

CertificateCheck public_outcome(const tmcert::certificate::CheckOutcome& o) { return {o.ok, o.message, o.proven}; }

}  // namespace

CertificateCheck check_certificate(const Scene& scene, const std::string& path) {
  return public_errors([&] {
    const nlohmann::json doc = tmcert::certificate::read_certificate_file(path);
    return public_outcome(tmcert::certificate::check_certificate(*scene.impl().scene, doc, path));
  });
}

CertificateCheck check_certificate_text(const Scene& scene, const std::string& text, const std::string& source) {
  return public_errors([&] {
    const nlohmann::json doc = tmcert::certificate::parse_certificate_text(text, source);
    return public_outcome(tmcert::certificate::check_certificate(*scene.impl().scene, doc, source));
  });
}

}  // namespace tmcert::api
