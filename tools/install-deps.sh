#!/bin/sh
# Installs the Debian packages FOSSSim needs to build, test, fuzz, render and benchmark.
# Idempotent: installs only what is missing, and touches the network only then.
set -eu

# libmumps-seq-dev: the symmetric indefinite factorization of step matrices (sequential MUMPS).
# libhypre-dev: BoomerAMG, the algebraic multigrid of large step matrices (core/solvers/amg_solver.h;
# built against its headers, its library opened only by runs that ask for multigrid, docs/solvers.md).
# It brings OpenMPI: about 15 MB to download, 64 MB installed.
# libdart-external-odelcpsolver-dev: ODE's LCP solver (rigid-body contact, core/rigid/contact_lcp.h).
# pybind11-dev and python3-dev build the Python module (python/); NumPy and SciPy are what it
# returns, pytest runs its tests, matplotlib draws the examples' plots (examples/python/).
# bubblewrap confines the candidates fosssim-oracle grades; parallel (GNU parallel) runs the
# autograder kit's recipe for many submissions (autograder/grade-many.sh).
# librapidxml-dev (header-only) parses XML scenes (io/xml_tree); tinyxml2 writes the oracle's
# JUnit report.
# dpkg-dev: dpkg-shlibdeps finds the .deb's library dependencies (cpack -G DEB, tests/install).
# clang, libclang-rt-14-dev (libFuzzer and clang's sanitizer runtimes) and llvm (the symbolizer
# of sanitizer reports) build and run the fuzz targets of fuzz/.
PACKAGES="cmake ninja-build g++ pkg-config
  libeigen3-dev libtinyxml2-dev librapidxml-dev libcli11-dev nlohmann-json3-dev libsuitesparse-dev libopenblas-dev
  libmumps-seq-dev libhypre-dev libdart-external-odelcpsolver-dev
  libgtest-dev libbenchmark-dev python3
  pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-matplotlib dpkg-dev
  libcairo2-dev libssl-dev freeglut3-dev ffmpeg xvfb xauth
  clang libclang-rt-14-dev llvm
  bubblewrap parallel"
# What the WebAssembly build and its tests need (the web preset, and the ci-web check of the
# test workflow; docs/web.md): Emscripten's em++, Debian's header-only fast_float
# (std::from_chars for doubles) and chromium (the page's tests in a headless browser). On top
# of the packages above: 65 packages, 260 MB to download, 1.35 GB installed.
PACKAGES="$PACKAGES emscripten libfast-float-dev chromium"
# --web, which once added them, is still accepted and changes nothing.

missing=""
for package in $PACKAGES; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done

if [ -z "$missing" ]; then
  echo "install-deps: all packages are installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing$missing"
$SUDO apt-get update -q
# shellcheck disable=SC2086
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends $missing
