// The 3-D JavaScript API (web/src/bind_3d.cpp) against independent truth: closed forms of
// helices, arcs, Béziers and projectiles, frame invariants and the helix's torsion, slerp
// against the axis-angle formula, a natural cubic spline of the angle, the pinhole camera, and
// 3-D animations against the path at the eased progress; grape's errors as JS Errors.
'use strict';
const test = require('node:test');
const assert = require('node:assert');
const loadGrape = require('..');

const EPS = Number.EPSILON;
const V = (x, y, z) => ({ x, y, z });
const add = (a, b) => V(a.x + b.x, a.y + b.y, a.z + b.z);
const sub = (a, b) => V(a.x - b.x, a.y - b.y, a.z - b.z);
const mul = (a, s) => V(a.x * s, a.y * s, a.z * s);
const dot = (a, b) => a.x * b.x + a.y * b.y + a.z * b.z;
const cross = (a, b) => V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
const norm = (a) => Math.hypot(a.x, a.y, a.z);
const unit = (a) => mul(a, 1 / norm(a));
const dist = (a, b) => norm(sub(a, b));
// Rodrigues' formula: v turned by angle about the unit axis n.
const rodrigues = (n, angle, v) => add(add(mul(v, Math.cos(angle)), mul(cross(n, v), Math.sin(angle))),
  mul(n, dot(n, v) * (1 - Math.cos(angle))));
// The unit quaternion of a turn by angle about the unit axis n, written out.
const axisAngleQuat = (n, angle) => ({ w: Math.cos(angle / 2), x: Math.sin(angle / 2) * n.x, y: Math.sin(angle / 2) * n.y, z: Math.sin(angle / 2) * n.z });
const quatDistance = (a, b) => {  // q and −q are the same rotation
  const d = (s) => Math.hypot(a.w - s * b.w, a.x - s * b.x, a.y - s * b.y, a.z - s * b.z);
  return Math.min(d(1), d(-1));
};

