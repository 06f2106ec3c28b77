// Step-by-step mode: play, pause, step and scrub through mesh.events (recorded with
// options.trace). The mesh itself is the final one; the renderer dims it and highlights the
// vertices inserted up to the current event and that event's geometry.

const KIND_NAMES = ['segment split', 'circumcenter', 'off-center', 'rejected circumcenter'];

const fmt = (v) => (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : Number(v.toFixed(4)).toString());

/** One line describing event e. */
export function describeEvent(events, e) {
  const kind = events.kind[e];
  const where = `(${fmt(events.xy[2 * e])}, ${fmt(events.xy[2 * e + 1])})`;
  const vertex = events.vertex[e];
  const triangle = `(${events.triangle[3 * e]}, ${events.triangle[3 * e + 1]}, ${events.triangle[3 * e + 2]})`;
  switch (kind) {
    case 0: {
      const by = events.by[e];
      return `Split subsegment (${events.a[e]}, ${events.b[e]})${by >= 0 ? `, encroached by vertex ${by},` : ''} at its midpoint ${where}: vertex ${vertex}.`;
    }
    case 1:
      return `Inserted the circumcenter of skinny or large triangle ${triangle} at ${where}: vertex ${vertex}.`;
    case 2:
      return `Inserted the off-center of skinny triangle ${triangle} at ${where}: vertex ${vertex}.`;
    case 3:
      return `The circumcenter (${fmt(events.circumcenter[2 * e])}, ${fmt(events.circumcenter[2 * e + 1])}) of ${triangle} ` +
        `encroached subsegment (${events.a[e]}, ${events.b[e]}): rejected; split the subsegment at ${where} instead: vertex ${vertex}.`;
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
    this.index = 0;
    this.timer = null;
    el.first.addEventListener('click', () => this.go(0));
    el.back.addEventListener('click', () => this.step(-1));
    el.forward.addEventListener('click', () => this.step(1));
    el.last.addEventListener('click', () => this.go(this.count - 1));
    el.play.addEventListener('click', () => this.toggle());
    el.scrub.addEventListener('input', () => { this.pause(); this.go(Number(el.scrub.value)); });
    el.speed.addEventListener('change', () => { if (this.playing) { this.pause(); this.play(); } });
  }

  get count() { return this.events ? this.events.count : 0; }
  get playing() { return this.timer !== null; }

  /** New events (a new mesh): keep the position if it still exists. */
  setEvents(events) {
    this.events = events ?? null;
    const count = this.count;
    this.el.scrub.max = String(Math.max(0, count - 1));
    this.el.scrub.disabled = count === 0;
    if (count === 0) this.pause();
    this.go(Math.min(this.index, Math.max(0, count - 1)), false);
  }

  go(index, notify = true) {
    const count = this.count;
    this.index = Math.max(0, Math.min(index, Math.max(0, count - 1)));
    this.el.scrub.value = String(this.index);
    this.el.info.textContent = count === 0
      ? 'No refinement events: the input already meets the bounds.'
      : `Event ${this.index + 1} of ${count}: ${describeEvent(this.events, this.index)}`;
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
    if (this.index >= this.count - 1) this.go(0);
    const rate = Number(this.el.speed.value) || 8;
    this.timer = setInterval(() => {
      if (this.index >= this.count - 1) {
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
