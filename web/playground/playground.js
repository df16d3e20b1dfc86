// The playground: the seed's demos on grape.wasm, drawn with the canvas 2-D API. No framework.
// window.playground exposes each demo's state and a few deterministic controls, so a browser
// test can drive the page (web/test/browser.test.js).
'use strict';

const FRAME = 1 / 60;  // every demo advances in steps of 1/60 s, so runs repeat exactly
const colour = { ink: '#222', path: '#2a6fdb', ghost: '#c0392b', grid: '#eee', cue: '#e67e22', handle: '#16a085', dim: '#999' };

function $(id) { return document.getElementById(id); }
function median(values) {
  if (values.length === 0) return NaN;
  const s = [...values].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}
function polyline(ctx, xy, map = (x, y) => [x, y]) {
  ctx.beginPath();
  for (let i = 0; i < xy.length; i += 2) {
    const [x, y] = map(xy[i], xy[i + 1]);
    if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
  }
  ctx.stroke();
}
// A pointer event's position in canvas pixels (inside the border, whatever the CSS scale).
function canvasPoint(canvas, e) {
  const r = canvas.getBoundingClientRect();
  return [(e.clientX - r.left - canvas.clientLeft) * canvas.width / canvas.clientWidth,
    (e.clientY - r.top - canvas.clientTop) * canvas.height / canvas.clientHeight];
}
function disc(ctx, x, y, r, fill) {
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.fillStyle = fill;
  ctx.fill();
}
// A plot of series (arrays of numbers) in a box, each autoscaled to its own range.
function plot(ctx, box, series, title) {
  ctx.save();
  ctx.strokeStyle = '#ccc';
  ctx.strokeRect(box.x, box.y, box.w, box.h);
  ctx.fillStyle = colour.ink;
  ctx.font = '12px sans-serif';
  ctx.fillText(title, box.x + 6, box.y + 14);
  let line = 0;
  for (const { values, stroke, label } of series) {
    if (values.length < 2) continue;
    let lo = Math.min(...values), hi = Math.max(...values);
    if (hi - lo < 1e-300) { lo -= 1; hi += 1; }
    ctx.strokeStyle = stroke;
    ctx.beginPath();
    values.forEach((v, i) => {
      const x = box.x + (i / (values.length - 1)) * box.w;
      const y = box.y + box.h - 4 - ((v - lo) / (hi - lo)) * (box.h - 24);
      if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
    });
    ctx.stroke();
    ctx.fillStyle = stroke;
    ctx.fillText(`${label}: ${values[values.length - 1].toPrecision(3)} (max ${hi.toPrecision(3)})`, box.x + 6, box.y + 30 + 14 * line++);
  }
  ctx.restore();
}

// ---- the parabola, both ways -----------------------------------------------------------------

