"""tmcert: certified collision checks of moving polyhedra.

A Python binding of tmcert's public C++ API (``include/tmcert/``).  A scene
(bodies with exact geometry and motions, the body pairs to check) comes
from a file, a JSON string, a dict holding the tmcert-scene/1 document, or a
:class:`SceneBuilder` fed with NumPy arrays; :func:`verify` proves each
check ``safe`` or ``collision`` (with an exact witness), or reports it
``undecided`` where a limit was hit.

    >>> import tmcert
    >>> result = tmcert.verify("examples/octagons-collision.json")
    >>> result.verdict
    <Verdict.COLLISION: 'collision'>

**Numbers are exact.**  Wherever a scene takes a number, these are accepted:

* ``int`` (and NumPy integers): that integer;
* ``fractions.Fraction``: that fraction;
* ``decimal.Decimal`` and ``str`` (``"0.1"``, ``"1/3"``, ``"-1.25e-3"``):
  exactly the decimal or fraction they spell, as in a scene file;
* ``float`` (and NumPy floats): **exactly its binary value**, the same rule
  as the C++ API's ``Number(double)``: ``0.1`` is
  3602879701896397/36028797018963968, not 1/10.  This holds for dicts too:
  a dict is not JSON text, and its floats are already rounded.  Write
  ``"0.1"``, ``Decimal("0.1")`` or ``Fraction(1, 10)`` for one tenth, or
  read a JSON file with :meth:`Scene.from_file` (or
  ``json.load(f, parse_float=decimal.Decimal)``) to keep its decimals.

Results carry exact values (``fractions.Fraction``, or an
:class:`AlgebraicNumber` for a contact at an irrational instant) next to a
``*_float`` view of each for people and plots (a float64 NumPy array
when NumPy is installed, else a tuple of floats; NumPy is optional): each
float is the nearest to the exact value, or NaN for a value beyond the float range (|x| >= 2**1024 -
2**970, or nonzero and at most 2**-1075), never an infinity.  Bad
input raises :class:`InputError` (a ``ValueError``) with the message the
command line prints after ``tmcert: ``; a resource limit that leaves no
honest answer raises :class:`ResourceLimit`; a run cancelled by its
progress callback raises :class:`Cancelled`, and Ctrl-C during a run
raises KeyboardInterrupt within about a tenth of a second.
"""

from __future__ import annotations

import decimal
import enum
import json
import math
import numbers
import os
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Tuple, Union

try:  # NumPy is optional: arrays in and out when it is there, tuples and lists otherwise
    import numpy as np
except ImportError:  # pragma: no cover - depends on the environment
    np = None  # type: ignore[assignment]

from . import _tmcert
from ._tmcert import __version__
from ._tmcert import (Cancelled, InputError, Keyframes, Motion, Piecewise, Pose, RationalBezier, ResourceLimit,
                      Rotation, Scene)

__all__ = [
    "AlgebraicNumber", "BatchProgress", "BatchSummary", "Body", "Cancelled", "CertificateCheck", "Check",
    "InputError", "Keyframes", "Motion", "Piecewise", "Pose", "Progress", "RationalBezier", "ResourceLimit",
    "Result", "Robot", "Rotation", "Scene", "SceneBuilder", "Stats", "UndecidedInterval", "Verdict", "Witness",
    "batch", "batch_merge", "check", "load", "scene_from_dict", "verify",
]

NumberLike = Union[int, float, Fraction, decimal.Decimal, str]
PathLike = Union[str, "os.PathLike[str]"]


# ----------------------------------------------------------------- numbers

@dataclass(frozen=True)
class AlgebraicNumber:
    """An irrational real: the only root of ``root_of`` in the open ``interval``.

    ``root_of`` lists the integer coefficients of a square-free polynomial,
    constant term first; ``interval`` is an open rational interval isolating
    the root.  ``approx`` (also ``float(x)``) is for people.
    """

    root_of: Tuple[int, ...]
    interval: Tuple[Fraction, Fraction]
    approx: float

    def __float__(self) -> float:
        return self.approx

    def __str__(self) -> str:
        coefficients = ", ".join(str(c) for c in self.root_of)
        return f"root of [{coefficients}] in ({self.interval[0]}, {self.interval[1]})"


Time = Union[Fraction, AlgebraicNumber]
"""A parameter of a result: a Fraction, or an AlgebraicNumber."""


def _time(t: Any) -> Time:
    value = t.value
    if isinstance(value, _tmcert._Rational):
        return value.fraction()
    return AlgebraicNumber(tuple(int(c) for c in value.root_of),
                           (value.lower.fraction(), value.upper.fraction()), value.approx)


def _point(p: Optional[Sequence[Any]]) -> Optional[Tuple[Fraction, Fraction, Fraction]]:
    return None if p is None else (p[0].fraction(), p[1].fraction(), p[2].fraction())


_BOOLS: Tuple[type, ...] = (bool,) if np is None else (bool, np.bool_)

FloatArray = Any
"""A float64 NumPy array when NumPy is installed, else a tuple of floats (nested for 2-d)."""


def _is_array(value: Any) -> bool:
    return np is not None and isinstance(value, np.ndarray)


