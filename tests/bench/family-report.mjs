// Summaries and Markdown of the family mode (family-mode.mjs): per family and over all PLCs, for one
// placement.

const geoMean = (values) => (values.length ? Math.exp(values.reduce((s, v) => s + Math.log(v), 0) / values.length) : null);
const median = (values) => (values.length ? [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)] : null);
const fmt = (x, digits = 3) => (x === null || x === undefined || Number.isNaN(x) ? '–' : x.toFixed(digits));
const percent = (k, n) => (n ? `${((100 * k) / n).toFixed(0)}%` : '–');
const ANGLE_TOLERANCE = 1e-7;  // degrees, as the Catch2 validator's angleTolDeg

// Complete, and every non-exempt triangle at or above the bound (judged from the output arrays).
export function holdsBound(r, angle) {
  return r.status === 'ok' && r.complete && r.nonExemptMin >= angle - ANGLE_TOLERANCE;
}

function ratios(rows, angle) {
  const values = [];
  for (const row of rows) {
    const t = row.triangle[angle];
    const r = row.ruppert[angle];
    if (t?.status === 'ok' && t.triangles > 0 && r?.status === 'ok') values.push(r.triangles / t.triangles);
  }
  return values;
}

// The high-angle measures over some rows at one angle.
function highAngleMeasures(rows, angle) {
  const misses = [];
  const times = [];
  const heldOver33 = [];  // a held mesh's triangles over the same PLC's 33-degree mesh's
  let held = 0;
  for (const row of rows) {
    const r = row.ruppert[angle];
    const at33 = row.ruppert[33];
    if (r.status === 'ok') times.push(r.ms);
    if (holdsBound(r, angle)) {
      held++;
      if (at33?.status === 'ok' && at33.triangles > 0) heldOver33.push(r.triangles / at33.triangles);
      continue;
    }
    misses.push({
      name: row.name, angle, status: r.status, error: r.error, triangles: r.triangles, nonExemptMin: r.nonExemptMin,
      complete: r.complete, reasons: r.reasons,
      over33: r.status === 'ok' && at33?.status === 'ok' ? r.triangles / at33.triangles : null,
    });
  }
  const okMisses = misses.filter((m) => m.status === 'ok');
  return {
    plcs: rows.length, held, share: rows.length ? held / rows.length : null, heldOver33: geoMean(heldOver33),
    medianMs: median(times), maxMs: times.length ? Math.max(...times) : null,
    timeouts: misses.filter((m) => m.status === 'timeout').length,
    worstMissAngle: okMisses.length ? Math.min(...okMisses.map((m) => m.nonExemptMin)) : null,
    maxMissOver33: okMisses.some((m) => m.over33 !== null) ? Math.max(...okMisses.map((m) => m.over33 ?? 0)) : null,
    misses,
  };
}

function measures(rows, options) {
  const compared = {};
  for (const angle of options.angles) {
    const values = ratios(rows, angle);
    compared[angle] = {
      plcs: rows.length, compared: values.length, geoMean: geoMean(values),
      complete: rows.filter((row) => row.ruppert[angle]?.status === 'ok' && row.ruppert[angle].complete).length,
      held: rows.filter((row) => holdsBound(row.ruppert[angle], angle)).length,
    };
  }
  const high = {};
  for (const angle of options.highAngles) high[angle] = highAngleMeasures(rows, angle);
  return { compared, high };
}

