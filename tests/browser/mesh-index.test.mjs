// The page's point location (web/geometry/mesh-index.js), against a scan of every triangle, on meshes with
// holes and notches (where walks meet the boundary and the bucket grid answers) and a convex one.
// Plain node: the module needs no browser.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { presetDrawing } from '../../web/panels/presets.js';
import { locateTriangle } from '../../web/geometry/mesh-index.js';

function containing(mesh, x, y) {
  const p = mesh.points; const tri = mesh.triangles;
  const found = [];
  for (let t = 0; t < tri.length / 3; t++) {
    const [i, j, k] = [2 * tri[3 * t], 2 * tri[3 * t + 1], 2 * tri[3 * t + 2]];
    const side = (a, b) => (p[b] - p[a]) * (y - p[a + 1]) - (p[b + 1] - p[a + 1]) * (x - p[a]);
    if (side(i, j) >= 0 && side(j, k) >= 0 && side(k, i) >= 0) found.push(t);
  }
  return found;
}

test('locateTriangle finds the triangle a scan finds, from any hint, across holes and notches', async () => {
  const mesher = await init();
  let seed = 7;
  const random = () => { seed = (seed * 16807) % 2147483647; return seed / 2147483647; };
  for (const [preset, maxArea] of [['square-hole', 0.05], ['comb', 0.02], ['skyline', 0], ['fan', 0]]) {
    const drawing = { ...presetDrawing(preset), options: { ...DEFAULT_OPTIONS, maxArea } };
    const mesh = mesher.triangulate(toPlc(drawing), toMeshOptions(drawing));
    const p = mesh.points;
    let minX = Infinity; let minY = Infinity; let maxX = -Infinity; let maxY = -Infinity;
    for (let i = 0; i < p.length; i += 2) {
      minX = Math.min(minX, p[i]); maxX = Math.max(maxX, p[i]); minY = Math.min(minY, p[i + 1]); maxY = Math.max(maxY, p[i + 1]);
    }
    let hint = -1; let inside = 0; let outside = 0;
    for (let q = 0; q < 400; q++) {
      const x = minX - 0.05 * (maxX - minX) + random() * 1.1 * (maxX - minX);
      const y = minY - 0.05 * (maxY - minY) + random() * 1.1 * (maxY - minY);
      const expected = containing(mesh, x, y);
      const t = locateTriangle(mesh, x, y, q % 3 === 0 ? -1 : hint);
      if (expected.length === 0) {
        assert.equal(t, -1, `${preset}: (${x}, ${y}) is in no triangle, found ${t}`);
        outside++;
      } else {
        assert.ok(expected.includes(t), `${preset}: (${x}, ${y}) is in ${expected.join(' or ')}, found ${t}`);
        inside++;
        hint = t;
      }
    }
    assert.ok(inside > 100 && outside > 10, `${preset}: ${inside} points inside, ${outside} outside`);
  }
});