def _floats(values: Iterable[Any]) -> FloatArray:
    """A float64 array (NumPy), or a tuple of floats (nested tuples stay tuples)."""
    values = list(values)
    if np is not None:
        return np.array(values, dtype=np.float64)
    return tuple(tuple(v) if isinstance(v, tuple) else float(v) for v in values)


def _point3(p: Sequence[Any]) -> Tuple[Fraction, Fraction, Fraction]:
    return (p[0].fraction(), p[1].fraction(), p[2].fraction())


def _point_float(p: Sequence[Any]) -> FloatArray:
    return _floats(c.approx for c in p)


# ----------------------------------------------------------------- results

class Verdict(str, enum.Enum):
    """A check's or a result's verdict; equal to its string ("safe", ...)."""

    SAFE = "safe"            #: certified: no common point at any parameter
    COLLISION = "collision"  #: certified by an exact witness
    UNDECIDED = "undecided"  #: neither was proven (a limit was hit)

    def __str__(self) -> str:
        return self.value


@dataclass(frozen=True, eq=False)  # NumPy fields: compare the exact ones
class Witness:
    """Where and when two bodies provably touch (world coordinates).

    ``t`` is exact (``t_float`` for people).  ``point`` is the exact common
    point (three Fractions), or None at an algebraic time or an enclosed
    pose, where ``point_box`` (three ``(lo, hi)`` Fraction pairs) holds it;
    ``point_float`` is the point (or the box's centre) as a float array.
    With a clearance, ``points`` gives a point of each body (in the check's
    order) no farther apart than it; with a tolerance, body ``displaced``
    translated by ``displacement`` touches; where both bodies have a
    tolerance and only both translations together reach, the other body
    ``displaced_other`` is translated by ``displacement_other`` too.
    """

    t: Time
    t_float: float
    features: Tuple[str, str]
    point: Optional[Tuple[Fraction, Fraction, Fraction]]
    point_box: Optional[Tuple[Tuple[Fraction, Fraction], ...]]
    point_float: FloatArray
    points: Optional[Tuple[Tuple[Fraction, Fraction, Fraction], Tuple[Fraction, Fraction, Fraction]]]
    points_float: Optional[FloatArray]
    displacement: Optional[Tuple[Fraction, Fraction, Fraction]]
    displacement_float: Optional[FloatArray]
    displaced: Optional[str]
    displacement_other: Optional[Tuple[Fraction, Fraction, Fraction]] = None
    displacement_other_float: Optional[FloatArray] = None
    displaced_other: Optional[str] = None

    @staticmethod
    def _from(w: Any) -> "Witness":
        box = None if w.point_box is None else tuple((lo.fraction(), hi.fraction()) for lo, hi in w.point_box)
        points = None if w.points is None else (_point3(w.points[0]), _point3(w.points[1]))
        return Witness(
            t=_time(w.t), t_float=float(w.t.value.approx), features=(w.features[0], w.features[1]),
            point=_point(w.point), point_box=box, point_float=_floats(w.point_approx),
            points=points, points_float=None if w.points is None else _floats(tuple(c.approx for c in p) for p in w.points),
            displacement=_point(w.displacement),
            displacement_float=None if w.displacement is None else _point_float(w.displacement),
            displaced=w.displaced or None,
            displacement_other=_point(w.displacement_other),
            displacement_other_float=None if w.displacement_other is None else _point_float(w.displacement_other),
            displaced_other=w.displaced_other or None)


@dataclass(frozen=True)
class UndecidedInterval:
    """A parameter interval not cleared, and why: "epsilon", "depth", "limit",
    "after_undecided" (cleared only of contact beginning there, after a part
    not cleared, with the bodies not proven apart at its start) or
    "enlarged_model" (a URDF cylinder's or sphere's polyhedron touches there,
    and no contact of the true shape was proven)."""

    t: Tuple[Fraction, Fraction]
    t_float: Tuple[float, float]
    reason: str


@dataclass(frozen=True)
class Stats:
    """The work a check took (``seconds`` is wall time, not deterministic)."""

    nodes: int
    max_depth: int
    predicate_calls: int
    exact_fallbacks: int
    stops: int
    exact_pieces: int
    exact_undecided: int
    prefiltered: bool
    seconds: float


