#!/usr/bin/env bash
# Installs railodd's build and test dependencies from Debian 12's archive.
# Idempotent: does nothing (and needs no network) when all are present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libosmium2-dev libprotozero-dev zlib1g-dev libbz2-dev libexpat1-dev
  libgdal-dev gdal-bin libproj-dev proj-data
  libcgal-dev libeigen3-dev
  libpugixml-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  osmium-tool
  libxml2-utils python3-xmlschema sumo sumo-tools
  chromium
  slurmd slurmctld slurm-client munge
  clang libclang-rt-14-dev
  libboost-dev libmsgpack-cxx-dev  # CARLA's OpenDRIVE loader, ../shared/tools/carla-road (tests)
)
# Node.js for the report's web libraries (npm) and its browser test; a newer
# node already on the machine is kept.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The report's web libraries (Leaflet, uPlot) and puppeteer-core, at the
# versions of report/web/package-lock.json; again only when they changed.
web="$(dirname "$0")/../report/web"
if [ ! -f "$web/node_modules/.package-lock.json" ] || [ "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]; then
  echo "installing the report's web libraries (npm ci in report/web)"
  (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
fi
