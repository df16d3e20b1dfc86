// One way of timing every contender in bench.js and wasm.js: a garbage collection, a warm-up
// of at least one second of wall time (V8 optimizes hot code in tiers; a few frames leave it
// in the baseline tier), then rounds of the measured loop, each after a collection, timed in
// wall time (the figure) and process CPU time (a second column). Contenders given together
// run their rounds interleaved, so a noisy moment of the machine falls on all of them.
'use strict';

const WARM_UP_NS = 1e9;

function stats(values) {
  const s = [...values].sort((a, b) => a - b);
  const mid = s.length >> 1;
  return { median: s.length % 2 ? s[mid] : (s[mid - 1] + s[mid]) / 2, min: s[0], max: s[s.length - 1] };
}

// contenders: [{ name, step: () => void, frames, per: updates per frame }]. Returns, per name,
// { wall, cpu }: the median, min and max over `rounds` of ns per update.
function measure(contenders, rounds = 7) {
  for (const c of contenders) {
    global.gc();
    const t0 = process.hrtime.bigint();
    let k = 0;
    while (k < 3 || Number(process.hrtime.bigint() - t0) < WARM_UP_NS) { c.step(); ++k; }
  }
  const wall = contenders.map(() => []), cpu = contenders.map(() => []);
  for (let r = 0; r < rounds; ++r) {
    contenders.forEach((c, i) => {
      global.gc();
      const c0 = process.cpuUsage();
      const w0 = process.hrtime.bigint();
      for (let k = 0; k < c.frames; ++k) c.step();
      const w = Number(process.hrtime.bigint() - w0);
      const c1 = process.cpuUsage(c0);
      const updates = c.frames * c.per;
      wall[i].push(w / updates);
      cpu[i].push(((c1.user + c1.system) * 1000) / updates);
    });
  }
  const out = {};
  contenders.forEach((c, i) => { out[c.name] = { wall: stats(wall[i]), cpu: stats(cpu[i]) }; });
  return out;
}

// "171.7 (160.2–190.3) wall, 170.9 cpu": the median and range of wall time, CPU's median.
function format(t) {
  const f = (x) => x.toFixed(1);
  return `ns/update ${f(t.wall.median).padStart(8)} (${f(t.wall.min)}–${f(t.wall.max)}) wall, ${f(t.cpu.median)} cpu`;
}

module.exports = { measure, format };
