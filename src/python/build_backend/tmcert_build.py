"""The build backend of the Python package tmcert (PEP 517), standard library only.

``pip install .`` from the repository root builds the extension module
``tmcert._tmcert`` with CMake for the interpreter that runs pip (its
``sys.executable`` is CMake's ``Python3_EXECUTABLE``: its headers, its
extension suffix) and installs it with the pure-Python files of
``src/python/tmcert/`` as one wheel.  The backend needs nothing that is not
in Python's standard library, so pip installs it offline, into any virtual
environment, with or without build isolation.  What the build needs is
what the rest of tmcert needs (scripts/deps.sh): CMake, a C++20 compiler,
CGAL, Eigen, GMP, MPFR, Arb/FLINT, urdfdom, nlohmann-json, CLI11,
pybind11 and the interpreter's development headers (Debian python3-dev).

Configuration (``pip install . --config-settings KEY=VALUE`` or the
environment):

* ``build-dir`` / ``TMCERT_BUILD_DIR``: the CMake build folder (default:
  ``build-python-<interpreter tag>`` in the source tree, kept between
  builds, so a second install only relinks what changed).  A build folder
  configured for another interpreter (another extension suffix) is refused.
* ``jobs`` / ``CMAKE_BUILD_PARALLEL_LEVEL``: parallel compile jobs (default:
  the number of CPUs).
* ccache, when it is on the PATH, caches the compilation.

The wheel holds ``tmcert/`` (``__init__.py``, ``py.typed``, the stubs
``_tmcert.pyi`` and the extension module) and its ``dist-info``; NumPy is
optional (the extra ``numpy``).
"""

from __future__ import annotations

import base64
import csv
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import zipfile
from pathlib import Path
from typing import Dict, List, Optional

ROOT = Path(__file__).resolve().parents[3]
NAME = "tmcert"
SUMMARY = "Certified collision checks of moving polyhedra (toleranced motions, exact witnesses)"


def _version() -> str:
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*tmcert\s+VERSION\s+([0-9.]+)", text)
    if not match:
        raise RuntimeError("tmcert_build: no project(tmcert VERSION ...) in CMakeLists.txt")
    return match.group(1)


def _tag() -> str:
    """The wheel tag of the running interpreter: e.g. cp311-cp311-linux_x86_64."""
    impl = {"cpython": "cp", "pypy": "pp"}.get(sys.implementation.name, sys.implementation.name)
    interpreter = f"{impl}{sys.version_info.major}{sys.version_info.minor}"
    soabi = sysconfig.get_config_var("SOABI") or ""
    match = re.match(r"cpython-(\d+)(\w*)", soabi)
    abi = f"cp{match.group(1)}{match.group(2)}" if match else interpreter
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{interpreter}-{abi}-{platform}"


def _metadata() -> str:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    return "\n".join([
        "Metadata-Version: 2.1",
        f"Name: {NAME}",
        f"Version: {_version()}",
        f"Summary: {SUMMARY}",
        "Requires-Python: >=3.9",
        "Provides-Extra: numpy",
        "Requires-Dist: numpy; extra == \"numpy\"",
        "Description-Content-Type: text/markdown",
        "",
        readme,
    ])


def _setting(config_settings: Optional[Dict[str, str]], key: str, env: str) -> Optional[str]:
    if config_settings and config_settings.get(key):
        return str(config_settings[key])
    return os.environ.get(env) or None


def _run(command: List[str], log: List[str]) -> None:
    log.append("$ " + " ".join(command))
    print("tmcert_build: " + " ".join(command), file=sys.stderr, flush=True)
    process = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    log.append(process.stdout)
    if process.returncode != 0:
        sys.stderr.write(process.stdout[-20000:])
        raise RuntimeError(f"tmcert_build: {command[0]} failed (exit {process.returncode}); its output is above")


def _cached(build: Path, key: str) -> Optional[str]:
    cache = build / "CMakeCache.txt"
    if not cache.is_file():
        return None
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if line.startswith(key + ":"):
            return line.split("=", 1)[1]
    return None


def _same_interpreter(other: str) -> bool:
    """Does the interpreter `other` load the same extension modules as this one?"""
    if os.path.realpath(other) == os.path.realpath(sys.executable):
        return True
    probe = "import sys, sysconfig; print(sysconfig.get_config_var('EXT_SUFFIX'), sys.version_info[:2])"
    try:
        theirs = subprocess.run([other, "-c", probe], capture_output=True, text=True, timeout=60).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return False
    return theirs == f"{sysconfig.get_config_var('EXT_SUFFIX')} {sys.version_info[:2]}"


