#!/usr/bin/env bash
# Vendors three.js for the visual report (tmcert verify --report,
# src/html/): fetches the pinned npm package `three` with npm, and copies
# the two files of its ES-module build, OrbitControls and the licence into
# third_party/three/, which is committed: builds and CI need no network,
# and the page fetches nothing when it is viewed (CMake embeds the files,
# cmake/EmbedReportAssets.cmake).  Run from anywhere; needs npm and network.
#   bash scripts/vendor_three.sh            the pinned version below
#   bash scripts/vendor_three.sh 0.185.0    another version (then update the pin
#                                           here and check the report test)
set -euo pipefail

version="${1:-0.184.0}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dest="$root/third_party/three"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

(cd "$work" && npm pack --silent "three@$version" >/dev/null)
tar -xzf "$work/three-$version.tgz" -C "$work"
pkg="$work/package"

# Since r171 the module build is split: three.module.min.js (renderers)
# imports everything else from ./three.core.min.js.  Both are needed.
files=(build/three.module.min.js build/three.core.min.js examples/jsm/controls/OrbitControls.js LICENSE)
for f in "${files[@]}"; do
  if [ ! -f "$pkg/$f" ]; then
    echo "vendor_three.sh: three@$version has no $f; the report embeds exactly these files:" >&2
    printf '  %s\n' "${files[@]}" >&2
    exit 1
  fi
done
mkdir -p "$dest"
cp "$pkg/build/three.module.min.js" "$pkg/build/three.core.min.js" \
   "$pkg/examples/jsm/controls/OrbitControls.js" "$dest/"
cp "$pkg/LICENSE" "$dest/LICENSE"
{
  echo "three $version"
  echo "source: npm pack three@$version"
  (cd "$dest" && sha256sum three.module.min.js three.core.min.js OrbitControls.js LICENSE)
} > "$dest/VERSION"
echo "vendor_three.sh: three@$version copied to third_party/three/"
