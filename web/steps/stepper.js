// Step-by-step mode: play, pause, step and scrub through the refinement recorded in mesh.events
// (options.trace). Position k (0..events.count) is the mesh after k events (Steiner insertions, and
// the moves of free vertices the optimal placement makes), the k-th event being the one that made it; position 0 is the constrained Delaunay triangulation before
// refinement. StepReplay (step-replay.js) provides each position's mesh.

import { EventKind } from '../../wasm/index.js';
import { pointsAtStep, rejectedIsCircumcenter, splitShell } from '../geometry/event-geometry.js';
import { EVENT_KIND_LABELS as L } from '../labels.js';
import { describeCurveSplit } from './curve-events.js';

const fmt = (v) => (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : Number(v.toFixed(4)).toString());

/**
 * a and b, each as fmt gives it, with more digits when fewer would make a > b read as equal (or
 * reversed): "area 0.0010004 > max 0.001", never "area 0.001 > max 0.001".
 */
export function fmtCompared(a, b) {
  if (a === b) return [fmt(a), fmt(b)];
  for (let digits = 4; digits <= 17; digits++) {
    const [fa, fb] = [fmt(a), fmt(b)].map((text, i) => (digits === 4 ? text : Number([a, b][i].toPrecision(digits)).toString()));
    if (Math.sign(Number(fa) - Number(fb)) === Math.sign(a - b)) return [fa, fb];
  }
  return [String(a), String(b)];
}

/** The smallest angle, in degrees, of the triangle of vertices i, j, k of points. */
function smallestAngle(points, i, j, k) {
  const corner = (a, b, c) => {
    const ux = points[2 * b] - points[2 * a]; const uy = points[2 * b + 1] - points[2 * a + 1];
    const vx = points[2 * c] - points[2 * a]; const vy = points[2 * c + 1] - points[2 * a + 1];
    return Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
  };
  return Math.min(corner(i, j, k), corner(j, k, i), corner(k, i, j)) * 180 / Math.PI;
}

/** An angle under the bound to two decimals, or more when two would round it up to the bound. */
function angleBelow(angle, bound) {
  for (let digits = 2; digits <= 12; digits++) if (Number(angle.toFixed(digits)) < bound) return angle.toFixed(digits);
  return String(angle);
}

/** The area of the triangle of vertices i, j, k of points. */
function area(points, i, j, k) {
  const ux = points[2 * j] - points[2 * i]; const uy = points[2 * j + 1] - points[2 * i + 1];
  const vx = points[2 * k] - points[2 * i]; const vy = points[2 * k + 1] - points[2 * i + 1];
  return Math.abs(ux * vy - uy * vx) / 2;
}

/**
 * Why triangle (i, j, k) was split, with the values that decided it: 'skinny (smallest angle X° <
 * bound Y°)' when its angle is under the bound, else 'too large (area A > max B)' (the global bound,
 * else its region's), else its smallest angle alone.
 */
export function splitReason(points, i, j, k, context) {
  const angle = smallestAngle(points, i, j, k);
  const bound = context?.minAngle ?? 0;
  if (angle < bound) return `skinny (smallest angle ${angleBelow(angle, bound)}° < bound ${bound}°)`;
  const a = area(points, i, j, k);
  if (context?.maxArea > 0 && a > context.maxArea) {
    const [area, max] = fmtCompared(a, context.maxArea);
    return `too large (area ${area} > max ${max})`;
  }
  if (context?.regions?.some((r) => r.maxArea > 0)) return `too large for its region's max area (area ${fmt(a)}; smallest angle ${angle.toFixed(2)}°)`;
  return `(smallest angle ${angle.toFixed(2)}°)`;
}

/**
 * One line describing event e. With `context` ({ points: the final mesh's, minAngle, placement }),
 * a triangle's smallest angle is given against the bound, a split off the midpoint is named by its
 * concentric shell, and a rejected point by what it is (circumcenter or off-center; petal and
 * optimal points are never rejected).
 */
