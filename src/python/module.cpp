// _tmcert: the pybind11 binding of tmcert's public C++ API (include/tmcert/).
//
// Thin on purpose: it binds the API's types as they are, converts numbers
// both ways (Python int, fractions.Fraction, decimal.Decimal, str and float
// to tmcert::Number; tmcert::Rational to fractions.Fraction) and maps the
// API's exceptions.  The Pythonic layer (NumPy arrays, dict scenes, result
// objects) is the package around it, src/python/tmcert/__init__.py.
#include <tmcert/tmcert.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace py = pybind11;
namespace api = tmcert::api;

namespace {

// The Python types the conversions use, imported once and kept for the
// life of the interpreter (released handles: nothing to destroy at exit).
struct PythonTypes {
  py::handle fraction, decimal, integral, rational, real;
};
py::handle python_attr(const char* module, const char* name) {
  return py::object(py::module_::import(module).attr(name)).release();
}
const PythonTypes& python_types() {
  static const PythonTypes types{python_attr("fractions", "Fraction"), python_attr("decimal", "Decimal"),
                                 python_attr("numbers", "Integral"), python_attr("numbers", "Rational"),
                                 python_attr("numbers", "Real")};
  return types;
}

bool is_instance(py::handle object, py::handle type) {
  const int r = PyObject_IsInstance(object.ptr(), type.ptr());
  if (r < 0) throw py::error_already_set();
  return r == 1;
}

// Python refuses to convert ints of more than 4300 digits to and from
// decimal text (sys.get_int_max_str_digits(), Python 3.11); a scene's or a
// result's exact numbers may be longer (up to 10 000 digits in a scene, more
// in a result), so both conversions go by chunks of kChunk digits.
constexpr std::size_t kChunk = 4000;

py::handle chunk_power() {  // 10^kChunk
  static const py::handle power = py::int_(10).attr("__pow__")(kChunk).release();
  return power;
}

std::string int_text(const py::handle& value) {
  py::object v = py::reinterpret_borrow<py::object>(value);
  const bool negative = v < py::int_(0);
  if (negative) v = -v;
  std::vector<std::string> chunks;  // least significant first
  while (v >= chunk_power()) {
    const py::tuple qr = py::reinterpret_steal<py::tuple>(PyNumber_Divmod(v.ptr(), chunk_power().ptr()));
    if (!qr) throw py::error_already_set();
    std::string digits = py::str(qr[1]);
    chunks.push_back(std::string(kChunk - digits.size(), '0') + digits);
    v = qr[0];
  }
  std::string text = (negative ? "-" : "") + std::string(py::str(v));
  for (auto it = chunks.rbegin(); it != chunks.rend(); ++it) text += *it;
  return text;
}

py::object int_from_text(std::string_view text) {
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) text.remove_prefix(1);
  py::object v = py::int_(0);
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t n = std::min(kChunk, text.size() - start);
    v = v * py::int_(10).attr("__pow__")(n) + py::int_(py::str(std::string(text.substr(start, n))));
    start += n;
  }
  return negative ? py::object(-v) : v;
}

}  // namespace

namespace pybind11::detail {

// A scene number from Python, exactly:
//  * int (and any numbers.Integral, e.g. numpy.int64): that integer;
//  * fractions.Fraction (any numbers.Rational): "p/q";
//  * decimal.Decimal: the decimal it holds ("NaN" is an error when built);
//  * str: an integer, "p/q" or a decimal, as in a scene file;
//  * float (any other numbers.Real, e.g. numpy.float64): exactly its binary
//    value, as the C++ API's Number(double): 0.1 is not 1/10.
// bool is refused (True is not a coordinate).
template <>
struct type_caster<api::Number> {
  PYBIND11_TYPE_CASTER(api::Number, const_name("Number"));

  bool load(handle src, bool) {
    if (!src || PyBool_Check(src.ptr())) return false;
    if (PyUnicode_Check(src.ptr())) {
      value = api::Number(src.cast<std::string>());
    } else if (is_instance(src, python_types().integral)) {
      value = api::Number(int_text(py::int_(py::reinterpret_borrow<py::object>(src))));
    } else if (is_instance(src, python_types().rational)) {
      const py::object numerator = src.attr("numerator"), denominator = src.attr("denominator");
      value = api::Number(int_text(py::int_(numerator)) + "/" + int_text(py::int_(denominator)));
    } else if (is_instance(src, python_types().decimal)) {
      value = api::Number(std::string(py::str(src)));
    } else if (is_instance(src, python_types().real)) {
      const double d = PyFloat_AsDouble(src.ptr());
      if (d == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        return false;
      }
      value = api::Number(d);
    } else {
      return false;
    }
    return true;
  }

