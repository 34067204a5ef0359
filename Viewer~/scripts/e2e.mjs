// Browser test of the viewer: Debian's Chromium driven by playwright-core (no browser
// download). Serves a recorded tower with `fulcrum view`, steps and plays it, reads pixels
// back from the canvas, opens a soft scene through the file picker and checks that its strain
// colours change under load. Fails loudly (exit 1) on any problem, including a missing browser.
//
// Environment: as e2e-common.mjs, and DATA, the folder holding tower.frec and jelly.frec
// (default test-data).
import { resolve } from 'node:path';
import { BACKGROUND, check, distance, finish, launchBrowser, out, pixelAt, startRunner } from './e2e-common.mjs';

const data = resolve(process.env.DATA ?? 'test-data');

const { url, child } = await startRunner(['view', resolve(data, 'tower.frec')], /serving (http:\/\/\S+)/, 'fulcrum view');
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = [];
  page.on('pageerror', e => errors.push(String(e)));
  page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(url);
  await page.waitForFunction(() => window.fulcrumViewer?.loaded, null, { timeout: 30000 });
  const v = () => page.evaluate(() => ({ frame: window.fulcrumViewer.frame, step: window.fulcrumViewer.step, frameCount: window.fulcrumViewer.frameCount, playing: window.fulcrumViewer.playing }));

  let s = await v();
  check(s.frameCount > 10 && s.frame === 0, `tower recording served by fulcrum view and loaded (${s.frameCount} frames)`);
  const names = await page.evaluate(() => window.fulcrumViewer.bodyNames());
  const middle = names.indexOf('tower/10');
  check(middle > 0, `body names from the scene (tower/10 is #${middle})`);

  // Something is drawn where the tower is, and the background where it is not.
  const at = await page.evaluate(i => window.fulcrumViewer.bodyOnScreen(i), middle);
  const onTower = await pixelAt(page, at.x, at.y);
  const box = await page.locator('#viewport').boundingBox();
  const corner = await pixelAt(page, box.x + 5, box.y + 5);
  check(distance(onTower, BACKGROUND) > 40, `tower pixel ${onTower} differs from the background`);
  check(distance(corner, BACKGROUND) < 12, `corner pixel ${corner} is the background`);
  await page.screenshot({ path: resolve(out, 'viewer-tower.png') });

  // Step, step back, play, pause.
  await page.click('#btn-step');
  s = await v();
  check(s.frame === 1 && s.step === 1, `step button -> frame 1 (got ${s.frame}, step ${s.step})`);
  await page.click('#btn-step');
  await page.click('#btn-back');
  s = await v();
  check(s.frame === 1, `back button -> frame 1 (got ${s.frame})`);
  await page.click('#btn-play');
  await page.waitForTimeout(700);
  s = await v();
  check(s.playing && s.frame > 5, `play advances (frame ${s.frame} after 0.7 s)`);
  await page.click('#btn-play');
  const paused = (await v()).frame;
  await page.waitForTimeout(300);
  s = await v();
  check(!s.playing && s.frame === paused, `pause holds the frame (${paused} -> ${s.frame})`);
  await page.locator('#scrub').fill(String(s.frameCount - 1));
  s = await v();
  check(s.frame === s.frameCount - 1, `scrubber to the last frame (${s.frame})`);

  // Clicking a body shows its state.
  await page.evaluate(() => window.fulcrumViewer.goTo(0));
  const p = await page.evaluate(i => window.fulcrumViewer.bodyOnScreen(i), middle);
  await page.mouse.click(p.x, p.y);
  const sel = await page.evaluate(() => window.fulcrumViewer.selection);
  check(/^tower\/\d+ /.test(sel) && sel.includes('position'), `click selects a body: ${sel.split('\n')[0]}`);

  // The picture for the README: mid-run, contacts and normals on, a body selected.
  await page.evaluate(() => window.fulcrumViewer.goTo(Math.floor(window.fulcrumViewer.frameCount / 2)));
  await page.mouse.click(p.x, p.y);
  await page.screenshot({ path: resolve(out, 'viewer.png') });
  await page.evaluate(() => window.fulcrumViewer.goTo(0));

  // Contacts and normals are drawn: at a contact point of frame 30, switching both off
  // changes the pixel.
  await page.evaluate(() => window.fulcrumViewer.goTo(30));
  const cp = await page.evaluate(() => window.fulcrumViewer.contactOnScreen(0));
  const withContacts = await pixelAt(page, cp.x, cp.y);
  await page.click('#show-contacts');
  await page.click('#show-normals');
  const withoutContacts = await pixelAt(page, cp.x, cp.y);
  await page.click('#show-contacts');
  await page.click('#show-normals');
  check(distance(withContacts, withoutContacts) > 60, `contact overlay drawn (${withContacts} -> ${withoutContacts} when switched off)`);
  await page.evaluate(() => window.fulcrumViewer.goTo(0));

  // A toggle changes the picture: wireframe leaves background between the edges.
  const before = await pixelAt(page, p.x + 3, p.y + 3);
  await page.click('#show-wireframe');
  const after = await pixelAt(page, p.x + 3, p.y + 3);
  check(distance(before, after) > 20, `wireframe toggle changes the pixel (${before} -> ${after})`);
  await page.click('#show-wireframe');

  // Soft scene through the file picker: strain colours go from white towards yellow and red
  // under load (less blue), and the J map differs from the strain map.
  await page.setInputFiles('#file-input', resolve(data, 'jelly.frec'));
  await page.waitForFunction(() => document.querySelector('#file-name').textContent.startsWith('jelly.frec'), null, { timeout: 30000 });
  const soft = async frame => {
    await page.evaluate(f => window.fulcrumViewer.goTo(f), frame);
    const c = await page.evaluate(() => window.fulcrumViewer.softOnScreen(0));
    return pixelAt(page, c.x, c.y);
  };
  const rest = await soft(0);
  const count = (await v()).frameCount;
  const loaded = await soft(count - 1);
  await page.screenshot({ path: resolve(out, 'viewer-jelly.png') });
  check(distance(rest, BACKGROUND) > 40, `soft body drawn at rest (${rest})`);
  check((rest[2] - rest[0]) - (loaded[2] - loaded[0]) > 25, `strain colour turns yellow/red under load (rest ${rest} -> loaded ${loaded})`);
  await page.click('#show-strain');
  const plain = await pixelAt(page, ...Object.values(await page.evaluate(() => window.fulcrumViewer.softOnScreen(0))));
  check(distance(plain, loaded) > 20, `strain toggle off changes the colour (${loaded} -> ${plain})`);
  await page.click('#show-strain');

  check(errors.length === 0, `no page errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} finally {
  await browser.close();
  child.kill();
}
finish('viewer e2e');
