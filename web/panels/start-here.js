// "Start here": the five first steps (draw or pick a preset, set the angle, mesh, replay, export)
// over the canvas on a first visit. Dismissed once, it stays away (localStorage); the toolbar's
// Start here button shows it again. An embed shows it only when its URL asks (`&help=1`): the host
// page is the one that explains.
const $ = (id) => document.getElementById(id);
export const DISMISSED_KEY = 'ruppert:start-here-dismissed';

// Storage can be refused (privacy settings, a sandboxed frame): then the panel simply shows.
function remembered() {
  try {
    return localStorage.getItem(DISMISSED_KEY) === '1';
  } catch {
    return false;
  }
}

function remember(dismissed) {
  try {
    if (dismissed) localStorage.setItem(DISMISSED_KEY, '1');
    else localStorage.removeItem(DISMISSED_KEY);
  } catch {
    // Not kept: it shows again next time.
  }
}

/** @param {boolean} embedded whether the page is an embed (`?embed=1`) */
export function createStartHere({ embedded }) {
  const panel = $('start-here');
  const asked = new URLSearchParams(location.search).get('help') === '1';
  panel.hidden = embedded ? !asked : remembered();
  $('start-here-dismiss').addEventListener('click', () => {
    panel.hidden = true;
    remember(true);
    $('canvas').focus();
  });
  $('start-here-show').addEventListener('click', () => {
    panel.hidden = false;
    remember(false);
    $('start-here-dismiss').focus();
  });
}
