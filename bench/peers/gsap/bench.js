// The GSAP peer of bench/bench_anim.cpp: N tweens of plain objects {x, y} over random
// segments in a 1000 × 1000 box, power2.inOut (= quad-in-out), repeating forever with
// yoyo, play lengths 1 + 2·(i mod 1000)/1000 s, 1024 distinct segments, driven at 60 Hz by
// gsap.updateRoot(t) after removing it from GSAP's own ticker. Modes:
//   tween        x and y tweened to the segment's end (GSAP's core, two numbers)
//   motion       MotionPathPlugin along "M from L to" (GSAP measures paths by arc length)
//   motion-cubic MotionPathPlugin along the same cubic Bézier as bench_anim's (b)/(c)
//   timelines    bench_timeline's timelines of 10 sequential tweens (see runTimelines)
// Reports ns per tween update (timing.js: wall time after a collection and a warm-up of at
// least 1 s; the median and min–max of 7 rounds, process CPU time's median beside) and heap
// bytes per tween (after gc).
// Usage: node --expose-gc bench.js [mode...] [--n 1000,100000,1000000] [--rounds 7]
'use strict';
const { gsap } = require('gsap');
const { MotionPathPlugin } = require('gsap/MotionPathPlugin');
const { measure, format } = require('./timing.js');

MotionPathPlugin.headless = true;  // no DOM in Node
gsap.registerPlugin(MotionPathPlugin);
gsap.ticker.remove(gsap.updateRoot);
gsap.ticker.lagSmoothing(0);

const args = process.argv.slice(2);
let sizes = [1000, 100000, 1000000];
let rounds = 7;
const modes = [];
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--n') sizes = args[++i].split(',').map(Number);
  else if (args[i] === '--rounds') rounds = Number(args[++i]);
  else modes.push(args[i]);
}
if (modes.length === 0) modes.push('tween', 'motion', 'motion-cubic');

// Segments from a fixed-seed generator (not bench_anim's mt19937_64: only the kind of
// journey matters for timing).
function segments(count) {
  let s = 12345;
  const next = () => { s = (Math.imul(s, 1103515245) + 12345) >>> 0; return (s / 4294967296) * 1000; };
  const out = [];
  for (let i = 0; i < count; ++i) out.push({ x0: next(), y0: next(), x1: next(), y1: next() });
  return out;
}

function cubicPath(s) {
  // Controls at a third and two thirds of the chord pushed 0.4·chord to either side,
  // as scenes::bench_paths does.
  const dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const px = -dy * 0.4, py = dx * 0.4;
  const c1 = [s.x0 + dx / 3 + px, s.y0 + dy / 3 + py];
  const c2 = [s.x0 + dx * 2 / 3 - px, s.y0 + dy * 2 / 3 - py];
  return `M${s.x0},${s.y0} C${c1[0]},${c1[1]} ${c2[0]},${c2[1]} ${s.x1},${s.y1}`;
}

const frame = 1 / 60;
const framesFor = (n) => Math.max(10, Math.min(2000, Math.round(3e7 / n)));
let clock = 0;

function run(mode, n) {
  const segs = segments(1024);
  global.gc();
  const before = process.memoryUsage().heapUsed;
  const targets = new Array(n);
  const tweens = new Array(n);
  for (let i = 0; i < n; ++i) {
    const s = segs[i % 1024];
    const target = { x: s.x0, y: s.y0 };
    targets[i] = target;
    const vars = { duration: 1 + 2 * (i % 1000) / 1000, ease: 'power2.inOut', repeat: -1, yoyo: true };
    if (mode === 'tween') { vars.x = s.x1; vars.y = s.y1; }
    else if (mode === 'motion') vars.motionPath = { path: `M${s.x0},${s.y0} L${s.x1},${s.y1}` };
    else vars.motionPath = { path: cubicPath(s) };
    tweens[i] = gsap.to(target, vars);
  }
  global.gc();
  const bytes = (process.memoryUsage().heapUsed - before) / n;
  const step = () => { clock += frame; gsap.updateRoot(clock); };
  const t = measure([{ name: mode, step, frames: framesFor(n), per: n }], rounds)[mode];
  if (!Number.isFinite(targets[n - 1].x)) throw new Error('no motion');
  console.log(`gsap_${mode.padEnd(13)} N=${String(n).padStart(8)}  ${format(t)}  bytes/tween ${bytes.toFixed(0).padStart(6)}`);
  gsap.globalTimeline.clear();  // drop this run's tweens at once (killing 1e6 one by one crawls)
}

// bench_timeline's workload: N tweens as N/10 timelines (repeat -1) of 10 sequential x/y
// tweens, each played once per timeline play, power2.inOut, 1 + 2·(i mod 1000)/1000 s.
// Reports ns per live update (one active tween per timeline) and per tween held.
function runTimelines(n) {
  const segs = segments(1024);
  global.gc();
  const timelines = [];
  const targets = new Array(n);
  for (let t = 0; t < n / 10; ++t) {
    const tl = gsap.timeline({ repeat: -1 });
    for (let k = 0; k < 10; ++k) {
      const i = t * 10 + k;
      const s = segs[i % 1024];
      const target = { x: s.x0, y: s.y0 };
      targets[i] = target;
      tl.to(target, { x: s.x1, y: s.y1, duration: 1 + 2 * (i % 1000) / 1000, ease: 'power2.inOut' });
    }
    timelines.push(tl);
  }
  // Per live update: one active tween per timeline.
  const step = () => { clock += frame; gsap.updateRoot(clock); };
  const t = measure([{ name: 'timelines', step, frames: framesFor(n), per: n / 10 }], rounds).timelines;
  if (!Number.isFinite(targets[n - 1].x)) throw new Error('no motion');
  console.log(`gsap_timelines  N=${String(n).padStart(8)}  live updates: ${format(t)}  ns/tween held ${(t.wall.median / 10).toFixed(1).padStart(7)}`);
  gsap.globalTimeline.clear();
}

console.log(`GSAP ${gsap.version}, Node ${process.version}`);
for (const mode of modes) for (const n of sizes) {
  if (mode === 'timelines') runTimelines(n);
  else run(mode, n);
}
process.exit(0);  // GSAP's ticker would keep Node alive
