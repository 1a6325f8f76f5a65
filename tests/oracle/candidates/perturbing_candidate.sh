#!/bin/sh
# A deliberately wrong candidate: runs the real simulator ($FOSSSIM), then changes one double of
# its trajectory with $PERTURB_TOOL: frame $PERTURB_FRAME, particle $PERTURB_PARTICLE,
# component $PERTURB_COMPONENT (0 = position x), by $PERTURB_DELTA (or "flip-bit").
# The oracle must fail it at exactly that step and particle.
set -eu
scene="" out="" previous=""
for argument in "$@"; do
  case "$previous" in
    -s) scene="$argument" ;;
    -o) out="$argument" ;;
  esac
  previous="$argument"
done
"$FOSSSIM" "$@"
"$PERTURB_TOOL" "$scene" "$out" "$PERTURB_FRAME" "$PERTURB_PARTICLE" "${PERTURB_COMPONENT:-0}" \
  "${PERTURB_DELTA:-1e-9}"
