// The export buttons: the mesh in each of the package's formats or as a PNG of the canvas, the
// drawing itself as a .poly, and the link to the page as it is.
import { toPlc } from '../drawing.js';
import { canvasBlob, download, drawingPolyText, exportText } from './files.js';
import { setStatus } from '../panels/status-line.js';
import { drawingJsonText } from '../editing/curve-data.js';

const $ = (id) => document.getElementById(id);
const FORMATS = ['poly', 'json', 'svg', 'png', 'node', 'ele', 'msh', 'vtu', 'geojson'];

/**
 * @param {() => {mesh: object|null, plc: object|null}} meshed the latest mesh and the input it was made from
 * @param {() => object} drawing the drawing on the canvas
 * @param {object} renderer the Renderer (its snapshot for PNG)
 * @param {() => void} draw draws the frame now (PNG)
 * @param {() => boolean} writeLink writes the link into the URL; false when the drawing is too large for one
 */
export function createExportMenu({ meshed, drawing, renderer, draw, writeLink }) {
  async function exportAs(format) {
    const { mesh, plc } = meshed();
    if (mesh === null) {
      setStatus('Nothing to export: the drawing has no mesh yet.', 'error');
      return;
    }
    try {
      if (format === 'png') {
        draw();
        download(await canvasBlob(renderer.snapshot()), 'ruppert-mesh.png', 'png');
      } else {
        download(await exportText(format, mesh, plc), `ruppert-mesh.${format}`, format);
      }
      setStatus(`Exported ruppert-mesh.${format}.`, 'ok');
    } catch (error) {
      setStatus(`Export failed: ${error.message}`, 'error');
    }
  }
  for (const format of FORMATS) $(`export-${format}`).addEventListener('click', () => exportAs(format));
  // The drawing needs no mesh: what was drawn, as a .poly another program can mesh.
  $('export-drawing').addEventListener('click', () => {
    download(drawingPolyText(toPlc(drawing())), 'ruppert-drawing.poly', 'poly');
    setStatus('Exported ruppert-drawing.poly (the drawing, not its mesh).', 'ok');
  });

  // The drawing with its curves (which .poly cannot hold), in the JSON the file panel reads back.
  $('export-drawing-json').addEventListener('click', () => {
    download(drawingJsonText(toPlc(drawing())), 'ruppert-drawing.json', 'json');
    setStatus('Exported ruppert-drawing.json (the drawing with its curves, not its mesh).', 'ok');
  });

  $('copy-link').addEventListener('click', async () => {
    if (!writeLink()) {
      setStatus('This drawing is too large to fit in a link; export a .poly file instead.', 'warn');
      return;
    }
    try {
      await navigator.clipboard.writeText(location.href);
      setStatus('Link copied: it reproduces this drawing and its parameters.', 'ok');
    } catch {
      setStatus(`Copy this link: ${location.href}`, 'info');
    }
  });
}
