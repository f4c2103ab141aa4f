#!/usr/bin/env bash
# Fetches Gepetto/example-robot-data (the Franka Panda, the UR5 and others,
# as published: URDF, SRDF, meshes; BSD-licensed) for the scenes of
# examples/robot/ and the test that runs them, at a fixed release:
#   bash scripts/fetch_example_robot_data.sh [DIR]
# DIR defaults to examples/robot/example-robot-data (ignored by git). An
# existing copy is left as it is. With a copy elsewhere, point the test at it
# instead: cmake -DTMCERT_EXAMPLE_ROBOT_DATA=/path/to/example-robot-data, or
# the environment variable TMCERT_EXAMPLE_ROBOT_DATA; the scenes find the
# package through --package-path or ROS_PACKAGE_PATH (examples/robot/README.md).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-$here/examples/robot/example-robot-data}
release=v4.3.0
if [ -f "$dir/package.xml" ]; then
  echo "example-robot-data is already in $dir"
  exit 0
fi
command -v git >/dev/null 2>&1 || { echo "git is needed (apt-get install git)" >&2; exit 3; }
git clone --depth 1 --branch "$release" https://github.com/Gepetto/example-robot-data.git "$dir"
echo "example-robot-data $release is in $dir"
