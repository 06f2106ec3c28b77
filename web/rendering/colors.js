// The page's colors: the angle classes, region fills, the drawing's and overlays' colors and
// the segment markers', shared by every picture (the canvas, the curves, the side-by-side view).

/** Min-angle classes for coloring: [upper bound in degrees, color]. */
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

export const REGION_COLORS = ['#dbe7f5', '#f6d8b8', '#cfe8cf', '#ead1ef', '#f8f1b6', '#cdeaea', '#f3cdd3', '#e0e0e0'];

export const COLORS = {
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

// Segment markers (boundary markers): one color each, strong hues drawn over the fills; 0 (no
// marker) in the segments' black. Markers above the table's length reuse its colors in turn.
const MARKER_COLORS = ['#1c7ed6', '#c2255c', '#2b8a3e', '#862e9c', '#0b7285', '#5c940d', '#a61e4d', '#364fc7'];

export function markerColor(marker) {
  if (!marker) return COLORS.segment;
  const n = MARKER_COLORS.length;
  return MARKER_COLORS[(((Math.trunc(marker) - 1) % n) + n) % n];
}