export function describeEvent(events, e, context = null) {
  const kind = events.kind[e];
  const where = `(${fmt(events.xy[2 * e])}, ${fmt(events.xy[2 * e + 1])})`;
  const vertex = events.vertex[e];
  const [i, j, k] = [events.triangle[3 * e], events.triangle[3 * e + 1], events.triangle[3 * e + 2]];
  // The points as they were before this event (a later RELOCATED event may have moved some).
  const points = context?.points ? pointsAtStep(events, e, context.points) : null;
  // "skinny triangle (1, 2, 3) (smallest angle ...)" or "too large triangle (...) (area ...)".
  let triangle = `triangle (${i}, ${j}, ${k})`;
  if (points && i >= 0 && events.kind[e] !== EventKind.SEGMENT_SPLIT) {
    const reason = splitReason(points, i, j, k, context);
    const word = /^(skinny|too large)/.exec(reason)?.[1];
    triangle = word ? `${word} triangle (${i}, ${j}, ${k}) ${reason.slice(word.length + 1)}` : `triangle (${i}, ${j}, ${k}) ${reason}`;
  }
  // A split of a curve's piece (steps/curve-events.js) is told as such, whichever rule split it.
  const curveSplit = describeCurveSplit(events, e, context, where, triangle);
  if (curveSplit !== null) return curveSplit;
  switch (kind) {
    case EventKind.SEGMENT_SPLIT: {
      const by = events.by[e];
      const shell = points ? splitShell(events, e, points) : null;
      const at = shell === null ? `at its midpoint ${where}`
        : `on the concentric shell of radius ${fmt(shell.radius)} around vertex ${shell.center} (a power of two, §6.6), at ${where}`;
      return `Split subsegment (${events.a[e]}, ${events.b[e]})${by >= 0 ? `, encroached by vertex ${by},` : ''} ${at}: vertex ${vertex}.`;
    }
    case EventKind.CIRCUMCENTER:
      return `Inserted the ${L.CIRCUMCENTER} of ${triangle} at ${where}: vertex ${vertex}.`;
    case EventKind.OFF_CENTER:
      return `Inserted the ${L.OFF_CENTER} of ${triangle} at ${where}: vertex ${vertex}.`;
    case EventKind.REJECTED: {
      const circum = !points || rejectedIsCircumcenter(events, e, points);
      // Petal and optimal points are never rejected (they encroach nothing): what is, is the first choice.
      const what = circum ? L.CIRCUMCENTER : L.OFF_CENTER;
      return `The ${what} (${fmt(events.circumcenter[2 * e])}, ${fmt(events.circumcenter[2 * e + 1])}) of ${triangle} ` +
        `encroached subsegment (${events.a[e]}, ${events.b[e]}): rejected; split the subsegment at ${where} instead: vertex ${vertex}.`;
    }
    case EventKind.PETAL_POINT:
      return `Inserted the ${L.PETAL_POINT} of ${triangle} at ${where} (its off-center would have made a skinny triangle): vertex ${vertex}.`;
    case EventKind.OPTIMAL_POINT:
      return `Inserted the ${L.OPTIMAL_POINT} of ${triangle} at ${where} (its off-center would have made a skinny triangle): vertex ${vertex}.`;
    case EventKind.RELOCATED:
      return `Moved vertex ${vertex} from (${fmt(events.circumcenter[2 * e])}, ${fmt(events.circumcenter[2 * e + 1])}) to ${where}: ` +
        `no point fixed ${triangle}, so an endpoint of its shortest edge moved to where every triangle around it meets the bound.`;
    default:
      return `Event of unknown kind ${kind}.`;
  }
}

export class Stepper {
  /**
   * @param {object} el { root, first, back, play, forward, last, scrub, speed, info }
   * @param {(index: number) => void} onChange
   */
  constructor(el, onChange) {
    this.el = el;
    this.onChange = onChange;
    this.events = null;
    this.smoothing = null;  // { moved } for a smoothed mesh, else null
    this.index = 0;
    this.timer = null;
    el.first.addEventListener('click', () => this.go(0));
    el.back.addEventListener('click', () => this.step(-1));
    el.forward.addEventListener('click', () => this.step(1));
    el.last.addEventListener('click', () => this.go(this.count));
    el.play.addEventListener('click', () => this.toggle());
    el.scrub.addEventListener('input', () => { this.pause(); this.go(Number(el.scrub.value)); });
    el.speed.addEventListener('change', () => { if (this.playing) { this.pause(); this.play(); } });
  }

  /**
   * The number of steps: positions run from 0 (none) to count (the final mesh). A smoothed mesh
   * has one more than its events: the last step is the smoothing of the refined mesh.
   */
  get count() { return this.events ? this.events.count + (this.smoothing ? 1 : 0) : 0; }
  get playing() { return this.timer !== null; }

  /** The text of step `index` (> 0): its event's, or the smoothing's for the last of a smoothed mesh. */
  describe(index) {
    if (this.smoothing && index === this.count) {
      const { moved } = this.smoothing;
      const what = moved === null ? 'vertices moved (counting…)' : `${moved.toLocaleString('en-US')} vertices moved`;
      return `Smoothing: ${what}; the refined mesh of the step before, smoothed into the final mesh.`;
    }
    return describeEvent(this.events, index - 1, this.context);
  }

  /** How many vertices smoothing moved, once known (the last step's text says it). */
  setSmoothingMoved(moved) {
    if (!this.smoothing) return;
    this.smoothing.moved = moved;
    this.go(this.index, false);
  }

  /** New events (a new mesh): keep the position if it still exists. */
  /**
   * @param {object|null} events @param {object|null} context { points, minAngle } for the texts
   * @param {boolean} smoothed the mesh was smoothed after refinement: one more step
   */
  setEvents(events, context = null, smoothed = false) {
    this.events = events ?? null;
    this.context = context;
    this.smoothing = events && smoothed ? { moved: null } : null;
    const count = this.count;
    this.el.scrub.max = String(count);
    this.el.scrub.disabled = count === 0;
    if (count === 0) this.pause();
    // A new mesh of the same drawing keeps the position; a first one starts at the end.
    this.go(events ? Math.min(this.index, count) : 0);
  }

  go(index, notify = true) {
    const count = this.count;
    this.index = Math.max(0, Math.min(index, count));
    this.el.scrub.value = String(this.index);
    this.el.info.textContent = count === 0
      ? 'No refinement events: the input already meets the bounds.'
      : `Step ${this.index.toLocaleString('en-US')} of ${count.toLocaleString('en-US')}: ${this.index === 0
        ? 'the constrained Delaunay triangulation of the input, before refinement.'
        : this.describe(this.index)}`;
    if (notify) this.onChange(this.index);
  }

  step(delta) {
    this.pause();
    this.go(this.index + delta);
  }

  toggle() {
    if (this.playing) this.pause();
    else this.play();
  }

  play() {
    if (this.count === 0) return;
    if (this.index >= this.count) this.go(0);
    const rate = Number(this.el.speed.value) || 8;
    this.timer = setInterval(() => {
      if (this.index >= this.count) {
        this.pause();
        return;
      }
      this.go(this.index + 1);
    }, 1000 / rate);
    this.el.play.textContent = 'Pause';
    this.el.play.setAttribute('aria-label', 'Pause');
  }

  pause() {
    clearInterval(this.timer);
    this.timer = null;
    this.el.play.textContent = 'Play';
    this.el.play.setAttribute('aria-label', 'Play');
  }
}
