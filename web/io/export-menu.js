// The export buttons: the mesh in each of the package's formats or as a PNG of the canvas, the
// drawing itself as a .poly, and the link to the page as it is.
import { toPlc } from '../model/drawing.js';
import { curveToleranceOf, flattenCurves } from './flatten-curves.js';
import { canvasBlob, download, drawingPolyText, exportText } from './files.js';
import { drawingJsonText } from '../model/curve-data.js';

const $ = (id) => document.getElementById(id);
const FORMATS = ['poly', 'json', 'svg', 'png', 'node', 'ele', 'msh', 'vtu', 'geojson'];
// What each mesh export holds, said on the status line: those that open again to the same mesh
// (Open file), and what the others cannot hold. [text, status kind]
const OPENS_AGAIN = 'the whole domain (vertices, subsegments with their markers, holes); Open file reads it back to the same mesh';
const FORMAT_NOTES = {
  poly: [OPENS_AGAIN, 'ok'],
  json: [`the whole mesh; ${OPENS_AGAIN}`, 'ok'],
  geojson: [`a polygon per triangle; ${OPENS_AGAIN}`, 'ok'],
  node: ['the vertices only: a .node holds no segments, holes or triangles (the triangles are in .ele; the whole domain in .poly or .json)', 'warn'],
  ele: ['the triangles only, as numbers of the vertices of the .node exported with them: an .ele holds no coordinates', 'warn'],
  msh: ['the whole mesh for Gmsh (a physical group per boundary marker); the page does not read .msh back (use .poly or .json)', 'ok'],
  vtu: ['the whole mesh for ParaView; the page does not read .vtu back (use .poly or .json)', 'ok'],
  svg: ['a picture of the mesh; to mesh it again, export .poly or .json', 'ok'],
  png: ['the canvas as a reader would print it; to mesh it again, export .poly or .json', 'ok'],
};

/**
 * @param {() => {mesh: object|null, plc: object|null}} meshed the latest mesh and the input it was made from
 * @param {() => object} drawing the drawing on the canvas
 * @param {object} renderer the Renderer (its snapshot for PNG)
 * @param {() => void} drawForPrint draws the frame now without the editing aids (PNG)
 * @param {() => void} redraw draws the frame as the page shows it again
 * @param {() => boolean} writeLink writes the link into the URL; false when the drawing is too large for one
 * @param {object} status the status line (panels/status-line.js): setStatus(text, kind), showNotices(notices, error)
 */
export function createExportMenu({ meshed, drawing, renderer, drawForPrint, redraw, writeLink, status }) {
  const { setStatus } = status;
  async function exportAs(format) {
    const { mesh, plc } = meshed();
    if (mesh === null) {
      setStatus('Nothing to export: the drawing has no mesh yet.', 'error');
      return;
    }
    try {
      if (format === 'png') {
        drawForPrint();
        const picture = renderer.snapshot();
        const blob = canvasBlob(picture);
        redraw();
        download(await blob, 'ruppert-mesh.png', 'png');
      } else {
        download(await exportText(format, mesh, plc), `ruppert-mesh.${format}`, format);
      }
      const [note, kind] = FORMAT_NOTES[format];
      setStatus(`Exported ruppert-mesh.${format}: ${note}.`, kind);
    } catch (error) {
      setStatus(`Export failed: ${error.message}`, 'error');
    }
  }
  for (const format of FORMATS) $(`export-${format}`).addEventListener('click', () => exportAs(format));
  // The drawing needs no mesh: what was drawn, as a .poly another program can mesh. A .poly holds
  // no curves: each is cut into segments within the curve tolerance (flatten-curves.js), and the
  // status line says so.
  $('export-drawing').addEventListener('click', () => {
    const d = drawing();
    const plc = toPlc(d);
    const flat = flattenCurves(plc, d.options.curveTolerance);
    download(drawingPolyText(flat), 'ruppert-drawing.poly', 'poly');
    const curves = plc.curves?.length ?? 0;
    setStatus(curves === 0 ? 'Exported ruppert-drawing.poly (the drawing, not its mesh).'
      : `Exported ruppert-drawing.poly (the drawing, not its mesh): a .poly holds no curves, so its ${curves} ` +
        `curve${curves === 1 ? ' is' : 's are'} ${(flat.segments.length - plc.segments.length) / 2} segments within ` +
        `${Number(curveToleranceOf(plc, d.options.curveTolerance).toPrecision(3))} of ${curves === 1 ? 'it' : 'them'}; drawing .json keeps the curves.`, 'ok');
  });

  // The drawing with its curves (which .poly cannot hold), in the JSON the file panel reads back.
  $('export-drawing-json').addEventListener('click', () => {
    download(drawingJsonText(toPlc(drawing())), 'ruppert-drawing.json', 'json');
    setStatus('Exported ruppert-drawing.json (the drawing with its curves, not its mesh).', 'ok');
  });

  // The menu closes once an export is chosen, on Escape and on a click elsewhere.
  const menu = $('export-menu');
  menu.addEventListener('click', (event) => { if (event.target.closest('.menu-items button')) menu.open = false; });
  menu.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && menu.open) {
      menu.open = false;
      menu.querySelector('summary').focus();
    }
  });
  document.addEventListener('pointerdown', (event) => { if (menu.open && !menu.contains(event.target)) menu.open = false; });

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
