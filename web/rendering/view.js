// The view: which part of the world plane the canvas shows. World y points up, screen y down.
//
//   screen.x = width/2  + (world.x - centerX) * scale
//   screen.y = height/2 - (world.y - centerY) * scale        (CSS pixels)

export class View {
  constructor() {
    this.centerX = 0;
    this.centerY = 0;
    this.scale = 50;   // CSS pixels per world unit
    this.width = 1;    // canvas size in CSS pixels
    this.height = 1;
  }

  resize(width, height) {
    this.width = Math.max(1, width);
    this.height = Math.max(1, height);
  }

  toScreen(x, y) {
    return { x: this.width / 2 + (x - this.centerX) * this.scale, y: this.height / 2 - (y - this.centerY) * this.scale };
  }

  toWorld(sx, sy) {
    return { x: this.centerX + (sx - this.width / 2) / this.scale, y: this.centerY - (sy - this.height / 2) / this.scale };
  }

  /** The canvas 2D transform (for world-space paths), times the device pixel ratio. */
  matrix(dpr) {
    const s = this.scale * dpr;
    return [s, 0, 0, -s, (this.width / 2 - this.centerX * this.scale) * dpr, (this.height / 2 + this.centerY * this.scale) * dpr];
  }

  /** Moves the view by a screen-space drag of (dx, dy) pixels. */
  panBy(dx, dy) {
    this.centerX -= dx / this.scale;
    this.centerY += dy / this.scale;
  }

  /** Zooms by `factor` keeping the world point under screen (sx, sy) fixed. */
  zoomAt(sx, sy, factor) {
    const before = this.toWorld(sx, sy);
    this.scale = Math.min(1e12, Math.max(1e-12, this.scale * factor));
    const after = this.toWorld(sx, sy);
    this.centerX += before.x - after.x;
    this.centerY += before.y - after.y;
  }

  /** Shows the box with a margin. */
  fit(bounds, margin = 0.1) {
    if (bounds === null) return;
    const w = Math.max(bounds.maxX - bounds.minX, 1e-9);
    const h = Math.max(bounds.maxY - bounds.minY, 1e-9);
    const size = Math.max(w, h) === 1e-9 ? 1 : Math.max(w, h);
    this.centerX = (bounds.minX + bounds.maxX) / 2;
    this.centerY = (bounds.minY + bounds.maxY) / 2;
    const sx = this.width / (Math.max(w, size * 0.01) * (1 + 2 * margin));
    const sy = this.height / (Math.max(h, size * 0.01) * (1 + 2 * margin));
    this.scale = Math.min(sx, sy);
  }

  /** Grid spacing in world units: a power of ten times 1, 2 or 5, about 40 pixels on screen. */
  gridStep() {
    const target = 40 / this.scale;
    const power = 10 ** Math.floor(Math.log10(target));
    for (const m of [1, 2, 5, 10]) if (m * power >= target) return m * power;
    return 10 * power;
  }

  /** The visible world rectangle. */
  visibleBounds() {
    const a = this.toWorld(0, this.height);
    const b = this.toWorld(this.width, 0);
    return { minX: a.x, minY: a.y, maxX: b.x, maxY: b.y };
  }
}

/** Rounds to the grid, dropping floating-point noise (0.30000000000000004 -> 0.3). */
export function snapToGrid(value, step) {
  const snapped = Math.round(value / step) * step;
  return Number(snapped.toPrecision(12));
}
