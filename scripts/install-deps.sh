#!/usr/bin/env bash
# Installs what highlift needs to build and test: Debian packages, and the report's plotting
# library from the npm registry (pinned by report/web/package-lock.json, installed with npm ci
# into report/web/node_modules, embedded into the binary at build time).
# Idempotent: when everything is present it only checks (no apt-get update, no network).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config
  libboost-dev libeigen3-dev libsqlite3-dev sqlite3 nlohmann-json3-dev
  libsundials-dev libsuitesparse-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libfmt-dev
  libudunits2-dev libudunits2-data
  slurmctld slurmd slurm-client munge
  chromium
  clang libclang-rt-14-dev
)
# Node.js and npm (the report's plotting library, the browser test): Debian's nodejs and npm,
# unless a node with npm is already installed (a NodeSource nodejs package provides npm itself
# and conflicts with Debian's npm package).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# npm packages of the report (report/web/package-lock.json): npm ci when node_modules does not
# hold exactly the locked versions.
web=report/web
if [ -f "$web/package-lock.json" ]; then
  if [ -f "$web/node_modules/.package-lock.json" ] &&
     node -e '
       const lock = require(process.argv[1]), installed = require(process.argv[2]);
       const want = Object.entries(lock.packages).filter(([k]) => k.startsWith("node_modules/"));
       process.exit(want.every(([k, v]) => installed.packages[k] && installed.packages[k].version === v.version) ? 0 : 1);
     ' "$PWD/$web/package-lock.json" "$PWD/$web/node_modules/.package-lock.json"; then
    echo "install-deps: npm packages of $web present"
  else
    echo "install-deps: npm ci in $web"
    (cd "$web" && npm ci --no-audit --no-fund)
  fi
fi