@dataclass(frozen=True, eq=False)  # holds a Witness
class Check:
    """The result of one body pair.

    ``first_contact`` brackets the earliest possible contact (exact;
    ``first_contact_float`` for people): everything before its lower end is
    certified free of contact; None when the check is safe.  With
    ``first_contact_exact`` the witness's time is the first contact.
    ``witness`` is set iff the verdict is collision.  ``epsilon`` is the
    termination tolerance this check ran with: the one given, or else its
    own default, 1/1000 of the box of its two bodies' motion; with
    ``refined`` (no epsilon given, or ``"auto"``) the smallest one its
    re-searches of undecided parts used.

    The check's ``interval`` is partitioned into the parts certified free of
    contact (everything not listed), ``undecided``, and with a witness its
    time and after it ``not_searched`` (the witness time and the interval's
    end: nothing after the witness was searched); nothing else.
    """

    bodies: Tuple[str, str]
    verdict: Verdict
    epsilon: Fraction
    epsilon_float: float
    refined: bool
    clearance: Fraction
    clearance_violated: bool
    enlarged_model: bool
    first_contact: Optional[Tuple[Time, Time]]
    first_contact_float: Optional[Tuple[float, float]]
    first_contact_exact: bool
    witness: Optional[Witness]
    undecided: Tuple[UndecidedInterval, ...]
    stats: Stats
    interval: Tuple[Fraction, Fraction]
    not_searched: Optional[Tuple[Time, Time]]
    not_searched_float: Optional[Tuple[float, float]]

    @staticmethod
    def _from(c: Any) -> "Check":
        fc = c.first_contact
        ns = c.not_searched
        s = c.stats
        return Check(
            bodies=(c.bodies[0], c.bodies[1]), verdict=Verdict(c.verdict),
            epsilon=c.epsilon.fraction(), epsilon_float=c.epsilon.approx, refined=c.refined, clearance=c.clearance.fraction(),
            clearance_violated=c.clearance_violated, enlarged_model=c.enlarged_model,
            first_contact=None if fc is None else (_time(fc[0]), _time(fc[1])),
            first_contact_float=None if fc is None else (fc[0].value.approx, fc[1].value.approx),
            first_contact_exact=c.first_contact_exact,
            witness=None if c.witness is None else Witness._from(c.witness),
            undecided=tuple(UndecidedInterval((u.t0.fraction(), u.t1.fraction()), (u.t0.approx, u.t1.approx),
                                              u.reason) for u in c.undecided),
            stats=Stats(s.nodes, s.max_depth, s.predicate_calls, s.exact_fallbacks, s.stops, s.exact_pieces,
                        s.exact_undecided, s.prefiltered, s.seconds),
            interval=(c.interval[0].fraction(), c.interval[1].fraction()),
            not_searched=None if ns is None else (_time(ns[0]), _time(ns[1])),
            not_searched_float=None if ns is None else (ns[0].value.approx, ns[1].value.approx))


class Result:
    """What :func:`verify` returns: a verdict per check, with its proof data.

    ``str(result)`` is the command line's human summary; :meth:`to_json` is
    the tmcert-result/1 document ``tmcert verify --json`` prints.
    """

    def __init__(self, raw: Any) -> None:
        self._raw = raw
        self._checks: Optional[Tuple[Check, ...]] = None

    @property
    def verdict(self) -> Verdict:
        """Collision if any check is, else undecided if any check is, else safe."""
        return Verdict(self._raw.verdict)

    @property
    def kernel(self) -> str:
        """"filtered", "exact" or "fast"."""
        return str(self._raw.kernel)

    @property
    def certified(self) -> bool:
        """False only for the fast kernel, whose verdicts are not proofs."""
        return bool(self._raw.certified)

    @property
    def epsilon(self) -> Fraction:
        """The termination tolerance given (scene or ``epsilon=``), or else the
        largest of the checks' own (``Check.epsilon``: their defaults, or
        with refinement the smallest each used), exact."""
        return self._raw.epsilon.fraction()

    @property
    def epsilon_float(self) -> float:
        return float(self._raw.epsilon.approx)

    @property
    def checks(self) -> Tuple[Check, ...]:
        """The checks in the scene's order."""
        if self._checks is None:
            self._checks = tuple(Check._from(c) for c in self._raw.checks)
        return self._checks

    def to_json(self) -> str:
        """The tmcert-result/1 document (as ``tmcert verify --json``, up to "seconds")."""
        return str(self._raw.to_json())

    def to_dict(self) -> dict:
        """:meth:`to_json` parsed (exact numbers stay strings)."""
        return json.loads(self.to_json())

    def summary(self) -> str:
        """The human summary ``tmcert verify`` prints."""
        return str(self._raw.summary())

    def certificate(self) -> str:
        """The tmcert-certificate/2 document; needs ``verify(..., certificate=True)``."""
        return str(self._raw.certificate())

    def write_certificate(self, path: PathLike) -> None:
        """Writes :meth:`certificate` to ``path``.

        InputError, before anything is written, when ``path`` is empty, a
        directory, cannot be written or is one of the scene's files;
        ResourceLimit when the write fails (a full disk), leaving no partial
        file.
        """
        self._raw.write_certificate(os.fspath(path))

    @property
    def notes(self) -> Tuple[str, ...]:
        """What the reader did to data from real pipelines (docs/scene-format.md,
        "Data from real pipelines"): mesh faces not exactly planar split into
        fans, zero-area faces read as segments; the result document's "notes"."""
        return tuple(self._raw.notes)

    @property
    def warnings(self) -> Tuple[str, ...]:
        """Input read in a way that may not be meant (an rpy angle above 2 pi read
        as radians); the result document's "warnings"."""
        return tuple(self._raw.warnings)

    def report_html(self) -> str:
        """The visual report (``tmcert verify --report``): one self-contained HTML page."""
        return str(self._raw.report_html())

    def write_report(self, path: PathLike) -> None:
        """Writes :meth:`report_html` to ``path``, with the rules of :meth:`write_certificate`."""
        self._raw.write_report(os.fspath(path))

    def __str__(self) -> str:
        return self.summary()

    def __repr__(self) -> str:
        counts = {v: sum(1 for c in self._raw.checks if c.verdict == v.value) for v in Verdict}
        detail = ", ".join(f"{n} {v.value}" for v, n in counts.items() if n)
        return f"<tmcert.Result {self.verdict.value} ({detail}), kernel {self.kernel}>"


