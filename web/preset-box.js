// The presets box: the chapter's figures and other examples (presets.js) with their captions,
// and, when the server offers it, the corpus of real PLCs beside the repository.
import { DEFAULT_OPTIONS, fromPlc } from './drawing.js';
import { parseInput } from './files.js';
import { loading } from './meshing.js';
import { DEFAULT_PRESET, PRESETS, findPreset } from './presets.js';
import { setStatus } from './status-line.js';

const $ = (id) => document.getElementById(id);
const SHARED_PRESET = 'shared:';

function showCaption(text) {
  $('preset-caption').textContent = text;
  $('preset-caption').hidden = text === '';
}

/**
 * @param {object} app the page's state (drawing, stepMode)
 * @param {(drawing, how) => void} setDrawing
 * @param {() => void} turnOnSteps step mode on, for a preset that asks for it
 * @param {boolean} shared whether to look for the corpus (not in an embed)
 */
export function createPresetBox({ app, setDrawing, turnOnSteps, shared }) {
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
    applyPreset(findPreset(value), app.drawing.options);
  });

  /** Loads a preset: its drawing, its options over `base`, its caption, and step mode if it asks. */
  function applyPreset(preset, base) {
    showCaption(preset?.caption ?? '');
    if (!preset) return;
    if (preset.steps && !app.stepMode) turnOnSteps();
    setDrawing({ ...preset.build(), options: { ...base, ...(preset.options ?? {}) } });
  }

  /** The drawing is no longer a preset (edited, a file, a message): the box and caption say so. */
  function notPreset() {
    $('preset').value = '';
    showCaption('');
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
      setDrawing(fromPlc(plc, app.drawing.options));
      $('preset').value = SHARED_PRESET + name;
      setStatus(`Loaded ${name}: ${plc.points.length / 2} points, ${plc.segments.length / 2} segments.`, 'ok');
    } catch (error) {
      failed();
      setStatus(`Could not load ${name}: ${error.message}`, 'error');
    }
  }
  if (shared && sharedUrl !== null) addSharedPresets();

  /** The page opens on the default preset when its link has no drawing (no undo step). */
  function openDefault() {
    const preset = findPreset(DEFAULT_PRESET);
    $('preset').value = DEFAULT_PRESET;
    showCaption(preset.caption ?? '');
    setDrawing({ ...preset.build(), options: { ...DEFAULT_OPTIONS, ...(preset.options ?? {}) } }, { commit: false });
  }

  return { notPreset, openDefault };
}
