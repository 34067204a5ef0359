// The panel's two charts: stacked stage times per step and energy over time. Each is drawn
// once into an off-screen canvas; moving the frame cursor only blits it and draws a line.
import { Recording, STAGES, PROFILE_ENTRIES } from './reader';

export const STAGE_COLOURS = ['#4e79a7', '#f28e2b', '#59a14f', '#e15759', '#b07aa1', '#edc948', '#76b7b2'];
const ENERGY_SERIES = [
  { name: 'kinetic', colour: '#f28e2b' },
  { name: 'potential', colour: '#4e79a7' },
  { name: 'soft', colour: '#b07aa1' },
  { name: 'total', colour: '#e6ebf0' },
];

export class Chart {
  private readonly base: HTMLCanvasElement;
  constructor(private readonly canvas: HTMLCanvasElement, private readonly frames: number) {
    this.base = document.createElement('canvas');
    this.base.width = canvas.width;
    this.base.height = canvas.height;
  }
  get context(): CanvasRenderingContext2D { return this.base.getContext('2d')!; }
  cursor(frame: number): void {
    const g = this.canvas.getContext('2d')!;
    g.clearRect(0, 0, this.canvas.width, this.canvas.height);
    g.drawImage(this.base, 0, 0);
    const x = this.frames > 1 ? (frame / (this.frames - 1)) * (this.canvas.width - 1) : 0;
    g.strokeStyle = '#ffffffaa';
    g.beginPath();
    g.moveTo(x + 0.5, 0);
    g.lineTo(x + 0.5, this.canvas.height);
    g.stroke();
  }
}

function legend(element: HTMLElement, items: { name: string; colour: string }[]): void {
  element.innerHTML = items.map(i => `<span><i style="background:${i.colour}"></i>${i.name}</span>`).join('');
}

function label(g: CanvasRenderingContext2D, text: string, x: number, y: number): void {
  g.fillStyle = '#8fa0b3';
  g.font = '10px system-ui, sans-serif';
  g.fillText(text, x, y);
}

/** Stacked area of the seven stages' ms per frame; the top edge is the step's total. */
export function profileChart(canvas: HTMLCanvasElement, legendElement: HTMLElement, rec: Recording): Chart {
  const s = rec.series();
  const n = rec.frameCount;
  const chart = new Chart(canvas, n);
  const g = chart.context;
  const w = canvas.width, h = canvas.height;
  // The scale ignores the slowest 2 % of steps: the first steps run before the JIT has
  // compiled the solver and would flatten everything else. Clipped spikes run off the top.
  const totals = Array.from(s.profile[PROFILE_ENTRIES - 1]).sort((a, b) => a - b);
  const peak = totals.length ? totals[totals.length - 1] : 0;
  let max = totals.length ? totals[Math.min(totals.length - 1, Math.floor(0.98 * totals.length))] * 1.25 : 0;
  if (!(max > 0)) max = peak > 0 ? peak : 1;
  const x = (i: number) => (n > 1 ? (i / (n - 1)) * (w - 1) : 0);
  const y = (v: number) => h - 1 - (v / max) * (h - 14);
  const below = new Float32Array(n);
  for (let stage = 0; stage < STAGES.length; stage++) {
    g.fillStyle = STAGE_COLOURS[stage];
    g.beginPath();
    for (let i = 0; i < n; i++) g.lineTo(x(i), y(below[i] + s.profile[stage][i]));
    for (let i = n - 1; i >= 0; i--) g.lineTo(x(i), y(below[i]));
    g.closePath();
    g.fill();
    for (let i = 0; i < n; i++) below[i] += s.profile[stage][i];
  }
  label(g, `scale ${max.toPrecision(3)} ms` + (peak > max ? ` (peak ${peak.toPrecision(3)} ms clipped)` : ''), 4, 10);
  legend(legendElement, STAGES.map((name, i) => ({ name, colour: STAGE_COLOURS[i] })));
  return chart;
}

/** Kinetic energy, and potential, soft-body and total energy as changes from frame 0, over time. */
export function energyChart(canvas: HTMLCanvasElement, legendElement: HTMLElement, rec: Recording): Chart {
  const s = rec.series();
  const n = rec.frameCount;
  const chart = new Chart(canvas, n);
  const g = chart.context;
  const w = canvas.width, h = canvas.height;
  const series = [
    Float32Array.from(s.kinetic),
    s.potential.map(v => v - s.potential[0]),
    s.soft.map(v => v - s.soft[0]),
    Float32Array.from({ length: n }, (_, i) => s.kinetic[i] + s.potential[i] + s.soft[i] - (s.kinetic[0] + s.potential[0] + s.soft[0])),
  ];
  let lo = 0, hi = 0;
  for (const a of series) for (const v of a) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  if (hi - lo < 1e-9) { hi += 1; lo -= 1; }
  const x = (i: number) => (n > 1 ? (i / (n - 1)) * (w - 1) : 0);
  const y = (v: number) => h - 4 - ((v - lo) / (hi - lo)) * (h - 16);
  g.strokeStyle = '#3a424d';
  g.beginPath(); g.moveTo(0, y(0)); g.lineTo(w, y(0)); g.stroke();
  series.forEach((a, k) => {
    g.strokeStyle = ENERGY_SERIES[k].colour;
    g.lineWidth = 1.5;
    g.beginPath();
    for (let i = 0; i < n; i++) g.lineTo(x(i), y(a[i]));
    g.stroke();
  });
  label(g, `${lo.toPrecision(3)} … ${hi.toPrecision(3)} J`, 4, 10);
  legend(legendElement, ENERGY_SERIES);
  return chart;
}