test('grape-wasm 3-D API', async (t) => {
  const g = await loadGrape();

  await t.test('paths: closed forms of every kind', () => {
    // Helix: length 2π·turns·√(r² + c²) with c = rise/2π the rise per radian; a few roundings
    // of each closed form (the path's and this one), so 1e-14 relative (~45 ulp).
    const r = 2, rise = 3, turns = 2.5;
    const helix = g.Path3.helix({ center: V(1, -1, 0.5), radius: r, rise, turns });
    const c = rise / (2 * Math.PI);
    const L = 2 * Math.PI * turns * Math.hypot(r, c);
    assert.strictEqual(helix.kind(), 'helix');
    assert.ok(Math.abs(helix.length() - L) <= 1e-14 * L, `helix length ${helix.length()} vs ${L}`);
    // point(u) = centre + r(cos θ, sin θ, 0) + c·θ·z with θ = 2π·turns·u; the angle (up to 16 rad)
    // carries ~2 ulp of it into cos and sin, so 1e-14 of the helix's size.
    for (let u = 0; u <= 1; u += 0.0625) {
      const th = 2 * Math.PI * turns * u;
      const want = V(1 + r * Math.cos(th), -1 + r * Math.sin(th), 0.5 + c * th);
      assert.ok(dist(helix.point(u), want) <= 1e-14 * (r + rise * turns), `helix point at ${u}`);
      // u is proportional to arc length: lengthAt(u) = u·L.
      assert.ok(Math.abs(helix.lengthAt(u) - u * L) <= 1e-13 * L);
    }
    // uAtLength inverts lengthAt to ~1e-15 in u; 1e-13·L allows the quadrature's 1e-14.
    const bez = g.Path3.cubicBezier(V(0, 0, 0), V(4, 0, 1), V(4, 5, 2), V(9, 5, -1));
    for (const s of [0, 0.3, 2.5, 7, bez.length()]) assert.ok(Math.abs(bez.lengthAt(bez.uAtLength(s)) - s) <= 1e-13 * bez.length(), `s ${s}`);
    // The Bernstein form, written out.
    const P = [V(0, 0, 0), V(4, 0, 1), V(4, 5, 2), V(9, 5, -1)];
    const bern = (u) => { const v = 1 - u; return [v * v * v, 3 * u * v * v, 3 * u * u * v, u * u * u].reduce((acc, w, i) => add(acc, mul(P[i], w)), V(0, 0, 0)); };
    for (let u = 0; u <= 1; u += 0.125) assert.ok(dist(bez.point(u), bern(u)) <= 1e-14 * 10, `Bézier point at ${u}`);
    // Its length against chord sums with Richardson's extrapolation: the chord sum with N
    // chords falls short by a·N⁻² + O(N⁻⁴), so (4·S(2N) − S(N))/3 is within O(N⁻⁴) ≈ 1e-13·L
    // at N = 2000 for a polygon this tame, plus 4000 additions' rounding (< 1e-12·L): 1e-11·L.
    const chords = (n) => { let s = 0, a = bern(0); for (let i = 1; i <= n; ++i) { const b = bern(i / n); s += dist(a, b); a = b; } return s; };
    const extrapolated = (4 * chords(4000) - chords(2000)) / 3;
    assert.ok(Math.abs(bez.length() - extrapolated) <= 1e-11 * extrapolated, `Bézier length ${bez.length()} vs ${extrapolated}`);
    // Arc: r·|Δθ| exactly in closed form.
    const arc = g.Path3.arc({ center: V(0, 0, 3), axis: V(0, 1, 0), start: V(1, 0, 0), radius: 5, startAngle: 0.5, endAngle: -2 });
    assert.ok(Math.abs(arc.length() - 12.5) <= 4 * EPS * 12.5);
    // Counter-clockwise about +y from +x: e2 = y × x = −z.
    const th = 0.5 + 0.25 * (-2 - 0.5);
    assert.ok(dist(arc.point(0.25), V(5 * Math.cos(th), 0, 3 - 5 * Math.sin(th))) <= 1e-14 * 5);
    // A line's length and midpoint.
    const line = g.Path3.line(V(1, 2, 3), V(3, 5, 9));
    assert.strictEqual(line.length(), 7);
    assert.deepStrictEqual(line.point(0.5), V(2, 3.5, 6));
    // Projectile: position + v·t + ½·a·t², t = u·seconds; numbers chosen exact in binary.
    const shot = g.Path3.projectile(V(0, 0, 1), V(2, 1, 8), V(0, 0, -8), 2);
    assert.deepStrictEqual(shot.point(0.5), V(2, 1, 1 + 8 - 4));
    // Splines pass through their points at u = i/(n − 1); a closed one returns to its start.
    const pts = [0, 0, 0, 3, 1, 0, 4, 4, 2, 0, 5, 1];
    const cr = g.Path3.catmullRom(pts, 'centripetal');
    const loop = g.Path3.catmullRom(pts, 'chordal', true);
    const lin = g.Path3.linearSpline(pts);
    const tangents = [1, 0, 0, 0, 1, 0, -1, 0, 1, 0, 0, -1];
    const herm = g.Path3.hermite(pts, tangents);
    for (let i = 0; i < 4; ++i) {
      const p = V(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
      for (const path of [cr, lin, herm]) assert.ok(dist(path.point(i / 3), p) <= 1e-14 * 8, `${path.kind()} through point ${i}`);
      assert.ok(dist(loop.point(i / 4), p) <= 1e-14 * 8, `closed spline through point ${i}`);
      // Hermite: each segment takes 1/3 of u, so d/du = 3·d/dt and d1 = 3·tangent at the points.
      const d1 = herm.d1(i / 3);
      assert.ok(dist(d1, V(3 * tangents[3 * i], 3 * tangents[3 * i + 1], 3 * tangents[3 * i + 2])) <= 1e-13, `hermite d1 at ${i}`);
    }
    assert.ok(dist(loop.point(0), loop.point(1)) <= 1e-14 * 8);
    assert.deepStrictEqual(Array.from(lin.breaks()), [0, 1 / 3, 2 / 3, 1]);
    // A 2-D circle of radius 10 on a plane with axes of length 2: length 2·2π·10.
    const circle2 = g.Path.circle({ x: 0, y: 0 }, 10, 0, 2 * Math.PI);
    const lifted = g.Path3.onPlane(circle2, V(0, 0, 5), V(0, 2, 0), V(0, 0, 2));
    assert.ok(Math.abs(lifted.length() - 40 * Math.PI) <= 1e-13 * 40 * Math.PI);
    assert.ok(dist(lifted.point(0.25), V(0, 0, 25)) <= 1e-13 * 20);
    // Complex: each part starts at its cue; complexByLength's cue is the length share.
    const whole = g.Path3.complex([line, bez], [0, 0.4]);
    assert.ok(dist(whole.point(0.4), bez.point(0)) <= 1e-15 && dist(whole.point(0.2), line.point(0.5)) <= 1e-15);
    assert.strictEqual(whole.partCount(), 2);
    // Two equal parts by length: the second spans [0.5, 1] and starts at the line's start.
    const byLength = g.Path3.complexByLength([line, line]);
    assert.ok(dist(byLength.point(0.5), V(1, 2, 3)) <= 1e-15 && dist(byLength.point(0.25), line.point(0.5)) <= 1e-15);
    // Slice: point(v) = path.point(u0 + v(u1 − u0)).
    const piece = bez.slice(0.25, 0.75);
    assert.ok(dist(piece.point(0.5), bez.point(0.5)) <= 1e-14 && dist(piece.point(1), bez.point(0.75)) === 0);
    // The closest point of a line to q is the foot of the perpendicular.
    const q = V(0, 9, 0);
    const foot = add(V(1, 2, 3), mul(V(2, 3, 6), dot(sub(q, V(1, 2, 3)), V(2, 3, 6)) / 49));
    const near = line.closestPoint(q);
    assert.ok(dist(near.point, foot) <= 1e-13 * 10 && Math.abs(near.distance - dist(q, foot)) <= 1e-13 * 10);
    // Flatten: every vertex lies on the path (its nearest point within 1e-12 of the size).
    const flat = helix.flatten(0.01);
    assert.ok(flat.length % 3 === 0 && flat.length > 30);
    for (let i = 0; i < flat.length; i += 3 * 7) assert.ok(helix.closestPoint(V(flat[i], flat[i + 1], flat[i + 2])).distance <= 1e-12 * L);
    // Constant speed after reparametrizing: |d1| = length (the table's 1e-9).
    const even = bez.reparametrized();
    for (let u = 0; u <= 1; u += 0.1) assert.ok(Math.abs(norm(even.d1(u)) - bez.length()) <= 1e-9 * bez.length());
    const sampled = line.sample([0, 1]);
    assert.deepStrictEqual(Array.from(sampled), [1, 2, 3, 3, 5, 9]);
    const kinds = [line, g.Path3.quadraticBezier(V(0, 0, 0), V(1, 1, 1), V(2, 0, 0)), bez, cr, helix, whole, herm, lin, arc, shot, lifted, even, piece];
    assert.deepStrictEqual(kinds.map((p) => p.kind()), ['line', 'quadratic_bezier', 'cubic_bezier', 'catmull_rom', 'helix',
      'complex', 'hermite', 'linear_spline', 'arc', 'projectile', 'on_plane', 'reparametrized', 'slice']);
    const fitted = g.Path3.fit(Array.from({ length: 40 }, (_, i) => [Math.cos(i / 6), Math.sin(i / 6), i / 20]).flat(), { tolerance: 0.01 });
    assert.strictEqual(fitted.kind(), 'complex');
    for (const p of [...kinds, loop, circle2, byLength, fitted]) p.delete();
  });

  await t.test('frames: orthonormal, the helix torsion, Frenet and world-up modes', () => {
    const r = 3, rise = 4, turns = 1.5;
    const helix = g.Path3.helix({ radius: r, rise, turns });
    const c = rise / (2 * Math.PI);
    const L = helix.length();
    const rmf = new g.Frames3(helix, { mode: 'rmf', up: V(0, 0, 1) });
    const frenet = new g.Frames3(helix, { mode: 'frenet' });
    const upright = new g.Frames3(helix, { mode: 'reference_up' });
    assert.deepStrictEqual([rmf.mode(), frenet.mode(), upright.mode()], ['rmf', 'frenet', 'reference_up']);
    // Against the RMF the Frenet frame turns about the tangent at the torsion τ = c/(r² + c²):
    // the angle from the RMF normal to the Frenet normal changes by τ·Δs. The RMF's table holds
    // its roll within its tolerance of 1e-9 rad: 1e-8 rad.
    const tau = c / (r * r + c * c);
    const angle = (f) => Math.atan2(dot(cross(f.rmf.normal, f.frenet.normal), f.rmf.tangent), dot(f.rmf.normal, f.frenet.normal));
    const at = (u) => ({ rmf: rmf.frame(u), frenet: frenet.frame(u) });
    const a0 = angle(at(0));
    for (let u = 0; u <= 1; u += 1 / 32) {
      const f = at(u);
      // A few ulp from orthonormal (1e-14 is ~45 ulp).
      for (const fr of [f.rmf, f.frenet, upright.frame(u)]) {
        for (const v of [fr.tangent, fr.normal, fr.binormal]) assert.ok(Math.abs(norm(v) - 1) <= 1e-14);
        assert.ok(Math.abs(dot(fr.tangent, fr.normal)) <= 1e-14 && dist(cross(fr.tangent, fr.normal), fr.binormal) <= 1e-14);
        assert.ok(dist(fr.tangent, helix.tangent(u)) <= 1e-14 && dist(fr.point, helix.point(u)) <= 1e-14 * (r + rise));
      }
      let d = angle(f) - a0 - tau * u * L;
      d -= 2 * Math.PI * Math.round(d / (2 * Math.PI));
      assert.ok(Math.abs(d) <= 1e-8, `RMF vs Frenet at u = ${u}: ${d} rad from τ·s`);
      // Frenet's normal points at the axis: −(cos θ, sin θ, 0).
      const th = 2 * Math.PI * turns * u;
      assert.ok(dist(f.frenet.normal, V(-Math.cos(th), -Math.sin(th), 0)) <= 1e-14, `Frenet normal at ${u}`);
      // World up: the tangent is 12° from horizontal, far outside the cone, so the normal is
      // up without its part along the tangent, exactly (to rounding).
      const T = helix.tangent(u);
      assert.ok(dist(upright.frame(u).normal, unit(sub(V(0, 0, 1), mul(T, T.z)))) <= 1e-14);
    }
    // orientation(u) takes +x to the tangent, +y to the normal.
    const q = rmf.orientation(0.3), f = rmf.frame(0.3);
    assert.ok(dist(g.quatRotate(q, V(1, 0, 0)), f.tangent) <= 1e-14 && dist(g.quatRotate(q, V(0, 1, 0)), f.normal) <= 1e-14);
    // sample: 12 numbers a frame, the same as frame(u).
    const s = rmf.sample([0.3]);
    assert.deepStrictEqual(Array.from(s.slice(6, 9)), [f.normal.x, f.normal.y, f.normal.z]);
    // Mode closed on a closed loop: the frame at the end meets the one at the start (1e-8 rad, as above).
    const loop = g.Path3.catmullRom([0, 0, 0, 10, 0, 3, 10, 10, 0, 0, 10, 5], 'centripetal', true);
    const closed = new g.Frames3(loop, { mode: 'closed' });
    assert.ok(dist(closed.frame(0).normal, closed.frame(1).normal) <= 1e-8);
    // Mode ends: twisted so that the normal at u = 1 is endUp without its part along the
    // tangent; there T = (0, ·, ·) so +x is already perpendicular (1e-8 rad, as above).
    const ends = new g.Frames3(helix, { mode: 'ends', up: V(0, 0, 1), endUp: V(1, 0, 0) });
    assert.ok(Math.abs(helix.tangent(1).x) <= 1e-15 && dist(ends.frame(1).normal, V(1, 0, 0)) <= 1e-8);
    assert.ok(dist(ends.frame(0).normal, rmf.frame(0).normal) <= 1e-15 && ends.twist() !== 0);
    for (const o of [rmf, frenet, upright, helix, loop, closed, ends]) o.delete();
  });

  await t.test('roll and bank: keys, linear fill, the banking formula', () => {
    const track = new g.RollTrack([0, 0, 10, 1, 20, -1]);
    assert.strictEqual(track.rollAt(10), 1);
    assert.ok(Math.abs(track.rollAt(15) - 0) <= 4 * EPS && Math.abs(track.rollAt(2.5) - 0.25) <= 4 * EPS);
    assert.strictEqual(track.rollAt(-5), 0);
    assert.strictEqual(track.rollAt(99), -1);
    const spline = new g.RollTrack([0, 0, 10, 1, 20, -1], { interpolation: 'natural_spline' });
    assert.strictEqual(spline.rollAt(10), 1);
    // A flat circle of radius R taken at v: bank atan(v²/(gR)) (below the π/4 clamp here), the
    // closed form of a few roundings: 1e-14. The circle turns counter-clockwise about +z, so the
    // binormal tangent × up points outward and leaning in is a negative roll.
    const R = 20, v = 10, gravity = 9.81;
    const ring = g.Path3.arc({ radius: R });
    const want = -Math.atan(v * v / (gravity * R));
    assert.ok(Math.abs(g.bankAngle(ring, 0.3, { speed: v, gravity }) - want) <= 1e-14);
    assert.ok(Math.abs(g.bankAngle(ring, 0.3, { speed: 30, gravity, maxAngle: 0.5 }) + 0.5) === 0, 'clamped');
    // Rolled frames: the base frame turned by the roll about the tangent (n cos r + b sin r).
    const base = new g.Frames3(ring, { mode: 'reference_up' });
    const bank = g.bankTrack(ring, { speed: v, gravity });
    const rolled = new g.RolledFrames3(base, bank);
    const f0 = base.frame(0.6), f1 = rolled.frame(0.6), roll = rolled.roll(0.6);
    assert.ok(Math.abs(roll - want) <= 1e-14);
    assert.ok(dist(f1.normal, add(mul(f0.normal, Math.cos(roll)), mul(f0.binormal, Math.sin(roll)))) <= 1e-14);
    // Leaning into the curve: the rolled normal tips toward the centre.
    assert.ok(dot(f1.normal, sub(V(0, 0, 0), f1.point)) > 0);
    for (const o of [track, spline, ring, base, bank, rolled]) o.delete();
  });

  await t.test('quaternions: axis-angle, slerp, bases, Euler, QuatSpline', () => {
    const n = unit(V(1, -2, 2));
    // Slerp between two turns about one axis is the turn by the interpolated angle.
    // The sinc form is a few ulp from the closed form: 1e-15 (~4.5 ulp of 1).
    const a = g.quatFromAxisAngle(n, 0.3), b = g.quatFromAxisAngle(n, 2.5);
    assert.ok(quatDistance(a, axisAngleQuat(n, 0.3)) <= 1e-15);
    for (let t = 0; t <= 1; t += 0.125) assert.ok(quatDistance(g.quatSlerp(a, b, t), axisAngleQuat(n, 0.3 + t * 2.2)) <= 1e-15, `slerp at ${t}`);
    // Rotation against Rodrigues' formula (15 multiplications each way: 1e-14 of |v|).
    const v = V(3, 1, -4);
    assert.ok(dist(g.quatRotate(b, v), rodrigues(n, 2.5, v)) <= 1e-14 * norm(v));
    // From the rotated axes back to the rotation (Shepperd), and the basis of it.
    const q = g.quatFromBasis(rodrigues(n, 2.5, V(1, 0, 0)), rodrigues(n, 2.5, V(0, 1, 0)), rodrigues(n, 2.5, V(0, 0, 1)));
    assert.ok(quatDistance(q, b) <= 1e-15 * 4);
    const basis = g.quatToBasis(b);
    assert.ok(dist(basis.y, rodrigues(n, 2.5, V(0, 1, 0))) <= 1e-14);
    const aa = g.quatAxisAngle(b);
    assert.ok(Math.abs(aa.angle - 2.5) <= 1e-15 * 4 && dist(aa.axis, n) <= 1e-15 * 4);
    // Products compose right to left: rotate(a·b, v) = rotate(a, rotate(b, v)).
    assert.ok(dist(g.quatRotate(g.quatMultiply(a, b), v), g.quatRotate(a, g.quatRotate(b, v))) <= 1e-14 * norm(v));
    // Yaw alone in zyx is a turn about z.
    assert.ok(quatDistance(g.quatFromEuler({ first: 0.7, second: 0, third: 0 }, 'zyx'), axisAngleQuat(V(0, 0, 1), 0.7)) <= 1e-15);
    const e = g.quatToEuler(g.quatFromEuler({ first: 0.7, second: -0.4, third: 1.1 }, 'zyx'), 'zyx');
    assert.ok(Math.abs(e.first - 0.7) <= 1e-14 && Math.abs(e.second + 0.4) <= 1e-14 && Math.abs(e.third - 1.1) <= 1e-14);
    // QuatSpline: keys about one fixed axis give exactly a natural cubic spline of the angle.
    // The reference: second derivatives M from the tridiagonal system with M0 = M3 = 0.
    const ts = [0, 1, 2.5, 3], angles = [0, 0.5, 1.6, 1.7];
    const spline = new g.QuatSpline(ts, angles.map((x) => g.quatFromAxisAngle(V(0, 0, 1), x)));
    const h = [1, 1.5, 0.5];
    const rhs = [1, 2].map((i) => 6 * ((angles[i + 1] - angles[i]) / h[i] - (angles[i] - angles[i - 1]) / h[i - 1]));
    // [[2(h0+h1), h1], [h1, 2(h1+h2)]]·[M1, M2] = rhs
    const A = 2 * (h[0] + h[1]), B = h[1], C = 2 * (h[1] + h[2]), det = A * C - B * B;
    const M = [0, (rhs[0] * C - B * rhs[1]) / det, (A * rhs[1] - B * rhs[0]) / det, 0];
    const natural = (t) => {
      const i = t < 1 ? 0 : t < 2.5 ? 1 : 2, x0 = ts[i], x1 = ts[i + 1], hh = h[i];
      const A1 = (x1 - t) / hh, B1 = (t - x0) / hh;
      return A1 * angles[i] + B1 * angles[i + 1] + ((A1 ** 3 - A1) * M[i] + (B1 ** 3 - B1) * M[i + 1]) * hh * hh / 6;
    };
    for (const t of [0, 0.4, 1, 1.7, 2.5, 2.8, 3]) {
      const o = spline.orientation(t);
      // The solve ends at rounding: 1e-12 rad.
      assert.ok(Math.abs(2 * Math.atan2(o.z, o.w) - natural(t)) <= 1e-12, `spline angle at ${t}: ${2 * Math.atan2(o.z, o.w)} vs ${natural(t)}`);
    }
    assert.strictEqual(spline.size(), 4);
    assert.ok(quatDistance(spline.key(2), axisAngleQuat(V(0, 0, 1), 1.6)) <= 1e-15);
    spline.delete();
  });

  await t.test('views: the pinhole camera, orbit, oblique', () => {
    const eye = V(10, -6, 4), target = V(1, 2, 0.5), up = V(0, 0, 1), fov = 0.9;
    const view = g.View3.perspective(eye, target, up, fov);
    // The pinhole written out: forward f, right = f × up, up' = right × f; a point at depth d
    // and offsets (x, y) lands at (x, −y)/(d·tan(fov/2)). A few roundings of numbers ~1: 1e-14.
    const f = unit(sub(target, eye)), right = unit(cross(f, up)), up2 = cross(right, f);
    const focal = 1 / Math.tan(fov / 2);
    for (const p of [V(0, 0, 0), V(3, 3, 3), V(-2, 5, 1), target]) {
      const d = sub(p, eye), z = dot(d, f);
      const got = view.project(p);
      assert.ok(got.visible && Math.abs(got.depth - z) <= 1e-14 * z);
      assert.ok(Math.abs(got.point.x - dot(d, right) * focal / z) <= 1e-14 && Math.abs(got.point.y + dot(d, up2) * focal / z) <= 1e-14, `pinhole ${JSON.stringify(p)}`);
    }
    assert.ok(Math.abs(view.project(target).point.x) <= 1e-15 && Math.abs(view.project(target).point.y) <= 1e-15, 'the target at the centre');
    assert.strictEqual(view.project(add(eye, mul(f, -1))).visible, false, 'behind the camera');
    const many = view.projectMany([3, 3, 3, ...Object.values(add(eye, mul(f, -1)))]);
    assert.ok(Math.abs(many[0] - view.project(V(3, 3, 3)).point.x) === 0 && Number.isNaN(many[3]));
    // Orbit is a perspective camera at target + D(cos e cos a, cos e sin a, sin e).
    const D = 12, az = 2.2, el = 0.4;
    const orbit = g.View3.orbit(target, D, az, el, fov);
    const same = g.View3.perspective(add(target, mul(V(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)), D)), target, up, fov);
    const p = V(2, -1, 3);
    assert.ok(Math.hypot(orbit.project(p).point.x - same.project(p).point.x, orbit.project(p).point.y - same.project(p).point.y) <= 1e-14);
    assert.ok(orbit.isPerspective() && dist(orbit.eye(), same.eye()) <= 1e-14 * D);
    // Oblique: x + recede·cos(angle)·y, −(z + recede·sin(angle)·y).
    const ob = g.View3.oblique(Math.PI / 4, 0.5);
    const o = ob.project(V(2, 4, 1));
    assert.ok(Math.abs(o.point.x - (2 + 2 * Math.SQRT1_2)) <= 1e-15 * 4 && Math.abs(o.point.y + (1 + 2 * Math.SQRT1_2)) <= 1e-15 * 4);
    assert.strictEqual(ob.isPerspective(), false);
    for (const x of [view, orbit, same, ob]) x.delete();
  });

  await t.test('engine: 3-D slots at the eased progress, frame and world alignment, constant speed', () => {
    const path = g.Path3.helix({ radius: 4, rise: 6, turns: 2 });
    const engine = new g.Engine(1, 4);
    assert.strictEqual(engine.capacity3(), 4);
    const k0 = engine.add3(path, 2, { curve: 'quad-in-out', repeat: -1 }, { align: 'frame', forward: '+x', up: '+y', frames: { mode: 'rmf' } });
    const k1 = engine.add3(path, 2, { curve: 'sine-in' }, { align: 'world', forward: '+x', up: '+z' });
    const k2 = engine.add3(path, { speed: 3 }, { repeat: -1 });
    const k3 = engine.add3(path, 2, {}, { align: 'frame', frames: { mode: 'frenet' }, normalOffset: 0.5 });
    assert.deepStrictEqual([k0, k1, k2, k3], [0, 1, 2, 3]);
    const frames = new g.Frames3(path, { mode: 'rmf' });
    const frenet = new g.Frames3(path, { mode: 'frenet' });
    const dt = 1 / 64;  // exact in binary: time is k/64 exactly
    for (let k = 1; k <= 80; ++k) {
      engine.tick(dt);
      const time = k * dt;
      const xyz = engine.positions3();
      assert.strictEqual(xyz.length, 28);
      const slot = (i) => ({ p: V(xyz[7 * i], xyz[7 * i + 1], xyz[7 * i + 2]), q: { w: xyz[7 * i + 3], x: xyz[7 * i + 4], y: xyz[7 * i + 5], z: xyz[7 * i + 6] } });
      // Slot 0 is the path at quad-in-out of the play's time (the easing is the same code: a few ulp, 1e-15).
      const a0 = engine.animation3(0);
      const u = g.ease('quad-in-out', (time % 2) / 2);
      assert.ok(Math.abs(a0.progress() - u) <= 1e-15, `progress ${a0.progress()} vs ${u}`);
      const s0 = slot(0);
      assert.deepStrictEqual(s0.p, path.point(a0.progress()));
      assert.deepStrictEqual(a0.value3(), s0.p);
      // Its orientation is the frame's: +x on the tangent, +y on the normal (a few ulp).
      const f = frames.frame(a0.progress());
      assert.ok(dist(g.quatRotate(s0.q, V(1, 0, 0)), f.tangent) <= 1e-14 && dist(g.quatRotate(s0.q, V(0, 1, 0)), f.normal) <= 1e-14);
      a0.delete();
      // Slot 1 upright: +z on world up, +x on the tangent's horizontal part.
      const a1 = engine.animation3(1), s1 = slot(1), T = path.tangent(a1.progress());
      assert.ok(dist(g.quatRotate(s1.q, V(0, 0, 1)), V(0, 0, 1)) <= 1e-14);
      assert.ok(dist(g.quatRotate(s1.q, V(1, 0, 0)), unit(V(T.x, T.y, 0))) <= 1e-14);
      a1.delete();
      // Slot 2 at constant speed, linear: the distance along the path is 3·time (mod length),
      // to the reparametrization's 1e-9·length.
      const s2 = slot(2), L = path.length();
      const along = path.lengthAt(path.closestPoint(s2.p).u);
      assert.ok(Math.abs(along - ((3 * time) % L)) <= 1e-9 * L, `speed: ${along} vs ${3 * time}`);
      // Slot 3: half a unit along the Frenet normal (toward the axis), identity when done.
      const a3 = engine.animation3(3), s3 = slot(3);
      if (a3.alive()) {
        const fr = frenet.frame(a3.progress());
        assert.ok(dist(s3.p, add(fr.point, mul(fr.normal, 0.5))) <= 1e-14 * 16);
      }
      a3.delete();
    }
    engine.clear();
    assert.strictEqual(engine.used3(), 0);
    for (const o of [engine, frames, frenet, path]) o.delete();
  });

  await t.test('3-D errors arrive as Error with grape\'s message', () => {
    const path = g.Path3.line(V(0, 0, 0), V(1, 0, 0));
    assert.throws(() => g.Path3.helix({ radius: -1 }), /Path3::helix: radius: must be finite and > 0, got -1/);
    assert.throws(() => g.Path3.catmullRom([0, 0, 0, 1, 1]), /x, y, z triples \(got 5 numbers\)/);
    assert.throws(() => g.Path3.catmullRom([0, 0, 0, 1, 1, 1], 'wobbly'), /uniform, centripetal or chordal/);
    assert.throws(() => path.slice(0.5, 0.5), Error);
    assert.throws(() => new g.Frames3(path, { mode: 'sideways' }), /'mode' must be rmf, ends, closed, reference_up or frenet/);
    assert.throws(() => new g.Frames3(path, { up: V(1, 0, 0) }), /up/);
    assert.throws(() => g.View3.perspective(V(1, 1, 1), V(1, 1, 1)), /View3::perspective/);
    assert.throws(() => g.View3.orbit(V(0, 0, 0), -1, 0, 0), /distance/);
    assert.throws(() => g.View3.oblique(0.5, 2), /recede is not in \(0, 1\]/);
    assert.throws(() => g.quatFromBasis(V(1, 0, 0), V(1, 0, 0), V(0, 0, 1)), /from_basis/);
    assert.throws(() => g.quatFromAxisAngle(V(0, 0, 0), 1), Error);
    assert.throws(() => g.unitQuat(0, 0, 0, 0), /unit_quat: all four components are zero/);
    assert.throws(() => new g.QuatSpline([0, 0], [{ w: 1, x: 0, y: 0, z: 0 }, { w: 1, x: 0, y: 0, z: 0 }]), /QuatSpline/);
    assert.throws(() => new g.RollTrack([0, 0, 1]), /s, roll pairs/);
    assert.throws(() => new g.RollTrack([1, 0, 0, 1]), /RollTrack/);
    assert.throws(() => g.bankTrack(path, { samples: 1 }), /'samples' must be an integer/);
    const engine = new g.Engine(0, 1);
    assert.throws(() => engine.add3(path, 1, { heading: true }), Error);
    assert.throws(() => engine.add3(path, 'soon'), /timing must be a duration in seconds or \{speed/);
    assert.throws(() => engine.add3(path, { speed: 0 }), Error);
    assert.throws(() => engine.add3(path, 1, {}, { align: 'sideways' }), /'align' must be none, frame or world/);
    assert.throws(() => engine.add3(path, 1, {}, { forward: '+w' }), /'forward' must be \+x/);
    const frames = new g.Frames3(path);
    assert.throws(() => engine.add3(path, { speed: 1 }, {}, { align: 'frame', sharedFrames: frames }),
      /shared_frames must frame the path played \(in speed mode: path.reparametrized\(\)\)/);
    frames.delete();
    engine.add3(path, 1);
    assert.throws(() => engine.add3(path, 1), /all 1 3-D slots are used/);
    assert.throws(() => engine.animation3(1), /no 3-D slot 1/);
    assert.throws(() => new g.Engine(1).add3(path, 1), /all 0 3-D slots/);
    engine.delete(); path.delete();
  });
});