def _build_extension(config_settings: Optional[Dict[str, str]]) -> Path:
    """Configures and builds the target _tmcert; returns the folder of the package it built."""
    if shutil.which("cmake") is None:
        raise RuntimeError("tmcert_build: cmake is not on the PATH (Debian: bash scripts/deps.sh installs it)")
    given = _setting(config_settings, "build-dir", "TMCERT_BUILD_DIR")
    # Default: beside the usual build folder, at the same depth, so that
    # ccache (whose base_dir makes paths relative) finds the objects of a
    # build of the tree made with the same compiler flags.
    build = Path(given).resolve() if given else ROOT / f"build-python-{_tag()}"
    log: List[str] = []
    cached_python = _cached(build, "Python3_EXECUTABLE")
    if cached_python and not _same_interpreter(cached_python):
        raise RuntimeError(f"tmcert_build: {build} is configured for another interpreter ({cached_python}); "
                           f"give another build-dir for {sys.executable}")
    generated = any((build / name).is_file() for name in ("Makefile", "build.ninja"))
    if cached_python is None or not generated:  # not configured yet (or a configuration that failed)
        command = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                   "-DTMCERT_WITH_OMPL=OFF", "-DTMCERT_WITH_PYTHON=ON", "-DTMCERT_BUILD_BENCHMARKS=OFF",
                   f"-DPython3_EXECUTABLE={sys.executable}"]
        if shutil.which("ccache"):
            command.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        _run(command, log)
    jobs = _setting(config_settings, "jobs", "CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 2)
    _run(["cmake", "--build", str(build), "--target", "_tmcert", "-j", jobs], log)
    package = build / "python" / "tmcert"
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not (package / f"_tmcert{suffix}").is_file():
        raise RuntimeError(f"tmcert_build: the build made no {package / ('_tmcert' + suffix)} "
                           "(is pybind11 installed? Debian pybind11-dev python3-dev)")
    return package


def _record_line(path: str, data: bytes) -> List[str]:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode("ascii")
    return [path, f"sha256={digest}", str(len(data))]


def _dist_info(files: Dict[str, bytes]) -> Dict[str, bytes]:
    info = f"{NAME}-{_version()}.dist-info"
    out = {
        f"{info}/METADATA": _metadata().encode("utf-8"),
        f"{info}/WHEEL": (f"Wheel-Version: 1.0\nGenerator: tmcert_build\nRoot-Is-Purelib: false\n"
                          f"Tag: {_tag()}\n").encode("utf-8"),
        f"{info}/top_level.txt": f"{NAME}\n".encode("utf-8"),
    }
    record = io.StringIO()
    writer = csv.writer(record, lineterminator="\n")
    for path, data in list(files.items()) + list(out.items()):
        writer.writerow(_record_line(path, data))
    writer.writerow([f"{info}/RECORD", "", ""])
    out[f"{info}/RECORD"] = record.getvalue().encode("utf-8")
    return out


# ---------------------------------------------------------------- PEP 517 hooks

def get_requires_for_build_wheel(config_settings: Optional[Dict[str, str]] = None) -> List[str]:
    return []


def get_requires_for_build_sdist(config_settings: Optional[Dict[str, str]] = None) -> List[str]:
    return []


def prepare_metadata_for_build_wheel(metadata_directory: str,
                                     config_settings: Optional[Dict[str, str]] = None) -> str:
    info = f"{NAME}-{_version()}.dist-info"
    target = Path(metadata_directory) / info
    target.mkdir(parents=True, exist_ok=True)
    (target / "METADATA").write_text(_metadata(), encoding="utf-8")
    return info


def build_wheel(wheel_directory: str, config_settings: Optional[Dict[str, str]] = None,
                metadata_directory: Optional[str] = None) -> str:
    package = _build_extension(config_settings)
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    files: Dict[str, bytes] = {}
    for source in sorted((ROOT / "src" / "python" / "tmcert").iterdir()):
        if source.is_file() and (source.suffix in (".py", ".pyi") or source.name == "py.typed"):
            files[f"{NAME}/{source.name}"] = source.read_bytes()
    files[f"{NAME}/_tmcert{suffix}"] = (package / f"_tmcert{suffix}").read_bytes()
    wheel_name = f"{NAME}-{_version()}-{_tag()}.whl"
    Path(wheel_directory).mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(Path(wheel_directory) / wheel_name, "w", compression=zipfile.ZIP_DEFLATED) as wheel:
        for path, data in list(files.items()) + list(_dist_info(files).items()):
            entry = zipfile.ZipInfo(path, date_time=(2020, 1, 1, 0, 0, 0))
            entry.external_attr = (0o755 if path.endswith(suffix) else 0o644) << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(entry, data)
    return wheel_name


def build_sdist(sdist_directory: str, config_settings: Optional[Dict[str, str]] = None) -> str:
    """The tracked files of the repository (git ls-files), as name-version/..."""
    base = f"{NAME}-{_version()}"
    try:
        listed = subprocess.run(["git", "-C", str(ROOT), "ls-files", "-z"], capture_output=True, check=True).stdout
        paths = [p for p in listed.decode("utf-8").split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        raise RuntimeError("tmcert_build: an sdist is made from a git checkout (git ls-files)")
    name = f"{base}.tar.gz"
    Path(sdist_directory).mkdir(parents=True, exist_ok=True)
    with tarfile.open(Path(sdist_directory) / name, "w:gz") as tar:
        for path in paths:
            if (ROOT / path).is_file():
                tar.add(str(ROOT / path), arcname=f"{base}/{path}", recursive=False)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata().encode("utf-8")
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return name


__all__ = ["build_sdist", "build_wheel", "get_requires_for_build_sdist", "get_requires_for_build_wheel",
           "prepare_metadata_for_build_wheel"]

if __name__ == "__main__":  # python3 src/python/build_backend/tmcert_build.py WHEEL_DIR: a wheel, for tests
    print(build_wheel(sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp()))
