// Rough costs of the 3-D bindings under node: an engine tick over 10⁴ 3-D slots, without and
// with frame alignment, and the one-off builds of the playground's coaster (reparametrizing,
// Frames3 in each mode, bankTrack). Run: node web/bench/anim3.js (after scripts/build-web).
'use strict';
require('..')().then((g) => {
  const path = g.Path3.helix({ radius: 10, rise: 4, turns: 3 });
  const frames = new g.Frames3(path, { mode: 'rmf' });
  for (const [label, motion] of [['none', {}], ['frame (shared)', { align: 'frame', sharedFrames: frames }]]) {
    const n = 10000;
    const e = new g.Engine(0, n);
    for (let i = 0; i < n; ++i) e.add3(path, 2 + i / n, { repeat: -1, curve: 'quad-in-out' }, motion);
    for (let k = 0; k < 20; ++k) e.tick(1 / 60);
    const t0 = process.hrtime.bigint();
    const ticks = 200;
    for (let k = 0; k < ticks; ++k) e.tick(1 / 60);
    const ns = Number(process.hrtime.bigint() - t0) / ticks / n;
    console.log(`${n} 3-D animations, align ${label}: ${ns.toFixed(1)} ns per animation per tick`);
    e.delete();
  }
  const knots = [[-24, -10, 2], [-8, -10, 2]];
  for (let k = 0; k <= 8; ++k) { const phi = (k * Math.PI) / 4; knots.push([4 + 7 * Math.sin(phi), -10 + (3 * k) / 8, 9 - 7 * Math.cos(phi)]); }
  knots.push([18, -7, 2], [30, -2, 5], [32, 8, 9], [20, 14, 10], [0, 13, 7], [-16, 10, 4], [-30, 2, 2]);
  const track = g.Path3.catmullRom(knots.flat(), 'centripetal', true);
  let t0 = Date.now(); const even = track.reparametrized(); console.log(`coaster reparametrized: ${Date.now() - t0} ms`);
  for (const mode of ['rmf', 'closed', 'reference_up', 'frenet']) { t0 = process.hrtime.bigint(); const f = new g.Frames3(even, { mode }); console.log(`Frames3 ${mode}: ${(Number(process.hrtime.bigint() - t0) / 1e6).toFixed(1)} ms`); f.delete(); }
  t0 = process.hrtime.bigint(); g.bankTrack(even, { speed: 14, smoothing: 6 }).delete(); console.log(`bankTrack: ${(Number(process.hrtime.bigint() - t0) / 1e6).toFixed(1)} ms`);
});