function parabolaDemo(g) {
  const canvas = $('parabola');
  const ctx = canvas.getContext('2d');
  const integrators = ['euler', 'semi_implicit_euler', 'midpoint', 'rk4', 'velocity_verlet', 'rk45'];
  const select = $('parabola-integrator');
  for (const name of integrators) select.add(new Option(name, name, name === 'rk4', name === 'rk4'));
  let left, right, summary, history, hover = false;
  const options = () => ({
    method: $('parabola-method').value,
    integrator: select.value,
    stabilize: $('parabola-method').value === 'implicit' ? $('parabola-stabilize').value : 'none',
    forceX: Number($('parabola-force').value),
  });
  function reset() {
    if (left) { left.delete(); right.delete(); }
    const o = options();
    left = new g.ParabolaRun(o);
    right = new g.ParabolaRun({ ...o, method: 'parametric', stabilize: 'none' });
    const s = left.state();
    summary = { t: 0, maxResidual: 0, maxDistance: 0, beadDistance: 0, e0: s.energy, b0: right.state().energy };
    history = { distance: [], energy: [], beadEnergy: [] };
    $('parabola-force-value').textContent = o.forceX;
  }
  // One step of 1/60 s for both, with the same maxima `grape simulate parabola` reports.
  function step() {
    left.step(FRAME);
    right.step(FRAME);
    const a = left.state(), b = right.state();
    summary.t = a.t;
    summary.maxResidual = Math.max(summary.maxResidual, Math.abs(a.residual));
    summary.maxDistance = Math.max(summary.maxDistance, a.distance);
    summary.beadDistance = Math.max(summary.beadDistance, b.distance);
    history.distance.push(a.distance);
    history.energy.push((a.energy - summary.e0) / Math.abs(summary.e0));
    history.beadEnergy.push((b.energy - summary.b0) / Math.abs(summary.b0));
    for (const k in history) if (history[k].length > 600) history[k].shift();
  }
  function panel(x0, state, label, other) {
    // World x in [−220, 220], y in [−420, 20] (y down), into a 440 × 300 panel.
    const s = 0.68, ox = x0 + 220, oy = 12 + 420 * s;
    const map = (x, y) => [ox + x * s, oy + y * s];
    ctx.strokeStyle = colour.dim;
    ctx.beginPath();
    for (let x = -200; x <= 200; x += 4) { const [px, py] = map(x, -x * x / 100); if (x === -200) ctx.moveTo(px, py); else ctx.lineTo(px, py); }
    ctx.stroke();
    const [px, py] = map(state.x, state.y);
    disc(ctx, px, py, 7, other);
    ctx.fillStyle = colour.ink;
    ctx.font = '13px sans-serif';
    ctx.fillText(label, x0 + 10, 20);
    ctx.fillText(`x ${state.x.toFixed(2)}  y ${state.y.toFixed(2)}  |C| ${Math.abs(state.residual).toExponential(2)}`, x0 + 10, 36);
  }
  function draw() {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    panel(0, left.state(), $('parabola-method').value === 'seed' ? "the seed's closed-form force" : 'implicit: Witkin constraint force', colour.path);
    panel(450, right.state(), 'parametric: bead in its coordinate (Lagrange)', colour.ghost);
    plot(ctx, { x: 8, y: 310, w: 430, h: 122 }, [{ values: history.distance, stroke: colour.path, label: 'implicit drift |C|/|∇C| px' }], 'drift');
    plot(ctx, { x: 458, y: 310, w: 430, h: 122 }, [
      { values: history.energy, stroke: colour.path, label: 'implicit ΔE/E' },
      { values: history.beadEnergy, stroke: colour.ghost, label: 'parametric ΔE/E' }], 'energy');
    $('parabola-t').textContent = summary.t.toFixed(3);
    $('parabola-max-residual').textContent = summary.maxResidual.toPrecision(8);
    $('parabola-max-distance').textContent = summary.maxDistance.toPrecision(8);
    $('parabola-bead-distance').textContent = summary.beadDistance.toPrecision(3);
  }
  canvas.addEventListener('pointerenter', () => { hover = true; });
  canvas.addEventListener('pointerleave', () => { hover = false; });
  for (const id of ['parabola-method', 'parabola-integrator', 'parabola-stabilize', 'parabola-force']) $(id).addEventListener('input', reset);
  $('parabola-reset').addEventListener('click', reset);
  reset();
  let debt = 0;
  return {
    canvas,
    frame(dt) {
      if (hover || $('parabola-run').checked) {
        debt = Math.min(debt + dt, 0.25);  // real time, at most a quarter second behind
        while (debt >= FRAME) { step(); debt -= FRAME; }
      }
      draw();
    },
    reset,
    /** n steps of 1/60 s at once (a test's 10 simulated seconds), then a redraw. */
    advance(n) { for (let i = 0; i < n; ++i) step(); draw(); },
    summary: () => ({ ...summary, figures: { maxResidual: $('parabola-max-residual').textContent, maxDistance: $('parabola-max-distance').textContent } }),
    options,
  };
}

// ---- the path gallery ------------------------------------------------------------------------

