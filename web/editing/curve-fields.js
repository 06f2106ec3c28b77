// The Parameters panel's fields for curves: the curve tolerance (options.curveTolerance; empty or
// 0 is the core's automatic 1e-3 of the drawing's diagonal) and the selected curve's marker (the
// segment marker field serves a selected curve too).
import { CurveItem } from './curve-data.js';

const $ = (id) => document.getElementById(id);

/** Shows the drawing's tolerance (empty when automatic). */
export function syncCurveTolerance(options) {
  $('curve-tolerance').value = options.curveTolerance > 0 ? String(options.curveTolerance) : '';
}

/** Writes the field into the drawing's options on change (an undo step), refusing negatives. */
export function watchCurveTolerance(app, changed) {
  const field = $('curve-tolerance');
  field.addEventListener('change', () => {
    const text = field.value.trim();
    const value = text === '' ? 0 : Number(text);
    if (!Number.isFinite(value) || value < 0) {
      field.setAttribute('aria-invalid', 'true');
      return;
    }
    field.removeAttribute('aria-invalid');
    app.drawing.options.curveTolerance = value;
    changed(true);
  });
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