  static handle cast(const api::Number& n, return_value_policy, handle) { return py::str(n.text()).release(); }
};

}  // namespace pybind11::detail

namespace {

// One number, or a TypeError naming what came instead.
api::Number number(const py::handle& h) {
  py::detail::make_caster<api::Number> caster;
  if (!caster.load(h, true))
    throw py::type_error("expected a number (int, Fraction, Decimal, str or float), got " + std::string(py::repr(h)));
  return py::detail::cast_op<api::Number>(std::move(caster));
}

py::sequence sequence(const py::handle& h, const char* what) {
  if (!PySequence_Check(h.ptr()) || PyUnicode_Check(h.ptr()))
    throw py::type_error(std::string(what) + ": expected a sequence, got " + std::string(py::repr(h)));
  return py::reinterpret_borrow<py::sequence>(h);
}

py::object to_fraction(const api::Rational& r) {
  return python_types().fraction(int_from_text(r.numerator), int_from_text(r.denominator));
}

// A point of three numbers, or a (3, 4) / 12-number affine map, from any
// nested Python sequence (lists, tuples, NumPy arrays).
api::AffineMap affine_map(const py::handle& m) {
  api::AffineMap out;
  const py::sequence rows = sequence(m, "an affine map");
  if (py::len(rows) == 12) {
    for (std::size_t i = 0; i < 12; ++i) out[i] = number(rows[i]);
    return out;
  }
  if (py::len(rows) != 3) throw py::value_error("an affine map is a 3x4 matrix [A | a] (or 12 numbers, row by row)");
  for (std::size_t r = 0; r < 3; ++r) {
    const py::sequence row = sequence(py::object(rows[r]), "a row of an affine map");
    if (py::len(row) != 4) throw py::value_error("an affine map is a 3x4 matrix [A | a] (or 12 numbers, row by row)");
    for (std::size_t c = 0; c < 4; ++c) out[4 * r + c] = number(row[c]);
  }
  return out;
}

std::vector<api::AffineMap> affine_maps(const py::sequence& maps) {
  std::vector<api::AffineMap> out;
  out.reserve(py::len(maps));
  for (std::size_t i = 0; i < py::len(maps); ++i) {
    const py::object item = maps[i];  // owned: an accessor's item dies with the accessor
    out.push_back(affine_map(item));
  }
  return out;
}

api::Interpolation interpolation(const std::string& name) {
  if (name == "slerp") return api::Interpolation::Slerp;
  if (name == "screw") return api::Interpolation::Screw;
  if (name == "nlerp") return api::Interpolation::Nlerp;
  throw api::InputError("interpolation: expected \"slerp\", \"screw\" or \"nlerp\", got \"" + name + "\"");
}
const char* interpolation_name(api::Interpolation i) {
  switch (i) {
    case api::Interpolation::Slerp: return "slerp";
    case api::Interpolation::Screw: return "screw";
    case api::Interpolation::Nlerp: return "nlerp";
  }
  return "slerp";
}

api::Kernel kernel(const std::string& name) {
  if (name == "filtered") return api::Kernel::Filtered;
  if (name == "exact") return api::Kernel::Exact;
  if (name == "fast") return api::Kernel::Fast;
  throw api::InputError("kernel: expected \"filtered\", \"exact\" or \"fast\", got \"" + name + "\"");
}

// A C-contiguous float64 array's values (the caller checked its shape).
std::span<const double> doubles(const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
  return {a.data(), static_cast<std::size_t>(a.size())};
}

std::string rotation_repr(const api::Rotation& r) {
  static const char* kinds[] = {"identity", "quaternion", "rpy", "matrix"};
  std::string s = std::string("Rotation.") + kinds[static_cast<int>(r.kind)] + "(";
  for (std::size_t i = 0; i < r.values.size(); ++i) s += (i ? ", '" : "'") + r.values[i].text() + "'";
  return s + ")";
}

std::string point_repr(const api::Point& p) {
  return "('" + p[0].text() + "', '" + p[1].text() + "', '" + p[2].text() + "')";
}

// Runs a long call (verify, batch) on a thread of its own while the
// calling thread, which holds the GIL between short waits, looks for
// signals (PyErr_CheckSignals: Ctrl-C raises KeyboardInterrupt there) and
// calls the Python progress callback with the latest report.  The call's
// C++ progress hook (hook(), polled by the library every kPoll seconds)
// cancels the run once a signal handler raised, the callback returned
// False or raised; the run then ends within about one subdivision node's
// work, and the signal's exception, the callback's, or Cancelled is raised
// here: never a result of a cancelled run.
template <class Report>
class Interruptible {
 public:
  static constexpr double kPoll = 0.05;  // seconds

