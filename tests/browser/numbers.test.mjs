// Numbers as the page writes them (no browser: the modules are plain JS): grouped digits, and a
// comparison that never reads as equal or reversed because of rounding.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { Stepper, fmtCompared, splitReason } from '../../web/steps/stepper.js';

test('a too large triangle\'s area and the max it exceeds never read as equal', () => {
  // A right triangle of area 0.0010004 against a max of 0.001.
  const points = [0, 0, 0.02, 0, 0, 0.10004];
  const reason = splitReason(points, 0, 1, 2, { minAngle: 0, maxArea: 0.001 });
  const match = /area ([\d.e+-]+) > max ([\d.e+-]+)/.exec(reason);
  assert.ok(match, reason);
  assert.ok(Number(match[1]) > Number(match[2]), reason);
  for (const [a, b] of [[0.0010004, 0.001], [12.34561, 12.3456], [1.00000001, 1], [5e-4 + 1e-9, 5e-4], [0.5, 0.25]]) {
    const [fa, fb] = fmtCompared(a, b);
    assert.ok(Number(fa) > Number(fb), `${a} > ${b} written ${fa} > ${fb}`);
  }
  assert.deepEqual(fmtCompared(0.5, 0.25), ['0.5', '0.25'], 'no digits added when none are needed');
});

test('a skinny triangle\'s angle is written under its bound', () => {
  // Smallest angle 29.9990...°: two decimals would round it to the bound of 30°.
  const angle = 29.999 * Math.PI / 180;
  const points = [0, 0, 1, 0, Math.cos(angle), Math.sin(angle)];
  const reason = splitReason(points, 0, 1, 2, { minAngle: 30 });
  const match = /smallest angle ([\d.]+)° < bound 30°/.exec(reason);
  assert.ok(match, reason);
  assert.ok(Number(match[1]) < 30, reason);
});

test('step numbers are grouped: "Step 0 of 49,880"', () => {
  const element = () => ({ addEventListener() {}, setAttribute() {}, textContent: '', value: '', max: '', disabled: false });
  const el = Object.fromEntries(['first', 'back', 'forward', 'last', 'play', 'scrub', 'speed', 'info'].map((k) => [k, element()]));
  const stepper = new Stepper(el, () => {});
  stepper.setEvents({ count: 49880 });
  assert.match(el.info.textContent, /^Step 0 of 49,880: /);
});

test('crowded vertex labels move to a free corner or are left out, never drawn over each other', async () => {
  const { placeLabels } = await import('../../web/steps/step-overlay.js');
  const size = { width: 14, height: 12 };
  // Five vertices within a few pixels of one another, and one far away.
  const labels = [[100, 100], [102, 101], [99, 103], [101, 99], [100, 102], [300, 300]].map(([x, y]) => ({ x, y, ...size }));
  const placed = placeLabels(labels);
  assert.deepEqual(placed[0], { x: 105, y: 96 }, 'the first keeps the usual place, above right');
  assert.notEqual(placed[5], null, 'a label with room is drawn');
  const boxes = placed.filter(Boolean).map(({ x, y }) => ({ left: x, right: x + 14, top: y - 12, bottom: y }));
  for (let i = 0; i < boxes.length; i++) {
    for (let j = i + 1; j < boxes.length; j++) {
      const [a, b] = [boxes[i], boxes[j]];
      assert.ok(!(a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom), `labels ${i} and ${j} overlap`);
    }
  }
  assert.ok(placed.slice(0, 5).some((p) => p === null), 'five labels in one spot cannot all be drawn');
});
