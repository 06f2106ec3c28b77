// Types of the ruppert package. The layouts follow core/include/ruppert/ruppert.h.

/** Numbers in a plain array or any numeric typed array. */
export type NumberArray = ArrayLike<number>;

export interface Region {
  /** Seed point inside the region. */
  x: number;
  y: number;
  /** Copied to every triangle of the region (mesh.triangleAttributes). Default 0. */
  attribute?: number;
  /** Upper bound on triangle area in this region; <= 0 or absent: none. */
  maxArea?: number;
}

/** A curve's type: the core's names (ruppert.h's CurveType). */
export type CurveType = 'arc' | 'bezier';

/**
 * A curved boundary from point `from` to point `to`, bounding regions, holes and the domain as a
 * segment does; refinement splits it on the curve, so every vertex of its pieces lies on it, each
 * piece within options.curveTolerance of it. Its pieces' segmentIds are segments.length / 2 + its
 * index in curves.
 */
export type Curve =
  /** Counter-clockwise around center; from and to at the same distance from it. A circle is two arcs. */
  | { type: 'arc'; from: number; to: number; center: NumberArray; marker?: number }
  /** The cubic Bézier with inner control points controls = [x1, y1, x2, y2]. */
  | { type: 'bezier'; from: number; to: number; controls: NumberArray; marker?: number };

/** A planar straight-line graph. */
export interface Plc {
  /** Interleaved coordinates x0, y0, x1, y1, ... */
  points: NumberArray;
  /**
   * Pairs of 0-based point indices a0, b0, a1, b1, ... Without any, the convex hull of the points is
   * meshed (as Triangle does for a point set), with no notice; segments that enclose nothing get the
   * hull too, with a NOTHING_ENCLOSED notice.
   */
  segments?: NumberArray;
  /** Hole seeds hx0, hy0, hx1, hy1, ... */
  holes?: NumberArray;
  regions?: Region[];
  /**
   * Boundary markers, one per point, or empty: a nonzero one is kept in mesh.pointMarkers (see
   * Mesh.pointMarkers for Triangle's rules).
   */
  pointMarkers?: NumberArray;
  /** One per segment, or empty: every subsegment of the segment, and every vertex on it, carries it. */
  segmentMarkers?: NumberArray;
  /**
   * Per-point attributes, flat: attributesPerPoint values per point, point after point. Interpolated
   * linearly onto every new vertex (mesh.pointAttributes).
   */
  pointAttributes?: NumberArray;
  /** Values per point in pointAttributes; default: its length divided by the number of points. */
  attributesPerPoint?: number;
  /** 0 or 1: the index base writers print. */
  indexBase?: 0 | 1;
  /**
   * Refining a mesh (Triangle's -r): 3 point indices per triangle. The domain is their union; their
   * boundary edges join the segments (numbered after them in segmentIds); refined under the options.
   */
  triangles?: NumberArray;
  /**
   * One maximum area per triangle (<= 0: none). A new triangle's bound is the smallest among the old
   * triangles its interior meets, so every triangle lying within an old triangle meets its bound.
   */
  triangleMaxArea?: NumberArray;
  /** Curved boundaries; not with triangles. */
  curves?: Curve[];
}

/** What the readers return. */
export interface ParsedPlc extends Plc {
  points: Float64Array;
  segments: Uint32Array;
  holes: Float64Array;
  regions: Required<Region>[];
  pointMarkers: Int32Array;
  segmentMarkers: Int32Array;
  indexBase: 0 | 1;
  /** The .node's attribute columns, attributesPerPoint per point (empty without any). */
  pointAttributes: Float64Array;
  attributesPerPoint: number;
}

export interface Progress {
  insertedVertices: number;
  triangles: number;
  /** Degrees: smallest angle among triangles still queued as bad. */
  worstAngle: number;
}