function pathsDemo(g) {
  const canvas = $('paths');
  const ctx = canvas.getContext('2d');
  const P = (x, y) => ({ x, y });
  // Control points of the draggable kinds; the others are fixed shapes.
  const handles = {
    'quadratic Bézier': [P(120, 360), P(450, 20), P(780, 360)],
    'cubic Bézier': [P(80, 340), P(300, 40), P(600, 380), P(820, 80)],
    'linear spline': [P(80, 320), P(260, 100), P(450, 300), P(640, 90), P(820, 300)],
    'cosine spline': [P(80, 320), P(260, 100), P(450, 300), P(640, 90), P(820, 300)],
    'Catmull–Rom (centripetal)': [P(80, 320), P(260, 100), P(450, 300), P(640, 90), P(820, 300)],
  };
  const flat = (pts) => pts.flatMap((p) => [p.x, p.y]);
  const makers = {
    'cubic Bézier': (h) => g.Path.cubicBezier(h[0], h[1], h[2], h[3]),
    'quadratic Bézier': (h) => g.Path.quadraticBezier(h[0], h[1], h[2]),
    'linear spline': (h) => g.Path.linearSpline(flat(h)),
    'cosine spline': (h) => g.Path.cosineSpline(flat(h)),
    'Catmull–Rom (centripetal)': (h) => g.Path.catmullRom(flat(h), 'centripetal'),
    linear: () => g.Path.linear(P(100, 340), P(800, 80)),
    circle: () => g.Path.circle(P(450, 210), 170, 0, 2 * Math.PI),
    'elliptical arc': () => g.Path.ellipticalArc(P(450, 210), 330, 150, 0.2, 0.3, 5.6),
    spiral: () => g.Path.spiral(P(450, 210), 190, 0, 0, 4 * Math.PI),
    'sine wave': () => g.Path.sineWave(P(60, 210), P(840, 210), 3, 120),
    projectile: () => g.Path.physics(P(80, 390), P(360, -760), P(0, 800), 1.8),
    "the seed's complex path": () => {
      const parts = [g.Path.spiral(P(220, 210), 170, 0, 0, 2 * Math.PI), g.Path.linear(P(220, 210), P(500, 60)),
        g.Path.linear(P(500, 60), P(820, 360)), g.Path.linear(P(820, 360), P(560, 380))];
      const path = g.Path.complex(parts, [0, 0.25, 0.5, 0.6]);
      parts.forEach((p) => p.delete());
      return path;
    },
  };
  const select = $('paths-kind');
  for (const name of Object.keys(makers)) select.add(new Option(name, name, name === 'cubic Bézier', name === 'cubic Bézier'));
  for (const name of g.curveNames()) $('curve-names').append(new Option(name));
  for (const name of ['back-out(2.5)', 'elastic-out(1,0.3)', 'cubic-bezier(0.3,0,0.2,1)', 'steps(6,jump-end)']) $('curve-names').append(new Option(name));

  const engine = new g.Engine(2);  // slot 0: the marker, slot 1: the ghost in the other parametrization
  let path = null, even = null, polylineXY = null, ticks = null, curve = 'quad-in-out', drag = -1;
  function build(keepTime) {
    const time = keepTime && engine.used() > 0 ? (() => { const a = engine.animation(0); const t = a.time(); a.delete(); return t; })() : 0;
    let next;
    try {
      next = makers[select.value](handles[select.value]);
      g.parseCurve($('paths-curve').value).delete();  // a bad name reports here, before anything changes
      curve = $('paths-curve').value;
      $('paths-error').textContent = '';
    } catch (e) {
      $('paths-error').textContent = e.message;
      if (next) next.delete();
      if (path) return;
      next = makers.linear();
      curve = 'linear';
    }
    if (path) { path.delete(); even.delete(); }
    path = next;
    even = path.reparametrized();
    polylineXY = path.flatten(0.25);
    ticks = path.sample(Float64Array.from({ length: 21 }, (_, i) => i / 20));
    engine.clear();
    const arc = $('paths-arc').checked;
    const o = { curve, repeat: $('paths-loop').checked ? -1 : 0, reversed: $('paths-reverse').checked, yoyo: $('paths-yoyo').checked };
    const duration = Math.max(0.1, Number($('paths-duration').value) || 2);
    engine.add(arc ? even : path, duration, o);
    engine.add(arc ? path : even, duration, o);
    for (const k of [0, 1]) { const a = engine.animation(k); a.seek(time); a.delete(); }
  }
  function draw() {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.lineWidth = 2;
    ctx.strokeStyle = colour.path;
    polyline(ctx, polylineXY);
    ctx.lineWidth = 1;
    for (let i = 0; i < ticks.length; i += 2) disc(ctx, ticks[i], ticks[i + 1], 2, colour.cue);
    const h = handles[select.value];
    if (h) {
      ctx.strokeStyle = '#bbb';
      polyline(ctx, flat(h));
      for (const p of h) disc(ctx, p.x, p.y, 6, colour.handle);
    }
    const xy = engine.positions();
    disc(ctx, xy[2], xy[3], 6, 'rgba(192,57,43,0.45)');
    disc(ctx, xy[0], xy[1], 8, colour.ink);
    const a = engine.animation(0);
    $('paths-info').textContent = `${path.kind()} · length ${path.length().toFixed(3)} px · progress ${a.progress().toFixed(4)} · play ${a.repetition()} · ` +
      `black: ${$('paths-arc').checked ? 'arc length' : 'path u'}, red: the other`;
    a.delete();
  }
  const at = (e) => { const [x, y] = canvasPoint(canvas, e); return P(x, y); };
  canvas.addEventListener('pointerdown', (e) => {
    const h = handles[select.value];
    if (!h) return;
    const m = at(e);
    drag = h.findIndex((p) => Math.hypot(p.x - m.x, p.y - m.y) <= 12);
    if (drag >= 0) canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (drag < 0) return;
    handles[select.value][drag] = at(e);
    build(true);  // the animation follows the new shape at the same time
  });
  canvas.addEventListener('pointerup', () => { drag = -1; });
  for (const id of ['paths-kind', 'paths-duration', 'paths-loop', 'paths-reverse', 'paths-yoyo', 'paths-arc']) $(id).addEventListener('input', () => build(false));
  $('paths-curve').addEventListener('change', () => build(false));
  build(false);
  return {
    canvas,
    frame(dt) { engine.tick(dt); draw(); },
    select(kind) { select.value = kind; build(false); draw(); },
    /** The marker, and the current path's point at the marker's progress (equal when it follows). */
    state() {
      const a = engine.animation(0);
      const u = a.progress();
      const source = $('paths-arc').checked ? even : path;
      const xy = engine.positions();
      const s = { kind: select.value, handles: (handles[select.value] || []).map((p) => ({ ...p })), marker: { x: xy[0], y: xy[1] }, expected: source.point(u), progress: u, time: a.time(), length: path.length() };
      a.delete();
      return s;
    },
    pause(seconds) { for (const k of [0, 1]) { const a = engine.animation(k); a.seek(seconds); a.pause(); a.delete(); } draw(); },
  };
}

// ---- SVG path data ---------------------------------------------------------------------------

