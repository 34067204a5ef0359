// The viewer's page: loading (URL ?file=, drag and drop, file picker, or ?live= for a run
// streamed by `fulcrum run --live`), playback, the panel, and a small hook
// (window.fulcrumViewer) that the browser tests drive.
import { Vector3 } from 'three';
import { Recording, RecordingError, BodyType, BODY_ASLEEP, JOINT_KINDS } from './reader';
import { View3D, Toggles } from './view3d';
import { Chart, profileChart, energyChart } from './charts';

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

const viewport = $<HTMLDivElement>('viewport');
const view = new View3D(viewport);
const scrub = $<HTMLInputElement>('scrub');
const playButton = $<HTMLButtonElement>('btn-play');
const frameLabel = $<HTMLSpanElement>('frame-label');
const status = $<HTMLSpanElement>('status');
const selection = $<HTMLPreElement>('selection');

let rec: Recording | undefined;
let current = 0;
let playing = false;
let playClock = 0; // simulated seconds since the first frame
let lastTick = 0;
let times: Float64Array = new Float64Array(0);
let charts: Chart[] = [];
let recName = '';
let following = true;

function setStatus(text: string): void { status.textContent = text; }

function open(data: ArrayBuffer, name: string): void {
  let r: Recording;
  try {
    r = new Recording(data);
    if (r.frameCount === 0) throw new Error('the recording has no frames');
  } catch (e) {
    setStatus(`${name}: ${(e as Error).message}`);
    return;
  }
  closeLive();
  show(r, name);
  setStatus(r.truncated ? 'the file ends inside a frame (the run was cut off); that frame is left out' : '');
  goTo(0);
}

// Puts a recording on screen (the caller picks the frame).
function show(r: Recording, name: string): void {
  rec = r;
  recName = name;
  $('drop-hint').style.display = 'none';
  view.load(r);
  setPlaying(false);
  grown();
}

// The parts that depend on the number of frames: the file line, the time line and the charts.
function grown(): void {
  if (!rec) return;
  $('file-name').textContent = `${recName} — ${rec.header.bodies.length} bodies, ${rec.header.joints.length} joints, ${rec.header.softBodies.length} soft bodies, ${rec.frameCount} frames`;
  times = rec.series().time;
  scrub.max = String(rec.frameCount - 1);
  charts = [
    profileChart($('chart-profile'), $('legend-profile'), rec),
    energyChart($('chart-energy'), $('legend-energy'), rec),
  ];
}

function goTo(i: number): void {
  if (!rec) return;
  current = Math.max(0, Math.min(rec.frameCount - 1, i));
  const f = rec.frame(current);
  view.show(f);
  scrub.value = String(current);
  frameLabel.textContent = `step ${f.step}  t ${f.time.toFixed(3)} s  (${current + 1}/${rec.frameCount})`;
  for (const c of charts) c.cursor(current);
  describeSelection();
  // Live: on the newest frame, the view follows the frames that arrive; anywhere else it stays.
  following = current === rec.frameCount - 1;
}

function setPlaying(on: boolean): void {
  playing = on && !!rec;
  playButton.textContent = playing ? '❙❙' : '▶';
  if (!rec) return;
  if (playing) {
    if (current >= rec.frameCount - 1) goTo(0);
    playClock = times[current] - times[0];
    lastTick = performance.now();
    requestAnimationFrame(tick);
  }
}

// Plays in simulated time: each animation frame shows the last recorded frame whose time has
// passed, so --every K recordings and slow machines play at the right speed.
function tick(now: number): void {
  if (!playing || !rec) return;
  const speed = Number(($('speed') as HTMLSelectElement).value);
  playClock += ((now - lastTick) / 1000) * speed;
  lastTick = now;
  let i = current;
  while (i + 1 < rec.frameCount && times[i + 1] - times[0] <= playClock) i++;
  if (i !== current) goTo(i);
  if (current >= rec.frameCount - 1) { setPlaying(false); return; }
  requestAnimationFrame(tick);
}

function fmt(v: ArrayLike<number>, digits = 4): string {
  return Array.from(v, x => x.toFixed(digits)).join(', ');
}