export interface TriangulateOptions {
  /**
   * Minimum angle in degrees, in [0, 60]. Default 30. Above 34 it may be out of reach: then the
   * result is the best mesh reached (complete: false, reason 'ANGLE_UNREACHABLE', the angle reached
   * in stats.reachedAngle), never below 33 degrees outside the chapter's exemptions nor over four
   * times the triangles of the 33-degree mesh, when 33 degrees completes. With the default
   * placement the bound held on 100% / 93% / 5% of the benchmark's 300 generated PLCs at 35 / 38 /
   * 40 degrees (docs/measurements.md); a complete mesh at 38 had a median 4.9 (at most 15.5) times the
   * triangles of the same PLC's 33-degree mesh (native CLI, the same PLCs).
   */
  minAngle?: number;
  /**
   * Largest angle in degrees, in [0, 180]: 0 or absent for none, else above 60 and below 180 (any
   * such value goes with any minAngle). Default 0. No triangle gets a larger angle outside the
   * chapter's exemptions (in small input angles, on seditious edges); where refinement stops short,
   * complete is false and reasons say what remains.
   */
  maxAngle?: number;
  /** Global upper bound on triangle area; 0 or absent: none. */
  maxArea?: number;
  /** Budget of Steiner vertices; default automatic. Running out sets complete = false. */
  maxSteiner?: number;
  /** Maximum triangle area at (x, y); return <= 0 or Infinity for no bound there. */
  sizeFunction?: (x: number, y: number) => number;
  /** Record mesh.events (every insertion). */
  trace?: boolean;
  /** Compute stats.lfsIntegral, the chapter's size measure (section 6.5). */
  sizeMeasure?: boolean;
  /** Return mesh.triangleExemptions: per triangle, whether section 6.6 exempts it from the bounds. */
  exemptions?: boolean;
  /**
   * 'optimal' (default): Erten and Üngör's locally optimal Steiner points and relocation of free
   * vertices, the fewest triangles and the bounds of 35-40 degrees (not always: check complete);
   * 'offcenter': Üngör's off-centers, faster without maxArea; 'circumcenter'; 'petal'.
   */
  placement?: 'offcenter' | 'circumcenter' | 'petal' | 'optimal';
  /** 'lens' (default): diametral lenses, fewer splits; 'disk': the closed diametral disk of the chapter. */
  encroachment?: 'lens' | 'disk';
  /** 'cdt': constrained Delaunay refinement; 'box': Ruppert's original, conforming, in a box. */
  variant?: 'cdt' | 'box';
  /** Mesh the whole convex hull, not only what segments enclose. */
  convexHull?: boolean;
  /** With no hole seeds: regions at odd nesting depth are domain, even are holes. */
  autoHoles?: boolean;
  /** Called every few thousand insertions; return false to stop early (complete = false). */
  onProgress?: (progress: Progress) => boolean | void;
  /** Also return mesh.edges and mesh.edgeMarkers (Triangle's -e). */
  edges?: boolean;
  /**
   * No new vertex on the domain's boundary (Triangle's -Y): its subsegments stay as the input gave
   * them; triangles that only such a vertex could fix are left, reported as SEGMENT_SPLIT_FORBIDDEN.
   */
  noBoundarySteiner?: boolean;
  /** No new vertex on any segment (Triangle's -YY); as noBoundarySteiner otherwise. */
  noSegmentSteiner?: boolean;
  /** Leave unused input points out of mesh.points (Triangle's -j); mesh.inputToOutput maps the indices. */
  jettison?: boolean;
  /**
   * With plc.curves: the largest distance from a boundary edge to the curve it follows (input units).
   * Default (0): 1e-3 of the diagonal of the points' bounding box.
   */
  curveTolerance?: number;
  /**
   * Smoothing after refinement: true for 4 passes, or a number of passes in [0, 100]; default
   * false (0). Free vertices move towards the area-weighted mean of their star's circumcenters
   * (optimal Delaunay triangulation) and vertices on segments slide along them, flips keeping the
   * mesh constrained Delaunay; a move stays only if every triangle it changed keeps minAngle and
   * every area bound. The triangle count and the sizes stay; triangles get rounder (on the
   * benchmark's 300 generated PLCs at 30 degrees: mean smallest angle up 3.2 degrees, a third fewer
   * obtuse triangles; docs/measurements.md).
   */
  smooth?: boolean | number;
  /**
   * 2: quadratic triangles: mesh.triangles6, and one midpoint node per edge appended to points
   * (and pointMarkers) after the corner vertices. Default 1.
   */
  order?: 1 | 2;
  /** Also compute mesh.voronoi, the dual of the mesh. */
  voronoi?: boolean;
}