function svgDemo(g) {
  const canvas = $('svg');
  const ctx = canvas.getContext('2d');
  const engine = new g.Engine(1);
  let path = null, xy = null, starts = [];
  function build() {
    let next;
    try {
      next = g.parseSvgPath($('svg-data').value);
      $('svg-error').textContent = '';
    } catch (e) {
      $('svg-error').textContent = e.message;
      return;
    }
    if (path) path.delete();
    path = next;
    xy = path.flatten(0.25);
    const cues = path.cues();
    starts = Array.from(cues, (u) => path.point(u));
    engine.clear();
    const even = path.reparametrized();
    engine.add(even, Math.max(1, path.length() / 250), { repeat: -1, curve: 'sine-in-out', yoyo: true });
    even.delete();
    $('svg-info').textContent = `${path.partCount()} parts · length ${path.length().toFixed(3)} px · constant speed (reparametrized)`;
  }
  $('svg-data').addEventListener('input', build);
  build();
  return {
    canvas,
    frame(dt) {
      engine.tick(dt);
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.lineWidth = 2;
      ctx.strokeStyle = colour.path;
      polyline(ctx, xy);
      for (const p of starts) disc(ctx, p.x, p.y, 3.5, colour.cue);
      const m = engine.positions();
      disc(ctx, m[0], m[1], 7, colour.ink);
    },
    set(data) { $('svg-data').value = data; build(); },
    error: () => $('svg-error').textContent,
  };
}

// ---- chain and cloth -------------------------------------------------------------------------

function chainDemo(g) {
  const canvas = $('chain');
  const ctx = canvas.getContext('2d');
  const gravity = 9.81, width = 4.0, release = 0.5, grabOmega = 25;  // m/s², m, rad from the vertical, rad/s
  let system, kind, n, columns, rows, substeps, grabbed = -1, mouse = { x: 0, y: 0 };
  const frameMs = [];
  // Explicit integrators need ω·h ≤ 0.7 for the chain's fastest transverse mode,
  // ω ≈ 2·√(3·n·g/length)·√n (tension up to 3 chain weights; as grape studio's chain tab).
  const substepsFor = (links, length) => Math.min(64, Math.max(1, Math.ceil(2 * Math.sqrt(3) * links * Math.sqrt(gravity / length) * FRAME / 0.7)));
  function reset() {
    if (system) system.delete();
    kind = $('chain-kind').value;
    n = Math.max(2, Math.min(400, Math.round(Number($('chain-count').value)) || 200));
    system = new g.ParticleSystem({ integrator: 'rk4', drift: 'projection' });
    if (kind === 'chain') {
      const link = width / (n - 1);
      for (let k = 0; k < n; ++k)
        system.addParticle({ x: k * link * Math.sin(release), y: k * link * Math.cos(release) }, { x: 0, y: 0 }, k === 0 ? Infinity : 1);
      for (let k = 1; k < n; ++k) system.addDistance(k - 1, k, link);
      substeps = substepsFor(n, width);
    } else {
      columns = Math.max(2, Math.round(Math.sqrt(n)));
      rows = Math.max(2, Math.ceil(n / columns));
      const spacing = 3 / (rows - 1), x0 = -0.5 * spacing * (columns - 1);
      for (let r = 0; r < rows; ++r)
        for (let c = 0; c < columns; ++c)
          system.addParticle({ x: x0 + (c + r * Math.sin(release)) * spacing, y: r * Math.cos(release) * spacing }, { x: 0, y: 0 }, r === 0 ? Infinity : 1);
      for (let r = 0; r < rows; ++r)
        for (let c = 0; c < columns; ++c) {
          const i = r * columns + c;
          if (c + 1 < columns && r > 0) system.addDistance(i, i + 1, spacing);
          if (r + 1 < rows) system.addDistance(i, i + columns, spacing);
        }
      substeps = substepsFor(rows, 3);
    }
    system.addGravity({ x: 0, y: gravity });
    system.addDrag(0.5);
    grabbed = -1;
    frameMs.length = 0;
  }
  // World [−4.3, 4.3] × [−0.4, 4.5] (y down) to the canvas.
  const scale = canvas.height / 4.9, ox = canvas.width / 2, oy = 0.4 * scale;
  const toScreen = (x, y) => [ox + x * scale, oy + y * scale];
  function step() {
    const h = FRAME / substeps;
    const count = system.size();
    for (let i = 0; i < substeps; ++i) {
      if (grabbed >= 0) {
        // A critically damped spring to the mouse, as stiff as the chain is heavy, capped at its weight.
        const x = system.position(grabbed), v = system.velocity(grabbed);
        const omega = Math.min(grabOmega * Math.sqrt(count), 0.3 / h);
        let fx = (mouse.x - x.x) * omega * omega - v.x * 2 * omega, fy = (mouse.y - x.y) * omega * omega - v.y * 2 * omega;
        const f = Math.hypot(fx, fy), cap = count * gravity;
        if (f > cap) { fx *= cap / f; fy *= cap / f; }
        system.exertForce(grabbed, { x: fx, y: fy });
      }
      system.steps(h, 1);
    }
  }
  function draw() {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const xy = system.positions(), w = system.inverseMasses();
    ctx.strokeStyle = colour.path;
    ctx.lineWidth = 1.5;
    if (kind === 'chain') polyline(ctx, xy, toScreen);
    else {
      ctx.beginPath();
      for (let r = 0; r < rows; ++r)
        for (let c = 0; c < columns; ++c) {
          const i = r * columns + c;
          const [x, y] = toScreen(xy[2 * i], xy[2 * i + 1]);
          if (c + 1 < columns && r > 0) { const [x2, y2] = toScreen(xy[2 * i + 2], xy[2 * i + 3]); ctx.moveTo(x, y); ctx.lineTo(x2, y2); }
          if (r + 1 < rows) { const j = i + columns; const [x2, y2] = toScreen(xy[2 * j], xy[2 * j + 1]); ctx.moveTo(x, y); ctx.lineTo(x2, y2); }
        }
      ctx.stroke();
    }
    const radius = Math.max(2, Math.min(6, 0.4 * scale * width / n));
    for (let i = 0; i < xy.length; i += 2) {
      const [x, y] = toScreen(xy[i], xy[i + 1]);
      disc(ctx, x, y, w[i / 2] === 0 ? radius + 2 : radius, i / 2 === grabbed ? colour.ghost : w[i / 2] === 0 ? colour.ink : colour.path);
    }
  }
  const at = (e) => canvasPoint(canvas, e);
  canvas.addEventListener('pointerdown', (e) => {
    const [sx, sy] = at(e);
    const xy = system.positions(), w = system.inverseMasses();
    let best = 15;
    grabbed = -1;
    for (let i = 0; i < xy.length; i += 2) {
      const [x, y] = toScreen(xy[i], xy[i + 1]);
      const d = Math.hypot(x - sx, y - sy);
      if (d < best && w[i / 2] > 0) { best = d; grabbed = i / 2; }
    }
    if (grabbed >= 0) { mouse = { x: (sx - ox) / scale, y: (sy - oy) / scale }; canvas.setPointerCapture(e.pointerId); }
  });
  canvas.addEventListener('pointermove', (e) => { const [sx, sy] = at(e); mouse = { x: (sx - ox) / scale, y: (sy - oy) / scale }; });
  canvas.addEventListener('pointerup', () => { grabbed = -1; });
  $('chain-reset').addEventListener('click', reset);
  $('chain-kind').addEventListener('input', reset);
  $('chain-count').addEventListener('change', reset);
  reset();
  return {
    canvas,
    frame() {
      const start = performance.now();
      step();
      draw();
      frameMs.push(performance.now() - start);
      if (frameMs.length > 60) frameMs.shift();
      $('chain-frame-ms').textContent = median(frameMs).toFixed(2);
      $('chain-substeps').textContent = substeps;
      $('chain-link-error').textContent = system.maxResidual().distance.toExponential(2);
    },
    reset(count, scene = 'chain') { $('chain-count').value = count; $('chain-kind').value = scene; reset(); },
    /** The page's own counter: median ms per frame (steps + drawing) over the last 60 frames. */
    frameMs: () => ({ median: median(frameMs), samples: frameMs.length, substeps, particles: system.size() }),
    linkError: () => system.maxResidual().distance,
  };
}