function describeSelection(): void {
  if (!rec || view.selected < 0) { selection.textContent = 'nothing selected'; return; }
  const i = view.selected;
  const b = rec.header.bodies[i];
  const f = rec.frame(current);
  const p = f.positions.subarray(3 * i, 3 * i + 3), q = f.rotations.subarray(4 * i, 4 * i + 4);
  // Velocity is not recorded; the central difference of neighbouring frames estimates it.
  const a = rec.frame(Math.max(0, current - 1)), c = rec.frame(Math.min(rec.frameCount - 1, current + 1));
  const dt = c.time - a.time;
  const v = dt > 0 ? [0, 1, 2].map(k => (c.positions[3 * i + k] - a.positions[3 * i + k]) / dt) : [0, 0, 0];
  let contacts = 0, impulse = 0;
  for (let k = 0; k < f.contactCount; k++)
    if (f.contactBodies[2 * k] === i || f.contactBodies[2 * k + 1] === i) { contacts++; impulse += f.contacts[8 * k + 6]; }
  const joints = rec.header.joints.map((j, k) => ({ j, k })).filter(({ j }) => j.bodyA === i || j.bodyB === i)
    .map(({ j, k }) => `${j.name} (${JOINT_KINDS[j.kind] ?? j.kind}) error ${(f.joints[16 * k + 14] * 1000).toFixed(2)} mm`);
  selection.textContent = [
    `${b.name}  [#${i}, ${BodyType[b.type].toLowerCase()}${b.type === BodyType.Dynamic ? `, ${b.mass.toPrecision(4)} kg` : ''}]`,
    `position  ${fmt(p)} m`,
    `rotation  ${fmt(q)} (xyzw)`,
    `velocity  ${fmt(v, 3)} m/s (from frames)`,
    `state     ${(f.bodyFlags[i] & BODY_ASLEEP) ? 'asleep' : 'awake'}`,
    `contacts  ${contacts} points, normal impulse ${impulse.toPrecision(4)} N s`,
    ...joints,
  ].join('\n');
}

async function openUrl(url: string, name?: string): Promise<void> {
  setStatus(`loading ${url} …`);
  try {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    open(await response.arrayBuffer(), name ?? decodeURIComponent(url.split('/').pop() ?? url));
  } catch (e) {
    setStatus(`${url}: ${(e as Error).message}`);
  }
}

// Controls.
playButton.onclick = () => setPlaying(!playing);
$('btn-step').onclick = () => { setPlaying(false); goTo(current + 1); };
$('btn-back').onclick = () => { setPlaying(false); goTo(current - 1); };
$('btn-first').onclick = () => { setPlaying(false); goTo(0); };
scrub.oninput = () => { setPlaying(false); goTo(Number(scrub.value)); };
window.addEventListener('keydown', e => {
  if ((e.target as HTMLElement).tagName === 'INPUT' && (e.target as HTMLInputElement).type !== 'checkbox') return;
  if (e.key === ' ') { e.preventDefault(); setPlaying(!playing); }
  else if (e.key === 'ArrowRight') { setPlaying(false); goTo(current + 1); }
  else if (e.key === 'ArrowLeft') { setPlaying(false); goTo(current - 1); }
  else if (e.key === 'Home') { setPlaying(false); goTo(0); }
});

const toggleIds: Record<Exclude<keyof Toggles, 'measure'>, string> = {
  contacts: 'show-contacts', normals: 'show-normals', joints: 'show-joints', aabbs: 'show-aabbs',
  sleep: 'show-sleep', strain: 'show-strain', wireframe: 'show-wireframe',
};
const measure = $<HTMLSelectElement>('strain-measure');
measure.onchange = () => { view.toggles.measure = measure.value === 'j' ? 'j' : 'strain'; view.refresh(); };
for (const [key, id] of Object.entries(toggleIds) as [Exclude<keyof Toggles, 'measure'>, string][]) {
  const box = $<HTMLInputElement>(id);
  view.toggles[key] = box.checked;
  box.onchange = () => { view.toggles[key] = box.checked; view.refresh(); };
}

// Click (not drag) selects a body.
let down: { x: number; y: number } | undefined;
viewport.addEventListener('pointerdown', e => { down = { x: e.clientX, y: e.clientY }; });
viewport.addEventListener('pointerup', e => {
  if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
  view.selected = view.pick(e.clientX, e.clientY);
  view.refresh();
  describeSelection();
});

// Opening files.
$<HTMLInputElement>('file-input').onchange = async e => {
  const file = (e.target as HTMLInputElement).files?.[0];
  if (file) open(await file.arrayBuffer(), file.name);
};
viewport.addEventListener('dragover', e => { e.preventDefault(); viewport.classList.add('dragging'); });
viewport.addEventListener('dragleave', () => viewport.classList.remove('dragging'));
viewport.addEventListener('drop', async e => {
  e.preventDefault();
  viewport.classList.remove('dragging');
  const file = e.dataTransfer?.files[0];
  if (file) open(await file.arrayBuffer(), file.name);
});

