// Exact orientation and incircle signs for the package tests' validator, in plain JavaScript.
//
// A double is an integer times a power of two, so any few doubles are integers once scaled by the
// smallest power among them; in BigInt the determinants are then exact. A floating-point filter
// (Shewchuk's first error bounds) answers almost every call; BigInt runs only when the rounded
// determinant is too close to 0 to trust. Written from the definitions, not from the core's code:
// the validator must not share the mesher's arithmetic.

const EPSILON = 2 ** -53;
const ORIENT_BOUND = (3 + 16 * EPSILON) * EPSILON;
const INCIRCLE_BOUND = (10 + 96 * EPSILON) * EPSILON;

const view = new DataView(new ArrayBuffer(8));

// x = mantissa * 2^exponent with an integer mantissa (x finite).
function decompose(x) {
  view.setFloat64(0, x);
  const high = view.getUint32(0), low = view.getUint32(4);
  const biased = (high >>> 20) & 0x7ff;
  let mantissa = (BigInt(high & 0xfffff) << 32n) | BigInt(low);
  if (biased !== 0) mantissa |= 1n << 52n;
  const exponent = (biased === 0 ? 1 : biased) - 1075;
  return { mantissa: high >>> 31 ? -mantissa : mantissa, exponent };
}

// The values as BigInts sharing one scale (their ratios are exact).
function toIntegers(values) {
  const parts = values.map(decompose);
  let smallest = Infinity;
  for (const p of parts) if (p.mantissa !== 0n) smallest = Math.min(smallest, p.exponent);
  if (smallest === Infinity) smallest = 0;
  return parts.map((p) => p.mantissa << BigInt(p.exponent - smallest));
}

const sign = (big) => (big > 0n ? 1 : big < 0n ? -1 : 0);

// Sign of the orientation of (a, b, c): > 0 counter-clockwise, < 0 clockwise, 0 collinear.
export function orient(ax, ay, bx, by, cx, cy) {
  const l = (bx - ax) * (cy - ay), r = (by - ay) * (cx - ax);
  const det = l - r;
  if (Math.abs(det) > ORIENT_BOUND * (Math.abs(l) + Math.abs(r))) return Math.sign(det);
  const [Ax, Ay, Bx, By, Cx, Cy] = toIntegers([ax, ay, bx, by, cx, cy]);
  return sign((Bx - Ax) * (Cy - Ay) - (By - Ay) * (Cx - Ax));
}

// > 0 when d is strictly inside the circle through the counter-clockwise triangle a, b, c.
export function incircle(ax, ay, bx, by, cx, cy, dx, dy) {
  const adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy, cdx = cx - dx, cdy = cy - dy;
  const alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const det = alift * (bdx * cdy - bdy * cdx) + blift * (cdx * ady - cdy * adx) + clift * (adx * bdy - ady * bdx);
  const permanent = alift * (Math.abs(bdx * cdy) + Math.abs(bdy * cdx)) +
    blift * (Math.abs(cdx * ady) + Math.abs(cdy * adx)) + clift * (Math.abs(adx * bdy) + Math.abs(ady * bdx));
  if (Number.isFinite(permanent) && Math.abs(det) > INCIRCLE_BOUND * permanent) return Math.sign(det);
  const [Ax, Ay, Bx, By, Cx, Cy, Dx, Dy] = toIntegers([ax, ay, bx, by, cx, cy, dx, dy]);
  const [aX, aY, bX, bY, cX, cY] = [Ax - Dx, Ay - Dy, Bx - Dx, By - Dy, Cx - Dx, Cy - Dy];
  const aL = aX * aX + aY * aY, bL = bX * bX + bY * bY, cL = cX * cX + cY * cY;
  return sign(aL * (bX * cY - bY * cX) + bL * (cX * aY - cY * aX) + cL * (aX * bY - aY * bX));
}

// Sign of the orientation of (a, b, m) where m is the exact midpoint of u and w, which a double
// need not hold: rounding the midpoint can move it across an edge it lies half an ulp from.
// 2 * orient(a, b, m) = (b - a) x (u + w - 2a), exact in BigInt.
export function orientToMidpoint(ax, ay, bx, by, ux, uy, wx, wy) {
  const [Ax, Ay, Bx, By, Ux, Uy, Wx, Wy] = toIntegers([ax, ay, bx, by, ux, uy, wx, wy]);
  return sign((Bx - Ax) * (Uy + Wy - 2n * Ay) - (By - Ay) * (Ux + Wx - 2n * Ax));
}
