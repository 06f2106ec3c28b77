// The page's colours: the angle classes, region fills, the drawing's and overlays' colours and
// the segment markers', shared by every picture (the canvas, the curves, the side-by-side view).

/** Min-angle classes for colouring: [upper bound in degrees, colour]. */
export const ANGLE_CLASSES = [
  [10, '#b2182b'],
  [20, '#e0603f'],
  [25, '#f4a259'],
  [30, '#f6d77a'],
  [35, '#c7e3a5'],
  [40, '#88c9a1'],
  [50, '#5aa9c9'],
  [60.0001, '#4a78b5'],
];

export const REGION_COLOURS = ['#dbe7f5', '#f6d8b8', '#cfe8cf', '#ead1ef', '#f8f1b6', '#cdeaea', '#f3cdd3', '#e0e0e0'];

export const COLOURS = {
  background: '#ffffff',
  grid: '#eef0f4',
  gridStrong: '#d9dde6',
  edge: 'rgba(40, 48, 70, 0.55)',
  segment: '#111827',
  point: '#111827',
  selected: '#d6336c',
  hover: '#1d4ed8',
  hole: '#c92a2a',
  region: '#5f3dc4',
  notice: '#e8590c',
  exempt: '#7048e8',     // triangles nestled in small input angles (§6.6), hatched
  // Seditious edges and their triangles (§6.6): teal, a hue none of the angle classes has (the
  // 20-25° class is orange).
  seditious: '#0b7285',
};

// Segment markers (boundary markers): one colour each, strong hues drawn over the fills; 0 (no
// marker) in the segments' black. Markers above the table's length reuse its colours in turn.
const MARKER_COLOURS = ['#1c7ed6', '#c2255c', '#2b8a3e', '#862e9c', '#0b7285', '#5c940d', '#a61e4d', '#364fc7'];

export function markerColour(marker) {
  if (!marker) return COLOURS.segment;
  const n = MARKER_COLOURS.length;
  return MARKER_COLOURS[(((Math.trunc(marker) - 1) % n) + n) % n];
}

