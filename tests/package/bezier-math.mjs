// Cubic Béziers for the tests' own checks of curved boundaries (package and browser tests), apart
// from the core's curve code: c = [x0, y0, x1, y1, x2, y2, x3, y3].

/** The cubic's point at parameter t. */
export function bezierAt(c, t) {
  const s = 1 - t, w = [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t];
  return [0, 1].map((k) => w[0] * c[k] + w[1] * c[2 + k] + w[2] * c[4 + k] + w[3] * c[6 + k]);
}

/** The parameter of the cubic's point nearest q: dense samples, then a ternary search around the best. */
export function nearestT(c, q) {
  const d2 = (t) => { const [x, y] = bezierAt(c, t); return (x - q[0]) ** 2 + (y - q[1]) ** 2; };
  let best = 0;
  for (let i = 1; i <= 4096; i++) if (d2(i / 4096) < d2(best)) best = i / 4096;
  let lo = Math.max(0, best - 1 / 4096), hi = Math.min(1, best + 1 / 4096);
  for (let k = 0; k < 200; k++) {
    const m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (d2(m1) < d2(m2)) hi = m2; else lo = m1;
  }
  return (lo + hi) / 2;
}

/** Distance from q to the cubic. */
export function distanceToBezier(c, q) {
  const [x, y] = bezierAt(c, nearestT(c, q));
  return Math.hypot(x - q[0], y - q[1]);
}