@dataclass(frozen=True)
class CertificateCheck:
    """What :func:`check` returns; true when every claim of the certificate is proven.

    ``message`` names the failing claim when not ``ok``; ``proven`` says per
    check what was proven when ``ok``.
    """

    ok: bool
    message: str
    proven: Tuple[str, ...]

    def __bool__(self) -> bool:
        return self.ok


# ----------------------------------------------------------------- scenes

_INT64 = 2 ** 63


def _json_value(value: Any, path: str) -> Any:
    """A dict scene's value as JSON, numbers as their exact text."""
    if value is None or isinstance(value, _BOOLS):
        return None if value is None else bool(value)
    if isinstance(value, str):
        return value
    if isinstance(value, numbers.Integral):
        v = int(value)
        return v if -_INT64 < v < _INT64 else _tmcert._int_text(v)
    if isinstance(value, numbers.Rational):
        return f"{_tmcert._int_text(int(value.numerator))}/{_tmcert._int_text(int(value.denominator))}"
    if isinstance(value, decimal.Decimal):
        return str(value)
    if isinstance(value, numbers.Real):
        f = float(value)
        if not math.isfinite(f):
            return str(f)  # "nan", "inf": the reader names the field
        n, d = f.as_integer_ratio()
        return f"{_tmcert._int_text(n)}/{_tmcert._int_text(d)}"
    if isinstance(value, Mapping):
        out = {}
        for key, item in value.items():
            if not isinstance(key, str):
                raise InputError(f"<dict>: {path or 'document'}: key {key!r} is not a string")
            out[key] = _json_value(item, f"{path}.{key}" if path else key)
        return out
    if isinstance(value, (list, tuple)) or _is_array(value):
        return [_json_value(item, f"{path}[{i}]") for i, item in enumerate(value)]
    raise InputError(f"<dict>: {path or 'document'}: cannot use a {type(value).__name__} in a scene")


def scene_from_dict(document: Mapping[str, Any], base_dir: Optional[PathLike] = None,
                    source: str = "<dict>") -> Scene:
    """A scene from the tmcert-scene/1 document as Python objects.

    Numbers may be int, Fraction, Decimal, str or float (a float is its
    exact binary value; see the module's docstring); arrays may be lists,
    tuples or NumPy arrays.  Relative ``mesh``, ``urdf`` and ``srdf`` files
    and ``package_paths`` folders are taken relative to ``base_dir``
    (default: the current directory).  Messages
    name ``source`` and the field, as for a file.
    """
    doc = _json_value(document, "")
    if base_dir is not None and isinstance(doc, dict):
        base = os.fspath(base_dir)
        paths = doc.get("package_paths")
        if isinstance(paths, list):
            doc["package_paths"] = [os.path.join(base, p) if isinstance(p, str) and not os.path.isabs(p) else p
                                    for p in paths]
        for key, field in (("bodies", "mesh"), ("robots", "urdf"), ("robots", "srdf")):
            items = doc.get(key)
            if isinstance(items, list):
                for item in items:
                    if isinstance(item, dict) and isinstance(item.get(field), str) \
                            and not os.path.isabs(item[field]):
                        item[field] = os.path.join(base, item[field])
    return Scene.from_json(json.dumps(doc), source)


