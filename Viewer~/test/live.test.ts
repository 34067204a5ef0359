// Live mode's reader path: a recording that arrives in pieces (fulcrum run --live sends the
// .frec bytes in WebSocket messages of any size) lists exactly the frames that are whole.
import { readFileSync, existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { Recording, RecordingError } from '../src/reader';

const path = resolve(process.env.DATA ?? 'test-data', 'tower.frec');

describe('a recording growing in pieces (live mode)', () => {
  if (!existsSync(path)) throw new Error(`${path} is missing: run scripts/ci.sh, which records it with the C# runner`);
  const bytes = new Uint8Array(readFileSync(path));
  const whole = new Recording(bytes);

  it('lists the same frames as the whole file, whatever the piece boundaries', () => {
    // A header cut short is an error that says so (the viewer waits for more).
    expect(() => new Recording(bytes.subarray(0, 40))).toThrow(RecordingError);
    expect(() => new Recording(bytes.subarray(0, 40))).toThrow(/ends early/);
    const headerAndSome = whole.frameOffsets[3] + 10; // inside frame 3
    const rec = new Recording(bytes.slice(0, headerAndSome));
    expect(rec.frameCount).toBe(3);
    expect(rec.truncated).toBe(true);
    let length = headerAndSome, added = 0;
    const piece = 997; // not a multiple of any frame's size
    while (length < bytes.length) {
      length = Math.min(bytes.length, length + piece);
      // A fresh copy each time, as the viewer's growing buffer is reallocated.
      added += rec.extend(bytes.slice(0, length));
    }
    expect(rec.frameCount).toBe(whole.frameCount);
    expect(added).toBe(whole.frameCount - 3);
    expect(rec.truncated).toBe(false);
    for (const i of [0, 2, 3, 90, whole.frameCount - 1]) expect(rec.frame(i)).toEqual(whole.frame(i));
    expect(rec.series().time).toEqual(whole.series().time);
  });

  it('refuses to shrink', () => {
    const rec = new Recording(bytes);
    expect(() => rec.extend(bytes.subarray(0, 100))).toThrow(/cannot shrink/);
  });
});
