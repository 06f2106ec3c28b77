// Probe (the size of meshes above 34 degrees): how many triangles would greedy vertex
// removal take out of a finished mesh? Each free Steiner vertex (a circumcenter or off-center, not
// on a segment) is removed when the Delaunay triangulation of its star's ring has every angle at the
// bound; passes repeat until none goes. If the meshes at 38-40 degrees were bloated by vertices the
// bound does not need, this would shrink them toward the 33-degree mesh.
//
// Usage: node tests/bench/coarsening-probe.mjs [--cli build-native/core/ruppert] [--angle 40] FILE.poly...
import { execFileSync } from 'node:child_process';
import { cornerDegrees } from './mesh-exemptions.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i < 0 ? fallback : args.splice(i, 2)[1];
};
const cli = option('--cli', 'build-native/core/ruppert');
const angle = Number(option('--angle', '40'));
const FREE_KINDS = new Set([2, 3]);  // VertexKind Interior, OffCenter (ruppert.h)

function mesh(file, minAngle) {
  const out = execFileSync(cli, ['--quiet', '--min-angle', String(minAngle), '--format', 'json', '-o', '-', file],
    { maxBuffer: 1 << 30, timeout: 120000 });
  return JSON.parse(out);
}

const orient = (a, b, c) => (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
function inCircle(a, b, c, d) {
  const [ax, ay, bx, by, cx, cy] = [a[0] - d[0], a[1] - d[1], b[0] - d[0], b[1] - d[1], c[0] - d[0], c[1] - d[1]];
  return (ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay) +
    (cx * cx + cy * cy) * (ax * by - bx * ay);
}
function smallestAngle(a, b, c) {
  const at = (p, q, r) => cornerDegrees(p[0], p[1], q[0], q[1], r[0], r[1]);
  return Math.min(at(a, b, c), at(b, c, a), at(c, a, b));
}

// The ring around v in counter-clockwise order, or null where v is on the boundary.
function ringOf(v, star, tris) {
  const next = new Map();
  for (const t of star.get(v)) {
    const [a, b, c] = tris.get(t);
    const e = a === v ? [b, c] : b === v ? [c, a] : [a, b];
    next.set(e[0], e[1]);
  }
  const first = next.keys().next().value;
  const ring = [first];
  for (let u = next.get(first); u !== first; u = next.get(u)) {
    if (u === undefined || ring.length > next.size) return null;
    ring.push(u);
  }
  return ring.length === star.get(v).size ? ring : null;
}

// Delaunay ears of a star-shaped ring (one always exists), or null.
function delaunayEars(ring, pt) {
  const poly = ring.slice(), out = [];
  while (poly.length > 3) {
    let cut = -1;
    for (let i = 0; i < poly.length && cut < 0; ++i) {
      const a = poly[(i + poly.length - 1) % poly.length], b = poly[i], c = poly[(i + 1) % poly.length];
      if (orient(pt(a), pt(b), pt(c)) <= 0) continue;
      if (poly.every((w) => w === a || w === b || w === c || inCircle(pt(a), pt(b), pt(c), pt(w)) <= 0)) cut = i;
    }
    if (cut < 0) return null;
    out.push([poly[(cut + poly.length - 1) % poly.length], poly[cut], poly[(cut + 1) % poly.length]]);
    poly.splice(cut, 1);
  }
  return orient(pt(poly[0]), pt(poly[1]), pt(poly[2])) > 0 ? [...out, poly] : null;
}

function coarsen(m) {
  const pt = (i) => [m.points[2 * i], m.points[2 * i + 1]];
  const tris = new Map(), star = new Map();
  let id = 0;
  const add = (tri) => {
    tris.set(id, tri);
    for (const u of tri) (star.get(u) ?? star.set(u, new Set()).get(u)).add(id);
    ++id;
  };
  for (let t = 0; t < m.triangles.length / 3; ++t) add(m.triangles.slice(3 * t, 3 * t + 3));
  for (let removed = 1, pass = 0; removed > 0 && pass < 20; ++pass) {
    removed = 0;
    for (const v of [...star.keys()]) {
      if (!FREE_KINDS.has(m.vertexKinds[v])) continue;
      const ring = ringOf(v, star, tris);
      const ears = ring && delaunayEars(ring, pt);
      if (!ears || ears.some((e) => smallestAngle(pt(e[0]), pt(e[1]), pt(e[2])) < angle)) continue;
      for (const t of [...star.get(v)]) {
        for (const u of tris.get(t)) star.get(u).delete(t);
        tris.delete(t);
      }
      star.delete(v);
      ears.forEach(add);
      ++removed;
    }
  }
  return tris.size;
}

function areas(m) {
  const p = m.points, t = m.triangles, out = [];
  for (let k = 0; k < t.length; k += 3) {
    const [a, b, c] = [t[k], t[k + 1], t[k + 2]];
    out.push(Math.abs((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2);
  }
  return out;
}

console.log(`| input | 33° mesh | ${angle}° mesh | after removal | removed | ${angle}° triangles smaller than every 33° one |`);
console.log('|---|---|---|---|---|---|');
for (const file of args) {
  const m33 = mesh(file, 33);
  const base = m33.triangles.length / 3, smallest = Math.min(...areas(m33));
  const m = mesh(file, angle);
  const smaller = areas(m).filter((a) => a < smallest).length;
  const before = m.triangles.length / 3, after = coarsen(m);
  const share = (100 * (before - after) / before).toFixed(1);
  console.log(`| ${file.split('/').pop()}${m.complete ? '' : ' (incomplete)'} | ${base} | ${before} | ${after} | ${share}% | ${smaller} |`);
}
