// The playground in a real browser: Debian's chromium driven by puppeteer-core.
//  - the page loads and every demo draws something, each different from the others;
//  - a scripted drag moves a Bézier control point and the marker follows the new shape;
//  - 10 simulated seconds of the parabola give the figures `grape simulate parabola` prints;
//  - the chain at 200 particles: the page's own frame-time counter, reported;
//  - the 3-D coaster draws its track, its car rides the engine's slot in the banked frame, and
//    dragging the view or choosing another frame mode changes the picture;
//  - a screenshot for the guide (docs/images/web-playground.png).
// Environment: CHROMIUM (default: chromium on PATH), GRAPE_TOOL (the native tool),
// GRAPE_WEB_SHOTS (folder for screenshots, default build-web/browser-check).
'use strict';
const test = require('node:test');
const assert = require('node:assert');
const { execFileSync, spawn } = require('child_process');
const fs = require('fs');
const net = require('net');
const path = require('path');
const puppeteer = require('puppeteer-core');

const root = path.resolve(__dirname, '..', '..');
const tool = process.env.GRAPE_TOOL || path.join(root, 'build', 'apps', 'grape', 'grape');
const shots = path.resolve(process.env.GRAPE_WEB_SHOTS || path.join(root, 'build-web', 'browser-check'));
const chromium = process.env.CHROMIUM || execFileSync('sh', ['-c', 'command -v chromium'], { encoding: 'utf8' }).trim();

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.listen(0, '127.0.0.1', () => { const { port } = server.address(); server.close(() => resolve(port)); });
    server.on('error', reject);
  });
}

async function serve() {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', path.join(root, 'web')],
    { stdio: 'ignore' });
  const url = `http://127.0.0.1:${port}/playground/`;
  for (let i = 0; i < 100; ++i) {
    try { const r = await fetch(url); if (r.ok) return { server, url }; } catch { /* not up yet */ }
    await new Promise((r) => setTimeout(r, 100));
  }
  server.kill();
  throw new Error(`python3 -m http.server did not start on port ${port}`);
}

