// Opening files: the file picker and drag-and-drop onto the canvas (files.js reads them with the
// package's readers).
import { fromPlc } from '../model/drawing.js';
import { parseInput } from './files.js';

const $ = (id) => document.getElementById(id);

/**
 * @param {() => object} drawingOptions the drawing's options, which carry over to the file's
 * @param {(drawing) => void} setDrawing
 * @param {() => void} notPreset the presets box no longer names the drawing
 * @param {() => () => void} loading marks the page busy reading a file; returns the function that ends it
 * @param {object} status the status line (panels/status-line.js): setStatus(text, kind), showNotices(notices, error)
 */
export function createFilePanel({ drawingOptions, setDrawing, notPreset, loading, status }) {
  const { setStatus, showNotices } = status;
  async function loadFile(file) {
    const failed = loading();
    try {
      const text = await file.text();
      const plc = await parseInput(text, file.name);
      notPreset();
      setDrawing(fromPlc(plc, drawingOptions()));
      setStatus(`Loaded ${file.name}: ${plc.points.length / 2} points, ${plc.segments.length / 2} segments.`, 'ok');
    } catch (error) {
      failed();
      setStatus(`Could not load ${file.name}: ${error.message}`, 'error');
      showNotices([], error);
    }
  }
  $('file-input').addEventListener('change', () => {
    const file = $('file-input').files[0];
    if (file) loadFile(file);
    $('file-input').value = '';
  });

  const wrap = $('canvas-wrap');
  wrap.addEventListener('dragover', (e) => {
    if (![...(e.dataTransfer?.types ?? [])].includes('Files')) return;
    e.preventDefault();
    $('drop-hint').hidden = false;
  });
  wrap.addEventListener('dragleave', () => { $('drop-hint').hidden = true; });
  wrap.addEventListener('drop', (e) => {
    e.preventDefault();
    $('drop-hint').hidden = true;
    const file = e.dataTransfer?.files?.[0];
    if (file) loadFile(file);
  });
}
