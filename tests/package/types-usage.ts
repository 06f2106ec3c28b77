// Compiled with `tsc --noEmit --strict` against the installed package (see run-installed.mjs):
// the declarations must accept the documented usage and reject obvious misuse.
import {
  init, createMeshWorker, MeshError, ERROR_CODES, VertexKind, EventKind, NO_NEIGHBOR,
  parsePoly, toPoly, toSvg,
  parseGeoJson, toMsh, toVtu, toGeoJson,
  type Mesh, type Mesher, type Plc, type TriangulateOptions, type ErrorCode, type Progress,
} from 'ruppert';
import { toVoronoiNode, type ParsedMeshPlc, type Voronoi } from 'ruppert';  // issue 16, derived

async function example(): Promise<number> {
  const mesher: Mesher = await init();
  const plc: Plc = {
    points: new Float64Array([0, 0, 1, 0, 1, 1, 0, 1]),
    segments: [0, 1, 1, 2, 2, 3, 3, 0],
    holes: [],
    regions: [{ x: 0.5, y: 0.5, attribute: 1, maxArea: 0.1 }],
  };
  const options: TriangulateOptions = {
    minAngle: 30, maxArea: 0.01, maxSteiner: 1000, trace: true,
    placement: 'offcenter', encroachment: 'lens', variant: 'cdt', convexHull: false, autoHoles: false,
    sizeFunction: (x: number, y: number) => 0.01 * (1 + x + y),
    onProgress: (p: Progress) => p.triangles < 1e6,
  };
  const mesh: Mesh = mesher.triangulate(plc, options);
  const triangles: Uint32Array = mesh.triangles;
  const neighbors: Int32Array = mesh.neighbors;
  const kinds: Uint8Array = mesh.vertexKinds;
  const boundary = neighbors.filter((n) => n === NO_NEIGHBOR).length;
  const interior = kinds.filter((k) => k === VertexKind.INTERIOR).length;
  const splits = mesh.events ? mesh.events.kind.filter((k) => k === EventKind.SEGMENT_SPLIT).length : 0;
  const text: string = toPoly(mesh, plc) + toSvg(mesh) + mesher.toNode(mesh) + mesher.toEle(mesh);
  const parsed = parsePoly(text);
  // Formats solvers, viewers and GIS read (issue 16).
  const solverText: string = toMsh(mesh, plc) + toVtu(mesh) + toGeoJson(mesh) + mesher.toMsh(mesh) + mesher.toVtu(mesh);
  const fromGis: Plc = parseGeoJson(mesher.toGeoJson(mesh), 'mesh.geojson');
  const gisPoints: Float64Array = mesher.parseGeoJson(solverText.length > 0 ? toGeoJson(mesh) : '').points;
  void fromGis.points;
  void gisPoints.length;
  const split = parsePoly('0 2 0 0\n1 0\n0 0 1\n0\n', { name: 'a.poly', node: '2 2 0 0\n0 0 0\n1 1 1\n', nodeName: 'a.node' });
  void split.segments;
  const firstX: number = parsed.points[0];
  const reasons: string[] = mesh.reasons.map((r) => `${r.kind}: ${r.message}`);
  return triangles.length + boundary + interior + splits + firstX + reasons.length + mesh.stats.minAngle;
}

async function worker(): Promise<Mesh> {
  const meshWorker = createMeshWorker({ workerUrl: new URL('https://example.org/worker.js'), wasmUrl: '/ruppert.wasm' });
  const controller = new AbortController();
  try {
    return await meshWorker.triangulate({ points: [0, 0, 1, 0, 0, 1] }, { minAngle: 20 },
      { signal: controller.signal, onProgress: (p) => console.log(p.insertedVertices) });
  } catch (error) {
    if (error instanceof MeshError) {
      const code: ErrorCode = error.code;
      if (ERROR_CODES.includes(code)) throw error;
    }
    throw error;
  } finally {
    await meshWorker.terminate();
  }
}

// Misuse the declarations must reject:
async function misuse(mesher: Mesher): Promise<void> {
  // @ts-expect-error placement is a fixed set of names
  mesher.triangulate({ points: [] }, { placement: 'centroid' });
  // @ts-expect-error points are required
  mesher.triangulate({ segments: [0, 1] });
  // @ts-expect-error the worker cannot take a function
  createMeshWorker().triangulate({ points: [] }, { sizeFunction: () => 1 });
  // @ts-expect-error a function cannot be sent to the worker
  createMeshWorker({ locateFile: (file: string) => file });
  // @ts-expect-error parsePoly's options have no 'nodes'
  parsePoly('', { nodes: '' });
  // @ts-expect-error mesh.triangles is not writable as a plain array
  const t: number[] = (await init()).triangulate({ points: [] }).triangles;
  void t;
}

void example;
void worker;
void misuse;

// Issue 16, derived outputs: refining a mesh, order 2, the Voronoi dual.
async function derived(mesher: Mesher): Promise<void> {
  const old = mesher.triangulate({ points: [0, 0, 1, 0, 0, 1] });
  const plc: ParsedMeshPlc = mesher.parseEle(mesher.toEle(old), { node: mesher.toNode(old), area: '1\n0 0.1\n' });
  const mesh = mesher.triangulate({ points: plc.points, triangles: plc.triangles, triangleMaxArea: [0.1] },
    { order: 2, voronoi: true });
  const six: Uint32Array | undefined = mesh.triangles6;
  const dual: Voronoi | undefined = mesh.voronoi;
  const rays: Float64Array | undefined = dual?.rayDirections;
  const text: string = mesher.toVoronoiEdge(mesh) + toVoronoiNode(mesh);
  // @ts-expect-error order is 1 or 2
  mesher.triangulate({ points: [] }, { order: 3 });
  // @ts-expect-error parseEle needs the .node text
  mesher.parseEle('', {});
  void six, void rays, void text;
}
void derived;

// Issue 45, curves: arcs and cubic Béziers, and their tolerance.
function curved(mesher: Mesher): void {
  const plc: Plc = {
    points: [0, 0, 1, 0, 0, 1],
    segments: [0, 1, 2, 0],
    curves: [{ type: 'arc', from: 1, to: 2, center: [0, 0], marker: 2 }, { type: 'bezier', from: 2, to: 1, controls: [0.5, 2, 2, 0.5] }],
  };
  void mesher.triangulate(plc, { curveTolerance: 1e-3 });
  // @ts-expect-error an arc has a center, not controls
  mesher.triangulate({ points: [], curves: [{ type: 'arc', from: 0, to: 1, controls: [0, 0, 1, 1] }] });
  // @ts-expect-error a curve's type is 'arc' or 'bezier'
  mesher.triangulate({ points: [], curves: [{ type: 'spline', from: 0, to: 1, center: [0, 0] }] });
}
void curved;
