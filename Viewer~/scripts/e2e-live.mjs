// Browser test of live mode: `fulcrum run tower-20 --live` streams a run in real time and
// Debian's Chromium (playwright-core) watches it: the frame counter advances as frames
// arrive, the view follows the newest frame and draws the tower, scrubbing back stops the
// following and going to the last frame resumes it. Fails loudly (exit 1) on any problem.
//
// Environment: as e2e-common.mjs (FULCRUM, CHROMIUM, OUT) and SCENES, the folder of the
// scene files (default ../Samples~/Scenes).
import { resolve } from 'node:path';
import { BACKGROUND, check, distance, finish, launchBrowser, out, pixelAt, startRunner } from './e2e-common.mjs';

const scenes = resolve(process.env.SCENES ?? '../Samples~/Scenes');

// `fulcrum run --live`: 3600 steps at real time (60 s) outlast the test; it is stopped at the end.
const { url, child } = await startRunner(['run', resolve(scenes, 'tower-20.json'), '--steps', '3600', '--live'], /live: (http:\/\/\S+)/, 'fulcrum run --live');
const browser = await launchBrowser();
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
  // To the last frame in one page task: a count read here first may be stale by the time the
  // slider moves (frames keep arriving), and the viewer rightly keeps still on any other frame.
  await page.locator('#scrub').evaluate(el => { el.value = el.max; el.dispatchEvent(new Event('input')); });
  const resumed = (await v()).frame;
  s = await until(x => x.frame > resumed + 10);
  check(s.live.following && s.frame > resumed + 10, `back on the last frame: follows again (${resumed} -> ${s.frame})`);

  check(errors.length === 0, `no page errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} finally {
  await browser.close();
  child.kill();
}
finish('viewer live e2e');
