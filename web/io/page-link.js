// The page's link: the drawing, its options, the step, the coloring and the view written into
// the URL hash (url-state.js encodes them), read back when the page opens or the hash changes.
import { MAX_HASH_LENGTH, decodeDrawing, encodeDrawing, encodePageState } from './url-state.js';

const $ = (id) => document.getElementById(id);

/**
 * @param {object} app the page's state (drawing, stepMode, colorMode, viewMoved), read only
 * @param {object} view the View on screen
 * @param {() => number} stepIndex the step shown in step mode
 * @param {(drawing) => void} onLinkChanged a drawing from a hash the page did not write itself
 * @param {object} status the status line (panels/status-line.js): setStatus(text, kind), showNotices(notices, error)
 */
export function createPageLink({ app, view, stepIndex, onLinkChanged, status }) {
  const { setStatus } = status;
  // The hash this page wrote last ('' when the state was too long for a link): a hashchange to it
  // is the page's own, not a link opened.
  let written = '';

  /** Writes the state into the URL hash; false when it is too long for a link (the hash is cleared). */
  function write() {
    const state = encodePageState({
      step: app.stepMode ? stepIndex() : null,
      color: app.colorMode,
      view: app.viewMoved ? { x: view.centerX, y: view.centerY, scale: view.scale } : null,
    });
    const hash = `${encodeDrawing(app.drawing)}${state}`;
    const base = `${location.pathname}${location.search}`;
    // The embed's link to the full page carries the same state.
    $('open-full').href = `${location.pathname}#${hash}`;
    if (hash.length > MAX_HASH_LENGTH) {
      written = '';
      window.history.replaceState(null, '', base);
      return false;
    }
    written = `#${hash}`;
    if (location.hash !== written) window.history.replaceState(null, '', `${base}#${hash}`);
    return true;
  }

  // Steps, pans and zooms change the link too, but at most a few times a second (browsers
  // throttle history.replaceState calls).
  let timer = null;
  function writeSoon() {
    if (timer !== null) return;
    timer = setTimeout(() => { timer = null; write(); }, 300);
  }

  /** The link's drawing, or null (none, or unreadable: the status line says so). */
  function read() {
    try {
      return decodeDrawing(location.hash);
    } catch (error) {
      setStatus(`The link's drawing could not be read (${error.message}); showing the default drawing.`, 'error');
      return null;
    }
  }

  window.addEventListener('hashchange', () => {
    if (location.hash === written) return;
    const drawing = read();
    if (drawing) onLinkChanged(drawing);
  });

  return { write, writeSoon, read };
}
