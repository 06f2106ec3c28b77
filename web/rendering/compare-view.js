// Two placements side by side (the "off-centers against circumcenters" preset): the drawing meshed
// once per placement at the page's other options, each mesh drawn on its own canvas, colored by
// min angle as the main canvas is, with its triangle count and smallest angle as its caption.
// While it shows, it takes the main canvas's place; every change of the drawing or its options
// meshes both again (in a worker of its own, so a slow placement never blocks the page), and
// closing it brings the main canvas back.
import { createMeshWorker } from '../../wasm/index.js';
import { boundsOf } from '../geometry/bounds.js';
import { toMeshOptions, toPlc } from '../model/drawing.js';
import { PLACEMENT_LABELS } from '../labels.js';
import { minAngles } from '../geometry/mesh-geometry.js';
import { clearedCanvas } from './canvas-2d.js';
import { ANGLE_CLASSES, COLORS } from './colors.js';

const $ = (id) => document.getElementById(id);

/** The angle class color of a smallest angle, as the legend gives it. */
function angleColor(angle) {
  for (const [upper, color] of ANGLE_CLASSES) if (angle < upper) return color;
  return ANGLE_CLASSES[ANGLE_CLASSES.length - 1][1];
}

/** Draws the mesh fitted in the canvas (its CSS size), triangles by min angle, edges over them. */
function drawMesh(canvas, mesh) {
  const { ctx, width, height } = clearedCanvas(canvas, 300, 200);
  if (!mesh) return;
  const box = boundsOf(mesh.points);
  const scale = 0.92 * Math.min(width / Math.max(box.maxX - box.minX, 1e-12), height / Math.max(box.maxY - box.minY, 1e-12));
  const ox = width / 2 - ((box.minX + box.maxX) / 2) * scale;
  const oy = height / 2 + ((box.minY + box.maxY) / 2) * scale;
  const p = mesh.points;
  const tri = mesh.triangles;
  const angles = minAngles(mesh);
  // One path per color class, then all edges in one stroke: a few fills however large the mesh.
  const paths = new Map();
  const edges = new Path2D();
  for (let t = 0; t < tri.length / 3; t++) {
    const color = angleColor(angles[t]);
    if (!paths.has(color)) paths.set(color, new Path2D());
    for (const path of [paths.get(color), edges]) {
      path.moveTo(ox + p[2 * tri[3 * t]] * scale, oy - p[2 * tri[3 * t] + 1] * scale);
      path.lineTo(ox + p[2 * tri[3 * t + 1]] * scale, oy - p[2 * tri[3 * t + 1] + 1] * scale);
      path.lineTo(ox + p[2 * tri[3 * t + 2]] * scale, oy - p[2 * tri[3 * t + 2] + 1] * scale);
      path.closePath();
    }
  }
  for (const [color, path] of paths) {
    ctx.fillStyle = color;
    ctx.fill(path);
  }
  ctx.strokeStyle = COLORS.edge;
  ctx.lineWidth = 0.5;
  ctx.stroke(edges);
}

/** The caption of one side: the placement, its triangle count and smallest angle. */
export function compareCaption(placement, mesh) {
  const name = PLACEMENT_LABELS[placement]?.replace(/ \(.*\)$/, '') ?? placement;
  if (!mesh) return `${name}: could not be meshed`;
  const s = mesh.stats;
  return `${name}: ${s.triangles.toLocaleString('en-US')} triangles, smallest angle ${s.minAngle.toFixed(2)}°`;
}

/**
 * @param {() => object} drawing the drawing to mesh once per placement
 * @param {() => void} onClose the comparison was closed by the reader (the preset box may say so)
 */
export function createCompareView({ drawing, onClose = () => {} }) {
  const figure = $('compare');
  const sides = [...figure.querySelectorAll('.compare-side')].map((side) => ({
    canvas: side.querySelector('canvas'), caption: side.querySelector('figcaption'), mesh: null,
  }));
  let placements = null;   // [left, right] while shown, else null
  let worker = null;
  let busy = false;
  let generation = 0;

  function setShown(shown) {
    figure.hidden = !shown;
    document.body.classList.toggle('comparing', shown);
  }

  /** Meshes the drawing once per placement, the newest call winning; figure[data-state] says where it stands. */
  async function update() {
    if (placements === null) return;
    const mine = ++generation;
    // A mesh still running belongs to an older drawing: its worker goes, a fresh one takes over.
    if (busy) {
      worker?.terminate();
      worker = null;
    }
    worker ??= createMeshWorker();
    busy = true;
    figure.dataset.state = 'meshing';
    const shown = drawing();
    const plc = toPlc(shown);
    const meshes = [];
    for (const placement of placements) {
      const options = { ...toMeshOptions(shown), placement };
      meshes.push(await worker.triangulate(plc, options).catch(() => null));
      if (mine !== generation) return;
    }
    busy = false;
    sides.forEach((side, i) => {
      side.mesh = meshes[i];
      side.caption.textContent = compareCaption(placements[i], meshes[i]);
      drawMesh(side.canvas, meshes[i]);
    });
    figure.dataset.state = 'done';
  }

  function redraw() {
    if (placements !== null) for (const side of sides) drawMesh(side.canvas, side.mesh);
  }
  new ResizeObserver(redraw).observe(figure);

  $('compare-close').addEventListener('click', () => {
    hide();
    onClose();
  });

  /**
   * Shows the two placements side by side; they are meshed when the drawing's own mesh arrives
   * (update, from meshing.js), so always from the drawing being shown, and after every change.
   */
  function show(pair) {
    placements = pair;
    generation++;
    figure.dataset.state = 'meshing';
    setShown(true);
  }

  function hide() {
    if (placements === null) return;
    placements = null;
    generation++;
    setShown(false);
    delete figure.dataset.state;
  }

  return { show, hide, update, get shown() { return placements !== null; } };
}