  Interruptible(py::object callback, double interval) : callback_(std::move(callback)), interval_(interval) {
    if (!std::isfinite(interval) || !(interval > 0) || interval > 3600)
      throw api::InputError("progress_interval: must be a number of seconds, > 0 and at most 3600");
    if (!callback_.is_none() && !PyCallable_Check(callback_.ptr()))
      throw py::type_error("progress: expected a callable or None");
  }

  std::function<bool(const Report&)> hook() {
    return [this](const Report& r) {
      std::lock_guard<std::mutex> lock(mutex_);
      latest_ = r;
      fresh_ = true;
      return !cancel_;
    };
  }

  template <class Work>
  auto run(Work work) -> decltype(work()) {
    using Out = decltype(work());
    std::optional<Out> out;
    std::exception_ptr error;
    bool done = false;
    std::condition_variable finished;
    std::thread thread([&] {
      try {
        out.emplace(work());
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex_);
      done = true;
      finished.notify_all();
    });
    std::optional<py::error_already_set> raised;  // KeyboardInterrupt, or the callback's exception
    bool refused = false;                          // the callback returned False
    auto next_call = std::chrono::steady_clock::now() + std::chrono::duration<double>(interval_);
    for (;;) {
      bool over;
      {
        py::gil_scoped_release unlocked;
        std::unique_lock<std::mutex> lock(mutex_);
        over = finished.wait_for(lock, std::chrono::duration<double>(kPoll), [&] { return done; });
      }
      if (over || raised || refused) break;
      if (PyErr_CheckSignals() != 0) {
        raised.emplace();  // fetches the pending exception
        cancel();
        continue;
      }
      if (!callback_.is_none() && std::chrono::steady_clock::now() >= next_call) {
        next_call += std::chrono::duration<double>(interval_);
        if (!call_back()) refused = true;
        if (refused) cancel();
        raised = std::move(pending_);
        if (raised) cancel();
      }
    }
    {
      py::gil_scoped_release unlocked;
      thread.join();
    }
    if (raised) throw std::move(*raised);
    if (refused) throw api::Cancelled("cancelled: the progress callback returned False");
    if (error) std::rethrow_exception(error);
    if (!callback_.is_none()) {  // the last report (fraction 1)
      call_back();
      if (pending_) throw std::move(*pending_);
    }
    return std::move(*out);
  }

 private:
  void cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    cancel_ = true;
  }
  // Calls the callback with the latest report (when there is a new one);
  // false when it returned False; an exception it raised goes to pending_.
  bool call_back() {
    std::optional<Report> report;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (fresh_) report = latest_;
      fresh_ = false;
    }
    if (!report) return true;
    try {
      const py::object answer = callback_(*report);
      return !(answer.ptr() == Py_False);
    } catch (py::error_already_set& e) {
      pending_.emplace(std::move(e));
      return true;
    }
  }

  py::object callback_;
  double interval_;
  std::mutex mutex_;
  Report latest_{};
  bool fresh_ = false;
  bool cancel_ = false;
  std::optional<py::error_already_set> pending_;
};

}  // namespace

