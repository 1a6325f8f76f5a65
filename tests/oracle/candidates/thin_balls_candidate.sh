#!/bin/sh
# A deliberately wrong candidate for collision scenes: runs the real simulator ($FOSSSIM) on a
# copy of the scene whose radii 0.2 are 0.19, so that it misses the collisions the scene has.
# The oracle must fail it and name the missed collision.
set -eu
scene="" out="" previous=""
for argument in "$@"; do
  case "$previous" in
    -s) scene="$argument" ;;
    -o) out="$argument" ;;
  esac
  previous="$argument"
done
sed 's/radius="0.2"/radius="0.19"/g' "$scene" > thin.xml
"$FOSSSIM" -s thin.xml -d 0 -q -o "$out"
