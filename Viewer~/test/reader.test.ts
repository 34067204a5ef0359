// The TypeScript reader against recordings written by the C# runner (scripts/ci.sh writes
// them into test-data/ first: tower-20 for 180 steps, jelly-stack for 120 steps).
import { readFileSync, existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { Recording, RecordingError, ShapeType, BodyType, BODY_ASLEEP, PROFILE_ENTRIES, vertexMean } from '../src/reader';

const data = resolve(process.env.DATA ?? 'test-data');
function load(name: string): Recording {
  const path = resolve(data, name);
  if (!existsSync(path)) throw new Error(`${path} is missing: run scripts/ci.sh, which records it with the C# runner`);
  return new Recording(readFileSync(path));
}

describe('tower-20 recorded by fulcrum run --record', () => {
  const rec = load('tower.frec');

  it('has the scene\'s bodies and box shapes in the header', () => {
    const h = rec.header;
    expect(h.version).toBe(1);
    expect(h.timestep).toBeCloseTo(1 / 60, 6);
    expect(h.gravity).toEqual([0, expect.closeTo(-9.81, 5), 0]);
    expect(h.bodies).toHaveLength(21);
    expect(h.bodies[0]).toMatchObject({ name: 'ground', type: BodyType.Static, mass: 0 });
    expect(h.bodies.slice(1).map(b => b.name)).toEqual(Array.from({ length: 20 }, (_, i) => `tower/${i}`));
    expect(h.bodies[1].type).toBe(BodyType.Dynamic);
    expect(h.bodies[1].mass).toBeGreaterThan(0);
    expect(h.shapes).toHaveLength(21);
    expect(h.shapes.slice(1).every(s => s.type === ShapeType.Box && s.halfExtents![1] === 0.5)).toBe(true);
    expect(h.joints).toHaveLength(0);
    expect(h.softBodies).toHaveLength(0);
  });

  it('has one frame per step from 0 to 180 with stage times and energy', () => {
    expect(rec.frameCount).toBe(181);
    expect(rec.frame(0)).toMatchObject({ step: 0, time: 0, contactCount: 0 });
    const last = rec.frame(180);
    expect(last.step).toBe(180);
    expect(last.time).toBeCloseTo(3, 4);
    const s = rec.series();
    for (let i = 1; i < rec.frameCount; i++) {
      expect(s.time[i]).toBeGreaterThan(s.time[i - 1]);
      expect(s.profile[PROFILE_ENTRIES - 1][i]).toBeGreaterThan(0);
    }
    expect(s.kinetic[0]).toBe(0);
    expect(s.potential[0]).toBeGreaterThan(0);
  });

  it('keeps the tower standing, with contacts pushing up, and lets it fall asleep', () => {
    const f = rec.frame(30);
    const x = (i: number) => f.positions[3 * i], y = (i: number) => f.positions[3 * i + 1];
    for (let i = 1; i <= 20; i++) {
      expect(Math.abs(x(i))).toBeLessThan(0.01);
      expect(y(i)).toBeGreaterThan(i - 1);
    }
    expect(f.contactCount).toBeGreaterThan(20 * 3);
    for (let k = 0; k < f.contactCount; k++) {
      const n = f.contacts.subarray(8 * k + 3, 8 * k + 6);
      expect(Math.hypot(n[0], n[1], n[2])).toBeCloseTo(1, 4);
      expect(Math.abs(n[1])).toBeCloseTo(1, 3);
      expect(f.contacts[8 * k + 6]).toBeGreaterThanOrEqual(0);
    }
    const end = rec.frame(180);
    for (let i = 1; i <= 20; i++) expect(end.bodyFlags[i] & BODY_ASLEEP).toBe(BODY_ASLEEP);
  });
});

describe('jelly-stack recorded by fulcrum run --record', () => {
  const rec = load('jelly.frec');

  it('has three tetrahedral soft bodies whose surface indexes their vertices', () => {
    expect(rec.header.softBodies.map(s => s.name)).toEqual(['bottom', 'middle', 'top']);
    for (const s of rec.header.softBodies) {
      expect(s.verticesPerElement).toBe(4);
      expect(s.elements.length % 4).toBe(0);
      expect(s.surface.length % 3).toBe(0);
      expect(Math.max(...s.surface)).toBeLessThan(s.vertexCount);
      expect(Math.max(...s.elements)).toBeLessThan(s.vertexCount);
    }
  });

  it('starts unstrained and is strained under load, at nearly constant volume', () => {
    const first = rec.frame(0), last = rec.frame(rec.frameCount - 1);
    expect(Math.max(...first.softStrain[0])).toBeLessThan(1e-4);
    expect(Math.max(...last.softStrain[0])).toBeGreaterThan(0.02);
    for (const j of last.softJ[0]) expect(j).toBeGreaterThan(0.8);
    const bottom = rec.header.softBodies[0];
    const v = vertexMean(bottom, last.softStrain[0], undefined, 0);
    expect(v).toHaveLength(bottom.vertexCount);
    expect(last.softPositions[0]).toHaveLength(3 * bottom.vertexCount);
  });
});

describe('malformed input', () => {
  const bytes = readFileSync(resolve(data, 'tower.frec'));

  it('refuses another file type', () => {
    const copy = Uint8Array.from(bytes);
    copy[0] = 0x58;
    expect(() => new Recording(copy)).toThrow(/not a Fulcrum recording/);
  });

  it('leaves out a last frame cut short and refuses a cut header', () => {
    const whole = new Recording(bytes);
    const cut = new Recording(bytes.subarray(0, bytes.length - 5));
    expect(whole.truncated).toBe(false);
    expect(cut.truncated).toBe(true);
    expect(cut.frameCount).toBe(whole.frameCount - 1);
    expect(() => new Recording(bytes.subarray(0, 30))).toThrow(RecordingError);
  });

  it('refuses an unknown version', () => {
    const copy = Uint8Array.from(bytes);
    copy[4] = 99;
    expect(() => new Recording(copy)).toThrow(/version 99/);
  });
});

describe('vertexMean', () => {
  it('averages element values over the elements that use each vertex', () => {
    const body = { name: 't', vertexCount: 5, verticesPerElement: 4, elements: Uint32Array.from([0, 1, 2, 3, 1, 2, 3, 4]), surface: new Uint32Array(0) };
    expect(Array.from(vertexMean(body, Float32Array.from([1, 3])))).toEqual([1, 2, 2, 2, 3]);
  });
});
