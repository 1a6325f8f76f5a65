# The hostile submission's build: it tries the same escapes while the kit builds it (its
# simulator is already there), then succeeds. What it stole would land in its own folder, where
# its simulator looks for it; the test checks the rest from outside.
echo escaped > "$KIT_TEST_OUTSIDE/build-escaped" 2>/dev/null
cat "$KIT_TEST_OTHER" > stolen 2>/dev/null || rm -f stolen
bash -c 'exec 3<>"/dev/tcp/127.0.0.1/$KIT_TEST_PORT"' 2>/dev/null
setsid sleep "$KIT_TEST_TOKEN" </dev/null >/dev/null 2>&1 &
exit 0