// ---- sprites ---------------------------------------------------------------------------------

function spritesDemo(g) {
  const canvas = $('sprites');
  const ctx = canvas.getContext('2d');
  const frames = 16, size = 48;
  const sheet = new g.TileSheet({ width: frames * size, height: size, columns: frames, rows: 1 });
  // The sheet, drawn once: a wheel whose spoke turns a sixteenth per frame, numbered.
  const image = document.createElement('canvas');
  image.width = sheet.width();
  image.height = sheet.height();
  const ic = image.getContext('2d');
  for (let k = 0; k < frames; ++k) {
    const r = sheet.frame(k), cx = r.x + r.width / 2, cy = r.y + r.height / 2;
    ic.fillStyle = `hsl(${(k * 360) / frames}, 60%, 85%)`;
    ic.fillRect(r.x + 1, r.y + 1, r.width - 2, r.height - 2);
    ic.strokeStyle = colour.ink;
    ic.lineWidth = 2;
    ic.beginPath(); ic.arc(cx, cy, 18, 0, 2 * Math.PI); ic.stroke();
    const a = (2 * Math.PI * k) / frames;
    ic.beginPath(); ic.moveTo(cx, cy); ic.lineTo(cx + 18 * Math.cos(a), cy + 18 * Math.sin(a)); ic.stroke();
    ic.fillStyle = colour.ink; ic.font = '10px sans-serif'; ic.fillText(String(k), r.x + 3, r.y + 11);
  }
  const player = new g.SpritePlayer(frames, { rate: 0.5 });
  $('sprites-rate').addEventListener('input', () => { player.setRate(Number($('sprites-rate').value)); $('sprites-rate-value').textContent = $('sprites-rate').value; });
  $('sprites-mode').addEventListener('input', () => { player.setMode($('sprites-mode').value); player.play(); });
  return {
    canvas,
    frame() {
      player.advance();  // one step per game frame
      const k = player.frame(), r = sheet.frame(k);
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.drawImage(image, 10, 10, image.width * 1.15, image.height * 1.15);
      ctx.strokeStyle = colour.ghost; ctx.lineWidth = 3;
      ctx.strokeRect(10 + r.x * 1.15, 10, r.width * 1.15, r.height * 1.15);
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(image, r.x, r.y, r.width, r.height, 20, 80, 160, 160);
      ctx.fillStyle = colour.ink; ctx.font = '14px sans-serif';
      ctx.fillText(`frame ${k}   rate ${player.rate()}   remainder ${player.remainder().toFixed(3)}   ${player.mode()}${player.playing() ? '' : ' (finished)'}`, 200, 120);
      ctx.fillText('frame = start + trunc(rate · steps), wrapped: the remainder carries the fraction', 200, 150);
    },
    state: () => ({ frame: player.frame(), rate: player.rate() }),
  };
}

