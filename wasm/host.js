// What only Node can do: read a file: URL, start a worker_threads worker. The package's "node"
// export (node.js) registers it; browser bundles never import node.js, so they hold no Node code.
let nodeHost = null;

/** @param {{ readFile(url: URL): Promise<Uint8Array>, spawnWorker(url?: string | URL): object }} host */
export function registerNodeHost(host) {
  nodeHost = host;
}

/** The registered Node host, or null in browsers (and in Node before node.js is loaded). */
export function getNodeHost() {
  return nodeHost;
}

// Where a classic-script bundle (esbuild's default iife format, which has no import.meta.url) was
// loaded from; document.currentScript is only set while that script first runs, so read it now.
export const classicScriptUrl = globalThis.document?.currentScript?.src || globalThis.location?.href;

/** A URL as the platform resolves it (relative to the page or worker), for error messages. */
export function absoluteUrl(url) {
  try {
    return new URL(url, globalThis.location?.href).href;
  } catch {
    return String(url);
  }
}
