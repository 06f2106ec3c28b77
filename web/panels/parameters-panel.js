// The Parameters panel: min angle (slider and number), max angle, max area, Steiner placement, algorithm,
// encroachment, Steiner budget, the region seed fields (for new seeds, or the selected one) and the
// selected segment's marker.
// Each field writes app.drawing.options and reports the change; sync() shows a drawing's options.
import { DEFAULT_OPTIONS, Item, MIN_ANGLE_RANGE, PAGE_FLAGS, flagOption, segmentMarkers } from '../model/drawing.js';
import { ENCROACHMENT_LABELS, PLACEMENT_LABELS, PRACTICAL_ANGLE, VARIANT_LABELS } from '../labels.js';
import { curveMarkerOf, setCurveMarker, syncCurveTolerance } from './curve-fields.js';
import { checkOptions } from '../../wasm/input-checks.js';

const $ = (id) => document.getElementById(id);

/** The field's number, or null when it is empty or not a number. */
function readNumber(input) {
  if (input.value.trim() === '') return null;
  const value = Number(input.value);
  return Number.isFinite(value) ? value : null;
}

/**
 * A field of a package option, read as the package reads that option: { value } (null when empty:
 * the default, none or automatic), or { error }, the package's own message for that value, so that
 * the page refuses exactly what triangulate() refuses.
 */
export function readOption(input, name) {
  const text = input.value.trim();
  if (text === '') return { value: null };
  const value = Number(text);
  try {
    checkOptions({ [name]: value });
  } catch (error) {
    return { error: `${error.message} (${error.code ?? 'INVALID_OPTION'})` };
  }
  return { value };
}

/** Whether the min angle is past what the placement usually reaches (the warning under the slider). */
export function pastPractical(options) {
  return options.minAngle > (PRACTICAL_ANGLE[options.placement] ?? PRACTICAL_ANGLE.offcenter);
}

/** A select's entries from a table of labels keyed by the option's values (labels.js). */
function fillSelect(select, labels) {
  for (const [value, label] of Object.entries(labels)) {
    const option = document.createElement('option');
    option.value = value;
    option.textContent = label;
    select.append(option);
  }
}

/**
 * @param {object} app the page's state (drawing)
 * @param {object} editor the Editor (its selection: the region seed the fields edit)
 * @param {(commit: boolean) => void} changed an option changed; `commit` records an undo step
 * @param {object} status the status line (panels/status-line.js): setStatus(text, kind), showNotices(notices, error)
 */
