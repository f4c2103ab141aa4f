#!/usr/bin/env bash
# tmcert and Tight-Inclusion side by side on continuous-collision query
# files (bench/ccd_side_by_side.cpp), built from Tight-Inclusion's public
# source next to tmcert's build (not part of the default build).
#
#   bench/tight_inclusion.sh TIGHT_INCLUSION_SRC QUERIES_DIR [ROUNDS] [BUILD]
#
# TIGHT_INCLUSION_SRC: a checkout of Continuous-Collision-Detection/Tight-Inclusion;
# QUERIES_DIR: a checkout of Continuous-Collision-Detection/Sample-Queries
# (every *.csv under it is run); BUILD: tmcert's build directory (default
# build, with libtmcert.a).  Tight-Inclusion's sources are compiled as
# they are, with double precision input, its config.hpp generated here and
# its spdlog logger replaced by a no-op (it only logs overflow and timers).
set -euo pipefail
ti=${1:?usage: tight_inclusion.sh TIGHT_INCLUSION_SRC QUERIES_DIR [ROUNDS] [BUILD]}
queries=${2:?usage: tight_inclusion.sh TIGHT_INCLUSION_SRC QUERIES_DIR [ROUNDS] [BUILD]}
rounds=${3:-3}
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${4:-$here/build}" && pwd)
out="$build/tight_inclusion"
mkdir -p "$out/shim/tight_inclusion"
cat > "$out/shim/tight_inclusion/config.hpp" <<'H'
#pragma once
#define TIGHT_INCLUSION_NAME "tight_inclusion"
#define TIGHT_INCLUSION_WITH_DOUBLE_PRECISION
H
cat > "$out/shim/tight_inclusion/logger.hpp" <<'H'
#pragma once
namespace ticcd {
struct NullLogger {
  template <class... A> void error(A&&...) {}
  template <class... A> void warn(A&&...) {}
  template <class... A> void info(A&&...) {}
  template <class... A> void debug(A&&...) {}
  template <class... A> void trace(A&&...) {}
};
inline NullLogger& logger() { static NullLogger l; return l; }
}  // namespace ticcd
H
[ -f "$build/libtmcert.a" ] || { echo "no $build/libtmcert.a: build tmcert first (make build)" >&2; exit 3; }
flags="-O3 -DNDEBUG -std=c++20 -frounding-math -I$out/shim -I$ti/src -I$here -I/usr/include/eigen3"
objs=()
for f in ccd interval interval_root_finder avx; do
  g++ $flags -c "$ti/src/tight_inclusion/$f.cpp" -o "$out/$f.o"
  objs+=("$out/$f.o")
done
g++ $flags "$here/bench/ccd_side_by_side.cpp" "${objs[@]}" "$build/libtmcert.a" -lgmpxx -lgmp -lmpfr -lflint-arb -lflint \
  -lurdfdom_model -ltinyxml -lconsole_bridge -lassimp -lpthread \
  -o "$out/ccd_side_by_side"
mapfile -t files < <(find "$queries" -name '*.csv' | sort)
"$out/ccd_side_by_side" "$rounds" "${files[@]}"
