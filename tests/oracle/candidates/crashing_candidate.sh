#!/bin/sh
# A candidate that crashes: it says something and kills itself with SIGSEGV.
echo "about to crash" >&2
kill -SEGV $$
