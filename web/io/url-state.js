// The drawing in the URL hash, so that a link reproduces it:
//
//   #d=<base64url of compact JSON>
//   { "v": 1, "p": [x0, y0, ...], "s": [a0, b0, ...], "m": [marker per segment] (only if any), "h": [hx0, hy0, ...],
//     "r": [[x, y, attribute, maxArea], ...],
//     "o": [minAngle, maxArea, "o" | "c", maxSteiner, "c" | "b", "l" | "d", page flag bits (only if any is on)],
//     "c": [curve, ...] (only if any: model/curve-data.js), "t": curveTolerance (only if not 0),
//     "a": maxAngle (only if set) }
//
// maxArea 0 = none, maxSteiner -1 = automatic, "o"/"c"/"p"/"t" = off-center / circumcenter / petal / optimal placement,
// "c"/"b" = CDT / bounding-box variant, "l"/"d" = diametral lens / disk encroachment. The last two
// were appended later: links without them (or with unknown values) get the defaults, CDT and lens;
// so was the seventh, the page flags that are on (drawing.js's PAGE_FLAGS, one bit each), present
// only when one is (older links wrote 1 for the size measure, the first flag).
import { DEFAULT_OPTIONS, MIN_ANGLE_RANGE, PAGE_FLAGS, flagOption } from '../model/drawing.js';
import { decodeCurves, encodeCurves } from '../model/curve-data.js';

/** Links longer than this are not written (browsers and chat apps truncate them). */
export const MAX_HASH_LENGTH = 64_000;

function toBase64Url(text) {
  const bytes = new TextEncoder().encode(text);
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text) {
  const base64 = text.replace(/-/g, '+').replace(/_/g, '/');
  const binary = atob(base64 + '='.repeat((4 - (base64.length % 4)) % 4));
  return new TextDecoder().decode(Uint8Array.from(binary, (c) => c.charCodeAt(0)));
}

const PLACEMENT_CODES = new Map([['offcenter', 'o'], ['circumcenter', 'c'], ['petal', 'p'], ['optimal', 't']]);
const PLACEMENT_NAMES = new Map([...PLACEMENT_CODES].map(([name, code]) => [code, name]));

/** The page flags that are on in these options, as bits in PAGE_FLAGS' order (0: none). */
const pageFlagBits = (options) => PAGE_FLAGS.reduce((bits, id, k) => (options[flagOption(id)] === true || options[flagOption(id)] > 0 ? bits | (1 << k) : bits), 0);

export function encodeDrawing(d) {
  const o = d.options;
  const flags = pageFlagBits(o);
  const compact = {
    v: 1,
    p: d.points,
    s: d.segments,
    h: d.holes,
    // Segment markers only when some segment has one (older links have none: all 0).
    ...((d.segmentMarkers ?? []).some((m) => m !== 0) ? { m: d.segmentMarkers } : {}),
    r: d.regions.map((r) => [r.x, r.y, r.attribute ?? 0, r.maxArea > 0 ? r.maxArea : 0]),
    o: [o.minAngle, o.maxArea > 0 ? o.maxArea : 0, PLACEMENT_CODES.get(o.placement) ?? 't',
      Number.isInteger(o.maxSteiner) ? o.maxSteiner : -1,
      o.variant === 'box' ? 'b' : 'c', o.encroachment === 'disk' ? 'd' : 'l',
      // Only when a page flag is on (older links have no 7th entry: all off).
      ...(flags ? [flags] : [])],
    ...encodeCurves(d),
    ...(o.curveTolerance > 0 ? { t: o.curveTolerance } : {}),
    ...(o.maxAngle > 0 ? { a: o.maxAngle } : {}),
  };
  return `d=${toBase64Url(JSON.stringify(compact))}`;
}

const finiteArray = (value, what) => {
  if (!Array.isArray(value) || !value.every((x) => typeof x === 'number' && Number.isFinite(x))) {
    throw new Error(`link: ${what} must be an array of numbers`);
  }
  return value;
};