PYBIND11_MODULE(_tmcert, m) {
  m.doc() = "tmcert's public C++ API (include/tmcert/), bound with pybind11; use the package tmcert.";
  m.attr("__version__") = TMCERT_VERSION;
  m.def("_int_text", [](const py::int_& v) { return int_text(v); },
        "An int's decimal text, however long (str() stops at sys.get_int_max_str_digits()).");

  // Exceptions: the API's, with their messages (the command line prints
  // them after "tmcert: ").  InputError is a ValueError.
  py::register_exception<api::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<api::ResourceLimit>(m, "ResourceLimit", PyExc_RuntimeError);
  py::register_exception<api::Cancelled>(m, "Cancelled", PyExc_RuntimeError);

  // ------------------------------------------------------------ motions
  py::class_<api::Rotation>(m, "Rotation", "A rotation of a rigid pose (identity, quaternion, rpy or matrix).")
      .def_static("identity", &api::Rotation::identity, "The identity.")
      .def_static("quaternion", &api::Rotation::quaternion, py::arg("w"), py::arg("x"), py::arg("y"), py::arg("z"),
                  "The rotation of the nonzero quaternion q/|q| (exact: its matrix is rational).")
      .def_static("rpy", &api::Rotation::rpy, py::arg("roll"), py::arg("pitch"), py::arg("yaw"),
                  "Radians, URDF's convention R = Rz(yaw) Ry(pitch) Rx(roll) (enclosed rigorously).")
      .def_static(
          "matrix",
          [](const py::sequence& rows) {
            std::array<api::Number, 9> v;
            if (py::len(rows) == 9) {
              for (std::size_t i = 0; i < 9; ++i) v[i] = number(rows[i]);
            } else {
              if (py::len(rows) != 3) throw py::value_error("a rotation matrix is 3x3 (or 9 numbers, row by row)");
              for (std::size_t r = 0; r < 3; ++r) {
                const py::sequence row = sequence(py::object(rows[r]), "a row of a rotation matrix");
                if (py::len(row) != 3) throw py::value_error("a rotation matrix is 3x3 (or 9 numbers, row by row)");
                for (std::size_t c = 0; c < 3; ++c) v[3 * r + c] = number(row[c]);
              }
            }
            return api::Rotation::matrix(v);
          },
          py::arg("rows"), "Rows of an exactly orthonormal 3x3 matrix with determinant +1.")
      .def_property_readonly("kind",
                             [](const api::Rotation& r) {
                               static const char* kinds[] = {"identity", "quaternion", "rpy", "matrix"};
                               return kinds[static_cast<int>(r.kind)];
                             })
      .def_readonly("values", &api::Rotation::values, "The numbers as exact text.")
      .def("__repr__", &rotation_repr);

  py::class_<api::Pose>(m, "Pose", "A rigid pose x -> R x + translation.")
      .def(py::init([](const api::Point& translation, const api::Rotation& rotation) {
             return api::Pose{translation, rotation};
           }),
           py::arg("translation") = api::Point{0, 0, 0}, py::arg("rotation") = api::Rotation::identity())
      .def_readonly("translation", &api::Pose::translation)
      .def_readonly("rotation", &api::Pose::rotation)
      .def("__repr__", [](const api::Pose& p) {
        return "Pose(translation=" + point_repr(p.translation) + ", rotation=" + rotation_repr(p.rotation) + ")";
      });

  py::class_<api::RationalBezier>(
      m, "RationalBezier",
      "A rational Bezier curve of affine maps: control points (k, 3, 4) [A | a], positive weights (default 1), "
      "over the scene parameters `interval` (default (0, 1)).")
      .def(py::init([](const py::sequence& control_points, std::optional<std::vector<api::Number>> weights,
                       std::pair<api::Number, api::Number> interval) {
             return api::RationalBezier{affine_maps(control_points), weights.value_or(std::vector<api::Number>{}),
                                        std::move(interval)};
           }),
           py::arg("control_points"), py::arg("weights") = py::none(),
           py::arg("interval") = std::pair<api::Number, api::Number>{0, 1})
      .def_property_readonly("degree", [](const api::RationalBezier& b) { return int(b.control_points.size()) - 1; })
      .def("__repr__", [](const api::RationalBezier& b) {
        return "RationalBezier(degree " + std::to_string(int(b.control_points.size()) - 1) + ", interval ['" +
               b.interval.first.text() + "', '" + b.interval.second.text() + "'])";
      });

  py::class_<api::Keyframes>(m, "Keyframes",
                             "Rigid poses at strictly increasing times (default: evenly spaced over [0, 1]), "
                             "interpolated by \"slerp\" (default), \"screw\" or \"nlerp\".")
      .def(py::init([](std::vector<api::Pose> poses, std::optional<std::vector<api::Number>> times,
                       const std::string& interp) {
             return api::Keyframes{std::move(poses), times.value_or(std::vector<api::Number>{}),
                                   interpolation(interp)};
           }),
           py::arg("poses"), py::arg("times") = py::none(), py::arg("interpolation") = "slerp")
      .def_readonly("poses", &api::Keyframes::poses)
      .def_property_readonly("interpolation", [](const api::Keyframes& k) { return interpolation_name(k.interpolation); })
      .def("__repr__", [](const api::Keyframes& k) {
        return "Keyframes(" + std::to_string(k.poses.size()) + " poses, " + interpolation_name(k.interpolation) + ")";
      });

  py::class_<api::Motion> motion(m, "Motion", "One of the motion types: RationalBezier, Keyframes or Piecewise.");
  py::class_<api::Piecewise>(m, "Piecewise",
                             "Motions whose intervals abut exactly and whose poses agree exactly at every join.")
      .def(py::init([](std::vector<api::Motion> pieces) { return api::Piecewise{std::move(pieces)}; }),
           py::arg("pieces"))
      .def_property_readonly("pieces", [](const api::Piecewise& p) { return p.pieces; })
      .def("__repr__", [](const api::Piecewise& p) { return "Piecewise(" + std::to_string(p.pieces.size()) + " pieces)"; });
  motion.def(py::init<api::RationalBezier>())
      .def(py::init<api::Keyframes>())
      .def(py::init<api::Piecewise>())
      .def_static("translation", &api::Motion::translation, py::arg("start"), py::arg("end"), py::arg("t0") = 0,
                  py::arg("t1") = 1,
                  "A pure translation from `start` to `end` over [t0, t1] (a degree-1 rational Bezier curve).")
      .def_property_readonly("value", [](const api::Motion& mo) -> py::object {
        return std::visit([](const auto& v) { return py::cast(v); }, mo.value());
      });
  py::implicitly_convertible<api::RationalBezier, api::Motion>();
  py::implicitly_convertible<api::Keyframes, api::Motion>();
  py::implicitly_convertible<api::Piecewise, api::Motion>();

  // ------------------------------------------------------------ scenes
  py::class_<api::Scene>(m, "Scene", "An immutable, validated tmcert-scene/1 scene.")
      .def_static("from_file", py::overload_cast<const std::string&>(&api::Scene::from_file), py::arg("path"),
                  "Reads and validates a scene file (mesh and URDF files relative to it).")
      .def_static("from_file",
                  py::overload_cast<const std::string&, const std::vector<std::string>&>(&api::Scene::from_file),
                  py::arg("path"), py::arg("package_paths"),
                  "The same, with folders searched for package:// URIs before the scene's and ROS_PACKAGE_PATH.")
      .def_static("from_json", &api::Scene::from_json, py::arg("text"), py::arg("source") = "<json>",
                  "Reads and validates a tmcert-scene/1 document; `source` names it in messages.")
      .def_property_readonly("body_names", &api::Scene::body_names, "Body names in scene order.")
      .def("moves", &api::Scene::moves, py::arg("body"), "Does body number `body` move?")
      .def_property_readonly("checks", &api::Scene::checks, "The body pairs verify() checks, in order.")
      .def_property_readonly(
          "epsilon",
          [](const api::Scene& s) -> py::object {
            const auto e = s.epsilon();
            return e ? to_fraction(*e) : py::none();
          },
          "The scene's epsilon as written (None: the default applies), a Fraction.")
      .def(
          "default_epsilon",
          [](const api::Scene& s, const std::string& a, const std::string& b) { return to_fraction(s.default_epsilon(a, b)); },
          py::arg("a"), py::arg("b"),
          "The epsilon a check of bodies a and b uses when none is given: 1/1000 of the diagonal of the box of "
          "everything the two bodies sweep (six significant digits), a Fraction.")
      .def_property_readonly("max_depth", &api::Scene::max_depth)
      .def_property_readonly("source", &api::Scene::source)
      .def_property_readonly("notes", &api::Scene::notes,
                             "What the reader did to data from real pipelines (fan splits, zero-area faces).")
      .def_property_readonly("warnings", &api::Scene::warnings,
                             "Input read in a way that may not be meant (an rpy angle above 2 pi as radians).")
      .def("__len__", &api::Scene::body_count)
      .def("__repr__", [](const api::Scene& s) {
        return "<tmcert.Scene " + s.source() + ": " + std::to_string(s.body_count()) + " bodies, " +
               std::to_string(s.checks().size()) + " checks>";
      });

  using BB = api::BodyBuilder;
  using Flat = py::array_t<double, py::array::c_style | py::array::forcecast>;
  using Sizes = py::array_t<std::size_t, py::array::c_style | py::array::forcecast>;
  const auto self = py::return_value_policy::reference_internal;
  py::class_<BB>(m, "_BodyBuilder")
      .def_property_readonly("name", &BB::name)
      .def("polygons_xyz",
           [](BB& b, const Flat& xyz, const Sizes& indices, const Sizes& sizes) -> BB& {
             return b.polygons(doubles(xyz), std::span(indices.data(), indices.size()),
                               std::span(sizes.data(), sizes.size()));
           }, self)
      .def("polygons_exact",
           [](BB& b, const std::vector<api::Point>& vertices, const std::vector<std::vector<std::size_t>>& faces)
               -> BB& { return b.polygons(std::span(vertices), faces); }, self)
      .def("triangles_xyz",
           [](BB& b, const Flat& xyz, const Sizes& indices) -> BB& {
             return b.triangles(doubles(xyz), std::span(indices.data(), indices.size()));
           }, self)
      .def("triangles_exact",
           [](BB& b, const std::vector<api::Point>& vertices, const std::vector<std::size_t>& indices) -> BB& {
             return b.triangles(std::span(vertices), std::span(indices));
           }, self)
      .def("segments_xyz", [](BB& b, const Flat& xyz) -> BB& { return b.segments(doubles(xyz)); }, self)
      .def("segment", &BB::segment, self)
      .def("points_xyz", [](BB& b, const Flat& xyz) -> BB& { return b.points(doubles(xyz)); }, self)
      .def("point", &BB::point, self)
      .def("mesh", &BB::mesh, self)
      .def("solid", &BB::solid, self)
      .def("mass", &BB::mass, self)
      .def("tolerance", &BB::tolerance, self)
      .def("motion", &BB::motion, self);

  using RB = api::RobotBuilder;
  py::class_<RB>(m, "_RobotBuilder")
      .def_property_readonly("name", &RB::name)
      .def("base", &RB::base, self)
      .def("path", &RB::path, self)
      .def("interpolation", &RB::interpolation, self)
      .def("self_collision", &RB::self_collision, self)
      .def("allow", &RB::allow, self)
      .def("srdf", &RB::srdf, self);

  using SB = api::SceneBuilder;
  py::class_<SB>(m, "_SceneBuilder")
      .def(py::init<>())
      .def("add_body", &SB::add_body, self)
      .def("add_robot", &SB::add_robot, self)
      .def("check", py::overload_cast<std::string, std::string>(&SB::check), self)
      .def("check_with_clearance", py::overload_cast<std::string, std::string, api::Number>(&SB::check), self)
      .def("epsilon", &SB::epsilon, self)
      .def("max_depth", &SB::max_depth, self)
      .def("clearance", &SB::clearance, self)
      .def("package_path", &SB::package_path, self)
      .def("build", &SB::build)
      .def("to_json", &SB::to_json);

  // ------------------------------------------------------------ results
  py::class_<api::Rational>(m, "_Rational")
      .def_readonly("text", &api::Rational::text)
      .def_readonly("approx", &api::Rational::approx)
      .def_readonly("approx_text", &api::Rational::approx_text)
      .def("fraction", &to_fraction);
  py::class_<api::AlgebraicNumber>(m, "_AlgebraicNumber")
      .def_readonly("root_of", &api::AlgebraicNumber::root_of)
      .def_readonly("lower", &api::AlgebraicNumber::lower)
      .def_readonly("upper", &api::AlgebraicNumber::upper)
      .def_readonly("approx_text", &api::AlgebraicNumber::approx_text)
      .def_readonly("approx", &api::AlgebraicNumber::approx);
  py::class_<api::Time>(m, "_Time").def_readonly("value", &api::Time::value);
  py::class_<api::Witness>(m, "_Witness")
      .def_readonly("t", &api::Witness::t)
      .def_readonly("features", &api::Witness::features)
      .def_readonly("point", &api::Witness::point)
      .def_readonly("point_box", &api::Witness::point_box)
      .def_readonly("points", &api::Witness::points)
      .def_readonly("displacement", &api::Witness::displacement)
      .def_readonly("displaced", &api::Witness::displaced)
      .def_readonly("displacement_other", &api::Witness::displacement_other)
      .def_readonly("displaced_other", &api::Witness::displaced_other)
      .def_readonly("point_approx", &api::Witness::point_approx);
  py::class_<api::UndecidedInterval>(m, "_UndecidedInterval")
      .def_readonly("t0", &api::UndecidedInterval::t0)
      .def_readonly("t1", &api::UndecidedInterval::t1)
      .def_property_readonly("reason", [](const api::UndecidedInterval& u) { return api::to_string(u.reason); });
  py::class_<api::CheckStats>(m, "_CheckStats")
      .def_readonly("nodes", &api::CheckStats::nodes)
      .def_readonly("max_depth", &api::CheckStats::max_depth)
      .def_readonly("predicate_calls", &api::CheckStats::predicate_calls)
      .def_readonly("exact_fallbacks", &api::CheckStats::exact_fallbacks)
      .def_readonly("stops", &api::CheckStats::stops)
      .def_readonly("exact_pieces", &api::CheckStats::exact_pieces)
      .def_readonly("exact_undecided", &api::CheckStats::exact_undecided)
      .def_readonly("prefiltered", &api::CheckStats::prefiltered)
      .def_readonly("seconds", &api::CheckStats::seconds);
  py::class_<api::CheckResult>(m, "_CheckResult")
      .def_readonly("bodies", &api::CheckResult::bodies)
      .def_property_readonly("verdict", [](const api::CheckResult& c) { return api::to_string(c.verdict); })
      .def_readonly("epsilon", &api::CheckResult::epsilon)
      .def_readonly("refined", &api::CheckResult::refined)
      .def_readonly("clearance", &api::CheckResult::clearance)
      .def_readonly("clearance_violated", &api::CheckResult::clearance_violated)
      .def_readonly("enlarged_model", &api::CheckResult::enlarged_model)
      .def_readonly("first_contact", &api::CheckResult::first_contact)
      .def_readonly("first_contact_exact", &api::CheckResult::first_contact_exact)
      .def_readonly("witness", &api::CheckResult::witness)
      .def_readonly("undecided", &api::CheckResult::undecided)
      .def_readonly("interval", &api::CheckResult::interval)
      .def_readonly("not_searched", &api::CheckResult::not_searched)
      .def_readonly("stats", &api::CheckResult::stats);
  py::class_<api::Result>(m, "_Result")
      .def_property_readonly("verdict", [](const api::Result& r) { return api::to_string(r.verdict()); })
      .def_property_readonly("kernel", [](const api::Result& r) { return api::to_string(r.kernel()); })
      .def_property_readonly("certified", &api::Result::certified)
      .def_property_readonly("epsilon", &api::Result::epsilon)
      .def_property_readonly("checks", &api::Result::checks)
      .def("to_json", &api::Result::to_json)
      .def("summary", &api::Result::summary)
      .def("certificate", &api::Result::certificate)
      .def("write_certificate", &api::Result::write_certificate, py::arg("path"),
           py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("notes", &api::Result::notes)
      .def_property_readonly("warnings", &api::Result::warnings)
      .def("report_html", &api::Result::report_html, py::call_guard<py::gil_scoped_release>())
      .def("write_report", &api::Result::write_report, py::arg("path"), py::call_guard<py::gil_scoped_release>());

  py::class_<api::Progress>(m, "_Progress")
      .def_readonly("fraction", &api::Progress::fraction)
      .def_readonly("checks_done", &api::Progress::checks_done)
      .def_readonly("checks", &api::Progress::checks)
      .def_readonly("activity", &api::Progress::activity)
      .def_readonly("seconds", &api::Progress::seconds);
  py::class_<api::BatchProgress>(m, "_BatchProgress")
      .def_readonly("requests_read", &api::BatchProgress::requests_read)
      .def_readonly("requests_written", &api::BatchProgress::requests_written)
      .def_readonly("activity", &api::BatchProgress::activity)
      .def_readonly("seconds", &api::BatchProgress::seconds);
  py::class_<api::BatchSummary>(m, "_BatchSummary")
      .def_readonly("requests", &api::BatchSummary::requests)
      .def_readonly("safe", &api::BatchSummary::safe)
      .def_readonly("collision", &api::BatchSummary::collision)
      .def_readonly("undecided", &api::BatchSummary::undecided)
      .def_readonly("errors", &api::BatchSummary::errors)
      .def_readonly("exit_code", &api::BatchSummary::exit_code);

  // verify() and batch() run without the GIL, on a thread of their own,
  // while the calling thread polls for signals (Ctrl-C: KeyboardInterrupt
  // cancels the run within about a tenth of a second plus one subdivision
  // node's work) and calls the progress callback; other Python threads go
  // on meanwhile (and several verify() calls run in parallel).
  m.def(
      "verify",
      [](const api::Scene& scene, const std::string& kernel_name, std::optional<api::Number> epsilon,
         std::optional<int> max_depth, int threads, std::optional<double> time_limit, bool all_pairs,
         bool certificate, py::object progress, double progress_interval) {
        api::VerifyOptions options;
        options.kernel = kernel(kernel_name);
        options.epsilon = std::move(epsilon);
        options.max_depth = max_depth;
        options.threads = threads;
        options.time_limit = time_limit;
        options.all_pairs = all_pairs;
        options.certificate = certificate;
        Interruptible<api::Progress> run(std::move(progress), progress_interval);
        options.progress = run.hook();
        options.progress_interval = Interruptible<api::Progress>::kPoll;
        return run.run([&] { return api::verify(scene, options); });
      },
      py::arg("scene"), py::arg("kernel"), py::arg("epsilon"), py::arg("max_depth"), py::arg("threads"),
      py::arg("time_limit"), py::arg("all_pairs"), py::arg("certificate"), py::arg("progress") = py::none(),
      py::arg("progress_interval") = 0.5);

  m.def(
      "batch",
      [](const std::string& requests, const std::string& scene, const std::string& output, const std::string& shard,
         const std::string& kernel_name, std::optional<api::Number> epsilon, std::optional<int> max_depth,
         std::optional<double> time_limit, int threads, bool stats, py::object progress, double progress_interval) {
        api::BatchOptions options;
        options.requests = requests;
        options.scene = scene;
        options.output = output;
        options.shard = shard;
        options.kernel = kernel(kernel_name);
        options.epsilon = std::move(epsilon);
        options.max_depth = max_depth;
        options.time_limit = time_limit;
        options.threads = threads;
        options.stats = stats;
        Interruptible<api::BatchProgress> run(std::move(progress), progress_interval);
        options.progress = run.hook();
        options.progress_interval = Interruptible<api::BatchProgress>::kPoll;
        return run.run([&] { return api::batch(options); });
      },
      py::arg("requests"), py::arg("scene"), py::arg("output"), py::arg("shard"), py::arg("kernel"),
      py::arg("epsilon"), py::arg("max_depth"), py::arg("time_limit"), py::arg("threads"), py::arg("stats"),
      py::arg("progress") = py::none(), py::arg("progress_interval") = 0.5);
  m.def("batch_merge", &api::batch_merge, py::arg("shards"), py::arg("output"),
        py::call_guard<py::gil_scoped_release>());

  py::class_<api::CertificateCheck>(m, "_CertificateCheck")
      .def_readonly("ok", &api::CertificateCheck::ok)
      .def_readonly("message", &api::CertificateCheck::message)
      .def_readonly("proven", &api::CertificateCheck::proven);
  m.def("check_certificate", &api::check_certificate, py::arg("scene"), py::arg("path"),
        py::call_guard<py::gil_scoped_release>());
  m.def("check_certificate_text", &api::check_certificate_text, py::arg("scene"), py::arg("text"),
        py::arg("source") = "<certificate>", py::call_guard<py::gil_scoped_release>());
}