def load(scene: "SceneLike") -> Scene:
    """A Scene from a Scene, a SceneBuilder, a dict (:func:`scene_from_dict`) or a file path."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, SceneBuilder):
        return scene.build()
    if isinstance(scene, Mapping):
        return scene_from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_file(os.fspath(scene))
    raise TypeError(f"expected a Scene, SceneBuilder, dict or file path, got {type(scene).__name__}")


Scene.from_dict = staticmethod(scene_from_dict)  # type: ignore[assignment]  # declared in _tmcert.pyi


def _vertices(vertices: Any, what: str) -> Tuple[Any, Optional[list]]:
    """(float64 (n, 3) array, None) or (None, exact points) for ``vertices``."""
    if _is_array(vertices) and vertices.dtype.kind == "f":
        array = np.ascontiguousarray(vertices, dtype=np.float64)
        if array.ndim != 2 or array.shape[1] != 3:
            raise InputError(f"{what}: expected an (n, 3) array of points, got shape {array.shape}")
        return array, None
    rows = vertices.tolist() if _is_array(vertices) else list(vertices)
    points = []
    for row in rows:
        if isinstance(row, (str, bytes)) or not hasattr(row, "__len__") or len(row) != 3:
            shape = f"({len(rows)}, {len(row) if hasattr(row, '__len__') and not isinstance(row, (str, bytes)) else '?'})"
            raise InputError(f"{what}: expected an (n, 3) array of points, got shape {shape}")
        points.append(tuple(row))
    return None, points


def _faces(faces: Any, what: str) -> list:
    """Faces as lists of vertex indices (an (m, k) integer array, or ragged lists)."""
    if _is_array(faces):
        if faces.dtype.kind not in "iu" or faces.ndim != 2:
            raise InputError(f"{what}: expected an (m, k) integer array of vertex indices, got "
                             f"{faces.dtype} of shape {faces.shape}")
        faces = faces.tolist()
    out = []
    for i, face in enumerate(faces):
        row = []
        for j, index in enumerate(face):
            if isinstance(index, _BOOLS) or not isinstance(index, numbers.Integral):
                raise InputError(f"{what}[{i}][{j}]: a vertex index is an integer, got {index!r}")
            if index < 0:
                raise InputError(f"{what}[{i}][{j}]: negative vertex index {int(index)}")
            row.append(int(index))
        out.append(row)
    return out


def _flag(value: Any, what: str) -> bool:
    if not isinstance(value, _BOOLS):
        raise TypeError(f"{what}: expected True or False, got {value!r}")
    return bool(value)


class Body:
    """One body of a :class:`SceneBuilder`; every method adds to it and returns it.

    Vertex arrays are (n, 3): float64 arrays are taken exactly as their
    binary values (fast path); anything else (lists, object arrays of
    Fractions, integer arrays) number by number with the package's rule.
    Polygons, triangles and mesh faces are numbered in the order added.
    """

    def __init__(self, raw: Any) -> None:
        self._raw = raw

    @property
    def name(self) -> str:
        return str(self._raw.name)

    def polygons(self, vertices: Any, faces: Any) -> "Body":
        """Polygons: ``faces`` an (m, k) integer array or lists of indices into ``vertices`` (planar, simple)."""
        xyz, exact = _vertices(vertices, f"{self.name}: vertices")
        face_list = _faces(faces, f"{self.name}: faces")
        if xyz is not None:
            indices = np.array([i for f in face_list for i in f], dtype=np.uintp)
            sizes = np.array([len(f) for f in face_list], dtype=np.uintp)
            self._raw.polygons_xyz(xyz.ravel(), indices, sizes)
        else:
            self._raw.polygons_exact(exact, face_list)
        return self

    def polygon(self, vertices: Any) -> "Body":
        """One polygon, its (k, 3) vertices in order."""
        n = len(vertices)
        return self.polygons(vertices, [list(range(n))])

    def triangles(self, vertices: Any, triangles: Any) -> "Body":
        """Triangles: ``triangles`` an (m, 3) integer array of indices into ``vertices``."""
        xyz, exact = _vertices(vertices, f"{self.name}: vertices")
        face_list = _faces(triangles, f"{self.name}: triangles")
        if any(len(f) != 3 for f in face_list):
            raise InputError(f"{self.name}: triangles: expected three vertex indices per triangle")
        indices = [i for f in face_list for i in f]
        if xyz is not None:
            self._raw.triangles_xyz(xyz.ravel(), np.array(indices, dtype=np.uintp))
        else:
            self._raw.triangles_exact(exact, indices)
        return self

    def segments(self, segments: Any) -> "Body":
        """Segments: an (m, 2, 3) array of endpoint pairs (distinct endpoints)."""
        if len(segments) == 0:
            return self
        if _is_array(segments) and segments.dtype.kind == "f":
            array = np.ascontiguousarray(segments, dtype=np.float64)
            if array.ndim != 3 or array.shape[1:] != (2, 3):
                raise InputError(f"{self.name}: segments: expected an (m, 2, 3) array, got shape {array.shape}")
            self._raw.segments_xyz(array.ravel())
            return self
        rows = segments.tolist() if _is_array(segments) else list(segments)
        for row in rows:
            if len(row) != 2 or any(isinstance(p, (str, bytes)) or len(p) != 3 for p in row):
                raise InputError(f"{self.name}: segments: expected an (m, 2, 3) array of endpoint pairs")
        for a, b in rows:
            self._raw.segment(tuple(a), tuple(b))
        return self

    def points(self, points: Any) -> "Body":
        """Isolated points: an (n, 3) array."""
        xyz, exact = _vertices(points, f"{self.name}: points")
        if xyz is not None:
            self._raw.points_xyz(xyz.ravel())
        else:
            for p in exact or []:
                self._raw.point(p)
        return self

    def mesh(self, path: PathLike) -> "Body":
        """A mesh file (OFF, OBJ or STL, read exactly), one per body."""
        self._raw.mesh(os.fspath(path))
        return self

    def solid(self, value: bool = True) -> "Body":
        """The inside counts as part of the body (its polygons must form closed shells)."""
        self._raw.solid(_flag(value, f"{self.name}: solid"))
        return self

    def mass(self, points: Any, weights: Iterable[NumberLike]) -> "Body":
        """The metric's mass points ((n, 3), not coplanar) and positive weights."""
        _, exact = _vertices(points.tolist() if _is_array(points) else points, f"{self.name}: mass points")
        self._raw.mass(exact, list(weights))
        return self

    def tolerance(self, r: NumberLike) -> "Body":
        """Every pose within ``r`` of the nominal one (body metric) is possible."""
        self._raw.tolerance(r)
        return self

    def motion(self, motion: Union[Motion, RationalBezier, Keyframes, Piecewise]) -> "Body":
        """The body's motion (default: fixed at the identity); replaces an earlier one."""
        self._raw.motion(motion)
        return self


