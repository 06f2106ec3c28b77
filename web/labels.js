// What the page calls the names that come from the core: plain objects keyed by the core's own
// names (the package's VertexKind and EventKind keys, its reason kinds, the values of the
// placement, variant and encroachment options), so that the page's words live in one file and a
// test can check these keys against the names the package exports. No DOM here: Node imports it.

/** mesh.vertexKinds (VertexKind), in the hover line. */
export const VERTEX_KIND_LABELS = {
  INPUT: 'input',
  SEGMENT_SPLIT: 'segment split',
  INTERIOR: 'interior (circumcenter)',
  OFF_CENTER: 'off-center',
  INTERSECTION: 'intersection',
  UNUSED: 'unused',
};

/**
 * mesh.events.kind (EventKind), in the Events row (in this order) and the step texts. The page
 * tells two splits and two rejected points apart by measuring (event-geometry.js): a split off its
 * subsegment's midpoint is a concentric-shell split, and a rejected point is the circumcenter or
 * the off-center (petal and optimal points are never rejected).
 */
export const EVENT_KIND_LABELS = {
  SEGMENT_SPLIT: { midpoint: 'midpoint split', shell: 'shell split', curve: 'curve split' },
  CIRCUMCENTER: 'circumcenter',
  OFF_CENTER: 'off-center',
  PETAL_POINT: 'petal point',
  OPTIMAL_POINT: 'optimal point',
  RELOCATED: 'relocated vertex',
  REJECTED: { circumcenter: 'rejected circumcenter', offCenter: 'rejected off-center' },
};

/**
 * The reasons (mesh.reasons' kinds) whose triangles the page finds and marks itself
 * (mesh.triangleExemptions): their legend rows and their part of the Mesh panel's Exempt row.
 */
export const EXEMPTION_LABELS = {
  SMALL_INPUT_ANGLE: { legend: 'in a small input angle (exempt)', row: 'in small input angles (hatched)' },
  SEDITIOUS_EDGE: { legend: 'seditious edge (exempt)', row: 'on seditious edges (edge in teal)' },
};

/** options.placement, the Steiner placement box's entries (in this order). */
export const PLACEMENT_LABELS = {
  optimal: 'optimal points (fewest triangles, bounds of 35-40°)',
  offcenter: 'off-center (faster)',
  circumcenter: 'circumcenter',
  petal: 'petal',
};

/**
 * The largest min angle each placement usually reaches (README's option table: 35-40 degrees with
 * the optimal points; off-centers about 34, circumcenters about 33): past it the page warns.
 */
export const PRACTICAL_ANGLE = { optimal: 40, offcenter: 34, circumcenter: 33, petal: 34 };

/** options.variant, the Algorithm box's entries. */
export const VARIANT_LABELS = {
  cdt: 'Constrained Delaunay (CDT)',
  box: "Delaunay in a bounding box (Ruppert's original)",
};

/** options.encroachment, the Encroachment box's entries. */
export const ENCROACHMENT_LABELS = {
  lens: 'Diametral lens',
  disk: 'Diametral disk',
};

/** mesh.notices' kinds (NoticeKind): what the mesher repaired in the input, in the list under the canvas. */
export const NOTICE_LABELS = {
  DUPLICATE_POINT: 'Duplicate point',
  ZERO_LENGTH_SEGMENT: 'Segment of zero length',
  DUPLICATE_SEGMENT: 'Duplicate segment',
  VERTEX_ON_SEGMENT: 'Vertex on a segment',
  SEGMENTS_CROSS: 'Segments cross',
  SEGMENTS_OVERLAP: 'Segments overlap',
  HOLE_OUTSIDE_DOMAIN: 'Hole seed outside the domain',
  REGION_OUTSIDE_DOMAIN: 'Region seed outside the domain',
  NOTHING_ENCLOSED: 'Nothing enclosed',
};

/** A code with no label of its own (an error's: DEGENERATE_INPUT) as words: 'Degenerate input'. */
export function codeWords(code) {
  const words = String(code).toLowerCase().replace(/_/g, ' ');
  return words.charAt(0).toUpperCase() + words.slice(1);
}

/**
 * A message's decimal numbers to six significant digits: the core prints coordinates in full
 * (0.30000000000000004), which says nothing more to a reader. Whole numbers (indices) stay.
 */
export function roundNumbers(text) {
  return String(text).replace(/-?(?:\d+\.\d+|\.\d+)(?:e[+-]?\d+)?|-?\d+e[+-]?\d+/gi,
    (number) => String(Number(Number(number).toPrecision(6))));
}
