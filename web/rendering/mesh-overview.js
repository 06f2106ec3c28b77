// The overview picture of a mesh, rasterized on the CPU for gl-mesh.js: the whole mesh as one
// texture, shown for the triangles too small on screen to be worth drawing as triangles. One sample
// per texel at its center, in the color of the triangle there; the edges as the gray their
// density gives (the share of a one-device-pixel line, at the scale that fits the mesh, that they
// cover in the triangle). `box`: the mesh's { minX, minY, maxX, maxY }, `fit` (device pixels per
// world unit when the box fills the canvas) and `limit` (the largest texture). Both return
// { image: Uint32Array of little-endian RGBA texels, size: { width, height, sx, sy } } with
// sx, sy texels per world unit.
import { walk } from '../geometry/mesh-index.js';

/**
 * Texels across the box's longer side in the sharp overview: texels of at most 2 device pixels
 * while the box is up to 1280 device pixels across.
 */
export const OVERVIEW_TEXELS = 2560;

/** '#rrggbb' or 'rgba(r, g, b, a)' as four numbers in 0..1. */
export function parseColor(css) {
  if (css.startsWith('#')) {
    const n = parseInt(css.slice(1), 16);
    return [(n >> 16 & 255) / 255, (n >> 8 & 255) / 255, (n & 255) / 255, 1];
  }
  const [r, g, b, a = 1] = css.replace(/[^\d.,]/g, '').split(',').map(Number);
  return [r / 255, g / 255, b / 255, a];
}

/** The overview's texels: `texels` across the box's longer side, within the GL's limit. */
function overviewSize(box, texels) {
  const { minX, minY, maxX, maxY, limit } = box;
  const w = Math.max(maxX - minX, 1e-300); const h = Math.max(maxY - minY, 1e-300);
  const perUnit = Math.max(1, Math.min(texels, limit)) / Math.max(w, h);
  const width = Math.max(1, Math.min(limit, Math.ceil(w * perUnit)));
  const height = Math.max(1, Math.min(limit, Math.ceil(h * perUnit)));
  return { width, height, sx: width / w, sy: height / h };
}

/** Texel colors of each class with an edge share of q / 16 blended in: shades[17 * class + q]. */
function shadeTable(palette, edgeColor) {
  const [er, eg, eb, ea] = parseColor(edgeColor);
  const shades = new Uint32Array(palette.length * 17);
  palette.forEach((css, c) => {
    const [fr, fg, fb] = parseColor(css);
    for (let q = 0; q <= 16; q++) {
      const on = (q / 16) * ea;
      const r = Math.round(255 * (fr + (er - fr) * on)); const g = Math.round(255 * (fg + (eg - fg) * on));
      const b = Math.round(255 * (fb + (eb - fb) * on));
      shades[17 * c + q] = ((255 << 24) | (b << 16) | (g << 8) | r) >>> 0;  // little-endian RGBA bytes
    }
  });
  return shades;
}

/**
 * The quick overview of a large mesh (its first picture): one texel per device pixel at the
 * scale that fits the mesh, each texel's triangle found by walking from the previous texel's
 * (or the one above it), so only the triangles under texel centers are looked at. A texel whose
 * walk meets the boundary from both starts (outside the domain, or behind a hole or a notch)
 * stays transparent; the sharp overview made with the triangles fills it a moment later.
 */