// ---- key state -------------------------------------------------------------------------------

function keysDemo(g) {
  const canvas = $('keys');
  const ctx = canvas.getContext('2d');
  const layout = [
    ['Digit1', 'Digit2', 'Digit3', 'Digit4', 'Digit5', 'Digit6', 'Digit7', 'Digit8', 'Digit9', 'Digit0'],
    ['KeyQ', 'KeyW', 'KeyE', 'KeyR', 'KeyT', 'KeyY', 'KeyU', 'KeyI', 'KeyO', 'KeyP'],
    ['KeyA', 'KeyS', 'KeyD', 'KeyF', 'KeyG', 'KeyH', 'KeyJ', 'KeyK', 'KeyL'],
    ['ShiftLeft', 'KeyZ', 'KeyX', 'KeyC', 'KeyV', 'KeyB', 'KeyN', 'KeyM', 'ArrowUp'],
    ['ControlLeft', 'AltLeft', 'Space', 'ArrowLeft', 'ArrowDown', 'ArrowRight'],
  ];
  const codes = layout.flat();
  const index = new Map(codes.map((c, i) => [c, i]));
  const keys = new g.KeyState(512);
  const save = keys.mask([index.get('ControlLeft'), index.get('KeyS')]);
  let saved = 0, events = 0;
  const flashes = new Map();  // key → frames left of its edge flash
  window.addEventListener('keydown', (e) => {
    const k = index.get(e.code);
    if (k === undefined) return;
    if (e.ctrlKey && e.code === 'KeyS') e.preventDefault();
    if (!e.repeat) { keys.press(k); ++events; }
  });
  window.addEventListener('keyup', (e) => { const k = index.get(e.code); if (k !== undefined) { keys.release(k); ++events; } });
  window.addEventListener('blur', () => keys.releaseAll());
  return {
    canvas,
    frame() {
      if (keys.allDown(save) && keys.pressedThisFrame(index.get('KeyS'))) saved = 60;
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.font = '11px sans-serif';
      layout.forEach((row, r) => row.forEach((code, c) => {
        const k = index.get(code), wide = code.length > 6 && !code.startsWith('Digit') && !code.startsWith('Key') ? 1.6 : 1;
        const x = 12 + c * 62 + r * 14, y = 12 + r * 44;
        if (keys.pressedThisFrame(k)) flashes.set(k, ['#2ecc71', 12]);
        if (keys.releasedThisFrame(k)) flashes.set(k, ['#e74c3c', 12]);
        ctx.fillStyle = keys.isDown(k) ? colour.path : '#f2f2f2';
        ctx.fillRect(x, y, 56 * wide, 38);
        const flash = flashes.get(k);
        if (flash) { ctx.strokeStyle = flash[0]; ctx.lineWidth = 3; ctx.strokeRect(x, y, 56 * wide, 38); if (--flash[1] <= 0) flashes.delete(k); }
        ctx.fillStyle = keys.isDown(k) ? '#fff' : colour.ink;
        ctx.fillText(code.replace(/^(Key|Digit)/, ''), x + 5, y + 23);
      }));
      const down = keys.down();
      ctx.fillStyle = colour.ink;
      ctx.font = '13px sans-serif';
      ctx.fillText(`down: ${down.count()} key(s) ${down.setBits().map((k) => codes[k]).join(' ')}`, 620, 30);
      ctx.fillText(`Ctrl+S (allDown + pressedThisFrame): ${saved > 0 ? 'save!' : '–'}`, 620, 52);
      down.delete();
      if (saved > 0) --saved;
      keys.endFrame();
    },
    state: () => { const d = keys.down(); const s = { down: d.setBits().map((k) => codes[k]), events }; d.delete(); return s; },
  };
}

// ---- 3-D: a banked coaster -------------------------------------------------------------------