/** The dual of a mesh (options.voronoi): one vertex per triangle, one edge per mesh edge. */
export interface Voronoi {
  /** Circumcenter of triangle t at 2t, 2t+1 (it may lie outside its triangle and the domain). */
  points: Float64Array;
  /** Two Voronoi vertex indices per mesh edge; the second is -1 for a ray (a boundary edge). */
  edges: Int32Array;
  /** Two per mesh edge: a ray's direction, the boundary edge's outward normal (its length); 0, 0 otherwise. */
  rayDirections: Float64Array;
  /** Two per edge: the mesh edge (vertex indices) each dual edge crosses. */
  meshEdges: Uint32Array;
}

// The names in these unions (and in ErrorCode, VertexKind, EventKind and Options' placement,
// encroachment and variant) are the core's, written once in core/include/ruppert/ruppert.h; TypeScript
// needs them literally, so tests/package/names.test.mjs fails when one here differs from the binding's.
export type ReasonKind = 'SMALL_INPUT_ANGLE' | 'SEDITIOUS_EDGE' | 'STEINER_BUDGET' | 'PRECISION_FLOOR' | 'CANCELLED'
  // minAngle above 34 degrees that refinement could not reach (directly, in four attempts of up to
  // 16, 128, 128 and 16 times the 33-degree mesh's triangles): the mesh is the best one reached
  // (stats.reachedAngle): the 33-degree mesh, or better, from raising its bound a degree at a time
  // while the mesh improved.
  | 'ANGLE_UNREACHABLE'
  // noBoundarySteiner / noSegmentSteiner: triangles left bad because only a vertex on a subsegment
  // that may not be split would fix them.
  | 'SEGMENT_SPLIT_FORBIDDEN';
export type NoticeKind = 'DUPLICATE_POINT' | 'ZERO_LENGTH_SEGMENT' | 'DUPLICATE_SEGMENT' | 'VERTEX_ON_SEGMENT' |
  'SEGMENTS_CROSS' | 'SEGMENTS_OVERLAP' | 'HOLE_OUTSIDE_DOMAIN' | 'REGION_OUTSIDE_DOMAIN' | 'NOTHING_ENCLOSED';

export interface Reason {
  kind: ReasonKind;
  /** How many triangles or subsegments remain because of it. */
  count: number;
  message: string;
}

export interface Notice {
  kind: NoticeKind;
  a: number;
  b: number;
  x: number;
  y: number;
  message: string;
}

export interface Stats {
  vertices: number;
  triangles: number;
  minAngle: number;
  maxAngle: number;
  /**
   * Degrees: the smallest angle over the triangles the angle bound applies to (those in small input
   * angles and on seditious edges left out): >= minAngle when complete; with 'ANGLE_UNREACHABLE',
   * the angle the returned mesh reached.
   */
  reachedAngle: number;
  /** 180 bins of 1 degree over all three angles of every triangle. */
  angleHistogram: Float64Array;
  inputVertices: number;
  segmentVertices: number;
  interiorVertices: number;
  offCenterVertices: number;
  intersectionVertices: number;
  rejectedCircumcenters: number;
  lfsIntegral: number;
  trianglesPerLfsIntegral: number;
  milliseconds: number;
}

/**
 * The trace, one entry per step (an insertion, or a RELOCATED move of a vertex), as a structure of
 * arrays. Step k's mesh is the one `maxSteiner: k` gives with the same options.
 */
export interface Events {
  count: number;
  /** EventKind per event. */
  kind: Uint8Array;
  /** Id of the vertex inserted (RELOCATED: moved). */
  vertex: Uint32Array;
  /** Where: x, y per event. */
  xy: Float64Array;
  /** Subsegment endpoints (SEGMENT_SPLIT, REJECTED). */
  a: Uint32Array;
  b: Uint32Array;
  /** Encroaching vertex (SEGMENT_SPLIT), -1 if none. */
  by: Int32Array;
  /** The skinny triangle's three vertices per event (every kind but SEGMENT_SPLIT). */
  triangle: Uint32Array;
  /** x, y per event: the rejected circumcenter (REJECTED); where the vertex was before (RELOCATED). */
  circumcenter: Float64Array;
}