class Robot:
    """A robot from a URDF file moving in joint space (:meth:`SceneBuilder.add_robot`)."""

    def __init__(self, raw: Any) -> None:
        self._raw = raw

    @property
    def name(self) -> str:
        return str(self._raw.name)

    def base(self, pose: Pose) -> "Robot":
        """Where the root link is placed (default: the identity)."""
        self._raw.base(pose)
        return self

    def path(self, joints: Sequence[str], times: Iterable[NumberLike], positions: Any) -> "Robot":
        """Linear in joint space (unless :meth:`interpolation` says otherwise): ``positions`` one row per time, columns in the order of ``joints``."""
        rows = [list(row) for row in positions]
        self._raw.path(list(joints), list(times), rows)
        return self

    def interpolation(self, how: str, velocities: Any = None, accelerations: Any = None) -> "Robot":
        """The path as a controller executes a time-parameterised trajectory:
        ``"cubic"`` splines in time with ``velocities`` (dq/dt), ``"quintic"``
        with also ``accelerations``, one row per time like the positions;
        ``"linear"`` (the default) takes neither.  Limits hold on the whole
        polynomial."""
        vel = [list(row) for row in velocities] if velocities is not None else []
        acc = [list(row) for row in accelerations] if accelerations is not None else []
        self._raw.interpolation(str(how), vel, acc)
        return self

    def self_collision(self, value: bool = True) -> "Robot":
        """Check pairs of its own links (not parent and child, not allowed)."""
        self._raw.self_collision(_flag(value, f"{self.name}: self_collision"))
        return self

    def allow(self, link_a: str, link_b: str) -> "Robot":
        """A pair of links never checked against each other."""
        self._raw.allow(link_a, link_b)
        return self

    def srdf(self, file: PathLike) -> "Robot":
        """Every ``<disable_collisions link1 link2>`` of a MoveIt SRDF file as allowed pairs."""
        self._raw.srdf(os.fspath(file))
        return self


class SceneBuilder:
    """Builds a scene in code: bodies from NumPy arrays, motions, robots, checks.

        b = tmcert.SceneBuilder()
        b.add_body("table").triangles(table_xyz, table_triangles)
        b.add_body("box").triangles(box_xyz, box_triangles).motion(
            tmcert.Motion.translation((0, 0, 2), (0, 0, "-1/2")))
        scene = b.build()   # InputError naming the field, as for a file

    Nothing is checked until :meth:`build`; messages then name the field as
    in a tmcert-scene/1 document ("SceneBuilder: bodies[1].polygons[3]: ...").
    """

    def __init__(self) -> None:
        self._raw = _tmcert._SceneBuilder()

    def add_body(self, name: str) -> Body:
        """A new body with a unique, non-empty name."""
        return Body(self._raw.add_body(name))

    def add_robot(self, name: str, urdf: PathLike) -> Robot:
        """A robot from ``urdf``; its links' bodies are named "<name>/<link>"."""
        return Robot(self._raw.add_robot(name, os.fspath(urdf)))

    def check(self, body_a: str, body_b: str, clearance: Optional[NumberLike] = None) -> "SceneBuilder":
        """A pair to check (default: every moving body against every other body)."""
        if clearance is None:
            self._raw.check(body_a, body_b)
        else:
            self._raw.check_with_clearance(body_a, body_b, clearance)
        return self

    def epsilon(self, e: NumberLike) -> "SceneBuilder":
        """Termination tolerance, a length (default: 1/1000 of the scene diagonal)."""
        self._raw.epsilon(e)
        return self

    def max_depth(self, depth: int) -> "SceneBuilder":
        """Subdivision depth limit, 1 to 200 (default 40)."""
        self._raw.max_depth(_bounded(depth, "max_depth", 1, 200))
        return self

    def clearance(self, d: NumberLike) -> "SceneBuilder":
        """Minimum separation of every check without its own (default 0)."""
        self._raw.clearance(d)
        return self

    def package_path(self, folder: PathLike) -> "SceneBuilder":
        """A folder searched for ``package://NAME/...`` mesh URIs (before ROS_PACKAGE_PATH)."""
        self._raw.package_path(os.fspath(folder))
        return self

    def build(self) -> Scene:
        """Validates everything and returns the scene (InputError naming the field)."""
        return self._raw.build()

    def to_json(self) -> str:
        """The scene as a tmcert-scene/1 document, numbers as exact strings."""
        return str(self._raw.to_json())


SceneLike = Union[Scene, SceneBuilder, Mapping[str, Any], str, "os.PathLike[str]"]


# ----------------------------------------------------------------- verify

