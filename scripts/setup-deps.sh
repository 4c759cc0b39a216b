#!/usr/bin/env bash
# Installs the Debian packages cmx needs, only those that are missing.
# Does nothing (and needs no root) when everything is present.
# Usage: scripts/setup-deps.sh [--fuzz] [--bench] [--dataset] [--gmsh]
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libgmp-dev libmpfr-dev libboost-dev   # the core library: GMP, MPFR, Boost headers
  doctest-dev                           # tests
  libcli11-dev                          # the cmx program's command lines (header-only)
  nlohmann-json3-dev                    # api/: JSON string escaping of the reports (header-only)
  libeigen3-dev                         # algorithm/: sparse solver of the Tutte initial map (header-only)
  libglpk-dev                           # reference LP backend (tests, fuzz, bench only)
  libtet1.5-dev                         # TetGen's copy of Shewchuk's predicates (oracle only)
  libbenchmark-dev                      # bench/
  python3                               # independent checkers in ../shared/tools
  zlib1g-dev python3-meshio python3-pytest  # io: zlib-compressed VTU; tests: meshio interoperability
  pybind11-dev python3-pybind11 python3-dev python3-numpy  # python/: the cmx module (pybind11); its tests (pytest, meshio)
)
for arg in "$@"; do
  case "$arg" in
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    --bench) packages+=(libcgal-dev) ;;
    --dataset) packages+=(parallel) ;;  # bench/dataset/run.sh
    --gmsh) packages+=(gmsh) ;;         # the test that Gmsh itself opens cmx's .msh (skipped without)
    *) echo "setup-deps.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup-deps.sh: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
