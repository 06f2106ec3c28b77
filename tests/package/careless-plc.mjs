// Random PLCs of the kind careless callers make, for the package's sweep (careless.test.mjs):
// polygons that cross themselves, segments crossing and overlapping each other, duplicate and
// near-duplicate points, points on segments, segments that nearly overlap (sharing an end, or
// ending a hair apart, at angles down to 1e-12 rad), and hole seeds anywhere.
//
// Every coordinate is exact in doubles: a point is an integer grid position (0..1024) times a cell
// of 2^-50 to 2^10 (extents 2^-40 to 2^20), plus an offset of 0 (at the origin) or of up to 2^31
// extents (far from it), and near-duplicates and near-overlaps move a point by a power of two that
// the offset still resolves. Deterministic for a seed on every platform (its own generator).

// mulberry32: a small 32-bit generator whose sequence depends only on the seed.
function generator(seed) {
  let state = seed >>> 0;
  const next = () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let z = state;
    z = Math.imul(z ^ (z >>> 15), z | 1);
    z ^= z + Math.imul(z ^ (z >>> 7), z | 61);
    return ((z ^ (z >>> 14)) >>> 0) / 2 ** 32;
  };
  const below = (n) => Math.floor(next() * n);
  return { next, below, chance: (p) => next() < p, pick: (list) => list[below(list.length)] };
}

const kGrid = 1024;

/** One careless PLC and the options to mesh it with. */
export function carelessPlc(seed) {
  const r = generator(seed * 2654435761 + 12345);
  const cell = 2 ** (r.below(61) - 50);
  const far = r.chance(0.5);
  // Offsets in whole cells, below 2^41 cells, so that (offset + grid) * cell keeps 53 bits.
  const offset = far ? [r.below(2 ** 20) * 2 ** 21 - 2 ** 40, r.below(2 ** 20) * 2 ** 21] : [-kGrid / 2, -kGrid / 2];
  const points = [], segments = [], holes = [];
  const add = (x, y) => (points.push(x, y), points.length / 2 - 1);
  const gridPoint = () => add((offset[0] + r.below(kGrid + 1)) * cell, (offset[1] + r.below(kGrid + 1)) * cell);
  const xy = (i) => [points[2 * i], points[2 * i + 1]];
  const join = (a, b) => segments.push(a, b);
  const anyPoint = () => (points.length ? r.below(points.length / 2) : gridPoint());
  // A point `steps` binary orders below the cell away from point i, or a grid point when the
  // offset cannot resolve it (the sum would round).
  const nudged = (i, steps) => {
    const [x, y] = xy(i);
    const d = cell * 2 ** -steps, dx = r.pick([d, -d, 0]), dy = dx === 0 ? r.pick([d, -d]) : r.pick([d, -d, 0]);
    return x + dx - x === dx && y + dy - y === dy ? add(x + dx, y + dy) : gridPoint();
  };
  const actions = [
    () => { // a polygon of 3 to 7 random points, crossing itself more often than not
      const first = gridPoint();
      let last = first;
      for (let k = 1 + r.below(6); k > 0; k--) { const next = gridPoint(); join(last, next); last = next; }
      join(last, first);
    },
    () => join(gridPoint(), gridPoint()), // a free segment, crossing whatever it meets
    () => join(anyPoint(), anyPoint()), // between existing points: duplicates, overlaps, zero length
    () => { // collinear overlap: a segment over part of another, or beyond it
      if (segments.length < 2) return;
      const s = r.below(segments.length / 2), [ax, ay] = xy(segments[2 * s]), [bx, by] = xy(segments[2 * s + 1]);
      const at = (t) => add(ax + t * (bx - ax), ay + t * (by - ay));
      join(at(r.pick([-0.5, 0, 0.25, 0.5])), at(r.pick([0.75, 1, 1.5])));
    },
    () => { // a point in the middle of a segment, sometimes joined to another point
      if (segments.length < 2) return;
      const s = r.below(segments.length / 2), [ax, ay] = xy(segments[2 * s]), [bx, by] = xy(segments[2 * s + 1]);
      const m = add(ax + (bx - ax) / 2, ay + (by - ay) / 2);
      if (r.chance(0.5)) join(m, anyPoint());
    },
    () => { const i = anyPoint(); add(...xy(i)); if (r.chance(0.5)) join(points.length / 2 - 1, anyPoint()); },
    () => { const i = anyPoint(); join(nudged(i, r.below(40)), anyPoint()); }, // near-duplicate point
    () => { // a near-overlap: from a segment's end to a hair beside its other end, or beside itself
      if (segments.length < 2) return;
      const s = r.below(segments.length / 2), a = segments[2 * s], b = segments[2 * s + 1];
      const start = r.chance(0.6) ? a : nudged(a, 10 + r.below(30));
      join(start, nudged(b, r.below(42)));
    },
    () => { // a hole seed anywhere: on a grid point (maybe a vertex), or between them
      const c = () => (r.below(kGrid + 1) + (r.chance(0.5) ? 0.5 : 0));
      holes.push((offset[0] + c()) * cell, (offset[1] + c()) * cell);
    },
  ];
  for (let k = 4 + r.below(12); k > 0; k--) r.pick(actions)();
  if (segments.length === 0) actions[0]();
  const minAngle = r.pick([0, 0, 20, 30, 33]);
  return { plc: { points, segments, holes }, options: { minAngle, maxSteiner: 20000 }, cell, far };
}

/** The PLC as .poly text, its options in the first line (for a finding to become a fixture). */
export function toPolyText({ plc, options }) {
  const lines = [`# options ${JSON.stringify(options)}`, `${plc.points.length / 2} 2 0 0`];
  for (let i = 0; i < plc.points.length / 2; i++) lines.push(`${i} ${plc.points[2 * i]} ${plc.points[2 * i + 1]}`);
  lines.push(`${plc.segments.length / 2} 0`);
  for (let i = 0; i < plc.segments.length / 2; i++) lines.push(`${i} ${plc.segments[2 * i]} ${plc.segments[2 * i + 1]}`);
  lines.push(`${plc.holes.length / 2}`);
  for (let i = 0; i < plc.holes.length / 2; i++) lines.push(`${i} ${plc.holes[2 * i]} ${plc.holes[2 * i + 1]}`);
  return `${lines.join('\n')}\n`;
}