function coasterDemo(g) {
  const canvas = $('coaster');
  const ctx = canvas.getContext('2d');
  const V = (x, y, z) => ({ x, y, z });
  const speed = 14, gauge = 0.9;  // m/s along the track, half the distance between the rails (m)
  // A closed track (z up, metres): a straight, a vertical loop that drifts sideways by 3 m so
  // that it clears itself, a climbing turn and a descent back to the start.
  const knots = [[-24, -10, 2], [-8, -10, 2]];
  for (let k = 0; k <= 8; ++k) {
    const phi = (k * Math.PI) / 4;  // round the loop, 7 m in radius, centre 9 m up
    knots.push([4 + 7 * Math.sin(phi), -10 + (3 * k) / 8, 9 - 7 * Math.cos(phi)]);
  }
  knots.push([18, -7, 2], [30, -2, 5], [32, 8, 9], [20, 14, 10], [0, 13, 7], [-16, 10, 4], [-30, 2, 2]);
  const track = g.Path3.catmullRom(knots.flat(), 'centripetal', true);
  const even = track.reparametrized();  // u proportional to arc length: the engine plays it as it is
  const length = even.length();
  const center = (() => { const b = even.bounds(); return V((b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, b.min.z + 4); })();  // aimed low: most of the track is near the ground
  const railUs = Float64Array.from({ length: 721 }, (_, i) => i / 720);
  const tieUs = Float64Array.from({ length: Math.round(length / 1.5) }, (_, i) => i / Math.round(length / 1.5));
  const engine = new g.Engine(0, 1);
  const select = $('coaster-mode');
  let frames = null, roll = null, rolled = null, rails = null, ties = null;
  let azimuth = -1.25, elevation = 0.38, view = null, drag = null, time = 0;
  const modes = { banked: 'reference_up', reference_up: 'reference_up', rmf: 'rmf', closed: 'closed', frenet: 'frenet' };
  function orbit() {
    if (view) view.delete();
    view = g.View3.orbit(center, 52, azimuth, elevation, 0.75);
  }
  function build() {
    for (const o of [frames, roll, rolled]) if (o) o.delete();
    frames = new g.Frames3(even, { mode: modes[select.value] });
    // Banked: the roll a rider at `speed` leans by in each turn (atan v²κ/g, up to 60°),
    // averaged over 6 m so that it eases in and out; the other modes are the frames as they are.
    roll = select.value === 'banked' ? g.bankTrack(even, { speed, maxAngle: Math.PI / 3, smoothing: 6 }) : new g.RollTrack([0, 0]);
    rolled = new g.RolledFrames3(frames, roll);
    // Rails: the track's centre line ± gauge along the banked binormal; ties across every 1.5 m.
    const side = (f, us, s) => { const xyz = new Float64Array(3 * us.length); for (let i = 0; i < us.length; ++i) for (let c = 0; c < 3; ++c) xyz[3 * i + c] = f[12 * i + c] + s * f[12 * i + 9 + c]; return xyz; };
    const railFrames = rolled.sample(railUs), tieFrames = rolled.sample(tieUs);
    rails = [side(railFrames, railUs, gauge), side(railFrames, railUs, -gauge)];
    ties = [side(tieFrames, tieUs, gauge), side(tieFrames, tieUs, -gauge)];
    const keep = engine.used3() > 0 ? (() => { const a = engine.animation3(0); const t = a.time(); a.delete(); return t; })() : time;
    engine.clear();
    // The car: constant speed, its orientation the frame's (+x forward, +y up); the bank is
    // added below as a turn about the forward axis.
    engine.add3(even, { speed }, { repeat: -1 }, { align: 'frame', sharedFrames: frames, forward: '+x', up: '+y' });
    const a = engine.animation3(0); a.seek(keep); a.delete();
  }
  // Picture coordinates (half height 1) to canvas pixels.
  const scale = canvas.height * 0.5, cx = canvas.width / 2, cy = canvas.height / 2;
  const toCanvas = (x, y) => [cx + x * scale, cy + y * scale];
  function strokeProjected(xyz) {
    const p = view.projectMany(xyz);
    ctx.beginPath();
    let pen = false;
    for (let i = 0; i < p.length; i += 3) {
      if (Number.isNaN(p[i])) { pen = false; continue; }
      const [x, y] = toCanvas(p[i], p[i + 1]);
      if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      pen = true;
    }
    ctx.stroke();
  }
  // The car in its banked frame: slot orientation (the frame) times the roll about +x.
  function car() {
    const xyz = engine.positions3();
    const a = engine.animation3(0);
    const u = a.progress();
    a.delete();
    const frame = { w: xyz[3], x: xyz[4], y: xyz[5], z: xyz[6] };
    const banked = g.quatMultiply(frame, g.quatFromAxisAngle(V(1, 0, 0), rolled.roll(u)));
    return { u, position: V(xyz[0], xyz[1], xyz[2]), orientation: banked, roll: rolled.roll(u) };
  }
  function draw() {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    // The ground: a grid on z = 0.
    ctx.lineWidth = 1;
    ctx.strokeStyle = '#ddd';
    for (let k = -40; k <= 40; k += 8) {
      strokeProjected([k, -24, 0, k, 24, 0]);
      if (Math.abs(k) <= 24) strokeProjected([-40, k, 0, 40, k, 0]);
    }
    // Supports from the centre line down to the ground every few ties.
    ctx.strokeStyle = '#ccc';
    const centre = even.sample(tieUs);
    for (let i = 0; i < centre.length; i += 3 * 6) strokeProjected([centre[i], centre[i + 1], centre[i + 2], centre[i], centre[i + 1], 0]);
    ctx.strokeStyle = '#b5651d';
    ctx.lineWidth = 1.5;
    const [a, b] = [view.projectMany(ties[0]), view.projectMany(ties[1])];
    ctx.beginPath();
    for (let i = 0; i < a.length; i += 3) {
      if (Number.isNaN(a[i]) || Number.isNaN(b[i])) continue;
      ctx.moveTo(...toCanvas(a[i], a[i + 1]));
      ctx.lineTo(...toCanvas(b[i], b[i + 1]));
    }
    ctx.stroke();
    ctx.lineWidth = 2.5;
    ctx.strokeStyle = colour.path;
    for (const r of rails) strokeProjected(r);
    // The car: a box 3 m long, 1.6 m wide, 1 m tall in its banked frame, and its up as a mast.
    const c = car();
    const T = g.quatRotate(c.orientation, V(1, 0, 0)), N = g.quatRotate(c.orientation, V(0, 1, 0)), B = g.quatRotate(c.orientation, V(0, 0, 1));
    const at = (f, n, s) => V(c.position.x + f * T.x + n * N.x + s * B.x, c.position.y + f * T.y + n * N.y + s * B.y, c.position.z + f * T.z + n * N.z + s * B.z);
    const box = [at(-1.5, 0.2, -0.8), at(1.5, 0.2, -0.8), at(1.5, 0.2, 0.8), at(-1.5, 0.2, 0.8),
      at(-1.5, 1.2, -0.8), at(1.5, 1.2, -0.8), at(1.5, 1.2, 0.8), at(-1.5, 1.2, 0.8)];
    const pts = view.projectMany(box.flatMap((p) => [p.x, p.y, p.z]));
    const corner = (k) => toCanvas(pts[3 * k], pts[3 * k + 1]);
    ctx.fillStyle = 'rgba(192,57,43,0.85)';
    ctx.strokeStyle = colour.ink;
    ctx.lineWidth = 1;
    for (const face of [[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 5, 4], [3, 2, 6, 7], [1, 2, 6, 5]]) {
      if (face.some((k) => Number.isNaN(pts[3 * k]))) continue;
      ctx.beginPath();
      face.forEach((k, i) => { const [x, y] = corner(k); if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y); });
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
    }
    ctx.strokeStyle = colour.handle;
    ctx.lineWidth = 2;
    const top = at(0, 4, 0);
    strokeProjected([c.position.x, c.position.y, c.position.z, top.x, top.y, top.z]);
    ctx.fillStyle = colour.ink;
    ctx.font = '13px sans-serif';
    ctx.fillText('drag to turn the view', 10, 18);
    $('coaster-info').textContent = `track ${length.toFixed(2)} m · ${speed} m/s · u ${c.u.toFixed(4)} · roll ${(c.roll * 180 / Math.PI).toFixed(1)}° · ` +
      `frame ${frames.mode()}${frames.mode() === 'reference_up' ? ` (${frames.coneCount()} vertical stretches)` : ''} · view azimuth ${azimuth.toFixed(2)}, elevation ${elevation.toFixed(2)}`;
  }
  canvas.addEventListener('pointerdown', (e) => { drag = canvasPoint(canvas, e); canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const [x, y] = canvasPoint(canvas, e);
    azimuth -= (x - drag[0]) * 0.01;
    elevation = Math.max(-0.3, Math.min(1.4, elevation + (y - drag[1]) * 0.01));
    drag = [x, y];
    orbit();
    draw();
  });
  canvas.addEventListener('pointerup', () => { drag = null; });
  select.addEventListener('input', () => { build(); draw(); });
  orbit();
  build();
  return {
    canvas,
    frame(dt) { engine.tick(dt); const a = engine.animation3(0); time = a.time(); a.delete(); draw(); },
    select(mode) { select.value = mode; build(); draw(); },
    pause(seconds) { const a = engine.animation3(0); a.seek(seconds); a.pause(); a.delete(); draw(); },
    /** The car (engine slot, banked), the path and rolled frame at its progress, and where
     *  24 vertices of a rail, evenly spaced along the track, land on the canvas. */
    state() {
      const c = car();
      const f = rolled.frame(c.u);
      const projected = view.projectMany(Float64Array.from({ length: 72 }, (_, k) => rails[0][3 * 30 * Math.floor(k / 3) + (k % 3)]));
      const track = [];
      for (let i = 0; i < projected.length; i += 3) if (!Number.isNaN(projected[i])) track.push(toCanvas(projected[i], projected[i + 1]));
      return { mode: select.value, frameMode: frames.mode(), azimuth, elevation, u: c.u, position: c.position, expected: even.point(c.u),
        orientation: c.orientation, roll: c.roll, rolledFrame: f, track };
    },
  };
}

// ---- start -----------------------------------------------------------------------------------

createGrape().then((g) => {
  const demos = { parabola: parabolaDemo(g), paths: pathsDemo(g), svg: svgDemo(g), chain: chainDemo(g), sprites: spritesDemo(g), keys: keysDemo(g), coaster: coasterDemo(g) };
  let last = performance.now();
  let running = true;
  function loop(now) {
    const dt = Math.max(0, Math.min(0.1, (now - last) / 1000));  // the first frame may predate `last`
    last = now;
    if (running) for (const d of Object.values(demos)) d.frame(dt);
    requestAnimationFrame(loop);
  }
  for (const d of Object.values(demos)) d.frame(0);
  requestAnimationFrame(loop);
  $('status').textContent = 'ready';
  window.playground = {
    ...demos, grape: g, ready: true,
    /** Stops the animation loop (a test then advances demos itself); start() resumes it. */
    stop() { running = false; }, start() { running = true; last = performance.now(); },
  };
}).catch((e) => { $('status').textContent = `failed to load grape.wasm: ${e}`; throw e; });
