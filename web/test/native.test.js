// The WebAssembly build against the native build: the same inputs through the `grape` tool
// (JSON with 17 significant digits, so every number reads back as the same double) and
// through the module.
//
// Why the two agree, and how closely: +, −, ×, ÷ and sqrt are correctly rounded IEEE-754
// operations in both builds, and neither contracts a·b + c into an FMA (x86-64 without
// -march, and WebAssembly, have none), so code made only of them gives identical bits.
// sin, cos, exp2, pow, atan2 and hypot come from different C libraries (glibc natively, musl
// in emscripten); each is within 1 ulp of the exact value, so the two can differ by 2 ulp,
// and the few operations after them (an easing's 1 − x, a derivative's chain rule) can at
// most double that: 4 ulp of the result's scale.
'use strict';
const test = require('node:test');
const assert = require('node:assert');
const { grape, ulpDistance } = require('./native.js');
const loadGrape = require('..');

const LIBM_ULPS = 4;

// SVG data covering every segment kind: lines, cubic and smooth cubic, quadratic and smooth
// quadratic, circular and elliptical arcs, closepath and a second subpath.
const SVG = [
  'M0 0 L3 4',
  'M0 0 C0 100 100 100 100 0',
  'M10 10 Q 50 90 90 10 T 170 10',
  'M0 0 A 50 30 20 1 1 100 40',
  'M0 0 A 50 50 0 0 1 100 0 Z',
  'M5 5 h 40 v 30 c 10 10 -20 30 -40 0 s 10 -50 30 -20 z M100 100 l 10 10',
];
const US = [0, 0.1, 0.25, 0.5, 0.77, 1];

// Within `ulps` units of `scale` (the quantity's natural size, so values near 0 are judged
// against it rather than against their own tiny magnitude).
function close(actual, expected, ulps, scale, what) {
  const tolerance = ulps * Number.EPSILON * Math.max(Math.abs(expected), scale);
  assert.ok(Math.abs(actual - expected) <= tolerance,
    `${what}: wasm ${actual} vs native ${expected} (${ulpDistance(actual, expected).toFixed(1)} ulp, bound ${ulps} ulp of ${scale})`);
}

