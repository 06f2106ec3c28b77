// The line over the canvas about the triangle under the pointer: its angles, radius-edge ratio,
// area, vertices with their kinds, and region attribute.
import { VertexKind } from '../../wasm/index.js';
import { VERTEX_KIND_LABELS } from '../labels.js';
import { triangleShape } from '../geometry/mesh-geometry.js';
import { locateTriangle } from '../geometry/mesh-index.js';

// mesh.vertexKinds holds VertexKind values; the labels are keyed by their names.
const VERTEX_KIND_NAMES = Object.fromEntries(Object.entries(VertexKind).map(([name, value]) => [value, name]));

/**
 * @param {object} app the page's state (mesh, stepMesh, hoverTriangle)
 * @param {() => void} scheduleDraw
 * @returns {(world: {x, y} | null) => void} the pointer at a world point, or gone
 */
export function createHoverInfo({ app, scheduleDraw }) {
  const info = document.getElementById('hover-info');
  return (world) => {
    if (world === null || app.mesh === null) {
      info.hidden = true;
      if (app.hoverTriangle !== -1) { app.hoverTriangle = -1; }
      scheduleDraw();
      return;
    }
    // In step mode the mesh on screen is that of the step shown.
    const mesh = app.stepMesh ?? app.mesh;
    const t = locateTriangle(mesh, world.x, world.y, app.hoverTriangle);
    app.hoverTriangle = t;
    if (t < 0) {
      info.hidden = true;
    } else {
      const shape = triangleShape(mesh, t);
      const kinds = shape.vertices.map((v) => `${v} ${VERTEX_KIND_LABELS[VERTEX_KIND_NAMES[mesh.vertexKinds[v]]] ?? '?'}`);
      const attribute = mesh.triangleAttributes[t];
      info.textContent = `Triangle ${t}: angles ${shape.angles.map((a) => `${a.toFixed(2)}°`).join(', ')}; ` +
        `radius-edge ratio ${shape.radiusEdge.toFixed(3)}; area ${shape.area.toPrecision(4)}; ` +
        `vertices ${kinds.join(', ')}${attribute ? `; attribute ${attribute}` : ''}`;
      info.hidden = false;
    }
    scheduleDraw();
  };
}
