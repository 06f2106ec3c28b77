// Unknown keys are mistakes (`{ Segments: [...] }` would otherwise mesh the convex hull without a
// word): every object the API takes is checked against its known keys, with a did-you-mean.

// Levenshtein distance, for short keys only.
function editDistance(a, b) {
  let previous = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const current = [i];
    for (let j = 1; j <= b.length; j++) {
      current[j] = Math.min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    }
    previous = current;
  }
  return previous[b.length];
}

/** The known key `key` was probably meant as, or undefined. */
export function nearestKey(key, known) {
  const plain = (s) => s.toLowerCase().replace(/[-_\s]/g, '');
  const k = plain(key);
  return known.find((name) => plain(name) === k) ??
    known.find((name) => editDistance(plain(name), k) <= 2) ??
    (k.length >= 3 ? known.find((name) => plain(name).includes(k)) : undefined);
}

/**
 * Throws makeError(message) for the first own key of `object` not in `known`.
 * @param {string} what how the message names the object, e.g. "the input" or "regions[2]"
 */
export function rejectUnknownKeys(object, known, what, makeError) {
  for (const key of Object.keys(object)) {
    if (known.includes(key)) continue;
    const near = nearestKey(key, known);
    throw makeError(`${what} has an unknown key '${key}'${near ? ` (did you mean '${near}'?)` : ''}; ` +
      `the keys are ${known.join(', ')}`);
  }
}
