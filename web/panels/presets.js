// Example drawings. Each builds points + segments from simple outlines, so the coordinates can be
// read (and changed) here. A preset may carry options (applied when it is chosen, over the page's
// current ones), a one-line caption naming the chapter's figure it redraws, and `steps: true` to
// open it in step-by-step mode, and `stages` (a function of the trace) to name the steps that
// show a figure's snapshots.
import { EventKind } from '../../wasm/index.js';
import { flagOptions } from '../model/drawing.js';

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

/**
 * The chapter's Figure 6.4: a polygon with a segment ab inside it, every segment an edge of the
 * Delaunay triangulation of the vertices (so stage (b) is that triangulation). With circumcenters,
 * diametral disks and 30 degrees its refinement runs as the figure's does: the bottom edge is split
 * at its midpoint first, then a second encroached edge, then a skinny triangle's circumcenter
 * falls in ab's diametral disk and is rejected, ab being split instead (13 steps in all).
 */
function figure64() {
  const d = blank();
  ring(d, [0, 0.5, 6.5, -0.5, 9, 0, 10.5, 4, 7, 5.5, 7.5, 7.5, 3, 8.5, 2, 5.5, -0.5, 5.5]);
  const a = d.points.length / 2;
  d.points.push(1.8, 2.3, 6.8, 4.5);  // a and b
  d.segments.push(a, a + 1);
  return d;
}

/** A rectangle with a segment near its bottom: skinny triangles' circumcenters fall in its disk. */
function encroachedSegment() {
  const d = blank();
  ring(d, [0, 0, 12, 0, 12, 4, 0, 4]);
  d.points.push(3, 0.6, 9, 0.6);
  d.segments.push(4, 5);
  return d;
}

