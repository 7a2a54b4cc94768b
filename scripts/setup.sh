#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages only), then configures and builds cutcom in ./build.
# Run as root on a fresh machine, or as any user once the packages are there.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ make cmake ca-certificates
  libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev
  librapidcheck-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libmimalloc-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# A profile-guided build (CUTCOM_PGO in CMakeLists.txt): the command built with counters, a
# training run (scripts/pgo_training.sh), then everything built with the profiles. CUTCOM_PGO=off
# in the environment builds without (quicker while developing: a plain Release build).
if [[ "${CUTCOM_PGO:-on}" == off ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCUTCOM_PGO=off
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCUTCOM_PGO=generate
  cmake --build build -j"$(nproc)" --target cutcom
  bash scripts/pgo_training.sh build
  cmake -S . -B build -DCUTCOM_PGO=use
fi
cmake --build build -j"$(nproc)"
