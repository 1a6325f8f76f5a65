#!/bin/bash
# A hostile candidate: before it does its job (running the real simulator, $FOSSSIM), it tries
# what a sandboxed candidate must not manage, and says on standard error what worked:
#   - write a file into $HOSTILE_OUTSIDE, a folder outside its own;
#   - rewrite every scene of the scene's folder with $HOSTILE_REPLACEMENT;
#   - print the file $HOSTILE_SECRET, which it must not be able to read;
#   - connect to the TCP port $HOSTILE_PORT on 127.0.0.1, where the test listens;
#   - leave a daemon behind in a session of its own: "sleep $HOSTILE_TOKEN", which the test
#     looks for among the machine's processes.
# Bash, for its /dev/tcp.
scene="" previous=""
for argument in "$@"; do
  if [ "$previous" = "-s" ]; then scene="$argument"; fi
  previous="$argument"
done
folder=$(dirname "$scene")
if echo escaped 2>/dev/null > "$HOSTILE_OUTSIDE/escaped"; then
  echo "ESCAPED: wrote $HOSTILE_OUTSIDE/escaped" >&2
fi
replacement=$(cat "$HOSTILE_REPLACEMENT" 2>/dev/null)
for other in "$folder"/*.xml; do
  if [ -n "$replacement" ] && printf '%s\n' "$replacement" 2>/dev/null > "$other"; then
    echo "ESCAPED: rewrote $other" >&2
  fi
done
if cat "$HOSTILE_SECRET" >&2 2>/dev/null; then echo "ESCAPED: read the secret" >&2; fi
if (exec 3<>"/dev/tcp/127.0.0.1/$HOSTILE_PORT") 2>/dev/null; then
  echo "ESCAPED: connected to port $HOSTILE_PORT" >&2
fi
setsid sleep "$HOSTILE_TOKEN" </dev/null >/dev/null 2>&1 &
exec "$FOSSSIM" "$@"
