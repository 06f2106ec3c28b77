// The Display panel: the coloring of the triangles and its legend, and the vertex numbers toggle.
import { VERTEX_NUMBERS_UP_TO, exemptionLegend, legendEntries, markerLegend } from '../rendering/render.js';

const $ = (id) => document.getElementById(id);

/**
 * @param {object} app the page's state (colorMode, mesh, exemptions)
 * @param {() => void} scheduleDraw
 * @param {() => void} writeLink the coloring is in the link
 */
export function createDisplayPanel({ app, scheduleDraw, writeLink }) {
  /** The legend of the color mode and of the exemptions marked on the canvas. */
  function updateLegend() {
    const entries = [...legendEntries(app.colorMode, app.mesh), ...exemptionLegend(app.exemptions), ...markerLegend(app.drawing)];
    $('legend').replaceChildren(...entries.map(({ color, label, hatched }) => {
      const item = document.createElement('span');
      item.className = 'legend-item';
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = hatched ? `repeating-linear-gradient(135deg, ${color} 0 2px, #fff 2px 5px)` : color;
      item.append(swatch, label);
      return item;
    }));
  }

  // Vertex numbers on demand, for meshes small enough to read them.
  function vertexNumbersNote() {
    const note = $('vertex-numbers-note');
    const many = app.mesh && app.mesh.points.length / 2 > VERTEX_NUMBERS_UP_TO;
    note.hidden = !($('vertex-numbers').checked && many);
    note.textContent = `shown for meshes of up to ${VERTEX_NUMBERS_UP_TO.toLocaleString('en-US')} vertices`;
  }
  $('vertex-numbers').addEventListener('change', () => {
    vertexNumbersNote();
    scheduleDraw();
  });

  $('color-mode').addEventListener('change', () => {
    app.colorMode = $('color-mode').value;
    updateLegend();
    writeLink();
    scheduleDraw();
  });

  /** The color mode a link asked for. */
  function setColorMode(mode) {
    $('color-mode').value = mode;
    app.colorMode = mode;
  }

  return {
    updateLegend, vertexNumbersNote, setColorMode,
    get vertexNumbers() { return $('vertex-numbers').checked; },
  };
}