export function walkOverview(mesh, box, palette, classOf, edgeColor) {
  const p = mesh.points;
  const tri = mesh.triangles;
  const { minX, minY, maxX, maxY, fit } = box;
  const size = overviewSize(box, Math.min(OVERVIEW_TEXELS, fit * Math.max(maxX - minX, maxY - minY)));
  const shades = shadeTable(palette, edgeColor);
  const lineTexels = size.sx / fit;  // one device pixel at the scale that fits the mesh
  const image = new Uint32Array(size.width * size.height);
  const above = new Int32Array(size.width).fill(-1);
  const seen = new Uint32Array(tri.length / 3);  // triangle -> its texel color (0: not yet)
  // The first walk starts at the triangle whose first corner is nearest the first texel.
  let last = 0;
  let best = Infinity;
  const fx = minX + 0.5 / size.sx; const fy = minY + 0.5 / size.sy;
  for (let t = 0; t < tri.length / 3; t++) {
    const v = 2 * tri[3 * t];
    const d = (p[v] - fx) * (p[v] - fx) + (p[v + 1] - fy) * (p[v + 1] - fy);
    if (d < best) { best = d; last = t; }
  }
  for (let y = 0; y < size.height; y++) {
    const wy = minY + (y + 0.5) / size.sy;
    for (let x = 0; x < size.width; x++) {
      const wx = minX + (x + 0.5) / size.sx;
      let t = walk(mesh, last, wx, wy, 512);
      if (t < 0 && above[x] >= 0) t = walk(mesh, above[x], wx, wy, 512);
      above[x] = t;
      if (t < 0) continue;
      last = t;
      let color = seen[t];
      if (color === 0) {
        const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
        const perimeter = Math.hypot(p[j] - p[i], p[j + 1] - p[i + 1]) + Math.hypot(p[k] - p[j], p[k + 1] - p[j + 1]) +
          Math.hypot(p[i] - p[k], p[i + 1] - p[k + 1]);
        const area2 = Math.abs((p[j] - p[i]) * (p[k + 1] - p[i + 1]) - (p[j + 1] - p[i + 1]) * (p[k] - p[i]));
        const on = area2 > 0 ? (lineTexels * perimeter) / (area2 * size.sx) : 1;
        color = shades[17 * classOf(t) + (on >= 1 ? 16 : Math.round(on * 16))];
        seen[t] = color;
      }
      image[y * size.width + x] = color;
    }
    last = above[0] >= 0 ? above[0] : last;
  }
  return { image, size };
}

/**
 * The sharp overview: every triangle rasterized (one sample per texel at its center, found by
 * scanning the triangle's texel box), OVERVIEW_TEXELS across the box's longer side: texels of
 * at most 2 device pixels up to 1280 device pixels across the box. The edges are the share of
 * a one-device-pixel line (at the scale that fits the mesh) they would cover in the triangle:
 * half its perimeter times the line's width, over its area.
 */
export function rasterizeOverview(mesh, box, palette, classes, edgeColor) {
  const p = mesh.points;
  const tri = mesh.triangles;
  const { minX, minY } = box;
  const size = overviewSize(box, OVERVIEW_TEXELS);
  const { width, height, sx, sy } = size;
  const lineTexels = sx / box.fit;
  const shades = shadeTable(palette, edgeColor);
  const image = new Uint32Array(width * height);  // transparent where there is no triangle
  for (let t = 0; t < tri.length / 3; t++) {
    const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
    // Texel coordinates (texel centers at integer + 0.5).
    const ax = (p[i] - minX) * sx; const ay = (p[i + 1] - minY) * sy;
    const bx = (p[j] - minX) * sx; const by = (p[j + 1] - minY) * sy;
    const cx = (p[k] - minX) * sx; const cy = (p[k + 1] - minY) * sy;
    const x0 = Math.max(0, Math.ceil((ax < bx ? (ax < cx ? ax : cx) : (bx < cx ? bx : cx)) - 0.5));
    const x1 = Math.min(width - 1, Math.floor((ax > bx ? (ax > cx ? ax : cx) : (bx > cx ? bx : cx)) - 0.5));
    if (x0 > x1) continue;
    const y0 = Math.max(0, Math.ceil((ay < by ? (ay < cy ? ay : cy) : (by < cy ? by : cy)) - 0.5));
    const y1 = Math.min(height - 1, Math.floor((ay > by ? (ay > cy ? ay : cy) : (by > cy ? by : cy)) - 0.5));
    if (y0 > y1) continue;
    const area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (area2 <= 0) continue;
    const perimeter = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay)) +
      Math.sqrt((cx - bx) * (cx - bx) + (cy - by) * (cy - by)) + Math.sqrt((ax - cx) * (ax - cx) + (ay - cy) * (ay - cy));
    const on = lineTexels * perimeter / area2;
    const color = shades[17 * classes[t] + (on >= 1 ? 16 : Math.round(on * 16))];
    for (let y = y0; y <= y1; y++) {
      const py = y + 0.5;
      for (let x = x0; x <= x1; x++) {
        const px = x + 0.5;
        if ((bx - ax) * (py - ay) - (by - ay) * (px - ax) < 0) continue;
        if ((cx - bx) * (py - by) - (cy - by) * (px - bx) < 0) continue;
        if ((ax - cx) * (py - cy) - (ay - cy) * (px - cx) < 0) continue;
        image[y * width + x] = color;
      }
    }
  }
  return { image, size };
}
