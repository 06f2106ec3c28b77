// The toolbar's tools and edit and view buttons (undo, redo, delete, clear, fit, snap), and the
// keys that are not the editor's own (editor.js passes them on).
import { emptyDrawing } from '../model/drawing.js';
import { TOOL_HINTS } from './editor.js';

const $ = (id) => document.getElementById(id);

/**
 * @param {object} app the page's state (drawing, snap, undo, redo)
 * @param {object} editor the Editor; `history` the History of the drawing
 * @param {HTMLCanvasElement} canvas the canvas the editor listens to
 * @param {() => void} fitView, scheduleDraw
 * @param {(drawing, how) => void} setDrawing for Clear
 * @param {() => void} syncRegion shows the selected region seed's values (parameters panel)
 * @param {(key) => boolean} stepShortcut the step mode keys (steps panel)
 * @param {() => void} notPreset the drawing is no longer a preset (its caption goes with it)
 */
export function createToolbar({ app, editor, history, canvas, fitView, scheduleDraw, setDrawing, syncRegion, stepShortcut, notPreset }) {
  function setTool(tool) {
    editor.setTool(tool);
    for (const button of document.querySelectorAll('[data-tool]')) {
      button.setAttribute('aria-pressed', String(button.dataset.tool === tool));
    }
    $('tool-hint').textContent = TOOL_HINTS[tool];
    canvas.style.cursor = tool === 'select' ? 'grab' : 'crosshair';
  }
  for (const button of document.querySelectorAll('[data-tool]')) {
    button.addEventListener('click', () => setTool(button.dataset.tool));
  }

  function setSnap() {
    app.snap = $('snap').checked;
    scheduleDraw();
  }

  function shortcut(key) {
    switch (key) {
      case 'f': fitView(); return true;
      case 'g': $('snap').checked = !$('snap').checked; setSnap(); return true;
      default: return stepShortcut(key);
    }
  }

  function updateButtons() {
    $('undo').disabled = !history.canUndo;
    $('redo').disabled = !history.canRedo;
    $('delete-selected').disabled = editor.selection === null;
  }

  $('undo').addEventListener('click', () => app.undo());
  $('redo').addEventListener('click', () => app.redo());
  $('delete-selected').addEventListener('click', () => editor.deleteSelection());
  $('clear').addEventListener('click', () => {
    notPreset();
    setDrawing(emptyDrawing(app.drawing.options), { fit: false });
  });
  $('fit').addEventListener('click', fitView);
  $('snap').addEventListener('change', setSnap);
  // The editor changes the selection on clicks; keep the Delete button's state in step.
  canvas.addEventListener('pointerup', () => { updateButtons(); syncRegion(); });
  canvas.addEventListener('pointerdown', () => queueMicrotask(() => { updateButtons(); syncRegion(); }));

  return { setTool, shortcut, updateButtons };
}
