#!/bin/bash
# Grades every submission of a folder, several at once with GNU parallel (Debian's `parallel`):
#   grade-many.sh SUBMISSIONS_FOLDER RESULTS_FOLDER [JOBS]
# Each sub-folder of SUBMISSIONS_FOLDER is one submission (as run_autograder takes it); its
# report goes to RESULTS_FOLDER/<name>/results.json, and RESULTS_FOLDER/scores.tsv lists
# "<name> <score>" for all of them. JOBS (default: the number of cores) submissions are graded
# at once, each with $KIT_JOBS scenes at once (default 2), so JOBS x KIT_JOBS candidates run at
# the same time. The time-outs are measured once, before any submission (run_autograder
# --measure). Every other setting is run_autograder's (KIT_* variables, docs/autograder.md).
set -eu
if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: grade-many.sh SUBMISSIONS_FOLDER RESULTS_FOLDER [JOBS]" >&2
  exit 2
fi
submissions=$1 out=$2 jobs=${3:-$(nproc)}
kit=$(cd "$(dirname "$0")" && pwd)
command -v parallel > /dev/null || { echo "grade-many.sh: GNU parallel is not installed" >&2; exit 2; }
[ -d "$submissions" ] || { echo "grade-many.sh: no folder $submissions" >&2; exit 2; }
mkdir -p "$out"
"$kit/run_autograder" --measure
# {} is a submission folder, {/} its name. --halt never: one failing submission does not stop
# the others; the exit status counts the submissions whose grading itself failed.
status=0
find "$submissions" -mindepth 1 -maxdepth 1 -type d -print0 | sort -z |
  parallel -0 --jobs "$jobs" --halt never --tag \
    KIT_SUBMISSION={} KIT_RESULTS="$out"/{/}/results.json "$kit/run_autograder" || status=$?
for report in "$out"/*/results.json; do
  [ -e "$report" ] || continue
  name=$(basename "$(dirname "$report")")
  printf '%s\t%s\n' "$name" "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["score"])' "$report")"
done > "$out/scores.tsv"
echo "grade-many.sh: $(wc -l < "$out/scores.tsv") reports; scores in $out/scores.tsv" >&2
exit $status
