#!/bin/sh
# A candidate that never finishes. The sleep is a child of the shell, so only killing the whole
# process group (or the sandbox) stops it. It sleeps ${ORACLE_TEST_SLEEP:-1000} seconds, so that
# a test can find it among the machine's processes by that argument, and writes "started" into
# sleep.pid in its working folder once it runs.
sleep "${ORACLE_TEST_SLEEP:-1000}" &
echo started > sleep.pid
wait