test('the playground in chromium', { timeout: 180000 }, async (t) => {
  fs.mkdirSync(shots, { recursive: true });
  const { server, url } = await serve();
  const browser = await puppeteer.launch({ executablePath: chromium, headless: true, args: ['--no-sandbox'] });
  const errors = [];
  try {
    const page = await browser.newPage();
    page.on('pageerror', (e) => errors.push(e.message));
    await page.setViewport({ width: 960, height: 1000 });
    await page.goto(url);
    await page.waitForFunction('window.playground && window.playground.ready', { timeout: 30000 });
    await new Promise((r) => setTimeout(r, 1000));  // a second of real frames
    await page.evaluate(() => playground.stop());   // from here the test advances the demos itself

    await t.test('every demo draws, and each differently', async () => {
      const canvases = await page.evaluate(() => {
        const out = {};
        for (const [name, demo] of Object.entries(playground)) {
          if (!demo || !demo.canvas) continue;
          demo.frame(1 / 60);
          const c = demo.canvas;
          const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
          let inked = 0, hash = 2166136261;
          for (let i = 0; i < data.length; i += 4) {
            if (data[i + 3] > 0) ++inked;  // canvases start transparent: anything drawn has alpha
            hash = Math.imul(hash ^ data[i] ^ (data[i + 1] << 8) ^ (data[i + 2] << 16) ^ (data[i + 3] << 24), 16777619);
          }
          out[name] = { inked: inked / (c.width * c.height), hash: hash >>> 0 };
        }
        return out;
      });
      assert.deepStrictEqual(Object.keys(canvases).sort(), ['chain', 'coaster', 'keys', 'parabola', 'paths', 'sprites', 'svg']);
      // 0.2 %: the thinnest picture, a chain hanging at rest, covers about 0.5 % of its canvas.
      for (const [name, c] of Object.entries(canvases)) assert.ok(c.inked > 0.002, `${name} draws on ${(100 * c.inked).toFixed(2)} % of its canvas`);
      const hashes = new Set(Object.values(canvases).map((c) => c.hash));
      assert.strictEqual(hashes.size, 7, 'seven different pictures');
    });

    await t.test('dragging a control point moves the path and the marker follows', async () => {
      await page.evaluate(() => { playground.paths.select('cubic Bézier'); playground.paths.pause(0.7); });
      const before = await page.evaluate(() => playground.paths.state());
      // Canvas pixels to page pixels: inside the border, at the CSS scale.
      const box = await page.evaluate(() => {
        const c = document.getElementById('paths');
        const r = c.getBoundingClientRect();
        return { x: r.left + c.clientLeft + window.scrollX, y: r.top + c.clientTop + window.scrollY, s: c.clientWidth / c.width };
      });
      await page.evaluate((y) => window.scrollTo(0, y - 100), box.y);
      const scroll = await page.evaluate(() => window.scrollY);
      const handle = before.handles[1];
      const at = (x, y) => [box.x + x * box.s, box.y - scroll + y * box.s];
      await page.mouse.move(...at(handle.x, handle.y));
      await page.mouse.down();
      for (let k = 1; k <= 10; ++k) await page.mouse.move(...at(handle.x + 12 * k, handle.y + 20 * k));
      await page.mouse.up();
      const after = await page.evaluate(() => playground.paths.state());
      // The handle lands where the mouse let go (to a pixel of rounding in the event positions).
      assert.ok(Math.abs(after.handles[1].x - (handle.x + 120)) <= 1 && Math.abs(after.handles[1].y - (handle.y + 200)) <= 1,
        `handle at ${JSON.stringify(after.handles[1])}`);
      assert.notStrictEqual(after.length, before.length, 'the path changed');
      assert.ok(Math.abs(after.time - before.time) <= 1e-12, 'the animation kept its time');
      // The marker is on the new path at the animation's progress (the engine's own number).
      assert.ok(Math.hypot(after.marker.x - after.expected.x, after.marker.y - after.expected.y) <= 1e-9 * after.length,
        `marker ${JSON.stringify(after.marker)} vs the path's point ${JSON.stringify(after.expected)}`);
      assert.ok(Math.hypot(after.marker.x - before.marker.x, after.marker.y - before.marker.y) > 1, 'the marker moved with the path');
    });

    await t.test('the parabola after 10 simulated seconds matches grape simulate', async () => {
      const native = JSON.parse(execFileSync(tool, ['simulate', 'parabola', '--seconds', '10'], { encoding: 'utf8' }));
      const page10 = await page.evaluate(() => {
        playground.parabola.reset();
        playground.parabola.advance(600);
        return playground.parabola.summary();
      });
      assert.deepStrictEqual([native.method, native.integrator, native.stabilize], ['implicit', 'rk4', 'none']);
      // Fixed RK4 steps of arithmetic and sqrt: the same bits as the native build (web/test/native.test.js).
      assert.strictEqual(page10.t, native.seconds);
      assert.strictEqual(page10.maxResidual, native.max_residual);
      assert.strictEqual(page10.maxDistance, native.max_distance);
      assert.strictEqual(page10.figures.maxResidual, native.max_residual.toPrecision(8));
      assert.strictEqual(page10.figures.maxDistance, native.max_distance.toPrecision(8));
    });

    await t.test('sprites follow the rate slider; keys show the key state', async () => {
      const sprite = await page.evaluate(() => {
        const slider = document.getElementById('sprites-rate');
        slider.value = '-2';
        slider.dispatchEvent(new Event('input'));
        const a = playground.sprites.state().frame;
        for (let i = 0; i < 3; ++i) playground.sprites.frame();
        return { a, b: playground.sprites.state().frame, rate: playground.sprites.state().rate };
      });
      assert.strictEqual(sprite.rate, -2);
      assert.strictEqual(sprite.b, ((sprite.a - 6) % 16 + 16) % 16);
      await page.focus('#keys');
      await page.keyboard.down('KeyA');
      await page.keyboard.down('ShiftLeft');
      const held = await page.evaluate(() => { playground.keys.frame(); return playground.keys.state(); });
      assert.deepStrictEqual(held.down.sort(), ['KeyA', 'ShiftLeft']);
      await page.keyboard.up('KeyA');
      await page.keyboard.up('ShiftLeft');
      const released = await page.evaluate(() => playground.keys.state());
      assert.deepStrictEqual(released.down, []);
    });

    await t.test('chain of 200 particles: the page\'s frame-time counter', async () => {
      await page.evaluate(() => { playground.chain.reset(200, 'chain'); playground.start(); });
      await page.waitForFunction(() => playground.chain.frameMs().samples >= 60, { timeout: 60000 });
      const f = await page.evaluate(() => playground.chain.frameMs());
      console.log(`chain: ${f.particles} particles, ${f.substeps} RK4 substeps per frame, median frame ${f.median.toFixed(2)} ms (steps + drawing, 60 frames)`);
      assert.strictEqual(f.particles, 200);
      assert.ok(Number.isFinite(f.median) && f.median > 0);
      assert.ok(await page.evaluate(() => playground.chain.linkError()) < 1e-9, 'projection holds the links');
      await page.evaluate(() => playground.stop());
    });

    await t.test('the 3-D coaster: track drawn, car banked on the engine\'s slot, drag and frame mode change the picture', async () => {
      // A hash of the coaster's pixels, and whether each sampled track point has ink within 2 px.
      const picture = () => page.evaluate(() => {
        const c = playground.coaster.canvas;
        const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let hash = 2166136261;
        for (let i = 0; i < data.length; i += 4) hash = Math.imul(hash ^ data[i] ^ (data[i + 1] << 8) ^ (data[i + 2] << 16) ^ (data[i + 3] << 24), 16777619);
        const s = playground.coaster.state();
        const onTrack = s.track.map(([x, y]) => {
          let ink = false;
          for (let dy = -2; dy <= 2; ++dy) for (let dx = -2; dx <= 2; ++dx) {
            const px = Math.round(x) + dx, py = Math.round(y) + dy;
            if (px >= 0 && py >= 0 && px < c.width && py < c.height && data[4 * (py * c.width + px) + 3] > 0) ink = true;
          }
          return ink;
        });
        return { hash: hash >>> 0, onTrack, state: s };
      });
      await page.evaluate(() => { playground.coaster.select('banked'); playground.coaster.pause(3.1); });
      const before = await picture();
      // The track lies inside the picture and every sampled vertex of a rail is inked (the rail
      // is stroked 2.5 px wide through it: 2 px either side finds it).
      assert.ok(before.onTrack.length >= 20, `${before.onTrack.length} of 24 track points in view`);
      assert.ok(before.onTrack.every((x) => x), `track points without ink: ${before.onTrack.map((x, i) => x ? -1 : i).filter((i) => i >= 0)}`);
      const s = before.state;
      // The car is where the engine put it: the path at the animation's progress (the same
      // evaluation: to rounding), and its banked axes are the rolled frame's (a product of two
      // unit quaternions and a rotation: 1e-14).
      assert.ok(Math.hypot(s.position.x - s.expected.x, s.position.y - s.expected.y, s.position.z - s.expected.z) <= 1e-12, 'car on the path');
      assert.strictEqual(s.frameMode, 'reference_up');
      assert.ok(Math.abs(s.roll) > 0.05, `banked by ${s.roll} rad at u ${s.u}`);
      const axes = await page.evaluate(() => {
        const g = playground.grape, s = playground.coaster.state();
        return { n: g.quatRotate(s.orientation, { x: 0, y: 1, z: 0 }), t: g.quatRotate(s.orientation, { x: 1, y: 0, z: 0 }), f: s.rolledFrame };
      });
      const d = (a, b) => Math.hypot(a.x - b.x, a.y - b.y, a.z - b.z);
      assert.ok(d(axes.n, axes.f.normal) <= 1e-14 && d(axes.t, axes.f.tangent) <= 1e-14, 'banked orientation = rolled frame');
      // Drag the view: the azimuth follows the mouse (0.01 rad per canvas pixel) and the picture changes.
      const box = await page.evaluate(() => {
        const c = document.getElementById('coaster');
        c.scrollIntoView();
        const r = c.getBoundingClientRect();
        return { x: r.left + c.clientLeft, y: r.top + c.clientTop, s: c.clientWidth / c.width };
      });
      await page.mouse.move(box.x + 300 * box.s, box.y + 200 * box.s);
      await page.mouse.down();
      for (let k = 1; k <= 10; ++k) await page.mouse.move(box.x + (300 + 8 * k) * box.s, box.y + 200 * box.s);
      await page.mouse.up();
      const dragged = await picture();
      assert.ok(Math.abs(dragged.state.azimuth - (s.azimuth - 0.8)) <= 0.02, `azimuth ${s.azimuth} → ${dragged.state.azimuth}`);
      assert.notStrictEqual(dragged.hash, before.hash, 'dragging turned the picture');
      assert.ok(dragged.onTrack.filter((x) => x).length >= 20, 'the track is still drawn');
      // Another frame mode: the rails and the car turn, the car stays on the path.
      await page.select('#coaster-mode', 'rmf');
      await page.evaluate(() => playground.coaster.pause(3.1));
      const rmf = await picture();
      assert.strictEqual(rmf.state.frameMode, 'rmf');
      assert.strictEqual(rmf.state.roll, 0);
      assert.notStrictEqual(rmf.hash, dragged.hash, 'the frame mode changed the picture');
      assert.ok(Math.abs(rmf.state.u - s.u) <= 1e-12, 'the car kept its time');
      const nb = dragged.state.rolledFrame.normal, nr = rmf.state.rolledFrame.normal;
      assert.ok(d(nb, nr) > 0.05, 'the car\'s up changed with the mode');
      await page.evaluate(() => playground.coaster.select('banked'));
    });

    await t.test('screenshot for the guide', async () => {
      await page.evaluate(() => {
        playground.paths.select("the seed's complex path");
        playground.paths.pause(1.3);
        playground.parabola.reset();
        playground.parabola.advance(200);
        for (const d of ['svg', 'chain', 'sprites', 'keys']) playground[d].frame(1 / 60);
        window.scrollTo(0, 0);
      });
      const file = path.join(shots, 'web-playground.png');
      await page.screenshot({ path: file, clip: { x: 0, y: 0, width: 960, height: 1290 } });
      assert.ok(fs.statSync(file).size > 20000);
      console.log(`screenshot: ${file}`);
    });

    assert.deepStrictEqual(errors, [], 'no errors on the page');
  } finally {
    await browser.close();
    server.kill();
  }
});
