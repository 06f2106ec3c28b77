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