export function createParametersPanel({ app, editor, changed, status }) {
  const { setStatus } = status;
  fillSelect($('placement'), PLACEMENT_LABELS);
  fillSelect($('variant'), VARIANT_LABELS);
  fillSelect($('encroachment'), ENCROACHMENT_LABELS);
  const minAngleRange = $('min-angle-range');
  const minAngleNumber = $('min-angle');

  /** Shows the drawing's options in the fields. */
  function sync() {
    const o = app.drawing.options;
    minAngleRange.value = String(o.minAngle);
    minAngleNumber.value = String(o.minAngle);
    $('min-angle-warning').hidden = !pastPractical(o);
    $('max-angle').value = o.maxAngle > 0 ? String(o.maxAngle) : '';
    $('max-area').value = o.maxArea > 0 ? String(o.maxArea) : '';
    for (const id of ['max-angle', 'max-area', 'max-steiner', 'curve-tolerance']) $(id).removeAttribute('aria-invalid');
    $('placement').value = o.placement;
    $('max-steiner').value = Number.isInteger(o.maxSteiner) ? String(o.maxSteiner) : '';
    $('variant').value = o.variant ?? DEFAULT_OPTIONS.variant;
    $('encroachment').value = o.encroachment ?? DEFAULT_OPTIONS.encroachment;
    for (const id of PAGE_FLAGS) $(id).checked = Boolean(o[flagOption(id)]);
    syncCurveTolerance(o);
  }

  const { min, max } = MIN_ANGLE_RANGE;
  const inRange = (value) => value !== null && value >= min && value <= max;
  for (const input of [minAngleRange, minAngleNumber]) input.min = String(min), input.max = String(max);

  function setMinAngle(value, commit) {
    if (!inRange(value)) {
      minAngleNumber.setAttribute('aria-invalid', 'true');
      setStatus(`Min angle must be a number from ${min} to ${max} degrees.`, 'error');
      return;
    }
    minAngleNumber.removeAttribute('aria-invalid');
    app.drawing.options.minAngle = value;
    $('min-angle-warning').hidden = !pastPractical(app.drawing.options);
    changed(commit);
  }
  // The slider re-meshes while it moves and records an undo step once it rests (browsers differ
  // in when they fire 'change' for keyboard input, so a short quiet period also commits).
  let sliderCommit = null;
  minAngleRange.addEventListener('input', () => {
    minAngleNumber.value = minAngleRange.value;
    setMinAngle(Number(minAngleRange.value), false);
    clearTimeout(sliderCommit);
    sliderCommit = setTimeout(() => changed(true), 600);
  });
  minAngleRange.addEventListener('change', () => {
    clearTimeout(sliderCommit);
    setMinAngle(Number(minAngleRange.value), true);
  });
  minAngleNumber.addEventListener('input', () => {
    const value = readNumber(minAngleNumber);
    if (inRange(value)) minAngleRange.value = String(value);
    setMinAngle(value, false);
  });
  minAngleNumber.addEventListener('change', () => setMinAngle(readNumber(minAngleNumber), true));

  /**
   * The option fields: a value the package refuses is marked and named on the status line, and
   * the drawing keeps its last valid value (nothing is meshed with a value silently changed).
   */
  const OPTION_FIELDS = [
    ['max-area', 'maxArea', 'Max area', (v) => (v > 0 ? v : null)],
    ['max-steiner', 'maxSteiner', 'Steiner budget', (v) => v],
    ['curve-tolerance', 'curveTolerance', 'Curve tolerance', (v) => v ?? 0],
  ];
  for (const [id, name, label, stored] of OPTION_FIELDS) {
    $(id).addEventListener('change', () => {
      const { value, error } = readOption($(id), name);
      if (error) {
        $(id).setAttribute('aria-invalid', 'true');
        setStatus(`${label}: ${error}; the mesh keeps the last valid value.`, 'error');
        return;
      }
      $(id).removeAttribute('aria-invalid');
      app.drawing.options[name] = stored(value);
      changed(true);
    });
  }
  // Empty (or 0) for none; otherwise the mesher takes only values above 60 and below 180.
  $('max-angle').addEventListener('change', () => {
    const value = readNumber($('max-angle'));
    if (value !== null && value !== 0 && !(value > 60 && value < 180)) {
      $('max-angle').setAttribute('aria-invalid', 'true');
      setStatus('Max angle must be above 60 and below 180 degrees (empty: none).', 'error');
      return;
    }
    $('max-angle').removeAttribute('aria-invalid');
    app.drawing.options.maxAngle = value !== null && value > 0 ? value : null;
    changed(true);
  });
  for (const name of ['placement', 'variant', 'encroachment']) {
    $(name).addEventListener('change', () => {
      app.drawing.options[name] = $(name).value;
      $('min-angle-warning').hidden = !pastPractical(app.drawing.options);
      changed(true);
    });
  }
  for (const id of PAGE_FLAGS) {
    $(id).addEventListener('change', () => {
      app.drawing.options[flagOption(id)] = $(id).checked;
      changed(true);
    });
  }

  /** The region seed fields' values: those of a new seed. */
  function regionSeed() {
    const attribute = readNumber($('region-attribute')) ?? 0;
    const maxArea = readNumber($('region-max-area'));
    return { attribute, maxArea: maxArea !== null && maxArea > 0 ? maxArea : null };
  }
  /** Shows the selected region seed's values in the fields, and the selected segment's marker. */
  function syncRegion() {
    const item = editor.selection;
    const segment = item?.kind === Item.SEGMENT && item.index < app.drawing.segments.length / 2;
    const curveMarker = curveMarkerOf(app.drawing, item);  // a selected curve's (or its handle's), else null
    $('segment-marker').disabled = !segment && curveMarker === null;
    $('segment-marker').value = segment ? String(segmentMarkers(app.drawing)[item.index]) : curveMarker !== null ? String(curveMarker) : '';
    if (item?.kind !== Item.REGION) return;
    const region = app.drawing.regions[item.index];
    if (!region) return;
    $('region-attribute').value = String(region.attribute ?? 0);
    $('region-max-area').value = region.maxArea > 0 ? String(region.maxArea) : '';
  }
  for (const id of ['region-attribute', 'region-max-area']) {
    $(id).addEventListener('change', () => {
      const item = editor.selection;
      if (item?.kind !== Item.REGION || !app.drawing.regions[item.index]) return;
      Object.assign(app.drawing.regions[item.index], regionSeed());
      changed(true);
    });
  }

  // The selected segment's boundary marker (a whole number; 0: none).
  $('segment-marker').addEventListener('change', () => {
    const item = editor.selection;
    const value = readNumber($('segment-marker'));
    if (value !== null && Number.isInteger(value) && setCurveMarker(app.drawing, item, value)) changed(true);
    if (item?.kind !== Item.SEGMENT || value === null || !Number.isInteger(value)) return;
    app.drawing.segmentMarkers = segmentMarkers(app.drawing);
    app.drawing.segmentMarkers[item.index] = value;
    changed(true);
  });

  return { sync, syncRegion, regionSeed };
}