/**
 * Every typed array of a result is a copy, never a view into WebAssembly memory. The mesh's own
 * arrays (stats.angleHistogram and, where asked for, edges, edgeMarkers, inputToOutput included)
 * are views into one ArrayBuffer that belongs to this result alone; triangles6 and voronoi's arrays
 * share a second one, and a trace's events have arrays of their own. `.slice()` an array to keep it
 * apart from the others.
 */
export interface Mesh {
  /** Input points first, same indices; then new vertices. x0, y0, x1, y1, ... */
  points: Float64Array;
  /** Three vertex indices per triangle, counter-clockwise. */
  triangles: Uint32Array;
  /** Three per triangle: neighbors[3t+i] is across the edge opposite triangles[3t+i]; -1 on the boundary. */
  neighbors: Int32Array;
  /** Two vertex indices per subsegment. */
  segments: Uint32Array;
  /**
   * Input segment index per subsegment, plc.segments.length / 2 + c for a piece of plc.curves[c], or
   * -1 for an added convex-hull edge.
   */
  segmentIds: Int32Array;
  /** VertexKind per point. */
  vertexKinds: Uint8Array;
  /** Region attribute per triangle. */
  triangleAttributes: Float64Array;
  /**
   * Boundary marker per point, Triangle's rules: a nonzero input marker is kept; else a vertex on an
   * input segment with a nonzero marker (its ends and every vertex inserted on it) has that marker
   * (on several: the lowest segment index's); else 1 on the mesh's boundary (holes included), 0 inside.
   */
  pointMarkers: Int32Array;
  /** Boundary marker per subsegment: its input segment's if nonzero, else 1 on the boundary, 0 inside. */
  segmentMarkers: Int32Array;
  /** With options.edges: every edge once, two vertex indices each. */
  edges?: Uint32Array;
  /** With options.edges: per edge, its subsegment's marker, else 1 on the boundary, 0 inside. */
  edgeMarkers?: Int32Array;
  /** attributesPerPoint values per point: the input's, interpolated linearly onto new vertices. */
  pointAttributes: Float64Array;
  attributesPerPoint: number;
  /**
   * With options.jettison: per input point, its index in points; a merged duplicate gives the index
   * of the point it was merged into, a point outside the domain -1.
   */
  inputToOutput?: Int32Array;
  /**
   * With options.exemptions: per triangle, 0, or why refinement left it below the angle bounds on
   * purpose (section 6.6): 1 its smallest angle is an input angle, 2 its shortest edge is seditious.
   */
  triangleExemptions?: Uint8Array;
  indexBase: 0 | 1;
  /** Every bound met, except the exemptions of small input angles (chapter 6.6). */
  complete: boolean;
  /** What is unmet and why; SMALL_INPUT_ANGLE / SEDITIOUS_EDGE entries are exemptions and may appear when complete. */
  reasons: Reason[];
  notices: Notice[];
  stats: Stats;
  /** Only with options.trace. */
  events?: Events;
  /**
   * Only with options.order = 2: six per triangle: its corners (as in triangles), then the midpoint
   * nodes of the edges opposite corners 0, 1, 2 (Triangle's -o2 order); shared between neighbors.
   */
  triangles6?: Uint32Array;
  /** Only with options.voronoi. */
  voronoi?: Voronoi;
}

/** The texts parseEle reads besides the .ele (Triangle's -r input). */
export interface ParseEleOptions {
  name?: string;
  /** Text of the .node file holding the points (required). */
  node: string;
  nodeName?: string;
  /** Text of the .poly: segments, holes, regions (declaring 0 points, or the .node's). */
  poly?: string;
  polyName?: string;
  /** Text of the .area file: a maximum area per triangle, -1 for none. */
  area?: string;
  areaName?: string;
}

