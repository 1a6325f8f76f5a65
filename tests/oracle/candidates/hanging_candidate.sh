#!/bin/sh
# A candidate that never finishes. The sleep is a child of the shell, so only killing the whole
# process group stops it; it records its process id so that the test can check it is gone.
sleep 1000 &
if [ -n "${ORACLE_TEST_PID_FILE:-}" ]; then echo $! > "$ORACLE_TEST_PID_FILE"; fi
wait
