// pipelens' service worker (web/sw.js; scripts/build-web.sh writes the build's version below).
//
// Two jobs:
//  - Offline: the page and the threaded build are kept when this worker installs (before it
//    takes the page over), every other file the page loads is kept as it passes through, and
//    everything is served from that cache, so a page opened once works without the network (a
//    class on a weak network). A new build has a new version, so a new worker, which fills a
//    cache of its own and drops the old. Kept at install, not when the page asks: a page that
//    ran before this worker controlled it (a first visit to a host that isolates it itself, or
//    a page of the previous build while this one installs) may never pass its files through
//    this worker, and its message may reach the previous worker, whose cache this one deletes.
//  - Threads: the threaded build needs shared memory, which a browser gives only to a page that
//    is cross-origin isolated (the `Cross-Origin-Opener-Policy` and `-Embedder-Policy` headers).
//    A static host that cannot send them still gets them: this worker adds them to every
//    response it serves (the page reloads once after the worker first takes it over).
// The single-threaded build (a page asked for `?threads=0`, or one whose thread pool did not
// start) is kept whole when the page says it runs it.
const VERSION = "pipelens-@BUILD@";
// Each build's files (scripts/build-web.sh lists them), relative to the page: the single-threaded
// build's and the threaded one's (empty in a build made without threads).
const FILES = { one: ["@ONE@"], threads: ["@THREADS@"] };

/** `files` and the page fetched past the browser's HTTP cache (which may still hold the previous
 * build's), kept in this build's cache; a file already kept is not fetched again. */
async function keep(files) {
  const cache = await caches.open(VERSION);
  for (const file of ["./", ...files]) {
    const url = new URL(file, self.location).href;
    if (await cache.match(url)) continue;
    const fresh = await fetch(url, { cache: "no-cache" });
    if (!fresh.ok) throw new Error(`${file}: HTTP ${fresh.status}`);
    await cache.put(url, fresh);
  }
}

// The page and the build almost every page runs (the worker isolates the page, so the threaded
// one) are kept before the worker installs: it installs with them, or not at all (and the next
// visit tries again).
self.addEventListener("install", (event) => {
  event.waitUntil(keep(FILES.threads).then(() => self.skipWaiting()));
});

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
  event.waitUntil(keep(files).catch((e) => console.warn("pipelens: not kept for offline use:", e)));
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