/** The drawing in a location hash ('#d=...'), or null when there is none. Throws on a damaged one. */
export function decodeDrawing(hash) {
  const match = /(?:^#?|&)d=([A-Za-z0-9_-]+)/.exec(hash);
  if (!match) return null;
  const data = JSON.parse(fromBase64Url(match[1]));
  if (data === null || typeof data !== 'object' || data.v !== 1) throw new Error('link: unknown format version');
  const points = finiteArray(data.p ?? [], 'points');
  const segments = finiteArray(data.s ?? [], 'segments');
  const holes = finiteArray(data.h ?? [], 'holes');
  const segmentMarkers = finiteArray(data.m ?? [], 'segment markers');
  if (segmentMarkers.length > segments.length / 2 || !segmentMarkers.every(Number.isInteger)) throw new Error('link: bad segment markers');
  if (points.length % 2 || segments.length % 2 || holes.length % 2) throw new Error('link: odd coordinate count');
  const n = points.length / 2;
  if (!segments.every((i) => Number.isInteger(i) && i >= 0 && i < n)) throw new Error('link: segment index out of range');
  const regions = (data.r ?? []).map((r) => {
    finiteArray(r, 'a region');
    return { x: r[0], y: r[1], attribute: r[2] ?? 0, maxArea: r[3] > 0 ? r[3] : null };
  });
  const [minAngle, maxArea, placement, maxSteiner, variant, encroachment, flagBits] = Array.isArray(data.o) ? data.o : [];
  const options = {
    minAngle: Number.isFinite(minAngle) ? Math.min(MIN_ANGLE_RANGE.max, Math.max(MIN_ANGLE_RANGE.min, minAngle))
      : DEFAULT_OPTIONS.minAngle,
    maxArea: maxArea > 0 ? maxArea : null,
    placement: PLACEMENT_NAMES.get(placement) ?? DEFAULT_OPTIONS.placement,
    maxSteiner: Number.isInteger(maxSteiner) && maxSteiner >= 0 ? maxSteiner : null,
    variant: variant === 'b' ? 'box' : 'cdt',
    encroachment: encroachment === 'd' ? 'disk' : 'lens',
    ...Object.fromEntries(PAGE_FLAGS.map((id, k) => [flagOption(id), Number.isInteger(flagBits) && ((flagBits >> k) & 1) === 1])),
    // Only when the link has one (links without curves read as before; absent means automatic).
    ...(typeof data.t === 'number' && data.t > 0 && Number.isFinite(data.t) ? { curveTolerance: data.t } : {}),
    // Only when the link has one; a value the mesher refuses reads as none.
    maxAngle: typeof data.a === 'number' && data.a > 60 && data.a < 180 ? data.a : null,
  };
  const curves = decodeCurves(data.c, n);
  return { points, segments, segmentMarkers, curves, holes, regions, options };
}

// What the page shows, beside the drawing: '&step=K' (step mode at step K), '&color=MODE' (the
// triangle coloring), '&view=CX,CY,SCALE' (the view's center and CSS pixels per unit). Each is
// optional; a link without them opens with the drawing fitted, colored by angle, not stepping.
const COLOR_MODES = ['angle', 'region', 'none'];

/** The hash suffix for the page state { step: number | null, color, view: { x, y, scale } | null }. */
export function encodePageState({ step = null, color = 'angle', view = null }) {
  let text = '';
  if (Number.isInteger(step) && step >= 0) text += `&step=${step}`;
  if (color !== 'angle' && COLOR_MODES.includes(color)) text += `&color=${color}`;
  if (view) text += `&view=${[view.x, view.y, view.scale].map((v) => Number(v.toPrecision(8))).join(',')}`;
  return text;
}

/** The page state in a location hash; absent or unreadable parts are null. */
export function decodePageState(hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const stepText = params.get('step');
  const step = stepText !== null && /^\d+$/.test(stepText) ? Number(stepText) : null;
  const color = COLOR_MODES.includes(params.get('color')) ? params.get('color') : null;
  const numbers = (params.get('view') ?? '').split(',').map(Number);
  const view = numbers.length === 3 && numbers.every(Number.isFinite) && numbers[2] > 0
    ? { x: numbers[0], y: numbers[1], scale: numbers[2] } : null;
  return { step, color, view };
}
