#!/usr/bin/env bash
# Installs the Debian 12 packages relmap builds and tests with, plus any named
# as arguments (e.g. python3-sklearn for the learning benchmark's reference).
# Idempotent: a machine that already has every package is left alone (no
# apt-get update).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkgconf git clang-format clang-tidy
  libeigen3-dev libboost-math-dev
  libpcl-dev
  libgrpc++-dev protobuf-compiler-grpc protobuf-compiler libprotobuf-dev
  libode-dev libyaml-dev  # the simulator; relmap-robot's YAML configs
  libspdlog-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libsqlite3-dev libssl-dev zlib1g-dev openssl
  libzstd-dev           # the compact frame cache (server/perception/word_planes.cpp)
  python3-grpcio python3-protobuf  # scripts/grpcurl-lite, the Python client
  python3-numpy python3-pytest     # the Python client (client/python) and its tests
  python3-venv python3-setuptools python3-wheel  # its offline `pip install` (README)
  libpq-dev postgresql  # the shared session store and its tests
  nginx python3-yaml    # the cluster test's load balancer; deploy/ YAML checks
  file                  # cpack -G DEB (dpkg-shlibdeps)
  # ROS 1 (Debian's own packages) for robot_adapter/ros: relmap_ros_bridge and its tests.
  # pluginlib-dev: rosbag's headers include it, and librosbag-dev does not depend on it.
  ros-core-dev librosbag-dev pluginlib-dev libsensor-msgs-dev libgeometry-msgs-dev
  libvisualization-msgs-dev libdiagnostic-msgs-dev libtf2-ros-dev
  "$@"
)

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
