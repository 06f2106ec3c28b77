// A 2D canvas made ready to draw in CSS pixels: its backing store sized to its CSS box at the
// device's pixel ratio (so lines stay sharp on high-density screens), scaled, and cleared.

/**
 * @param {HTMLCanvasElement} canvas
 * @param {number} fallbackWidth CSS width when the canvas has no layout yet (hidden, detached)
 * @param {number} fallbackHeight likewise
 * @returns {{ ctx: CanvasRenderingContext2D, width: number, height: number }} width, height in CSS pixels
 */
export function clearedCanvas(canvas, fallbackWidth, fallbackHeight) {
  const dpr = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || fallbackWidth;
  const height = canvas.clientHeight || fallbackHeight;
  if (canvas.width !== Math.round(width * dpr) || canvas.height !== Math.round(height * dpr)) {
    canvas.width = Math.round(width * dpr);
    canvas.height = Math.round(height * dpr);
  }
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, width, height);
  return { ctx, width, height };
}
