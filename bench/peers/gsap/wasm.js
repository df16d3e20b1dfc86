// GSAP 3 and grape.wasm side by side in one Node process: N tweens along cubic Béziers
// (1024 shared shapes, controls at a third and two thirds of the chord pushed 0.4·chord to
// either side, as bench.js and scenes::bench_paths make them), power2.inOut = quad-in-out,
// plays of 1 + 2·(i mod 1000)/1000 s repeating forever with yoyo, driven at 60 Hz.
//   by-u         GSAP: a tween of u with an onUpdate writing the Bézier's point (JavaScript)
//                grape: CubicBezierPath (u), positions read back from one Float64Array
//   arc-length   GSAP: MotionPathPlugin along the same "M C" path (it moves by measured length)
//                grape: the Bézier reparametrized() (constant speed)
// Reports ns per tween update (grape's includes reading every x and y back; timing.js: wall
// time after a collection and a warm-up of at least 1 s, median and min–max of 7 rounds
// interleaved between the two, CPU time's median beside), bytes per
// tween (GSAP: JS heap after gc; grape: the engine's storage, its position slot and handle),
// and the worst position error over 1000 sampled tweens against the exact point: the Bézier
// at u = eased progress (by-u) or at arc length progress·L found by grape's Newton solve on
// the quadrature length, to ~1e-15 (arc-length).
// Usage: node --expose-gc wasm.js [--n 100000,1000000] [--modes by-u,arc-length] [--rounds 7]
'use strict';
const { gsap } = require('gsap');
const { MotionPathPlugin } = require('gsap/MotionPathPlugin');
const loadGrape = require('grape-wasm');
const { measure, format } = require('./timing.js');

MotionPathPlugin.headless = true;
gsap.registerPlugin(MotionPathPlugin);
gsap.ticker.remove(gsap.updateRoot);
gsap.ticker.lagSmoothing(0);

const args = process.argv.slice(2);
let sizes = [100000, 1000000];
let modes = ['by-u', 'arc-length'];
let rounds = 7;
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--n') sizes = args[++i].split(',').map(Number);
  else if (args[i] === '--modes') modes = args[++i].split(',');
  else if (args[i] === '--rounds') rounds = Number(args[++i]);
}

function segments(count) {  // bench.js's generator
  let s = 12345;
  const next = () => { s = (Math.imul(s, 1103515245) + 12345) >>> 0; return (s / 4294967296) * 1000; };
  const out = [];
  for (let i = 0; i < count; ++i) out.push({ x0: next(), y0: next(), x1: next(), y1: next() });
  return out;
}
function controls(s) {
  const dx = s.x1 - s.x0, dy = s.y1 - s.y0, px = -dy * 0.4, py = dx * 0.4;
  return [{ x: s.x0, y: s.y0 }, { x: s.x0 + dx / 3 + px, y: s.y0 + dy / 3 + py },
    { x: s.x0 + dx * 2 / 3 - px, y: s.y0 + dy * 2 / 3 - py }, { x: s.x1, y: s.y1 }];
}
function bezier(c, u) {
  const v = 1 - u, a = v * v * v, b = 3 * v * v * u, d = 3 * v * u * u, e = u * u * u;
  return [a * c[0].x + b * c[1].x + d * c[2].x + e * c[3].x, a * c[0].y + b * c[1].y + d * c[2].y + e * c[3].y];
}
const duration = (i) => 1 + 2 * (i % 1000) / 1000;
const frame = 1 / 60;
const framesFor = (n) => Math.max(10, Math.min(2000, Math.round(3e7 / n)));

