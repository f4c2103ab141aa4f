"""The type stubs of the extension module (tmcert/_tmcert.pyi) against the
built module (mypy's stubtest), and the package type-checked against them
(mypy): a stub that names what the module does not have, misses what it
has, or that the package's calls do not fit fails here.  Debian
python3-mypy; skipped without it."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import tmcert

mypy = pytest.importorskip("mypy")

PACKAGE = Path(tmcert.__file__).resolve().parent


def run(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    env = dict(os.environ, MYPYPATH=str(PACKAGE.parent),
               PYTHONPATH=os.pathsep.join([str(PACKAGE.parent)] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    return subprocess.run([sys.executable, "-m", *args], capture_output=True, text=True, cwd=cwd, env=env,
                          timeout=600)


def test_stubs_are_installed_with_the_module() -> None:
    assert (PACKAGE / "_tmcert.pyi").is_file() and (PACKAGE / "py.typed").is_file()


def test_stubtest(tmp_path: Path) -> None:
    config = tmp_path / "mypy.ini"
    config.write_text("[mypy]\n")
    done = run("mypy.stubtest", "tmcert._tmcert", "--mypy-config-file", str(config), "--allowlist",
               str(Path(__file__).with_name("stubtest_allowlist.txt")), cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    # And the other way: every public name of the module has a stub.
    names = {line.split("(")[0].split(":")[0].split()[1] for line in (PACKAGE / "_tmcert.pyi").read_text().splitlines()
             if line.startswith(("def ", "class "))}
    missing = {n for n in dir(tmcert._tmcert) if not n.startswith("__")} - names - {"__version__"}
    assert not missing, f"no stub for {sorted(missing)}"


def test_the_package_type_checks(tmp_path: Path) -> None:
    use = tmp_path / "use.py"
    use.write_text(
        "import tmcert\n"
        "r: tmcert.Result = tmcert.verify('scene.json', epsilon='1/1000', progress=lambda p: p.fraction < 1)\n"
        "n: int = len(r.checks) + len(r.notes)\n"
        "s: tmcert.BatchSummary = tmcert.batch('requests.jsonl', scene='env.json')\n"
        "page: str = r.report_html()\n")
    # mypy follows the import: the package (tmcert/__init__.py against the
    # stubs) is checked along with the use of it.
    done = run("mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"), "--follow-imports=normal",
               str(use), cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
