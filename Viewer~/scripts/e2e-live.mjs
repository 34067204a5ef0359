// Browser test of live mode: `fulcrum run tower-20 --live` streams a run in real time and
// Debian's Chromium (playwright-core) watches it: the frame counter advances as frames
// arrive, the view follows the newest frame and draws the tower, scrubbing back stops the
// following and going to the last frame resumes it. Fails loudly (exit 1) on any problem.
//
// Environment: as scripts/e2e.mjs (FULCRUM, CHROMIUM, OUT) and SCENES, the folder of the
// scene files (default ../Samples~/Scenes).
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { chromium } from 'playwright-core';

const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';
const fulcrum = (process.env.FULCRUM ?? 'dotnet ../.artifacts/bin/Fulcrum.Runner/release/fulcrum.dll').split(' ');
const scenes = resolve(process.env.SCENES ?? '../Samples~/Scenes');
const out = resolve(process.env.OUT ?? 'test-output');
mkdirSync(out, { recursive: true });

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures++;
}

if (!existsSync(chromiumPath)) {
  console.error(`FAIL: no browser at ${chromiumPath} (apt-get install -y chromium)`);
  process.exit(1);
}

// `fulcrum run --live` on a port; resolves with the page URL it prints before the run starts.
// 3600 steps at real time (60 s) outlast the test; it is stopped at the end.
function runLive(port) {
  const args = ['run', resolve(scenes, 'tower-20.json'), '--steps', '3600', '--live', '--port', String(port)];
  const child = spawn(fulcrum[0], [...fulcrum.slice(1), ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolveUrl, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error(`fulcrum run --live printed no URL in 30 s:\n${text}`)), 30000);
    const onData = chunk => {
      text += chunk;
      const m = /live: (http:\/\/\S+)/.exec(text);
      if (m) { clearTimeout(timer); resolveUrl({ url: m[1], child }); }
    };
    child.stdout.on('data', onData);
    child.stderr.on('data', onData);
    child.on('exit', code => { clearTimeout(timer); reject(new Error(`fulcrum run --live exited ${code}:\n${text}`)); });
  });
}

// The pixel (RGB 0-255) at a page point of a real screenshot, decoded by the browser (as in e2e.mjs).
async function pixelAt(page, x, y) {
  await page.evaluate(() => window.fulcrumViewer.render());
  const png = (await page.screenshot()).toString('base64');
  return page.evaluate(async ([png, x, y]) => {
    const image = new Image();
    image.src = 'data:image/png;base64,' + png;
    await image.decode();
    const copy = document.createElement('canvas');
    copy.width = image.width; copy.height = image.height;
    const g = copy.getContext('2d');
    g.drawImage(image, 0, 0);
    const scale = image.width / window.innerWidth;
    return Array.from(g.getImageData(Math.round(x * scale), Math.round(y * scale), 1, 1).data.slice(0, 3));
  }, [png, x, y]);
}

const BACKGROUND = [0x20, 0x24, 0x2a];
const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

let server;
for (let attempt = 0; !server; attempt++) {
  try {
    server = await runLive(20000 + Math.floor(Math.random() * 20000));
  } catch (e) {
    if (attempt >= 4 || !/in use/.test(e.message)) throw e;
  }
}
const { url, child } = server;
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = [];
  page.on('pageerror', e => errors.push(String(e)));
  page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(url);
  await page.waitForFunction(() => window.fulcrumViewer?.loaded, null, { timeout: 30000 });
  const v = () => page.evaluate(() => ({
    frame: window.fulcrumViewer.frame, step: window.fulcrumViewer.step, frameCount: window.fulcrumViewer.frameCount,
    live: window.fulcrumViewer.live, label: document.querySelector('#frame-label').textContent,
  }));

  // Polls until `ok(state)` holds or `ms` pass; returns the last state. Software WebGL on a
  // busy CI machine may take most of a second per animation frame, so nothing here counts frames per second.
  const until = async (ok, ms = 8000) => {
    const end = Date.now() + ms;
    let s = await v();
    while (!ok(s) && Date.now() < end) { await page.waitForTimeout(100); s = await v(); }
    return s;
  };

  const first = await v();
  check(first.live && !first.live.ended, `live page connected to the run (${first.frameCount} frames so far)`);
  const later = await until(s => s.frameCount >= first.frameCount + 20 && s.frame === s.frameCount - 1);
  check(later.frameCount >= first.frameCount + 20, `frames arrive while the run goes (${first.frameCount} -> ${later.frameCount})`);
  check(later.frame === later.frameCount - 1 && later.step > first.step, `the view follows the newest frame (step ${first.step} -> ${later.step})`);
  check(later.label !== first.label && later.label.includes(`/${later.frameCount})`), `frame counter advances: '${first.label}' -> '${later.label}'`);

  // The tower is drawn where the newest frame says it is.
  const names = await page.evaluate(() => window.fulcrumViewer.bodyNames());
  const middle = names.indexOf('tower/10');
  check(middle > 0, `body names from the scene (tower/10 is #${middle})`);
  const at = await page.evaluate(i => window.fulcrumViewer.bodyOnScreen(i), middle);
  const onTower = await pixelAt(page, at.x, at.y);
  const box = await page.locator('#viewport').boundingBox();
  const corner = await pixelAt(page, box.x + 5, box.y + 5);
  check(distance(onTower, BACKGROUND) > 40, `tower pixel ${onTower} differs from the background`);
  check(distance(corner, BACKGROUND) < 12, `corner pixel ${corner} is the background`);
  await page.screenshot({ path: resolve(out, 'viewer-live.png') });

  // Scrubbing back holds the frame while more arrive; the last frame resumes following.
  await page.locator('#scrub').fill('5');
  const scrubbed = await v();
  let s = await until(x => x.frameCount >= scrubbed.frameCount + 10);
  check(s.frame === 5 && !s.live.following && s.frameCount >= scrubbed.frameCount + 10, `scrubbed back: stays on frame 5 while frames arrive (${scrubbed.frameCount} -> ${s.frameCount})`);
  await page.locator('#scrub').fill(String(s.frameCount - 1));
  const resumed = (await v()).frame;
  s = await until(x => x.frame > resumed + 10);
  check(s.live.following && s.frame > resumed + 10, `back on the last frame: follows again (${resumed} -> ${s.frame})`);

  check(errors.length === 0, `no page errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} finally {
  await browser.close();
  child.kill();
}
console.log(failures === 0 ? 'viewer live e2e: all checks passed' : `viewer live e2e: ${failures} check(s) FAILED`);
process.exit(failures === 0 ? 0 : 1);
