// pipelens' service worker (web/sw.js; scripts/build-web.sh writes the build's version below).
//
// Two jobs:
//  - Offline: every file the page loads is kept in a cache named for this build, and served from
//    it, so a page opened once works without the network (a class on a weak network). A new
//    build has a new version, so a new worker, which starts an empty cache and drops the old.
//  - Threads: the threaded build needs shared memory, which a browser gives only to a page that
//    is cross-origin isolated (the `Cross-Origin-Opener-Policy` and `-Embedder-Policy` headers).
//    A static host that cannot send them still gets them: this worker adds them to every
//    response it serves (the page reloads once after the worker first takes it over).
// A page loaded before this worker controlled it (its first visit, from a host that isolates it
// itself, so with no reload) did not pass its files through the worker: once it runs it says
// which build it runs, and the worker keeps the page and that build's files then.
const VERSION = "pipelens-@BUILD@";
// Each build's files (scripts/build-web.sh lists them), relative to the page: the single-threaded
// build's and the threaded one's, kept whole once the page says which it runs.
const FILES = { one: ["@ONE@"], threads: ["@THREADS@"] };

self.addEventListener("install", () => self.skipWaiting());

self.addEventListener("activate", (event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys()) {
      if (name.startsWith("pipelens-") && name !== VERSION) await caches.delete(name);
    }
    await self.clients.claim();
  })());
});

/** The cache's key for `url`: the page itself is one copy whatever its query (?lang=zh&step=3). */
function key(request) {
  return request.mode === "navigate" ? new URL("./", self.location).href : request;
}

self.addEventListener("message", (event) => {
  const files = FILES[event.data?.keep];
  if (!Array.isArray(files)) return;
  event.waitUntil((async () => {
    const cache = await caches.open(VERSION);
    for (const file of ["./", ...files]) {
      const url = new URL(file, self.location).href;
      if (await cache.match(url)) continue;
      try {
        const fresh = await fetch(url);
        if (fresh.ok) await cache.put(url, fresh);
      } catch (e) {
        console.warn(`pipelens: ${file} not kept for offline use:`, e);
      }
    }
  })());
});

/** The response with the isolation headers added (a new Response: headers are read-only). */
function isolated(response) {
  if (response.status === 0 || response.type === "opaque") return response;
  const headers = new Headers(response.headers);
  headers.set("Cross-Origin-Opener-Policy", "same-origin");
  headers.set("Cross-Origin-Embedder-Policy", "require-corp");
  headers.set("Cross-Origin-Resource-Policy", "same-origin");
  return new Response(response.body, { status: response.status, statusText: response.statusText, headers });
}

self.addEventListener("fetch", (event) => {
  const request = event.request;
  const url = new URL(request.url);
  if (request.method !== "GET" || url.origin !== self.location.origin) return;
  event.respondWith((async () => {
    const cache = await caches.open(VERSION);
    const kept = await cache.match(key(request), { ignoreSearch: request.mode === "navigate" });
    if (kept) return isolated(kept);
    try {
      const fresh = await fetch(request, { cache: "no-cache" });
      if (fresh.ok) await cache.put(key(request), fresh.clone());
      return isolated(fresh);
    } catch (e) {
      return new Response(`pipelens is offline and ${url.pathname} was not kept: ${e}`, {
        status: 503, headers: { "Content-Type": "text/plain; charset=utf-8" },
      });
    }
  })());
});
