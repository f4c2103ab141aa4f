#!/usr/bin/env bash
# Installs the Debian packages tmcert needs, and only those that are missing.
# Idempotent; needs root (or sudo) only when something is missing.
#   bash scripts/deps.sh        what make, make test and make demo need
#   bash scripts/deps.sh fuzz   also clang and its libFuzzer runtime (make fuzz,
#                               tests/fuzz/README.md)
set -euo pipefail

packages=(
  cmake g++ make
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev
  libboost-test-dev librapidcheck-dev
  nlohmann-json3-dev libcli11-dev
  libflint-arb-dev
  liburdfdom-dev        # URDF robots (src/io/urdf.cpp; brings TinyXML and console_bridge)
  libtinyxml-dev libconsole-bridge-dev
  libassimp-dev         # COLLADA (.dae) meshes (src/io/mesh.cpp)
  libtcmalloc-minimal4  # the command's thread-caching allocator (CMake option TMCERT_TCMALLOC; batch --threads)
  libfcl-dev            # only for bench/planner_path.cpp and bench/ompl_edges.cpp (FCL, the planners' checker)
  libassimp-dev         # only for bench/omplapp_fcl.cpp (OMPL.app's COLLADA meshes, as OMPL.app reads them)
  libompl-dev           # the OMPL motion validator (src/ompl/), its tests and examples
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python package (src/python/), its tests and example
  chromium              # the visual report's test (tests/html/report_browser.py), headless
  python3-venv python3-mypy  # pip install . into a fresh environment, the stubs' check (tests/python)
  slurm-wlm munge       # the single-node Slurm of the batch example's test (tests/regression/slurm.sh)
)
if [ "${1:-}" = "fuzz" ]; then
  # libFuzzer (-fsanitize=fuzzer) comes with clang's compiler-rt.
  packages+=(clang libclang-rt-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# The CCD query scripts (scripts/ccd_*.py) and their test need a Python 3,
# Debian's or any other on the PATH.
if ! command -v python3 >/dev/null 2>&1; then
  missing+=(python3)
fi

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "deps.sh: installing missing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "deps.sh: not root and no sudo; please install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
