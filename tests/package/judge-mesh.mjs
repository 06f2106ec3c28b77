// Judging a mesh the package returned for a PLC and options, shared by the hostile catalog and the
// careless-PLC sweep: the independent validator (validate-mesh.mjs) on a copy scaled near 1, the
// input's segments as chains even where the core repaired the input, and the angle bound when the
// mesh says it is complete.
import { validateMesh, triangleAngles } from './validate-mesh.mjs';

// The same mesh scaled by a power of two (exact) so that its largest coordinate is near 1: the
// validator's plain-double predicates would overflow on 1e300 or underflow on 1e-300 coordinates.
function scaled(mesh, plc) {
  let largest = 0;
  for (const v of mesh.points) largest = Math.max(largest, Math.abs(v));
  const exponent = largest > 0 ? -Math.ceil(Math.log2(largest)) : 0;
  // In two steps: for subnormal extents 2^exponent itself overflows.
  const half = 2 ** Math.trunc(exponent / 2), rest = 2 ** (exponent - Math.trunc(exponent / 2));
  const scale = (array) => Float64Array.from(array, (v) => v * half * rest);
  return { mesh: { ...mesh, points: scale(mesh.points) }, input: { ...plc, points: scale(plc.points) } };
}

/** Problems of `mesh`, made from `plc` with `options` (empty: valid). */
export function problemsOf(mesh, plc, options) {
  const { mesh: m, input } = scaled(mesh, plc);
  const problems = validateMesh(m, { input });
  // Angles: a complete mesh meets the bound unless the core names triangles it exempts (small input
  // angles, seditious edges: section 6.6), which this validator does not re-derive.
  const exempting = mesh.reasons.some((r) => r.kind === 'SMALL_INPUT_ANGLE' || r.kind === 'SEDITIOUS_EDGE');
  if (mesh.complete && options.minAngle > 0 && !exempting) {
    const t = m.triangles;
    for (let k = 0; k < t.length / 3; k++) {
      const smallest = Math.min(...triangleAngles(m.points, t[3 * k], t[3 * k + 1], t[3 * k + 2]));
      if (smallest < options.minAngle - 1e-6) problems.push(`complete, but triangle ${k} has angle ${smallest}`);
    }
  }
  if (!mesh.complete && mesh.reasons.length === 0) problems.push('incomplete without a reason');
  return problems;
}