/** Two segments 15 degrees apart inside a rectangle: splits near their shared vertex go to shells. */
function narrowCorner() {
  const d = blank();
  ring(d, [-2, -2, 12, -2, 12, 6, -2, 6]);
  d.points.push(0, 0, 10, 0, 9.659258, 2.58819);
  d.segments.push(4, 5, 4, 6);
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

/**
 * A square 100 wide with a triangle 0.5 wide near one corner: the local feature size runs from
 * about 0.5 there to about 50 at the far side, so the mesh grades over two orders of magnitude.
 */
function smallFeature() {
  const d = blank();
  ring(d, [0, 0, 100, 0, 100, 100, 0, 100]);
  ring(d, [12, 12, 12.5, 12, 12.25, 12.45]);
  d.holes.push(12.25, 12.15);
  return d;
}

/**
 * The first sight: the README's lake (an octagon with an island that is a hole) with a second,
 * small island and a jetty, so that the mesh grades visibly towards the small features.
 */
function lake() {
  const d = blank();
  ring(d, [0, 0, 4, -1, 8, 0, 10, 3, 8, 7, 4, 8, 1, 6, -1, 3]);
  ring(d, [4, 3, 6, 3, 6, 5, 4, 4.5]);
  d.holes.push(5, 3.8);
  ring(d, [7.6, 1.2, 7.75, 1.25, 7.675, 1.3725]);  // 0.15 wide: about 25 times the smallest triangles' size
  d.holes.push(7.675, 1.275);
  const jetty = d.points.length / 2;
  d.points.push(1, 1.5, 2.2, 2.6);
  d.segments.push(jetty, jetty + 1);
  return d;
}

/** Segments 5 degrees apart meeting at one vertex, inside a rectangle: small input angles (chapter 6.6). */
function smallAngleFan() {
  const d = blank();
  ring(d, [-5, -5, 15, -5, 15, 10, -5, 10]);
  const center = d.points.length / 2;
  d.points.push(0, 0);
  const spokes = 7;
  for (let i = 0; i < spokes; i++) {
    const angle = (i * 5 * Math.PI) / 180;
    d.points.push(Number((10 * Math.cos(angle)).toFixed(6)), Number((10 * Math.sin(angle)).toFixed(6)));
    d.segments.push(center, center + 1 + i);
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

/**
 * The chapter's Figure 6.9: two polygons, the top one extremely thin compared to the bottom one;
 * the mesh grades from the thin polygon's tiny features to the large one's.
 */
function twoPolygons() {
  const d = blank();
  ring(d, [0, 0, 12, 0, 14, 4, 10, 7, 3, 6.5, -1, 3]);
  ring(d, [0.5, 8, 13.5, 8.6, 13.5, 8.75, 0.5, 8.2]);
  return d;
}

/**
 * The unit square with a round hole of radius 0.25 at its center: the hole is two arcs
 * between (0.75, 0.5) and (0.25, 0.5); its seed sits off the center, so that the Select tool picks the
 * center handle there.
 */
function plateWithRoundHole() {
  const d = blank();
  ring(d, [0, 0, 1, 0, 1, 1, 0, 1]);
  d.points.push(0.75, 0.5, 0.25, 0.5);
  d.curves = [{ type: 'arc', from: 4, to: 5, center: [0.5, 0.5] }, { type: 'arc', from: 5, to: 4, center: [0.5, 0.5] }];
  d.holes.push(0.5, 0.6);
  return d;
}

export const PRESETS = [
  {
    id: 'lake', name: 'A lake with islands and a jetty (the first sight)', build: lake, options: { maxArea: 0.5 },
    caption: 'A lake with two islands (holes) and a jetty, no angle under 30° and no triangle larger than 0.5: ' +
      'the triangles shrink towards the small island and the jetty. Drag a vertex, change the angle, or pick a figure of the chapter.',
  },
  {
    id: 'skyline', name: 'Fig. 6.1: skyline at 28°', build: skyline, options: { minAngle: 28 },
    caption: 'Figure 6.1: a skyline and its Delaunay mesh with no angle under 28°.',
  },
  {
    id: 'figure-6-4', name: 'Fig. 6.4 (a)-(f): the refinement step by step', build: figure64, steps: true,
    // The algorithm of §6.2 as the book runs it: circumcenters, closed diametral disks (encroached
    // subsegments are always split first: the core's refinement loop has no other order).
    options: { minAngle: 30, placement: 'circumcenter', encroachment: 'disk' },
    caption: 'Figure 6.4: the algorithm of §6.2 (circumcenters, diametral disks, encroached subsegments first); ' +
      'the stage buttons (a)-(f) under the canvas show the figure\'s six snapshots.',
    stages: figure64Stages,
  },
  {
    id: 'encroachment', name: 'Encroachment and rejection (diametral disks)', build: encroachedSegment, steps: true,
    options: { minAngle: 30, placement: 'circumcenter', encroachment: 'disk' },
    caption: 'Encroachment (§6.2): circumcenters that fall in a subsegment\'s diametral disk are rejected and the subsegment split; ' +
      'switch Encroachment to the lens for fewer splits.',
  },
  {
    id: 'shells', name: 'Concentric shells: a 15° corner', build: narrowCorner, steps: true,
    options: { minAngle: 25, placement: 'circumcenter', encroachment: 'disk' },
    caption: 'Concentric shells (§6.6): near the 15° corner a subsegment is split on a circle of power-of-two radius, not at its midpoint; ' +
      'step to the shell splits (drawn with their shell).',
  },
  {
    id: 'placement-circumcenter', name: 'Circumcenters: two sizes at 33°', build: twoSizes,
    options: { minAngle: 33, placement: 'circumcenter' },
    caption: 'Circumcenters at 33°: about 1,100 triangles. Open "Off-centers: two sizes at 33°" to compare (§6.8).',
  },
  {
    id: 'placement-offcenter', name: 'Off-centers: two sizes at 33°', build: twoSizes,
    options: { minAngle: 33, placement: 'offcenter' },
    caption: 'Off-centers at 33°: about 200 triangles, five times fewer than circumcenters on the same input (§6.8).',
  },
  {
    id: 'placement-compare', name: 'Off-centers against circumcenters, side by side (33°)', build: twoSizes,
    // Both meshes are made by compare-view.js; the main mesh (the Mesh panel's) is the off-centers'.
    options: { minAngle: 33, placement: 'offcenter' }, compare: ['circumcenter', 'offcenter'],
    caption: 'Off-centers against circumcenters (§6.8): the same input at the same angle, one mesh per placement; ' +
      'compare the triangle counts under the two pictures. Change the min angle: both are meshed again.',
  },
  {
    id: 'size-measure', name: 'The size measure: a small feature far from a large one', build: smallFeature,
    options: flagOptions('size-measure'),
    caption: 'The size measure (§6.5): the local feature size is tiny near the small triangle and large far from it, ' +
      'and the triangles grow with it. Look at the grading, and at the Mesh panel\'s Size measure row: ' +
      'the integral of 1/lfs², to which a good mesh\'s triangle count is proportional.',
  },
  ...[5, 20, 30, 34.2].map((angle) => ({
    id: `figure-6-9-${String(angle).replace('.', '-')}`,
    name: `Fig. 6.9: two polygons at ${angle}°`,
    build: twoPolygons,
    options: { minAngle: angle },
    caption: `Figure 6.9: two polygons, the top one very thin, meshed with no angle under ${angle}° (the chapter shows 5, 20, 30 and 34.2°).`,
  })),
  {
    id: 'fan', name: 'Figs. 6.12-6.14: small input angles (5° fan)', build: smallAngleFan,
    caption: 'Figures 6.12-6.14: segments 5° apart. Concentric-shell splits stop the ping-pong of Fig. 6.12; ' +
      'triangles in the small angles and with seditious edges are left as they are.',
  },
  {
    id: 'comb', name: 'Fig. 6.16 right: comb, constrained Delaunay', build: comb, options: { variant: 'cdt' },
    title: 'Teeth 1 wide, gaps 0.05 wide. Compare with Fig. 6.16 left, Ruppert\'s original algorithm in a ' +
      'bounding box, or switch Algorithm: the box refines the narrow gaps outside too.',
    caption: 'Figure 6.16, right: the comb meshed by constrained Delaunay refinement: the narrow gaps outside are never looked across.',
  },
  {
    id: 'comb-box', name: 'Fig. 6.16 left: comb, Delaunay in a box', build: comb, options: { variant: 'box', minAngle: 20 },
    caption: 'Figure 6.16, left: Ruppert\'s original algorithm meshes a bounding box; the gaps are refined to their tiny width.',
  },
  { id: 'square-hole', name: 'Square with a square hole', build: squareWithHole },
  {
    id: 'plate-round-hole', name: 'A plate with a round hole (curves)', build: plateWithRoundHole,
    caption: 'A unit square with a hole of radius 0.25: the circle is two arcs, and every vertex on it lies on the circle. ' +
      'Drag the center handle (Select) to change the radius, or set the curve tolerance.',
  },
  { id: 'two-sizes', name: 'Two polygons of very different sizes, with regions', build: twoSizes },
];

// The first sight: a drawing whose mesh shows refinement (about 200 triangles, graded towards its
// small features) at the default angle; Fig. 6.9 at 30 degrees with the default placement is ten
// large triangles and a sliver.
export const DEFAULT_PRESET = 'lake';

const { SEGMENT_SPLIT, REJECTED } = EventKind;

/**
 * Figure 6.4's six stages in a trace of figure64 (or of an edited drawing: the stages found in
 * it): [{ figure, label, step, inputOnly, preview, caption }], `step` the replay's step that shows it;
 * (a) is step 0 with the input alone, (d) the step before the first rejected circumcenter with that
 * circumcenter drawn as considered (`preview`: the next event's triangle).
 */
export function figure64Stages(events) {
  if (!events || events.count === 0) return [];
  let split = -1;
  let rejected = -1;
  for (let e = 0; e < events.count && rejected < 0; e++) {
    if (events.kind[e] === SEGMENT_SPLIT && split < 0) split = e;
    if (events.kind[e] === REJECTED) rejected = e;
  }
  const stages = [
    { label: '(a)', step: 0, inputOnly: true, caption: 'The input PLC: a polygon and the segment ab inside it.' },
    { label: '(b)', step: 0, caption: 'The Delaunay triangulation of the input vertices: every segment is one of its edges.' },
  ];
  if (split >= 0 && (rejected < 0 || split < rejected)) {
    stages.push({ label: '(c)', step: split + 1, caption: 'The bottom edge is encroached, so it is split at its midpoint p.' });
  }
  if (rejected >= 0) {
    stages.push({
      label: '(d)', step: rejected, preview: true,
      caption: 'After all the encroached subsegments are split, the outlined triangle has poor quality, ' +
        'so the algorithm considers inserting its circumcenter c.',
    });
    stages.push({
      label: '(e)', step: rejected + 1,
      caption: 'Because c encroaches upon the segment ab (it lies in ab\'s diametral disk), c is not inserted; instead ab is split.',
    });
  }
  stages.push({ label: '(f)', step: events.count, caption: 'The final mesh.' });
  return stages.map((s) => ({ figure: 'Fig. 6.4', ...s }));
}

export function presetDrawing(id) {
  const preset = PRESETS.find((p) => p.id === id);
  return preset ? preset.build() : null;
}

/** The preset of that id (with its options, caption and steps flag), or null. */
export function findPreset(id) {
  return PRESETS.find((p) => p.id === id) ?? null;
}
