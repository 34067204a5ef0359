// The viewer's page: loading (URL ?file=, drag and drop, file picker), playback, the
// panel, and a small hook (window.fulcrumViewer) that the browser tests drive.
import { Vector3 } from 'three';
import { Recording, BodyType, BODY_ASLEEP, JOINT_KINDS } from './reader';
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

function setStatus(text: string): void { status.textContent = text; }

function open(data: ArrayBuffer, name: string): void {
  try {
    const r = new Recording(data);
    if (r.frameCount === 0) throw new Error('the recording has no frames');
    rec = r;
  } catch (e) {
    setStatus(`${name}: ${(e as Error).message}`);
    return;
  }
  setStatus(rec.truncated ? 'the file ends inside a frame (the run was cut off); that frame is left out' : '');
  $('drop-hint').style.display = 'none';
  $('file-name').textContent = `${name} — ${rec.header.bodies.length} bodies, ${rec.header.joints.length} joints, ${rec.header.softBodies.length} soft bodies, ${rec.frameCount} frames`;
  times = rec.series().time;
  scrub.max = String(rec.frameCount - 1);
  view.load(rec);
  charts = [
    profileChart($('chart-profile'), $('legend-profile'), rec),
    energyChart($('chart-energy'), $('legend-energy'), rec),
  ];
  setPlaying(false);
  goTo(0);
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

const params = new URLSearchParams(location.search);
const fileParam = params.get('file');
if (fileParam) void openUrl(fileParam, params.get('name') ?? undefined);

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
