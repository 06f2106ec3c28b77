// Example drawings. Each builds points + segments from simple outlines, so the coordinates can be
// read (and changed) here.

/** Adds a closed polygon (a ring of segments) and returns its first point index. */
function ring(d, coordinates) {
  const first = d.points.length / 2;
  const n = coordinates.length / 2;
  d.points.push(...coordinates);
  for (let i = 0; i < n; i++) d.segments.push(first + i, first + ((i + 1) % n));
  return first;
}

function blank() {
  return { points: [], segments: [], holes: [], regions: [] };
}

function squareWithHole() {
  const d = blank();
  ring(d, [0, 0, 10, 0, 10, 10, 0, 10]);
  ring(d, [4, 4, 6, 4, 6, 6, 4, 6]);
  d.holes.push(5, 5);
  return d;
}

/** In the spirit of the chapter's Figure 6.4: a small polygon with a segment inside it. */
function figure64() {
  const d = blank();
  ring(d, [0, 0, 6, -0.5, 9, 1, 10, 4, 7.5, 6, 8.5, 8, 3, 8.5, 1.5, 6.5, -1, 5.5]);
  const a = d.points.length / 2;
  d.points.push(2, 2.5, 7, 4.2);
  d.segments.push(a, a + 1);
  return d;
}

function skyline() {
  const d = blank();
  // Walk along the roofs from left to right, then back along the ground.
  const roof = [
    0, 3, 2, 3, 2, 7, 3.5, 7, 3.5, 5, 5, 5, 5, 11, 5.6, 12, 6.2, 11, 6.2, 5, 7.5, 5, 7.5, 8,
    9.5, 8, 9.5, 4, 11, 4, 11, 9.5, 11.8, 9.5, 11.8, 10.5, 12.6, 10.5, 12.6, 9.5, 13.4, 9.5, 13.4, 6,
    15, 6, 15, 2.5, 17, 2.5, 17, 7, 18, 7.6, 19, 7, 19, 3, 20, 3,
  ];
  ring(d, [...roof, 20, 0, 0, 0]);
  return d;
}

function twoSizes() {
  const d = blank();
  ring(d, [0, 0, 100, 0, 100, 60, 0, 60]);
  // A triangle 1 unit wide inside a 100 x 60 rectangle: the mesh grades from small to large.
  ring(d, [60, 25, 61, 25, 60.5, 25.9]);
  d.regions.push({ x: 20, y: 30, attribute: 1, maxArea: null }, { x: 60.5, y: 25.3, attribute: 2, maxArea: null });
  return d;
}

/** Segments 5 degrees apart meeting at one vertex, inside a rectangle: small input angles (chapter 6.6). */
function smallAngleFan() {
  const d = blank();
  ring(d, [-5, -5, 15, -5, 15, 10, -5, 10]);
  const centre = d.points.length / 2;
  d.points.push(0, 0);
  const spokes = 7;
  for (let i = 0; i < spokes; i++) {
    const angle = (i * 5 * Math.PI) / 180;
    d.points.push(Number((10 * Math.cos(angle)).toFixed(6)), Number((10 * Math.sin(angle)).toFixed(6)));
    d.segments.push(centre, centre + 1 + i);
  }
  return d;
}

/**
 * The chapter's Figure 6.16: a comb whose teeth are separated by narrow gaps outside the domain.
 * Constrained Delaunay refinement never looks across a gap; Ruppert's original algorithm meshes
 * the bounding box, so the gaps themselves are refined to their tiny width and the small
 * triangles spread into the teeth (several times more triangles).
 */
function comb() {
  const d = blank();
  const teeth = 6;
  const width = 1;      // of a tooth
  const gap = 0.05;     // between teeth: narrow compared to the teeth
  const height = 5;     // of a tooth above the back
  const back = 1.5;     // height of the back the teeth stand on
  const pitch = width + gap;
  const at = (x) => Number(x.toFixed(6));  // 1.05 * 6 - 0.05 is 6.250000000000001 in binary
  // Along the bottom, then right to left over the teeth; tooth i spans x in [i pitch, i pitch + width].
  const coordinates = [0, 0, at(teeth * pitch - gap), 0];
  for (let i = teeth - 1; i >= 0; i--) {
    coordinates.push(at(i * pitch + width), back + height, at(i * pitch), back + height);
    if (i > 0) coordinates.push(at(i * pitch), back, at(i * pitch - gap), back);
  }
  ring(d, coordinates);
  return d;
}

export const PRESETS = [
  { id: 'square-hole', name: 'Square with a square hole', build: squareWithHole },
  { id: 'figure-6-4', name: 'Polygon with an interior segment (Fig. 6.4-like)', build: figure64 },
  { id: 'skyline', name: 'Skyline', build: skyline },
  { id: 'two-sizes', name: 'Two polygons of very different sizes', build: twoSizes },
  { id: 'fan', name: 'Small-angle fan (5°)', build: smallAngleFan },
  {
    id: 'comb',
    name: 'Comb (Fig. 6.16): try Algorithm “box”',
    title: 'Teeth 1 wide, gaps 0.05 wide. Switch Algorithm to "Delaunay in a bounding box" to see the ' +
      'over-refinement of Ruppert\'s original algorithm in the gaps.',
    build: comb,
  },
];

export const DEFAULT_PRESET = 'figure-6-4';

export function presetDrawing(id) {
  const preset = PRESETS.find((p) => p.id === id);
  return preset ? preset.build() : null;
}