@dataclass(frozen=True)
class Progress:
    """What a ``progress`` callback of :func:`verify` is given.

    ``fraction``: the share of the checks' work done (each check one part;
    within a running check, the share of its parameter interval decided),
    below 1 while a check is left, 1 once every check is done (and in the
    last call).  ``activity``
    says what the run does now ("checking a x b: preparing body ..."), for
    people; its wording is not an interface.
    """

    fraction: float
    checks_done: int
    checks: int
    activity: str
    seconds: float


@dataclass(frozen=True)
class BatchProgress:
    """What a ``progress`` callback of :func:`batch` is given (the requests file is streamed)."""

    requests_read: int
    requests_written: int
    activity: str
    seconds: float


ProgressCallback = Callable[[Any], Optional[bool]]


def _progress_hook(progress: Optional[ProgressCallback], make: Callable[[Any], Any]) -> Optional[Callable[[Any], Any]]:
    if progress is None:
        return None
    if not callable(progress):
        raise TypeError(f"progress: expected a callable or None, got {progress!r}")
    callback = progress
    return lambda raw: callback(make(raw))


def verify(scene: SceneLike, epsilon: Optional[NumberLike] = None, kernel: str = "filtered",
           max_depth: Optional[int] = None, threads: int = 1, time_limit: Optional[float] = None,
           all_pairs: bool = False, certificate: bool = False, progress: Optional[ProgressCallback] = None,
           progress_interval: float = 0.5) -> Result:
    """Verifies every check of ``scene`` (as ``tmcert verify``).

    scene: a Scene, SceneBuilder, dict (tmcert-scene/1) or file path.
    epsilon: termination tolerance, a positive length, fixed (default: the
        scene's, else each check's default refined: undecided parts searched
        again at epsilon/10, ... down to epsilon/10^6, within time_limit or
        30 s per check); "auto": refined even when the scene gives one.
    kernel: "filtered" (certified, default), "exact" (certified, slow) or
        "fast" (plain doubles: NOT certified, and the result says so).
    max_depth: subdivision depth limit, 1 to 200 (default: the scene's).
    threads: worker threads, 1 to 256 (the result does not depend on it).
    time_limit: seconds per check; past it the rest of a check is undecided
        (default: 30 s per check when refined, the first search included;
        none with a given epsilon).
    all_pairs: carry every feature pair instead of the bounding volumes.
    certificate: keep what :meth:`Result.certificate` needs.
    progress: called with a :class:`Progress` about every
        ``progress_interval`` seconds, in the calling thread, and once more
        at the end (fraction 1); returning ``False`` cancels the run
        (:class:`Cancelled` is raised), an exception it raises cancels it
        and is raised again.

    Runs without holding the GIL, on a thread of its own.  Ctrl-C
    (KeyboardInterrupt) cancels it within about a tenth of a second plus
    one subdivision node's work, and raises KeyboardInterrupt: never a
    result of a cancelled run.  Raises InputError for bad options or a
    scene that cannot be verified, ResourceLimit, MemoryError.
    """
    hook = _progress_hook(progress, lambda r: Progress(r.fraction, r.checks_done, r.checks, r.activity, r.seconds))
    return Result(_tmcert.verify(load(scene), str(kernel), epsilon,
                                 None if max_depth is None else _bounded(max_depth, "max_depth", 1, 200),
                                 _bounded(threads, "threads", 1, 256),
                                 None if time_limit is None else float(time_limit), bool(all_pairs),
                                 bool(certificate), hook, float(progress_interval)))


@dataclass(frozen=True)
class BatchSummary:
    """What :func:`batch` returns.

    ``requests`` counts every request of the file (in every shard);
    ``safe``, ``collision``, ``undecided`` and ``errors`` (bad lines) this
    shard's; ``exit_code`` is ``tmcert batch``'s (1 a collision, else 2 an
    undecided or bad request, else 0).  ``results`` holds the result lines
    as dicts when no ``output`` file was given, else None.
    """

    requests: int
    safe: int
    collision: int
    undecided: int
    errors: int
    exit_code: int
    results: Optional[Tuple[dict, ...]]


