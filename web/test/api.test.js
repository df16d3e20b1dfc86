// The JavaScript API of the WebAssembly build against independent truth: closed forms,
// conservation, a reference model of the bit operations, and grape's errors as JS Errors.
'use strict';
const test = require('node:test');
const assert = require('node:assert');
const loadGrape = require('..');

// A fixed-seed generator (LCG), so every run checks the same inputs.
function lcg(seed) {
  let s = seed >>> 0;
  return () => { s = (Math.imul(s, 1664525) + 1013904223) >>> 0; return s / 4294967296; };
}

test('grape-wasm API', async (t) => {
  const g = await loadGrape();

  await t.test('paths: closed-form lengths, constant speed, every kind', () => {
    const line = g.Path.linear({ x: 0, y: 0 }, { x: 3, y: 4 });
    assert.strictEqual(line.length(), 5);
    assert.deepStrictEqual(line.point(0.5), { x: 1.5, y: 2 });
    // 2πr for a full circle; 1e-13: the closed form's few roundings of ~630.
    const circle = g.Path.circle({ x: 0, y: 0 }, 100, 0, 2 * Math.PI);
    assert.ok(Math.abs(circle.length() - 200 * Math.PI) <= 1e-13 * 200 * Math.PI);
    // Reparametrized: |d1| is the length everywhere (1e-9 relative, the table's accuracy).
    const bez = g.Path.cubicBezier({ x: 20, y: 20 }, { x: 400, y: 200 }, { x: 400, y: 600 }, { x: 600, y: 600 }, false);
    const even = bez.reparametrized();
    assert.strictEqual(even.kind(), 'reparametrized');
    for (let u = 0; u <= 1; u += 0.125) {
      const d = even.d1(u);
      assert.ok(Math.abs(Math.hypot(d.x, d.y) - bez.length()) <= 1e-9 * bez.length(), `|d1(${u})|`);
      // And point(u) lies u·L along the original.
      const s = bez.lengthAt(bez.uAtLength(u * bez.length()));
      assert.ok(Math.abs(s - u * bez.length()) <= 1e-9 * bez.length());
    }
    const kinds = [
      g.Path.ellipticalArc({ x: 0, y: 0 }, 50, 30, 0.3, 0, 3),
      g.Path.spiral({ x: 100, y: 100 }, 200, 0, 0, 2 * Math.PI),
      g.Path.sineWave({ x: 0, y: 0 }, { x: 100, y: 0 }, 2, 10),
      g.Path.quadraticBezier({ x: -200, y: -400 }, { x: 0, y: 400 }, { x: 200, y: -400 }, true),
      g.Path.linearSpline([0, 0, 10, 0, 10, 10]),
      g.Path.cosineSpline(new Float64Array([0, 0, 10, 0, 10, 10])),
      g.Path.hermiteSpline([0, 0, 10, 0], [5, 5, 5, -5]),
      g.Path.catmullRom([0, 0, 10, 0, 10, 10, 20, 10], 'centripetal'),
      g.Path.physics({ x: 0, y: 0 }, { x: 100, y: -300 }, { x: 0, y: 500 }, 1),
      g.Path.complex([line, circle], [0, 0.5]),
      g.Path.complexByLength([line, bez]),
      g.Path.svg('M0 0 H10 V10'),
    ];
    const names = kinds.map((p) => p.kind());
    assert.deepStrictEqual(names, ['elliptical_arc', 'spiral', 'sine_wave', 'reparametrized', 'linear_spline',
      'cosine_spline', 'hermite_spline', 'catmull_rom_spline', 'physics', 'complex', 'complex', 'complex']);
    // A projectile's point at u is the closed form at t = u·seconds.
    assert.deepStrictEqual(kinds[8].point(0.5), { x: 50, y: -150 + 0.5 * 500 * 0.25 });
    // Flatten: a polyline within its tolerance of the path, from its start to (within the
    // tolerance of) its end: the native build's last point is 6e-10 short of (600, 600) too.
    const flat = bez.flatten(0.1);
    assert.deepStrictEqual([flat[0], flat[1]], [20, 20]);
    assert.ok(Math.hypot(flat[flat.length - 2] - 600, flat[flat.length - 1] - 600) <= 0.1);
    // Every vertex lies on the path: a point of it is within half a sample spacing (0.021 px)
    // of one of 20001 samples spaced L/20000 along it.
    const us = Float64Array.from({ length: 20001 }, (_, i) => i / 20000);
    const dense = even.sample(us);  // constant speed: evenly spaced samples
    for (let i = 0; i + 1 < flat.length; i += 2) {
      let best = Infinity;
      for (let k = 0; k < dense.length; k += 2) best = Math.min(best, Math.hypot(dense[k] - flat[i], dense[k + 1] - flat[i + 1]));
      assert.ok(best <= 0.022, `vertex ${i / 2} is ${best} from the path`);
    }
    const parts = [kinds[9].part(0), kinds[9].part(1)];
    assert.strictEqual(kinds[9].partCount(), 2);
    assert.ok(parts[0].same(line));
    assert.deepStrictEqual(Array.from(kinds[9].cues()), [0, 0.5]);
    const sampled = line.sample([0, 0.5, 1]);
    assert.deepStrictEqual(Array.from(sampled), [0, 0, 1.5, 2, 3, 4]);
    for (const p of [...kinds, ...parts, line, circle, bez, even]) p.delete();
  });

  await t.test('errors arrive as Error with grape\'s message', () => {
    assert.throws(() => g.Path.linear({ x: NaN, y: 0 }, { x: 1, y: 1 }), (e) => e instanceof Error && /finite/.test(e.message));
    assert.throws(() => g.parseSvgPath('M0 0 L@'), /expected a number at offset 6, found '@'/);
    assert.throws(() => g.parseCurve('quad-sideways'), /unknown curve name 'quad-sideways'; valid names: linear/);
    assert.throws(() => g.Path.linearSpline([0, 0, 1]), /x, y pairs/);
    assert.throws(() => g.Path.catmullRom([0, 0, 1, 1], 'wobbly'), /uniform, centripetal or chordal/);
    const engine = new g.Engine(1);
    const line = g.Path.linear({ x: 0, y: 0 }, { x: 1, y: 0 });
    engine.add(line, 1);
    assert.throws(() => engine.add(line, 1), /all 1 slots are used/);
    assert.throws(() => engine.tick(-1), Error);
    assert.throws(() => new g.Engine(2).add(line, 1, { repeat: 0.5 }), /'repeat' must be an integer/);
    assert.throws(() => new g.Engine(2).add(line, 1, { repeat: 1e300 }), /'repeat' must be an integer/);
    assert.throws(() => new g.SpritePlayer(8, { startFrame: 1e20 }), /startFrame must be a whole number/);
    assert.throws(() => new g.KeyState(512).mask([3.5]), /not a code below 512/);
    const system = new g.ParticleSystem();
    assert.throws(() => system.addDistance(0, 1, 1), /no particle 0/);
    assert.throws(() => new g.ParticleSystem({ integrator: 'leapfrog' }), /leapfrog/);
    assert.throws(() => new g.BitVector(4, false).get(4), Error);
    assert.throws(() => new g.SpritePlayer(8, { rate: NaN }), Error);
    engine.delete(); line.delete(); system.delete();
  });

  await t.test('engine: one Float64Array view of every slot, exact time, events', () => {
    const n = 100;
    const engine = new g.Engine(n);
    const path = g.Path.linear({ x: 0, y: 0 }, { x: 100, y: 50 });
    for (let i = 0; i < n; ++i) engine.add(path, 1 + i / n, { curve: 'quad-in-out', repeat: -1, yoyo: true });
    let completed = 0;
    const once = g.Path.linear({ x: 0, y: 0 }, { x: 1, y: 1 });
    const single = new g.Engine(1);
    single.add(once, 1);
    const handle = single.animation(0);
    handle.onComplete(() => ++completed);
    for (let k = 0; k < 90; ++k) { engine.tick(1 / 60); single.tick(1 / 60); }
    assert.strictEqual(completed, 1);
    assert.strictEqual(handle.alive(), false);
    const xy = engine.positions();
    assert.strictEqual(xy.length, 2 * n);
    // Each slot equals the path at quad-in-out of its own phase (yoyo: the second play runs back).
    const t = 90 / 60;
    for (let i = 0; i < n; i += 9) {
      const d = 1 + i / n;
      const plays = t / d;
      const k = Math.floor(plays);
      let phase = plays - k;
      if (k % 2 === 1) phase = 1 - phase;
      const u = g.ease('quad-in-out', phase);
      // 1e-12: the tick sums 90 steps of 1/60 (about 50 roundings of a time ~1.5 s).
      assert.ok(Math.abs(xy[2 * i] - 100 * u) <= 1e-12 * 100, `slot ${i}: ${xy[2 * i]} vs ${100 * u}`);
      assert.ok(Math.abs(xy[2 * i + 1] - 50 * u) <= 1e-12 * 50);
    }
    // A part of a path at a sideways offset: u from 0.25 to 0.75 of a +x line, 2 beside it
    // (the normal of +x is +y); dyadic numbers, so exact.
    const lane = new g.Engine(2);
    const straight = g.Path.linear({ x: 0, y: 0 }, { x: 128, y: 0 });
    lane.add(straight, 1, { rangeStart: 0.25, rangeEnd: 0.75, offset: 2 });
    lane.tick(0.5);
    assert.deepStrictEqual(Array.from(lane.positions()), [64, 2]);
    assert.throws(() => lane.add(straight, 1, { rangeEnd: 2 }), /range_end/);
    lane.delete(); straight.delete();
    // Writing into JS objects.
    const target = { x: -1, y: -1 };
    const small = new g.Engine(0);
    const anim = small.animate(target, path, 2, { curve: 'linear' });
    small.tick(0.5);
    assert.deepStrictEqual(target, { x: 25, y: 12.5 });
    assert.strictEqual(anim.progress(), 0.25);
    handle.delete(); anim.delete();
    for (const o of [engine, single, small, path, once]) o.delete();
  });

  await t.test('particle system: a pendulum holds its rod at round-off and keeps its energy', () => {
    const system = new g.ParticleSystem({ integrator: 'rk4', drift: 'projection' });
    const bob = system.addParticle({ x: 100, y: 0 }, { x: 0, y: 0 }, 1);
    system.addGravity({ x: 0, y: 500 });
    system.addAnchor(bob, { x: 0, y: 0 }, 100);
    const e0 = system.energy();
    for (let i = 0; i < 600; ++i) system.step(1 / 240);
    const p = system.position(bob);
    // Projection holds |x| = 100 to round-off: 8ε·(1 + |x|) as the projection's own stop.
    assert.ok(Math.abs(Math.hypot(p.x, p.y) - 100) <= 8 * Number.EPSILON * 101 * 4);
    // E0 = 0 (at rest on the pivot's level); against the energy scale m·g·L = 50000, RK4 at
    // h = 1/240 (period ~1.3 s) with projection errs far less than 1e-6.
    assert.ok(Math.abs(system.energy() - e0) <= 1e-6 * 500 * 100, `${system.energy()} vs ${e0}`);
    const xy = system.positions();
    assert.deepStrictEqual([xy[0], xy[1]], [p.x, p.y]);
    // The seed's parabola as a conic: the particle stays on x² + 100y = 0.
    const para = new g.ParticleSystem({ drift: 'projection' });
    const q = para.addParticle({ x: 100, y: -100 }, { x: 0, y: 0 }, 1);
    para.addGravity({ x: 0, y: 500 });
    para.addConic(q, [1, 0, 0, 0, 100, 0]);
    for (let i = 0; i < 120; ++i) para.step(1 / 60);
    assert.ok(para.maxResidual().distance < 1e-9);
    system.delete(); para.delete();
  });

  await t.test('bead: energy on a circle, joins of a complex path', () => {
    const circle = g.Path.circle({ x: 0, y: 0 }, 100, 0, 2 * Math.PI);
    const bead = new g.Bead(circle, { u: 0, gravity: { x: 0, y: 500 } });
    const e0 = bead.energy();
    for (let i = 0; i < 240; ++i) bead.step(1 / 240);
    assert.ok(Math.abs(bead.energy() - e0) <= 1e-6 * Math.abs(e0) + 1e-6);
    const p = bead.position();
    assert.ok(Math.abs(Math.hypot(p.x, p.y) - 100) <= 1e-9);  // on the circle by construction
    const ramp = g.parseSvgPath('M0 0 L100 100 L200 100');
    const slider = new g.Bead(ramp, { gravity: { x: 0, y: 500 } });
    for (let i = 0; i < 240; ++i) slider.step(1 / 240);
    assert.ok(slider.crossings() >= 1, 'crossed the join');
    circle.delete(); bead.delete(); ramp.delete(); slider.delete();
  });

  await t.test('BitVector against a reference model of plain arrays', () => {
    const random = lcg(7);
    for (let round = 0; round < 20; ++round) {
      const size = 1 + Math.floor(random() * 300);
      const a = new g.BitVector(size, false);
      const b = new g.BitVector(size, false);
      const ra = new Array(size).fill(false);
      const rb = new Array(size).fill(false);
      for (let k = 0; k < size; ++k) {
        if (random() < 0.3) { a.set(k, true); ra[k] = true; }
        if (random() < 0.5) { b.set(k, true); rb[k] = true; }
      }
      const text = (r) => r.map((v) => (v ? '1' : '0')).join('');
      assert.strictEqual(a.toString(), text(ra));
      assert.strictEqual(a.and(b).toString(), text(ra.map((v, i) => v && rb[i])));
      assert.strictEqual(a.or(b).toString(), text(ra.map((v, i) => v || rb[i])));
      assert.strictEqual(a.xor(b).toString(), text(ra.map((v, i) => v !== rb[i])));
      assert.strictEqual(a.not().toString(), text(ra.map((v) => !v)));
      assert.strictEqual(a.count(), ra.filter(Boolean).length);
      assert.deepStrictEqual(a.setBits(), ra.flatMap((v, i) => (v ? [i] : [])));
      assert.strictEqual(a.findFirst(), ra.indexOf(true));
      assert.strictEqual(a.isSubsetOf(a.or(b)), true);
      assert.ok(g.BitVector.fromString(a.toString()).equals(a));
      a.delete(); b.delete();
    }
    const pairs = new g.PairBits(100);
    assert.strictEqual(pairs.pairCount(), 4950);
    assert.strictEqual(pairs.testAndSet(7, 3), false);
    assert.strictEqual(pairs.testAndSet(3, 7), true);
    pairs.delete();
  });

  await t.test('SpritePlayer: frame = start + trunc(rate·n) wrapped', () => {
    for (const rate of [0.5, 1.375, -2, 3]) {
      const player = new g.SpritePlayer(16, { rate, startFrame: 5 });
      for (let n = 1; n <= 100; ++n) {
        player.advance();
        const expected = ((5 + Math.trunc(rate * n)) % 16 + 16) % 16;
        assert.strictEqual(player.frame(), expected, `rate ${rate}, step ${n}`);
      }
      player.delete();
    }
    const sheet = new g.TileSheet({ width: 512, height: 64, columns: 16, rows: 1 });
    assert.deepStrictEqual(sheet.frame(3), { x: 96, y: 0, width: 32, height: 64 });
    sheet.delete();
  });

  await t.test('KeyState: down, the frame\'s edges and masks', () => {
    const keys = new g.KeyState(512);
    const save = keys.mask([224, 22]);
    keys.press(224);
    keys.press(22);
    assert.ok(keys.allDown(save) && keys.pressedThisFrame(22));
    keys.endFrame();
    assert.ok(keys.isDown(22) && !keys.pressedThisFrame(22));
    keys.release(22);
    assert.ok(keys.releasedThisFrame(22) && !keys.allDown(save) && keys.anyDown(save));
    assert.throws(() => keys.press(512), /512/);
    save.delete(); keys.delete();
  });
});
