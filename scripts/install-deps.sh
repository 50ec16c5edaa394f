#!/usr/bin/env bash
# Installs the Debian 12 packages slamtune needs. Idempotent, non-interactive, as root.
# Skips apt entirely when every package is already installed.
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config git
  libeigen3-dev libceres-dev libsuitesparse-dev libopencv-dev libpagmo-dev libboost-serialization-dev libtbb-dev
  libcli11-dev nlohmann-json3-dev libyaml-cpp-dev libspdlog-dev libfmt-dev
  libsqlite3-dev zlib1g-dev libpng-dev libzstd-dev liblz4-dev libbz2-dev libgtest-dev libgmock-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  sqlite3 python3  # the CLI tests inspect run databases and results.json and compute a CRC-32 with them
  chromium  # report_browser_cli_test.sh opens report.html in headless Chromium
  clang-format  # the house test checks that the sources are formatted as .clang-format says
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present, nothing to do"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
