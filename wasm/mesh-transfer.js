// The ArrayBuffers inside a mesh result, for postMessage's transfer list: a worker hands them
// over instead of copying (a 2-million-triangle mesh is ~70 MB of typed arrays).
export function meshBuffers(mesh) {
  const buffers = new Set();
  const visit = (value) => {
    if (ArrayBuffer.isView(value)) buffers.add(value.buffer);
    else if (value !== null && typeof value === 'object' && !Array.isArray(value)) Object.values(value).forEach(visit);
  };
  visit(mesh);
  return [...buffers];
}
