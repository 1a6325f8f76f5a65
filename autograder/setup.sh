#!/bin/bash
# Gradescope runs this once, as root, when it builds the autograder's image: the zip made by
# make-zip.sh is unpacked into /autograder/source (this file, run_autograder, and the
# repository's copy in fosssim/). It installs the Debian packages, builds FOSSSim (the
# reference) and fosssim-oracle, checks that the sandbox works here, and measures the
# reference's run time of every scene, from which run_autograder's time-outs come.
# docs/autograder.md describes the kit.
set -eu
source_dir=$(cd "$(dirname "$0")" && pwd)
repo=$source_dir/fosssim
[ -f "$repo/CMakeLists.txt" ] || { echo "setup.sh: no repository copy in $repo" >&2; exit 1; }

# The project's own dependency list (it includes bubblewrap, the sandbox, and parallel).
sh "$repo/tools/install-deps.sh"

# Only the two programs the kit runs: no tests, benchmarks, window or Python module.
cmake -S "$repo" --preset release -DFOSSSIM_BUILD_TESTS=OFF -DFOSSSIM_BUILD_BENCHMARKS=OFF \
  -DFOSSSIM_WITH_WINDOW=OFF -DFOSSSIM_PYTHON=OFF
cmake --build "$repo/build/release" -j "$(nproc)" --target FOSSSim fosssim-oracle

# The time-outs (and a first check that the oracle and its sandbox run on this image).
KIT_SOURCE=$source_dir "$source_dir/run_autograder" --measure
