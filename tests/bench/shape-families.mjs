// Shape families for the per-call benchmarks (speed-per-call.mjs), each at a few sizes, from small
// (tens of triangles) to large (tens of thousands). Deterministic: the same PLCs on every run.
// A PLC is { points, segments, holes, regions } with flat arrays, as triangulate() takes it.

// A closed polygon through `ring` (flat x, y) appended to plc.
function addRing(plc, ring) {
  const first = plc.points.length / 2;
  const count = ring.length / 2;
  plc.points.push(...ring);
  for (let i = 0; i < count; i++) plc.segments.push(first + i, first + ((i + 1) % count));
}

const emptyPlc = () => ({ points: [], segments: [], holes: [], regions: [] });

// A comb: a bar with `teeth` thin teeth, 1 wide overall: long thin pieces and many reflex corners.
export function comb(teeth) {
  const w = 1 / (2 * teeth - 1);  // tooth i spans [2i w, (2i + 1) w]; the last one ends at x = 1
  const ring = [0, 0, 1, 0];
  for (let i = teeth - 1; i >= 0; i--) {
    ring.push((2 * i + 1) * w, 1, 2 * i * w, 1);
    if (i > 0) ring.push(2 * i * w, 0.2, (2 * i - 1) * w, 0.2);
  }
  const plc = emptyPlc();
  addRing(plc, ring);
  return plc;
}

// A star with `spikes` spikes (inner radius 0.4): sharp convex tips and reflex notches.
export function star(spikes) {
  const ring = [];
  for (let i = 0; i < 2 * spikes; i++) {
    const a = (Math.PI * i) / spikes;
    const r = i % 2 === 0 ? 1 : 0.4;
    ring.push(r * Math.cos(a), r * Math.sin(a));
  }
  const plc = emptyPlc();
  addRing(plc, ring);
  return plc;
}

// The unit square with k x k square holes (a hole seed in each): many small boundaries.
export function perforated(k) {
  const plc = emptyPlc();
  addRing(plc, [0, 0, 1, 0, 1, 1, 0, 1]);
  const cell = 1 / k;
  for (let i = 0; i < k; i++) {
    for (let j = 0; j < k; j++) {
      const x0 = (i + 0.3) * cell, y0 = (j + 0.3) * cell, x1 = (i + 0.7) * cell, y1 = (j + 0.7) * cell;
      addRing(plc, [x0, y0, x1, y0, x1, y1, x0, y1]);
      plc.holes.push((i + 0.5) * cell, (j + 0.5) * cell);
    }
  }
  return plc;
}

// n pseudo-random points (xorshift32) inside the unit square, whose boundary is a polygon.
export function scatteredInSquare(n, seed = 2463534242) {
  const plc = emptyPlc();
  addRing(plc, [0, 0, 1, 0, 1, 1, 0, 1]);
  let x = seed;
  const next = () => {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    return 0.01 + 0.98 * ((x >>> 0) / 4294967296);
  };
  for (let i = 0; i < n; i++) plc.points.push(next(), next());
  return plc;
}

/** [{ name, family, plc }]: every family at its sizes. */
export function generatedFamilies() {
  const sizes = {
    comb: [[comb, 3], [comb, 10], [comb, 40], [comb, 200]],
    star: [[star, 5], [star, 20], [star, 100], [star, 500]],
    perforated: [[perforated, 1], [perforated, 3], [perforated, 10], [perforated, 30]],
    scattered: [[scatteredInSquare, 10], [scatteredInSquare, 100], [scatteredInSquare, 1000], [scatteredInSquare, 10000]],
  };
  return Object.entries(sizes).flatMap(([family, list]) =>
    list.map(([make, size]) => ({ name: `${family}-${size}`, family, plc: make(size) })));
}
