// The presets box: the chapter's figures and other examples (presets.js) with their captions,
// and, when the server offers it, the corpus of real PLCs beside the repository.
import { DEFAULT_OPTIONS, fromPlc } from '../model/drawing.js';
import { DEFAULT_PRESET, PRESETS, findPreset } from './presets.js';

const $ = (id) => document.getElementById(id);
const SHARED_PRESET = 'shared:';

function showCaption(text) {
  $('preset-caption').textContent = text;
  $('preset-caption').hidden = text === '';
}

/**
 * @param {() => object} drawingOptions the drawing's options, which a PLC of the corpus keeps
 * @param {(drawing, how) => void} setDrawing
 * @param {(on: boolean) => void} restartSteps step mode on or off as a preset asks, from step 0
 * @param {(stages: Function|null) => void} setStages the preset's figure stages (presets.js), or none
 * @param {object} compare the side-by-side view (compare-view.js): a preset with `compare` shows it
 * @param {boolean} shared whether to look for the corpus (not in an embed)
 * @param {(text, name) => Promise<object>} parseInput reads a PLC file of the corpus (io/files.js)
 * @param {() => () => void} loading marks the page busy reading a file; returns the function that ends it
 * @param {object} status the status line (panels/status-line.js): setStatus(text, kind), showNotices(notices, error)
 */
export function createPresetBox({ drawingOptions, setDrawing, restartSteps, setStages, compare, shared, parseInput, loading, status }) {
  const { setStatus } = status;
  for (const preset of PRESETS) {
    const option = document.createElement('option');
    option.value = preset.id;
    option.textContent = preset.name;
    if (preset.title) option.title = preset.title;
    $('preset').append(option);
  }
  $('preset').addEventListener('change', () => {
    const value = $('preset').value;
    if (value.startsWith(SHARED_PRESET)) {
      loadSharedPreset(value.slice(SHARED_PRESET.length));
      return;
    }
    if (value === '') showCaption('');
    else open(value);
  });

  /**
   * Opens the preset of that id in the same state whatever came before: its drawing, the default
   * options with its own over them, its caption, the view fitted, and the replay at step 0 when it
   * asks for steps, else at the final mesh (steps-panel.js's restart).
   * Returns false when there is no such preset.
   */
  function open(id, { commit = true, steps = true } = {}) {
    const preset = findPreset(id);
    if (!preset) return false;
    $('preset').value = preset.id;
    showCaption(preset.caption ?? '');
    if (steps) restartSteps(Boolean(preset.steps));
    setStages(preset.stages ?? null);
    if (preset.compare) compare.show(preset.compare);
    else compare.hide();
    setDrawing({ ...preset.build(), options: { ...DEFAULT_OPTIONS, ...(preset.options ?? {}) } }, { commit });
    return true;
  }

  /**
   * The drawing is no longer a preset (edited, a file, a message, an option changed): the box and
   * caption say so. `keepCompare`: the side-by-side view stays (it meshes whatever options are set).
   */
  function notPreset({ keepCompare = false } = {}) {
    $('preset').value = '';
    showCaption('');
    setStages(null);
    if (!keepCompare) compare.hide();
  }

  // The corpus of real PLCs beside the repository (../shared/data), when the server offers it:
  // web/serve.mjs does, at the URL of the page's <meta name="ruppert-shared-data">; the static site
  // (build-site.mjs) has no such tag, so it asks for nothing and the group is simply absent.
  const sharedUrl = document.querySelector('meta[name="ruppert-shared-data"]')?.content || null;
  async function addSharedPresets() {
    let list;
    try {
      const response = await fetch(new URL('index.json', new URL(sharedUrl, location.href)), { cache: 'no-cache' });
      if (!response.ok) return;
      list = await response.json();
    } catch {
      return;
    }
    if (!list?.available || !Array.isArray(list.files) || list.files.length === 0) return;
    const group = document.createElement('optgroup');
    group.label = 'Real inputs (../shared/data)';
    group.id = 'shared-presets';
    for (const name of list.files) {
      const option = document.createElement('option');
      option.value = SHARED_PRESET + name;
      option.textContent = name;
      group.append(option);
    }
    $('preset').append(group);
  }

  async function loadSharedPreset(name) {
    const failed = loading();
    try {
      const response = await fetch(new URL(encodeURIComponent(name), new URL(sharedUrl, location.href)), { cache: 'no-cache' });
      if (!response.ok) throw new Error(`the server answered ${response.status}`);
      const plc = await parseInput(await response.text(), name);
      showCaption('');
      setStages(null);
      compare.hide();
      setDrawing(fromPlc(plc, drawingOptions()));
      $('preset').value = SHARED_PRESET + name;
      setStatus(`Loaded ${name}: ${plc.points.length / 2} points, ${plc.segments.length / 2} segments.`, 'ok');
    } catch (error) {
      failed();
      setStatus(`Could not load ${name}: ${error.message}`, 'error');
    }
  }
  if (shared && sharedUrl !== null) addSharedPresets();

  /**
   * The page opens on the default preset when its link has no drawing (no undo step; step mode
   * as the link says).
   */
  function openDefault() {
    open(DEFAULT_PRESET, { commit: false, steps: false });
  }

  return { notPreset, open, openDefault };
}
