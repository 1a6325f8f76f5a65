#!/bin/sh
# A candidate that writes its trajectory file forever.
out="" previous=""
for argument in "$@"; do
  if [ "$previous" = "-o" ]; then out="$argument"; fi
  previous="$argument"
done
cat /dev/zero > "$out"
