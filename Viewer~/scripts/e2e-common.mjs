// What the browser tests (e2e.mjs, e2e-live.mjs) share: the environment, the check counter,
// starting the runner on a free port, launching Debian's Chromium, and reading pixels back.
//
// Environment: FULCRUM  command that runs the runner (default: dotnet ../.artifacts/bin/Fulcrum.Runner/release/fulcrum.dll)
//              CHROMIUM path of the browser (default /usr/bin/chromium)
//              OUT      folder for screenshots (default test-output)
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { chromium } from 'playwright-core';

export const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';
export const fulcrum = (process.env.FULCRUM ?? 'dotnet ../.artifacts/bin/Fulcrum.Runner/release/fulcrum.dll').split(' ');
export const out = resolve(process.env.OUT ?? 'test-output');
mkdirSync(out, { recursive: true });

let failures = 0;

/** Prints one check's outcome and counts the failures. */
export function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures++;
}

/** Prints the summary line and exits 0 when every check passed, 1 otherwise. */
export function finish(name) {
  console.log(failures === 0 ? `${name}: all checks passed` : `${name}: ${failures} check(s) FAILED`);
  process.exit(failures === 0 ? 0 : 1);
}

if (!existsSync(chromiumPath)) {
  console.error(`FAIL: no browser at ${chromiumPath} (apt-get install -y chromium)`);
  process.exit(1);
}

// The runner with `args` plus `--port N`; resolves with the URL it prints (the first match of
// `pattern`) and the child process.
function runner(args, port, pattern, what) {
  const child = spawn(fulcrum[0], [...fulcrum.slice(1), ...args, '--port', String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolveUrl, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error(`${what} printed no URL in 30 s:\n${text}`)), 30000);
    const onData = chunk => {
      text += chunk;
      const m = pattern.exec(text);
      if (m) { clearTimeout(timer); resolveUrl({ url: m[1], child }); }
    };
    child.stdout.on('data', onData);
    child.stderr.on('data', onData);
    child.on('exit', code => { clearTimeout(timer); reject(new Error(`${what} exited ${code}:\n${text}`)); });
  });
}

/** Starts the runner on a random port, another one if that is taken (--port N takes exactly N). */
export async function startRunner(args, pattern, what) {
  for (let attempt = 0; ; attempt++) {
    try {
      return await runner(args, 20000 + Math.floor(Math.random() * 20000), pattern, what);
    } catch (e) {
      if (attempt >= 4 || !/in use/.test(e.message)) throw e;
    }
  }
}

/** Headless Chromium with software WebGL. */
export function launchBrowser() {
  return chromium.launch({
    executablePath: chromiumPath,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
}

/**
 * The pixel (RGB 0-255) at a page point of a real Playwright screenshot of the page: the PNG
 * is decoded by the browser itself (an <img> drawn into a 2D canvas), so no decoder is needed here.
 */
export async function pixelAt(page, x, y) {
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

/** The viewer's background colour. */
export const BACKGROUND = [0x20, 0x24, 0x2a];

/** Euclidean distance between two RGB colours. */
export const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