/** What parseEle returns: a PLC with the triangles to refine. */
export interface ParsedMeshPlc extends ParsedPlc {
  triangles: Uint32Array;
  triangleMaxArea: Float64Array;
}

export type ErrorCode =
  | 'EMPTY_INPUT' | 'NON_FINITE_COORDINATE' | 'COORDINATE_RANGE' | 'INDEX_OUT_OF_RANGE'
  | 'DEGENERATE_INPUT' | 'HOLE_ON_SEGMENT' | 'INVALID_REGION' | 'INVALID_OPTION' | 'PARSE_ERROR'
  | 'IO_ERROR' | 'TOO_LARGE' | 'CANCELLED' | 'MALFORMED_INPUT' | 'EMPTY_DOMAIN' | 'INTERNAL';

export declare const ERROR_CODES: readonly ErrorCode[];

export declare class MeshError extends Error {
  constructor(code: ErrorCode, message: string, options?: { cause?: unknown });
  readonly name: 'MeshError';
  /** Stable, for branching; the message names the offending item. */
  readonly code: ErrorCode;
}

export declare const VertexKind: Readonly<{
  INPUT: 0; SEGMENT_SPLIT: 1; INTERIOR: 2; OFF_CENTER: 3; INTERSECTION: 4; UNUSED: 5;
}>;
export declare const EventKind: Readonly<{
  SEGMENT_SPLIT: 0; CIRCUMCENTER: 1; OFF_CENTER: 2; REJECTED: 3;
  /** The point placement 'petal' or 'optimal' chose instead of the off-center (never rejected). */
  PETAL_POINT: 4; OPTIMAL_POINT: 5;
  /** A free vertex the placement 'optimal' moved from `circumcenter` to `xy` (no vertex added). */
  RELOCATED: 6;
}>;
export declare const NO_NEIGHBOR: -1;
export declare const NO_INPUT_SEGMENT: -1;

export interface InitOptions {
  /**
   * Where ruppert.wasm is served. Default: where vite or webpack put it; unbundled, the package's
   * wasm/dist/ruppert.wasm; in a bundle of a bundler that copies no assets (esbuild), ruppert.wasm
   * beside the bundle.
   */
  wasmUrl?: string | URL;
  /** Called with 'ruppert.wasm' and 'ruppert-formats.wasm'; returns where each is served. */
  locateFile?: (file: string) => string;
  wasmBinary?: ArrayBuffer | ArrayBufferView;
  wasmModule?: WebAssembly.Module;
  /**
   * The text formats module (ruppert-formats.wasm: parsePoly, parseNode, parseJson, parseEle and
   * every to*() writer; parseGeoJson is in the mesher). true (default): loaded with the mesher, from
   * locateFile's answer, else beside `wasmUrl`, else where the package keeps it (as for
   * ruppert.wasm). false: not loaded (the mesher alone, as createMeshWorker's worker runs it); the
   * readers and writers then throw MeshError INVALID_OPTION. An object: its own source.
   */
  formats?: boolean | { wasmUrl?: string | URL; wasmBinary?: ArrayBuffer | ArrayBufferView; wasmModule?: WebAssembly.Module };
}

/** The second argument of parsePoly: a name for messages, or these. */
export interface ParsePolyOptions {
  /** Shown in error messages. Default '<poly>'. */
  name?: string;
  /** Text of the .node file holding the points of a .poly that declares 0 points (Triangle's split form). */
  node?: string;
  /** Shown in error messages about the .node text. Default '<node>'. */
  nodeName?: string;
}

