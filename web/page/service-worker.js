// Offline use: the page, FOSSSim's wasm (inside fosssim.js) and the scene index are cached when
// the service worker installs; every scene fetched later is cached as it is fetched. Requests
// are answered from the network when it answers (so a rebuilt page is seen at once) and from
// the cache when it does not.
"use strict";
const kCache = "fosssim-page";
const kShell = ["./", "index.html", "fosssim-page.js", "fosssim.js", "scenes/index.json"];

self.addEventListener("install", (event) => {
  event.waitUntil(caches.open(kCache).then((cache) => cache.addAll(kShell)));
  self.skipWaiting();
});

self.addEventListener("activate", (event) => { event.waitUntil(self.clients.claim()); });

self.addEventListener("fetch", (event) => {
  if (event.request.method !== "GET") return;
  event.respondWith(
    fetch(event.request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          caches.open(kCache).then((cache) => cache.put(event.request, copy));
        }
        return response;
      })
      .catch(() => caches.match(event.request, { ignoreSearch: true })
        .then((cached) => cached || Response.error())));
});
