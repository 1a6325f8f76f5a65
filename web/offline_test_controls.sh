#!/bin/bash
# By hand, not a ctest test: web.browser.offline must fail on a page whose offline use is broken.
# Makes three broken copies of the built page in a temporary folder (its files linked, one file
# changed) and runs `browser_test.py offline` on each; each run must fail (docs/web.md, "The
# offline test"). About 3 minutes, most of it the first case's 90 s wait for a worker.
#   web/offline_test_controls.sh [BUILD_PAGE]      (default: build/web/page), from the source tree
set -u
page=$(realpath "${1:-build/web/page}")
work=$(mktemp -d /tmp/fosssim-offline-controls-XXXXXX)
trap 'rm -rf "$work"' EXIT
for case in no-register caches-nothing no-scenes; do
  mkdir "$work/$case" && ln -s "$page"/* "$work/$case/"
done
# The page never registers its service worker.
rm "$work/no-register/fosssim-page.js"
grep -v 'navigator.serviceWorker.register(' "$page/fosssim-page.js" > "$work/no-register/fosssim-page.js"
# A worker that takes control of the page and passes every request to the network.
rm "$work/caches-nothing/service-worker.js"
cat > "$work/caches-nothing/service-worker.js" <<'JS'
self.addEventListener("install", () => { self.skipWaiting(); });
self.addEventListener("activate", (event) => { event.waitUntil(self.clients.claim()); });
self.addEventListener("fetch", (event) => { event.respondWith(fetch(event.request)); });
JS
# The real worker, except that it stores no scene it fetched.
rm "$work/no-scenes/service-worker.js"
sed 's|^\( *\)caches.open(kCache)|\1if (!event.request.url.includes("/scenes/")) caches.open(kCache)|' \
    "$page/service-worker.js" > "$work/no-scenes/service-worker.js"
status=0
for case in no-register caches-nothing no-scenes; do
  echo "== $case"
  if timeout -k 10 300 python3 "$(dirname "$0")/browser_test.py" offline --page "$work/$case" \
       --browser chromium --manifest oracle/manifest/golden.tsv \
       assets/t1m1/system_multiple_pendulum.xml | tail -1; [ "${PIPESTATUS[0]}" = 0 ]; then
    echo "web.browser.offline PASSED on a broken page ($case): it does not test offline use"
    status=1
  fi
done
exit $status
