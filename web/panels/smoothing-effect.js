// The Mesh panel's smoothing rows: when the mesh was smoothed, the histogram of its triangles'
// smallest angles drawn over that of the same mesh unsmoothed (an outline behind the bars), and
// each one's mean smallest angle and obtuse triangles, so that what smoothing did is seen at once.
import { SMALLEST_ANGLE_BINS, movedVertices, smallestAngleSummary } from '../geometry/mesh-geometry.js';
import { clearedCanvas } from '../rendering/canvas-2d.js';
import { niceCeiling } from './mesh-panel.js';

const COLORS = { after: '#3b5bdb', before: '#e8590c', bound: '#0b7285', axis: '#343a40', ground: '#f7f8fa' };

const count = (n) => n.toLocaleString('en-US');

/**
 * Bars of `after`'s smallest-angle histogram with `before`'s as a step outline over the same count
 * axis, and the min-angle bound as a solid line. canvas.dataset keeps the count axis' top.
 */
export function drawSmoothingHistogram(canvas, before, after, bound = null) {
  const { ctx, width: cssWidth, height: cssHeight } = clearedCanvas(canvas, 320, 120);
  ctx.font = '10px system-ui, sans-serif';
  const countMax = niceCeiling(Math.max(...before.histogram, ...after.histogram));
  const left = Math.max(34, Math.ceil(ctx.measureText(countMax.toLocaleString('en-US')).width) + 8);
  const top = 6;
  const bottom = cssHeight - 16;
  const width = cssWidth - left - 6;
  const x = (angle) => left + (angle / SMALLEST_ANGLE_BINS) * width;
  const y = (count) => bottom - (count / countMax) * (bottom - top);
  ctx.fillStyle = COLORS.ground;
  ctx.fillRect(left, top, width, bottom - top);
  ctx.fillStyle = COLORS.after;
  after.histogram.forEach((count, bin) => {
    if (count > 0) ctx.fillRect(x(bin), y(count), Math.max(1, x(bin + 1) - x(bin) - 0.5), bottom - y(count));
  });
  // The unsmoothed mesh's histogram as a step line, so that the bars under it stay visible.
  ctx.strokeStyle = COLORS.before;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.moveTo(x(0), bottom);
  before.histogram.forEach((count, bin) => { ctx.lineTo(x(bin), y(count)); ctx.lineTo(x(bin + 1), y(count)); });
  ctx.lineTo(x(SMALLEST_ANGLE_BINS), bottom);
  ctx.stroke();
  if (bound > 0) {
    ctx.strokeStyle = COLORS.bound;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(Math.round(x(bound)), top);
    ctx.lineTo(Math.round(x(bound)), bottom);
    ctx.stroke();
  }
  ctx.strokeStyle = COLORS.axis;
  ctx.fillStyle = COLORS.axis;
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(left - 0.5, top);
  ctx.lineTo(left - 0.5, bottom + 0.5);
  ctx.lineTo(left + width, bottom + 0.5);
  ctx.stroke();
  ctx.textAlign = 'right';
  ctx.fillText(countMax.toLocaleString('en-US'), left - 4, top + 8);
  ctx.fillText('0', left - 4, bottom);
  ctx.textAlign = 'center';
  for (const angle of [0, 10, 20, 30, 40, 50, 60]) ctx.fillText(`${angle}°`, Math.min(Math.max(x(angle), left + 8), cssWidth - 12), cssHeight - 4);
  canvas.dataset.countMax = String(countMax);
}

/** The rows in the page (index.html's #smoothing-effect): shown for smoothed meshes only. */
export function createSmoothingEffect() {
  const $ = (id) => document.getElementById(id);
  const box = $('smoothing-effect');
  return {
    /** The mesh on the page was smoothed: its rows wait for the unsmoothed mesh. */
    waiting() {
      box.hidden = false;
      box.dataset.state = 'waiting';
      $('smoothing-mean').textContent = 'meshing without smoothing…';
      $('smoothing-obtuse').textContent = '–';
      $('smoothing-moved').textContent = '–';
    },
    /** Both meshes: the rows and the histograms; returns how many vertices smoothing moved. */
    show(unsmoothed, smoothed, bound) {
      const before = smallestAngleSummary(unsmoothed);
      const after = smallestAngleSummary(smoothed);
      const moved = movedVertices(unsmoothed, smoothed);
      box.hidden = false;
      box.dataset.state = 'shown';
      $('smoothing-mean').textContent = `${before.mean.toFixed(2)}° before, ${after.mean.toFixed(2)}° after`;
      $('smoothing-obtuse').textContent = `${count(before.obtuse)} before, ${count(after.obtuse)} after, of ${count(after.triangles)}`;
      $('smoothing-moved').textContent = `${count(moved)} of ${count(smoothed.points.length / 2)}`;
      Object.assign(box.dataset, {
        beforeMean: String(before.mean), afterMean: String(after.mean),
        beforeObtuse: String(before.obtuse), afterObtuse: String(after.obtuse), moved: String(moved),
      });
      drawSmoothingHistogram($('smoothing-histogram'), before, after, bound);
      return moved;
    },
    /** Not smoothed, or no mesh: no rows. */
    hide() {
      box.hidden = true;
      delete box.dataset.state;
    },
  };
}