def batch(requests: Union[PathLike, Iterable[Union[Mapping[str, Any], str]]], scene: Optional[PathLike] = None,
          output: Optional[PathLike] = None, shard: Optional[str] = None, epsilon: Optional[NumberLike] = None,
          kernel: str = "filtered", max_depth: Optional[int] = None, time_limit: Optional[float] = None,
          threads: int = 1, stats: bool = False, progress: Optional[ProgressCallback] = None,
          progress_interval: float = 0.5) -> BatchSummary:
    """Certifies many motions against one environment (as ``tmcert batch``).

    requests: a JSON Lines file, or an iterable of requests (dicts, or JSON
        text lines); docs/scene-format.md, "Batch runs".  Mesh files of
        inline bodies are relative to the file's directory (for dicts: the
        current directory; give JSON text lines absolute file names).
    scene: the environment scene file (None: the first request line is the
        environment document).
    output: the results file; None: the results come back as
        ``BatchSummary.results``.
    shard: "i/n" for the requests whose index is i modulo n (an array job's
        share; merge the shards' files with :func:`batch_merge`).
    The other options are :func:`verify`'s (``threads`` runs requests in
    parallel; ``stats`` adds each check's stats).  ``progress`` gets a
    :class:`BatchProgress`; False cancels: no further line is written and
    :class:`Cancelled` is raised (KeyboardInterrupt likewise).
    """
    import tempfile

    # An empty file name is refused, never taken as absent (None is absent).
    _named_file(scene, "scene")
    _named_file(output, "output")
    with tempfile.TemporaryDirectory(prefix="tmcert-batch-") as work:
        if isinstance(requests, (str, os.PathLike)):
            requests_file = os.fspath(requests)
        else:
            requests_file = os.path.join(work, "requests.jsonl")
            with open(requests_file, "w", encoding="utf-8") as f:
                for i, line in enumerate(requests):
                    text = line if isinstance(line, str) else json.dumps(_absolute_meshes(
                        _json_value(line, f"requests[{i}]")))
                    if "\n" in text.strip():
                        raise InputError(f"requests[{i}]: a request is one line of JSON")
                    f.write(text.strip() + "\n")
        out_file = os.path.join(work, "results.jsonl") if output is None else os.fspath(output)
        hook = _progress_hook(progress, lambda r: BatchProgress(r.requests_read, r.requests_written, r.activity,
                                                                r.seconds))
        raw = _tmcert.batch(requests_file, "" if scene is None else os.fspath(scene), out_file,
                            "" if shard is None else str(shard), str(kernel), epsilon,
                            None if max_depth is None else _bounded(max_depth, "max_depth", 1, 200),
                            None if time_limit is None else float(time_limit), _bounded(threads, "threads", 1, 256),
                            bool(stats), hook, float(progress_interval))
        results = None
        if output is None:
            with open(out_file, encoding="utf-8") as f:
                results = tuple(json.loads(line) for line in f if line.strip())
    return BatchSummary(raw.requests, raw.safe, raw.collision, raw.undecided, raw.errors, raw.exit_code, results)


def _absolute_meshes(doc: Any) -> Any:
    """A request or environment document with its relative mesh and URDF files made absolute
    (relative to the current directory)."""
    if isinstance(doc, dict):
        bodies = list(doc.get("bodies", [])) if isinstance(doc.get("bodies"), list) else []
        if isinstance(doc.get("body"), dict):
            bodies.append(doc["body"])
        for body in bodies:
            if isinstance(body, dict) and isinstance(body.get("mesh"), str) and not os.path.isabs(body["mesh"]):
                body["mesh"] = os.path.abspath(body["mesh"])
        for robot in doc.get("robots", []) if isinstance(doc.get("robots"), list) else []:
            if isinstance(robot, dict) and isinstance(robot.get("urdf"), str) and not os.path.isabs(robot["urdf"]):
                robot["urdf"] = os.path.abspath(robot["urdf"])
    return doc


def batch_merge(shards: Iterable[PathLike], output: Optional[PathLike] = None) -> Optional[str]:
    """Merges the result files of a batch run's shards (as ``tmcert batch-merge``).

    Writes the bytes of the unsharded run to ``output``, or returns them as
    a str when ``output`` is None.  InputError when the files do not make up
    one run.
    """
    import tempfile

    files = [os.fspath(f) for f in shards]
    _named_file(output, "output")
    if output is not None:
        _tmcert.batch_merge(files, os.fspath(output))
        return None
    with tempfile.TemporaryDirectory(prefix="tmcert-merge-") as work:
        out_file = os.path.join(work, "merged.jsonl")
        _tmcert.batch_merge(files, out_file)
        with open(out_file, encoding="utf-8") as f:
            return f.read()


def _named_file(path: Optional[PathLike], what: str) -> None:
    """InputError for a file option given as an empty name (docs/scene-format.md "Output paths")."""
    if path is not None and os.fspath(path) == "":
        raise InputError(f"{what}: the file name is empty")


def _bounded(value: Any, what: str, low: int, high: int) -> int:
    """An integer option in [low, high], with the library's message otherwise."""
    if isinstance(value, _BOOLS) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{what}: expected an integer, got {value!r}")
    if not low <= int(value) <= high:
        raise InputError(f"{what}: must be between {low} and {high}, got {int(value)}")
    return int(value)


def check(certificate: Union[PathLike, Result, Mapping[str, Any]], scene: SceneLike) -> CertificateCheck:
    """Re-verifies a certificate against ``scene`` in exact arithmetic (as ``tmcert check``).

    certificate: a file path, a Result of ``verify(..., certificate=True)``,
        or the tmcert-certificate/2 document as a dict.
    A malformed certificate raises InputError; one whose claims fail gives
    a false CertificateCheck whose ``message`` names the failing claim.
    """
    s = load(scene)
    if isinstance(certificate, Result):
        raw = _tmcert.check_certificate_text(s, certificate.certificate(), "<result>")
    elif isinstance(certificate, Mapping):
        raw = _tmcert.check_certificate_text(s, json.dumps(certificate), "<dict>")
    else:
        raw = _tmcert.check_certificate(s, os.fspath(certificate))
    return CertificateCheck(bool(raw.ok), str(raw.message), tuple(raw.proven))
