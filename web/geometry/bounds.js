// Axis-aligned bounding boxes { minX, minY, maxX, maxY }: of a mesh's points, a chunk of its
// triangles, a drawing. One loop for all of them, so every box is made the same way.

/** A box that holds nothing yet (min above max): the first point included sets it. */
export function emptyBounds() {
  return { minX: Infinity, minY: Infinity, maxX: -Infinity, maxY: -Infinity };
}

/** Grows `box` (any object with the four fields) to hold the point (x, y). */
export function includePoint(box, x, y) {
  if (x < box.minX) box.minX = x;
  if (x > box.maxX) box.maxX = x;
  if (y < box.minY) box.minY = y;
  if (y > box.maxY) box.maxY = y;
}

/** The box of flat coordinates [x0, y0, x1, y1, ...], grown from `box` if given (empty if none). */
export function boundsOf(xy, box = emptyBounds()) {
  for (let i = 0; i < xy.length; i += 2) includePoint(box, xy[i], xy[i + 1]);
  return box;
}

/** Whether the box holds at least one point. */
export function hasBounds(box) {
  return box.minX <= box.maxX;
}
