// The lines under the canvas: the status line, the list of the mesher's notices and errors, and
// the progress indicator (its Cancel button is wired by meshing.js).
import { NOTICE_LABELS, codeWords, roundNumbers } from '../labels.js';
const $ = (id) => document.getElementById(id);
// Progress shows only for work that takes a noticeable time.
const PROGRESS_DELAY_MS = 200;

/** One line saying what just happened; `kind` ('info', 'ok', 'warn', 'error') colors it. */
export function setStatus(text, kind = 'info') {
  const status = $('status');
  status.textContent = text;
  status.dataset.kind = kind;
}

/**
 * One notice or error as the reader sees it: the code's words, the message with its coordinates
 * to six digits, and the code itself last (to look it up in the package's documentation).
 */
export function noticeText(code, message) {
  return `${NOTICE_LABELS[code] ?? codeWords(code)}: ${roundNumbers(message)} (${code})`;
}

/** The notices of the mesh (its repairs of the input) and, first, an error if there is one. */
export function showNotices(notices, error = null) {
  const list = $('notices');
  const items = notices.map((n) => {
    const li = document.createElement('li');
    li.className = 'notice';
    li.textContent = noticeText(n.kind, n.message);
    return li;
  });
  if (error) {
    const li = document.createElement('li');
    li.className = 'error';
    li.textContent = noticeText(error.code ?? error.name, error.message);
    items.unshift(li);
  }
  list.replaceChildren(...items);
}

let progressTimer = null;

/** A mesh request started: the indicator appears if it is still running after a moment. */
export function startProgress() {
  clearTimeout(progressTimer);
  progressTimer = setTimeout(() => {
    $('progress').hidden = false;
    $('cancel').hidden = false;
    $('progress-text').textContent = 'Meshing…';
  }, PROGRESS_DELAY_MS);
}

/** The worker's progress report (insertedVertices, triangles, worstAngle). */
export function showProgress(p) {
  $('progress-text').textContent =
    `Meshing… ${p.insertedVertices.toLocaleString('en-US')} vertices inserted, ${p.triangles.toLocaleString('en-US')} triangles, worst angle ${p.worstAngle.toFixed(1)}°`;
}

export function stopProgress() {
  clearTimeout(progressTimer);
  $('progress').hidden = true;
  $('cancel').hidden = true;
  $('progress-text').textContent = '';
}