// The targets for this placement, each check with its measured value.
function doneWhen(overall, families, options) {
  const checks = [];
  const geoAt = (a) => overall.compared[a]?.geoMean;
  if (overall.compared[30]) checks.push({ what: 'geo-mean ratio at 30° <= 0.90', value: fmt(geoAt(30)), ok: geoAt(30) <= 0.9 });
  if (overall.compared[33]) checks.push({ what: 'geo-mean ratio at 33° <= 0.85', value: fmt(geoAt(33)), ok: geoAt(33) <= 0.85 });
  for (const angle of options.angles) {
    const above = families.filter((f) => f.compared[angle].geoMean > 1);
    checks.push({ what: `no family above 1.0x at ${angle}°`, value: above.map((f) => `${f.family} ${fmt(f.compared[angle].geoMean)}`).join(', ') || 'none', ok: above.length === 0 });
  }
  // Above 34 degrees: the share held, and the held meshes' size over the 33-degree mesh (geometric mean).
  const targets = { 35: 0.98, 38: 0.95, 40: 0.9, 42: 0.6 };
  const sizeTargets = { 35: 1.3, 38: 2.0, 40: 2.5 };
  for (const angle of options.highAngles) {
    const h = overall.high[angle];
    if (targets[angle] !== undefined) checks.push({ what: `bound held at ${angle}° on >= ${targets[angle] * 100}%`, value: `${h.held}/${h.plcs} (${percent(h.held, h.plcs)})`, ok: h.share >= targets[angle] });
    if (sizeTargets[angle] !== undefined) checks.push({ what: `held meshes at ${angle}° <= ${sizeTargets[angle]}x the 33° mesh (geo-mean)`, value: `${fmt(h.heldOver33)}x`, ok: h.heldOver33 !== null && h.heldOver33 <= sizeTargets[angle] });
    checks.push({ what: `every miss at ${angle}° has non-exempt angles >= 30°, <= 4x the 33° mesh, within the time limit`,
      value: `${h.misses.length} misses, smallest ${fmt(h.worstMissAngle, 2)}°, max ${fmt(h.maxMissOver33, 2)}x, ${h.timeouts} timeouts`,
      ok: h.timeouts === 0 && h.misses.every((m) => m.status === 'ok' && m.nonExemptMin >= 30 && m.over33 !== null && m.over33 <= 4) });
  }
  return checks;
}

export function summarisePlacement(allRows, placement, options) {
  const rows = allRows.map((row) => ({ ...row, ruppert: row.ruppert[placement] }));
  const overall = measures(rows, options);
  const families = [...new Set(rows.map((r) => r.family))].sort().map((family) => ({ family, ...measures(rows.filter((r) => r.family === family), options) }));
  const worst = {};
  for (const angle of options.angles) {
    const ranked = families.filter((f) => f.compared[angle].geoMean !== null).sort((a, b) => b.compared[angle].geoMean - a.compared[angle].geoMean);
    worst[angle] = ranked.length ? { family: ranked[0].family, geoMean: ranked[0].compared[angle].geoMean } : null;
  }
  return { overall, families, worst, doneWhen: doneWhen(overall, families, options) };
}

function summaryTables(report, lines) {
  const { summary, options } = report;
  lines.push('| min angle | PLCs | compared | geo-mean ruppert/Triangle | worst family | ruppert complete | bound held |', '|---|---|---|---|---|---|---|');
  for (const angle of options.angles) {
    const c = summary.overall.compared[angle];
    const w = summary.worst[angle];
    lines.push(`| ${angle} | ${c.plcs} | ${c.compared} | ${fmt(c.geoMean)} | ${w ? `${w.family} ${fmt(w.geoMean)}` : '–'} | ${c.complete} | ${c.held} |`);
  }
  lines.push('', '| min angle (ruppert only) | PLCs | bound held | share | held / 33° mesh (geo-mean) | misses | smallest non-exempt ∠ of a miss | max miss / 33° mesh | timeouts | median ms | max ms |', '|---|---|---|---|---|---|---|---|---|---|---|');
  for (const angle of options.highAngles) {
    const h = summary.overall.high[angle];
    lines.push(`| ${angle} | ${h.plcs} | ${h.held} | ${percent(h.held, h.plcs)} | ${fmt(h.heldOver33)} | ${h.misses.length} | ${fmt(h.worstMissAngle, 2)} | ${fmt(h.maxMissOver33, 2)} | ${h.timeouts} | ${fmt(h.medianMs, 1)} | ${fmt(h.maxMs, 0)} |`);
  }
}