// Live mode: `fulcrum run SCENE --live` serves this page with ?live=/live and streams the
// recording over a WebSocket there (Documentation~/RecordingFormat.md, "Live mode"): binary
// messages whose concatenation is the .frec bytes, then the text message "end".
interface Live { socket: WebSocket; bytes: Uint8Array; length: number; ended: boolean; pending: boolean; charted: number }
let live: Live | undefined;

function openLive(path: string): void {
  const url = new URL(path, location.href);
  url.protocol = url.protocol === 'https:' ? 'wss:' : 'ws:';
  const socket = new WebSocket(url);
  socket.binaryType = 'arraybuffer';
  const l: Live = { socket, bytes: new Uint8Array(1 << 16), length: 0, ended: false, pending: false, charted: 0 };
  live = l;
  setStatus(`live: connecting to ${url} …`);
  socket.onmessage = e => {
    if (live !== l) return;
    if (typeof e.data === 'string') l.ended = l.ended || e.data === 'end';
    else append(l, new Uint8Array(e.data as ArrayBuffer));
    if (!l.pending) { l.pending = true; requestAnimationFrame(now => updateLive(l, now)); }
  };
  socket.onerror = () => { if (live === l && !rec) setStatus(`live: cannot connect to ${url}`); };
  socket.onclose = () => { if (live === l && !l.ended) setStatus(`live: disconnected after ${rec?.frameCount ?? 0} frames (the run was stopped)`); };
}

function closeLive(): void {
  if (!live) return;
  const l = live;
  live = undefined;
  l.socket.close();
}

function append(l: Live, chunk: Uint8Array): void {
  if (l.length + chunk.length > l.bytes.length) {
    const grownBytes = new Uint8Array(Math.max(2 * l.bytes.length, l.length + chunk.length));
    grownBytes.set(l.bytes.subarray(0, l.length));
    l.bytes = grownBytes;
  }
  l.bytes.set(chunk, l.length);
  l.length += chunk.length;
}

// Once per animation frame at most: new frames are listed, the time line grows (the charts
// every half second) and the view moves to the newest frame unless the user went back.
function updateLive(l: Live, now: number): void {
  l.pending = false;
  if (live !== l) return;
  const data = l.bytes.subarray(0, l.length);
  let added: number;
  if (!rec) {
    let r: Recording;
    try {
      r = new Recording(data);
    } catch (e) {
      // The header may still be arriving.
      if (!(e instanceof RecordingError && /ends early/.test(e.message))) setStatus(`live: ${(e as Error).message}`);
      return;
    }
    if (r.frameCount === 0) return;
    show(r, 'live run');
    following = true;
    added = r.frameCount;
  } else {
    added = rec.extend(data);
  }
  if (added > 0 || l.ended) {
    if (now - l.charted > 500 || l.ended) {
      grown();
      l.charted = now;
    } else {
      times = rec!.series().time;
      scrub.max = String(rec!.frameCount - 1);
    }
    if (following && !playing) goTo(rec!.frameCount - 1);
    else goTo(current);
  }
  setStatus(l.ended ? `live: the run finished (${rec!.frameCount} frames)` : `live: ${rec!.frameCount} frames${following ? '' : ' (go to the last frame to follow)'}`);
}

const params = new URLSearchParams(location.search);
const fileParam = params.get('file'), liveParam = params.get('live');
if (liveParam) openLive(liveParam);
else if (fileParam) void openUrl(fileParam, params.get('name') ?? undefined);

// For the browser tests (Viewer~/scripts/e2e.mjs) and for poking at a recording from the console.
declare global { interface Window { fulcrumViewer: unknown } }
window.fulcrumViewer = {
  get loaded() { return !!rec; },
  get frame() { return current; },
  get frameCount() { return rec?.frameCount ?? 0; },
  get step() { return rec ? rec.frame(current).step : -1; },
  get playing() { return playing; },
  get selection() { return selection.textContent; },
  get status() { return status.textContent; },
  /** Live mode: connected, finished, and whether the view follows the newest frame. */
  get live() { return live ? { ended: live.ended, following, bytes: live.length } : undefined; },
  bodyNames: () => rec?.header.bodies.map(b => b.name) ?? [],
  goTo,
  open: (bytes: ArrayBuffer, name: string) => open(bytes, name),
  /** Page pixel of body i's centre now. */
  bodyOnScreen: (i: number) => view.project(view.bodyCentre(i)),
  /** Page pixel of contact point k of the frame on screen. */
  contactOnScreen: (k: number) => {
    const c = rec!.frame(current).contacts;
    return view.project(new Vector3(c[8 * k], c[8 * k + 1], c[8 * k + 2]));
  },
  /** Page pixel of soft body k's centre now. */
  softOnScreen: (k: number) => view.project(view.softCentre(k)),
  render: () => view.render(),
};
