#!/bin/sh
# A candidate that writes a prepared file ($ORACLE_TEST_TRAJECTORY) as its trajectory, prints
# $ORACLE_TEST_STDERR on standard error, and exits with ${ORACLE_TEST_EXIT:-0}. The tests prepare
# short, oversized, NaN and random files with it.
set -eu
out="" previous=""
for argument in "$@"; do
  if [ "$previous" = "-o" ]; then out="$argument"; fi
  previous="$argument"
done
if [ -n "${ORACLE_TEST_TRAJECTORY:-}" ]; then cp "$ORACLE_TEST_TRAJECTORY" "$out"; fi
if [ -n "${ORACLE_TEST_STDERR:-}" ]; then printf '%s\n' "$ORACLE_TEST_STDERR" >&2; fi
exit "${ORACLE_TEST_EXIT:-0}"
