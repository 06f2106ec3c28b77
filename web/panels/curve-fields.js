// The Parameters panel's fields for curves: the curve tolerance (options.curveTolerance; empty or
// 0 is the core's automatic 1e-3 of the drawing's diagonal) and the selected curve's marker (the
// segment marker field serves a selected curve too).
import { CurveItem } from '../model/curve-data.js';

const $ = (id) => document.getElementById(id);

/** Shows the drawing's tolerance (empty when automatic). */
export function syncCurveTolerance(options) {
  $('curve-tolerance').value = options.curveTolerance > 0 ? String(options.curveTolerance) : '';
}

const curveOf = (d, item) => ((item?.kind === CurveItem.CURVE || item?.kind === CurveItem.HANDLE) ? d.curves?.[item.index] ?? null : null);

/** The marker of the selected curve (0: none), or null when no curve is selected. */
export function curveMarkerOf(d, item) {
  const c = curveOf(d, item);
  return c ? c.marker ?? 0 : null;
}

/** Sets the selected curve's marker; false when no curve is selected. */
export function setCurveMarker(d, item, value) {
  const c = curveOf(d, item);
  if (!c) return false;
  if (value) c.marker = value;
  else delete c.marker;
  return true;
}