let clock = 0;
// GSAP's tweens: the step of one frame, then the worst error and the clean-up.
function setUpGsap(mode, n, segs, exact) {
  global.gc();
  const before = process.memoryUsage().heapUsed;
  const targets = new Array(n), tweens = new Array(n);
  for (let i = 0; i < n; ++i) {
    const c = segs[i % 1024].c;
    const target = { x: c[0].x, y: c[0].y };
    targets[i] = target;
    const vars = { duration: duration(i), ease: 'power2.inOut', repeat: -1, yoyo: true };
    if (mode === 'by-u') {
      const proxy = { u: 0 };
      vars.u = 1;
      vars.onUpdate = () => { const p = bezier(c, proxy.u); target.x = p[0]; target.y = p[1]; };
      tweens[i] = gsap.to(proxy, vars);
    } else {
      vars.motionPath = { path: segs[i % 1024].svg };
      tweens[i] = gsap.to(target, vars);
    }
  }
  global.gc();
  const bytes = (process.memoryUsage().heapUsed - before) / n;
  const step = () => { clock += frame; gsap.updateRoot(clock); };
  const finish = () => {
    let worst = 0;
    for (let i = 0; i < n; i += Math.ceil(n / 1000)) {
      const p = exact(i % 1024, tweens[i].ratio);  // ratio: the eased progress of the current play
      worst = Math.max(worst, Math.hypot(targets[i].x - p.x, targets[i].y - p.y));
    }
    gsap.globalTimeline.clear();
    return worst;
  };
  return { bytes, step, finish };
}

// grape.wasm's engine, the same way.
function setUpGrape(g, n, paths, exact) {
  const engine = new g.Engine(n);
  const options = { curve: 'quad-in-out', repeat: -1, yoyo: true };
  for (let i = 0; i < n; ++i) engine.add(paths[i % 1024], duration(i), options);
  // Storage the engine holds (capacity included) + the 16-byte position slot + the 16-byte handle.
  const bytes = engine.storageBytes() / n + 32;
  let sink = 0;
  const step = () => {
    engine.tick(frame);
    const xy = engine.positions();
    let sum = 0;  // a local: a captured variable in the loop costs several ns per element
    for (let k = 0, m = xy.length; k < m; ++k) sum += xy[k];
    sink += sum;
  };
  const finish = () => {
    if (!Number.isFinite(sink)) throw new Error('no motion');
    let worst = 0;
    const xy = engine.positions();
    for (let i = 0; i < n; i += Math.ceil(n / 1000)) {
      const a = engine.animation(i);
      const p = exact(i % 1024, a.progress());
      a.delete();
      worst = Math.max(worst, Math.hypot(xy[2 * i] - p.x, xy[2 * i + 1] - p.y));
    }
    engine.delete();
    return worst;
  };
  return { bytes, step, finish };
}

loadGrape().then((g) => {
  console.log(`GSAP ${gsap.version}, grape.wasm, Node ${process.version}`);
  const segs = segments(1024).map((s) => {
    const c = controls(s);
    return { c, svg: `M${c[0].x},${c[0].y} C${c[1].x},${c[1].y} ${c[2].x},${c[2].y} ${c[3].x},${c[3].y}` };
  });
  const byU = segs.map((s) => g.Path.cubicBezier(s.c[0], s.c[1], s.c[2], s.c[3]));
  const even = byU.map((p) => p.reparametrized());
  const exact = {
    'by-u': (k, u) => byU[k].point(u),
    'arc-length': (k, r) => byU[k].point(byU[k].uAtLength(r * byU[k].length())),
  };
  for (const n of sizes) {
    for (const mode of modes) {
      const a = setUpGsap(mode, n, segs, exact[mode]);
      const b = setUpGrape(g, n, mode === 'by-u' ? byU : even, exact[mode]);
      const frames = framesFor(n);
      const t = measure([{ name: 'gsap', step: a.step, frames, per: n }, { name: 'wasm', step: b.step, frames, per: n }], rounds);
      const worstA = a.finish(), worstB = b.finish();
      console.log(`gsap_${mode.padEnd(11)} N=${String(n).padStart(8)}  ${format(t.gsap)}  bytes/tween ${a.bytes.toFixed(0).padStart(6)}  worst error ${worstA.toExponential(2)} px`);
      console.log(`wasm_${mode.padEnd(11)} N=${String(n).padStart(8)}  ${format(t.wasm)}  bytes/tween ${b.bytes.toFixed(0).padStart(6)}  worst error ${worstB.toExponential(2)} px`);
      console.log(`  gsap / wasm (wall medians) ${(t.gsap.wall.median / t.wasm.wall.median).toFixed(2)}`);
    }
  }
});
