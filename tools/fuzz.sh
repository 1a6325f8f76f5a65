#!/bin/sh
# Long fuzz campaigns: builds the fuzz preset and runs each fuzz target (fuzz/README.md) for a
# while, from its committed seeds plus what earlier campaigns found.
#
#   tools/fuzz.sh [TARGET...] [--minutes M] [--runs N] [--jobs J] [--merge]
#
# TARGET: xml_scene json_scene obj medit trajectory command_line (default: all, one after the
# other). --minutes: per target (default 30). --runs: also stop a target after N inputs (with one
# job). --jobs: fuzzing processes per target (default 1).
# --merge: afterwards, add the inputs that reach new code to fuzz/corpus/TARGET (review and
# commit them). Findings go to build/fuzz/campaign/TARGET/artifacts/; the script exits 1 when
# there is any.
set -eu
cd "$(dirname "$0")/.."
root="$PWD"

targets=""
minutes=30
runs=-1
jobs=1
merge=0
while [ $# -gt 0 ]; do
  case "$1" in
    --minutes) minutes="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --merge) merge=1; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets="$targets $1"; shift ;;
  esac
done
[ -n "$targets" ] || targets="xml_scene json_scene obj medit trajectory command_line"

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

found=0
for target in $targets; do
  fuzzer="$root/build/fuzz/fuzz/${target}_fuzzer"
  [ -x "$fuzzer" ] || { echo "fuzz.sh: no target $target" >&2; exit 2; }
  work="$root/build/fuzz/campaign/$target"
  mkdir -p "$work/corpus" "$work/artifacts"
  dictionary=""
  [ -f "fuzz/dictionaries/$target.dict" ] && dictionary="-dict=$root/fuzz/dictionaries/$target.dict"
  parallel=""
  [ "$jobs" -gt 1 ] && parallel="-jobs=$jobs -workers=$jobs"
  echo "fuzz.sh: $target for $minutes min with $jobs job(s); findings in $work/artifacts/"
  # Run in the work folder: with several jobs libFuzzer writes a fuzz-N.log per job there.
  # shellcheck disable=SC2086
  (cd "$work" && "$fuzzer" -max_total_time=$((minutes * 60)) -runs="$runs" -timeout=25 -rss_limit_mb=2048 \
    -print_final_stats=1 $parallel $dictionary -artifact_prefix="$work/artifacts/" \
    "$work/corpus" "$root/fuzz/corpus/$target" >"$work/log.txt" 2>&1) || true
  grep -hE "^(Done [0-9]+ runs|stat::number_of_executed_units|stat::average_exec_per_sec|SUMMARY)" \
    "$work"/log.txt "$work"/fuzz-*.log 2>/dev/null || true
  if [ -n "$(ls "$work/artifacts")" ]; then
    found=1
    echo "fuzz.sh: $target FOUND: $(ls "$work/artifacts" | tr '\n' ' ')"
    echo "  reproduce: $fuzzer $work/artifacts/<file>;  reduce: $fuzzer -minimize_crash=1 -runs=100000 $work/artifacts/<file>"
  fi
  if [ "$merge" = 1 ]; then
    "$fuzzer" -merge=1 $dictionary "fuzz/corpus/$target" "$work/corpus" >/dev/null 2>&1
    echo "fuzz.sh: merged new inputs into fuzz/corpus/$target"
  fi
done
exit $found