function familyTable(report, lines) {
  const { summary, options } = report;
  const head = ['family', 'PLCs', ...options.angles.map((a) => `${a}°`), ...options.highAngles.map((a) => `held ${a}°`), 'worst miss ∠', 'max miss / 33°', 'max ms'];
  lines.push(`| ${head.join(' | ')} |`, `|${head.map(() => '---').join('|')}|`);
  for (const f of summary.families) {
    const highs = options.highAngles.map((a) => f.high[a]);
    const missAngles = highs.map((h) => h.worstMissAngle).filter((x) => x !== null);
    const over = highs.map((h) => h.maxMissOver33).filter((x) => x !== null);
    const maxMs = Math.max(...highs.map((h) => h.maxMs ?? 0));
    lines.push(`| ${[f.family, highs[0]?.plcs ?? f.compared[options.angles[0]].plcs, ...options.angles.map((a) => fmt(f.compared[a].geoMean)),
      ...highs.map((h) => `${h.held}/${h.plcs}`), missAngles.length ? fmt(Math.min(...missAngles), 2) : '–',
      over.length ? fmt(Math.max(...over), 2) : '–', fmt(maxMs, 0)].join(' | ')} |`);
  }
}

export function familyMarkdown(report) {
  const { meta, summary, options } = report;
  const lines = [`# ruppert vs Triangle over the shape families: placement ${meta.placement}`, ''];
  lines.push(`Written by \`tests/bench/compare-triangle.mjs --dir\` (family mode) on ${meta.date}. ${meta.node}, ${meta.cpu}.`);
  lines.push(`ruppert ${meta.ruppert} (wasm/dist); Triangle: npm triangle-wasm ${meta.triangleWasm}.`);
  lines.push(`Command: \`${meta.command}\``, `Families written by \`build-native/tests/write_shape_families ${meta.dir}\`: ${meta.plcs} PLCs of ${meta.families} families; the whole run (every placement) took ${meta.minutes.toFixed(1)} min.`, '');
  lines.push('How: every PLC is meshed by Triangle (`-pzQq<angle>`, once per PLC and angle, cached beside the families) and by ruppert',
    `(\`{ minAngle${meta.placement === 'default' ? '' : `, placement: '${meta.placement}'`} }\`${meta.placement === 'default' ? ', the library\'s default placement' : ''}) in worker threads of one Node process, one timed run each.`,
    'Ratios are ruppert triangles / Triangle triangles (< 1: ruppert smaller), geometric means per family and over all PLCs.',
    `"Bound held": ruppert says complete and every triangle that is not exempt (the chapter's exemptions, §6.6: nestled in a small input angle, or with a seditious shortest edge; judged from the output arrays by tests/bench/mesh-exemptions.mjs) has its smallest angle >= the bound. Time limit ${options.ruppertTimeoutMs / 1000} s per ruppert run (wall time of one call, copy in and out included).`, '');
  lines.push('## Summary', '');
  summaryTables(report, lines);
  lines.push('', '## Targets', '', '| check | measured | met |', '|---|---|---|');
  for (const c of summary.doneWhen) lines.push(`| ${c.what} | ${c.value} | ${c.ok ? 'yes' : '**no**'} |`);
  lines.push('', '## Per family', '', `Columns ${options.angles.map((a) => `${a}°`).join(', ')}: geometric mean of ruppert/Triangle triangle counts. "held": PLCs where the bound held. "worst miss ∠": the smallest non-exempt angle of a result that missed its bound (at any ruppert-only angle); "max miss / 33°": its triangles over the same PLC's 33° mesh.`, '');
  familyTable(report, lines);
  lines.push('', '## Misses', '');
  const misses = options.highAngles.flatMap((a) => summary.overall.high[a].misses);
  if (misses.length === 0) lines.push('None.');
  for (const m of misses.slice(0, 200)) {
    lines.push(m.status === 'ok'
      ? `- ${m.name} @ ${m.angle}°: ${m.complete ? 'complete' : 'incomplete'}, smallest non-exempt ∠ ${fmt(m.nonExemptMin, 2)}, ${m.triangles} triangles (${fmt(m.over33, 2)}x the 33° mesh), reasons ${m.reasons.join(', ') || 'none'}`
      : `- ${m.name} @ ${m.angle}°: ${m.status} (${m.error})`);
  }
  if (misses.length > 200) lines.push(`- ... and ${misses.length - 200} more (in the JSON)`);
  lines.push('');
  return lines.join('\n');
}