test('native and wasm agree', async (t) => {
  const g = await loadGrape();

  await t.test('SVG path lengths: identical bits', () => {
    for (const data of SVG) {
      const path = g.parseSvgPath(data);
      assert.strictEqual(path.length(), grape('path', 'length', data).length, data);
      path.delete();
    }
  });

  await t.test('closest points (the 1e-12 contract) and frames (libm rounding)', () => {
    // The nearest point is a minimum, flat in u: libm's last-bit differences move u and the
    // point by more than they move the distance, which both builds promise within 1e-12 of
    // the path's size. Tangent, normal and curvature come from d1, d2 (arcs through sin/cos):
    // LIBM_ULPS of their scales, twice for curvature's quotient.
    const queries = [[3, 4], [250, -40], [-10, 120], [60, 60], [33, -7]];
    for (const data of SVG) {
      const path = g.parseSvgPath(data);
      const b = path.bounds();
      const size = Math.max(b.max.x - b.min.x, b.max.y - b.min.y);
      for (const [x, y] of queries) {
        const c = path.closestPoint(x, y);
        const n = grape('path', 'closest', data, x, y);
        assert.ok(Math.abs(c.distance - n.distance) <= 1e-12 * size, `${data} (${x}, ${y}): ${c.distance} vs ${n.distance}`);
        assert.ok(Math.abs(Math.hypot(c.point.x - x, c.point.y - y) - c.distance) <= 1e-12 * size, `${data} (${x}, ${y})`);
      }
      for (const u of [0.3, 0.5, 0.9]) {
        const f = path.frame(u);
        const n = grape('path', 'curvature', data, u);
        close(f.tangent.x, n.tx, LIBM_ULPS, 1, `${data} tx(${u})`);
        close(f.tangent.y, n.ty, LIBM_ULPS, 1, `${data} ty(${u})`);
        close(f.normal.x, n.nx, LIBM_ULPS, 1, `${data} nx(${u})`);
        close(f.normal.y, n.ny, LIBM_ULPS, 1, `${data} ny(${u})`);
        close(f.curvature, n.curvature, 2 * LIBM_ULPS, Math.max(Math.abs(n.curvature), 1 / size), `${data} κ(${u})`);
      }
      path.delete();
    }
  });

  await t.test('points and derivatives, by u and by arc length', () => {
    for (const data of SVG) {
      const parsed = g.parseSvgPath(data);
      const even = parsed.reparametrized();
      const scale = parsed.length();
      for (const u of US) {
        for (const [path, flag] of [[parsed, []], [even, ['--arc-length']]]) {
          const native = grape('path', 'point', data, u, ...flag);
          const p = path.point(u);
          const d = path.d1(u);
          // Points: sums and products of the segment formulas (arcs through sin/cos).
          close(p.x, native.x, LIBM_ULPS, scale, `${data} x(${u}) ${flag}`);
          close(p.y, native.y, LIBM_ULPS, scale, `${data} y(${u}) ${flag}`);
          close(d.x, native.dx, LIBM_ULPS, scale, `${data} dx(${u}) ${flag}`);
          close(d.y, native.dy, LIBM_ULPS, scale, `${data} dy(${u}) ${flag}`);
        }
      }
      even.delete();
      parsed.delete();
    }
  });

  await t.test('every named easing at nine times', () => {
    const names = [...g.curveNames(), 'back-out(2.5)', 'elastic-in(1.2,0.4)', 'cubic-bezier(0.25,0.1,0.25,1)',
      'steps(4,jump-end)', 'monotone(0,0,0.5,0.8,1,1)', 'ease-in-out', 'svg(M0,0 C0.2,0 0.3,1 1,1)', 'spring(170,26)'];
    let identical = 0;
    let total = 0;
    for (const name of names) {
      for (const time of [0, 0.1, 0.25, 0.3, 0.5, 0.7, 0.75, 0.9, 1]) {
        const native = grape('ease', name, time).progress;
        const wasm = g.ease(name, time);
        close(wasm, native, LIBM_ULPS, 1, `${name}(${time})`);  // progress is of order 1
        identical += Object.is(wasm, native) ? 1 : 0;
        ++total;
      }
    }
    // Only the transcendental curves may differ at all; most values are bit-identical.
    assert.ok(identical >= 0.9 * total, `${identical} of ${total} easing values bit-identical`);
  });

  await t.test('engine states equal the native path at the native easing', () => {
    // An animation of `duration` seconds sought to time s is at path.point(curve(s / duration))
    // (one play, not reversed): the engine must land on the tool's point at the tool's progress.
    const cases = [
      ['M0 0 C0 100 100 100 100 0', 'quad-in-out', 0.5],
      ['M10 10 Q 50 90 90 10 T 170 10', 'cubic-out', 1.5],
      ['M0 0 A 50 30 20 1 1 100 40', 'sine-in-out', 0.25],
      ['M5 5 h 40 v 30 c 10 10 -20 30 -40 0 s 10 -50 30 -20 z', 'bounce-out', 1.0],
    ];
    const duration = 2;  // s / 2 is exact
    const engine = new g.Engine(cases.length);
    const paths = cases.map(([data, curve]) => {
      const path = g.parseSvgPath(data);
      engine.add(path, duration, { curve });
      return path;
    });
    cases.forEach(([, , s], k) => { const a = engine.animation(k); a.seek(s); a.delete(); });
    const xy = engine.positions();
    cases.forEach(([data, curve, s], k) => {
      const u = grape('ease', curve, s / duration).progress;
      const native = grape('path', 'point', data, u);
      const scale = paths[k].length();
      close(xy[2 * k], native.x, LIBM_ULPS, scale, `${data} ${curve} x at ${s} s`);
      close(xy[2 * k + 1], native.y, LIBM_ULPS, scale, `${data} ${curve} y at ${s} s`);
    });
    engine.tick(0);  // a zero tick changes nothing
    assert.deepStrictEqual(Array.from(engine.positions()), Array.from(xy));
    paths.forEach((p) => p.delete());
    engine.delete();
  });

  await t.test('grape simulate parabola: every method and integrator for 10 s', () => {
    const fields = ['seconds', 'x', 'y', 'vx', 'vy', 'max_residual', 'max_distance', 'initial_energy', 'final_energy'];
    const runs = [];
    for (const method of ['implicit', 'parametric', 'seed'])
      for (const integrator of ['euler', 'symplectic', 'midpoint', 'rk4', 'verlet', 'rk45'])
        runs.push({ method, integrator, forceX: method === 'seed' ? 100 : 0 });
    runs.push({ method: 'implicit', integrator: 'rk4', stabilize: 'baumgarte' });
    runs.push({ method: 'implicit', integrator: 'rk4', stabilize: 'projection', forceX: 100 });
    for (const o of runs) {
      const native = grape('simulate', 'parabola', '--method', o.method, '--integrator', o.integrator,
        '--stabilize', o.stabilize || 'none', '--force-x', o.forceX || 0, '--seconds', 10);
      const wasm = g.runParabola(o, native.dt, 10);
      for (const f of fields) {
        if (o.integrator === 'rk45') {
          // The adaptive step comes from pow(error, −1/5) (libm): a step one ulp apart moves
          // the state by about the per-step error bound (1e-10 relative) per step, over 600
          // steps at most 6e-8 relative.
          const bound = 6e-8 * Math.max(Math.abs(native[f]), 1);
          assert.ok(Math.abs(wasm[f] - native[f]) <= bound, `${JSON.stringify(o)} ${f}: ${wasm[f]} vs ${native[f]}`);
        } else {
          // Fixed steps of arithmetic and sqrt only: identical bits.
          assert.strictEqual(wasm[f], native[f], `${JSON.stringify(o)} ${f}`);
        }
      }
    }
  });
});