export interface Mesher {
  /** Meshes a PLC. Throws MeshError on input that cannot be repaired. */
  triangulate(plc: Plc, options?: TriangulateOptions): Mesh;
  parsePoly(text: string, options?: string | ParsePolyOptions): ParsedPlc;
  parseNode(text: string, name?: string): ParsedPlc;
  parseJson(text: string, name?: string): ParsedPlc;
  toNode(mesh: Mesh): string;
  toEle(mesh: Mesh): string;
  /** Triangle's .edge text (mesh.edges if present, else computed). */
  toEdge(mesh: Mesh): string;
  toPoly(mesh: Mesh, input?: Plc): string;
  toJson(mesh: Mesh, input?: Plc): string;
  toSvg(mesh: Mesh): string;
  /** GeoJSON Polygon/MultiPolygon/Feature/FeatureCollection to a PLC; inner rings get hole seeds. */
  parseGeoJson(text: string, name?: string): ParsedPlc;
  /** Gmsh MSH 4.1 ASCII; `input` gives the segment markers that name the lines' physical groups. */
  toMsh(mesh: Mesh, input?: Plc): string;
  /** VTK XML UnstructuredGrid (ASCII); see VtuOptions. */
  toVtu(mesh: Mesh, options?: VtuOptions): string;
  /** GeoJSON FeatureCollection, one Polygon feature per triangle. */
  toGeoJson(mesh: Mesh): string;
  /** Triangle's .ele with its .node (and .poly, .area): a PLC whose triangles triangulate() refines. */
  parseEle(text: string, options: ParseEleOptions): ParsedMeshPlc;
  /** Triangle's .v.node / .v.edge texts of mesh.voronoi. */
  toVoronoiNode(mesh: Mesh): string;
  toVoronoiEdge(mesh: Mesh): string;
  /** Whether the text formats module is loaded (init() without formats: false). */
  readonly hasFormats: boolean;
  /** Resolves once a wasm instance is available (pending only right after an abort). */
  readonly ready: Promise<void>;
  memoryUsage(): { heapBytes: number; allocatedBytes: number };
}

/** Loads the WebAssembly modules (once, when called without options). */
export declare function init(options?: InitOptions): Promise<Mesher>;

/** The helpers below use the most recently initialised mesher: `await init()` first. */
export declare function parsePoly(text: string, options?: string | ParsePolyOptions): ParsedPlc;
export declare function parseNode(text: string, name?: string): ParsedPlc;
export declare function parseJson(text: string, name?: string): ParsedPlc;
export declare function toPoly(mesh: Mesh, input?: Plc): string;
export declare function toNode(mesh: Mesh): string;
export declare function toEle(mesh: Mesh): string;
export declare function toEdge(mesh: Mesh): string;
export declare function toJson(mesh: Mesh, input?: Plc): string;
export declare function toSvg(mesh: Mesh): string;
export declare function parseGeoJson(text: string, name?: string): ParsedPlc;
export declare function toMsh(mesh: Mesh, input?: Plc): string;
/** toVtu's options. */
export interface VtuOptions {
  /**
   * Also a line cell per subsegment after the triangles, with a cell array segmentMarker (each
   * line's marker, 0 for the triangles), as the CLI's --format vtu writes. Default false.
   */
  segmentCells?: boolean;
}
export declare function toVtu(mesh: Mesh, options?: VtuOptions): string;
export declare function toGeoJson(mesh: Mesh): string;
export declare function parseEle(text: string, options: ParseEleOptions): ParsedMeshPlc;
export declare function toVoronoiNode(mesh: Mesh): string;
export declare function toVoronoiEdge(mesh: Mesh): string;

export type WorkerOptions = Omit<TriangulateOptions, 'sizeFunction' | 'onProgress'>;

export interface MeshWorkerControl {
  /** Aborting terminates the worker at once; the promise rejects with MeshError 'CANCELLED'. */
  signal?: AbortSignal;
  onProgress?: (progress: Progress) => void;
}

export interface MeshWorker {
  triangulate(plc: Plc, options?: WorkerOptions, control?: MeshWorkerControl): Promise<Mesh>;
  /** Ends the worker; pending requests reject with 'CANCELLED'. */
  terminate(): Promise<void>;
}

export interface MeshWorkerOptions extends Omit<InitOptions, 'locateFile'> {
  /**
   * Where ruppert's worker script is served, for setups that place it themselves (browsers: a
   * module worker; Node: a file: URL of wasm/worker-node.js). Default: where vite or webpack put
   * it; otherwise worker.js beside the module (or the bundle) that calls createMeshWorker.
   */
  workerUrl?: string | URL;
}

/** A mesher in a Web Worker (browsers) or a worker_threads worker (Node). */
export declare function createMeshWorker(options?: MeshWorkerOptions): MeshWorker;
