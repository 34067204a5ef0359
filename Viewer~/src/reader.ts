// Reader of Fulcrum's .frec recordings (Documentation~/RecordingFormat.md, version 1).
// The header is decoded at once; frames are only indexed (each starts with its byte
// length) and decoded on demand, so a long recording opens without decoding every step.

export const MAGIC = 'FREC';
export const VERSION = 1;
/** Seven StepStage buckets in run order, then the whole step. */
export const STAGES = ['BroadPhase', 'NarrowPhase', 'Islands', 'Solve', 'SoftBodies', 'Continuous', 'SleepAndEvents'] as const;
export const PROFILE_ENTRIES = STAGES.length + 1;

export const BODY_ASLEEP = 1;
export const BODY_REMOVED = 2;
export const JOINT_BROKEN = 1;

export enum BodyType { Static = 0, Kinematic = 1, Dynamic = 2 }
export enum ShapeType { Sphere = 0, Box = 1, Capsule = 2, ConvexHull = 3, Plane = 4, TriangleMesh = 5 }
export const JOINT_KINDS = ['ball', 'hinge', 'distance', 'fixed', 'prismatic', 'coneTwist'];

export type Vec3 = [number, number, number];
export type Quat = [number, number, number, number];

export interface Body { name: string; type: BodyType; mass: number }

export interface Shape {
  body: number;
  type: ShapeType;
  position: Vec3;
  rotation: Quat;
  /** sphere: radius */ radius?: number;
  /** box */ halfExtents?: Vec3;
  /** capsule (axis y) */ halfHeight?: number;
  /** plane: normal . x = offset in the body frame */ normal?: Vec3;
  offset?: number;
  /** hull and mesh vertices, flat xyz */ vertices?: Float32Array;
  /** hull faces: vertex loops */ faces?: number[][];
  /** mesh triangles */ indices?: Uint32Array;
}

export interface Joint { name: string; kind: number; bodyA: number; bodyB: number }

export interface SoftBody {
  name: string;
  vertexCount: number;
  /** 4 for tetrahedra, 3 for shell triangles */
  verticesPerElement: number;
  elements: Uint32Array;
  /** triangles to draw */
  surface: Uint32Array;
}

export interface Header {
  version: number;
  timestep: number;
  gravity: Vec3;
  bodies: Body[];
  shapes: Shape[];
  joints: Joint[];
  softBodies: SoftBody[];
}

export interface Frame {
  step: number;
  time: number;
  /** ms per stage (STAGES order), then the total */
  profile: Float32Array;
  kinetic: number;
  potential: number;
  softEnergy: number;
  /** per body xyz */
  positions: Float32Array;
  /** per body xyzw */
  rotations: Float32Array;
  bodyFlags: Uint8Array;
  contactCount: number;
  /** per contact: position xyz, normal xyz, normal impulse, separation (8 floats) */
  contacts: Float32Array;
  /** per contact: body A, body B */
  contactBodies: Int32Array;
  /** per joint: anchorA xyz, anchorB xyz, frameA xyzw, frameB xyzw, error, stress (16 floats) */
  joints: Float32Array;
  jointFlags: Uint8Array;
  /** per soft body: vertex positions */
  softPositions: Float32Array[];
  /** per soft body: J per element */
  softJ: Float32Array[];
  /** per soft body: |E| (Green-Lagrange strain against the rest mesh) per element */
  softStrain: Float32Array[];
}

export class RecordingError extends Error {}

class Cursor {
  pos: number;
  constructor(readonly view: DataView, pos = 0) { this.pos = pos; }
  need(n: number): void {
    if (n < 0 || this.pos + n > this.view.byteLength)
      throw new RecordingError(`recording ends early at byte ${this.pos} (needed ${n} more)`);
  }
  u8(): number { this.need(1); return this.view.getUint8(this.pos++); }
  u16(): number { this.need(2); const v = this.view.getUint16(this.pos, true); this.pos += 2; return v; }
  u32(): number { this.need(4); const v = this.view.getUint32(this.pos, true); this.pos += 4; return v; }
  i32(): number { this.need(4); const v = this.view.getInt32(this.pos, true); this.pos += 4; return v; }
  f32(): number { this.need(4); const v = this.view.getFloat32(this.pos, true); this.pos += 4; return v; }
  f64(): number { this.need(8); const v = this.view.getFloat64(this.pos, true); this.pos += 8; return v; }
  vec3(): Vec3 { return [this.f32(), this.f32(), this.f32()]; }
  quat(): Quat { return [this.f32(), this.f32(), this.f32(), this.f32()]; }
  count(): number {
    const n = this.u32();
    if (n > this.view.byteLength) throw new RecordingError(`count ${n} at byte ${this.pos - 4} exceeds the file size`);
    return n;
  }
  str(): string {
    const n = this.u16();
    this.need(n);
    const bytes = new Uint8Array(this.view.buffer, this.view.byteOffset + this.pos, n);
    this.pos += n;
    return new TextDecoder().decode(bytes);
  }
  floats(into: Float32Array, offset: number, n: number): void {
    this.need(4 * n);
    for (let i = 0; i < n; i++) { into[offset + i] = this.view.getFloat32(this.pos, true); this.pos += 4; }
  }
  uints(n: number): Uint32Array {
    this.need(4 * n);
    const a = new Uint32Array(n);
    for (let i = 0; i < n; i++) { a[i] = this.view.getUint32(this.pos, true); this.pos += 4; }
    return a;
  }
}

export class Recording {
  readonly header: Header;
  /** byte offset of each frame's body (after its length field) */
  readonly frameOffsets: number[] = [];
  readonly frameEnds: number[] = [];
  /** whether the file ended inside a frame (that frame is left out) */
  truncated = false;
  private view: DataView;
  /** byte offset where the header ends and the first frame's length field starts */
  private readonly headerEnd: number;
  private cache = new Map<number, Frame>();

  constructor(data: ArrayBuffer | Uint8Array) {
    const bytes = data instanceof Uint8Array ? data : new Uint8Array(data);
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const c = new Cursor(this.view);
    let magic = '';
    for (let i = 0; i < 4; i++) magic += String.fromCharCode(c.u8());
    if (magic !== MAGIC) throw new RecordingError('not a Fulcrum recording (the magic is not FREC)');
    const version = c.u16();
    if (version !== VERSION) throw new RecordingError(`recording version ${version}; this viewer reads ${VERSION}`);
    c.u16();
    const timestep = c.f32();
    const gravity = c.vec3();
    const bodies: Body[] = [];
    for (let n = c.count(), i = 0; i < n; i++) bodies.push({ name: c.str(), type: c.u8(), mass: c.f32() });
    const shapes: Shape[] = [];
    for (let n = c.count(), i = 0; i < n; i++) shapes.push(readShape(c));
    const joints: Joint[] = [];
    for (let n = c.count(), i = 0; i < n; i++) joints.push({ name: c.str(), kind: c.u8(), bodyA: c.i32(), bodyB: c.i32() });
    const softBodies: SoftBody[] = [];
    for (let n = c.count(), i = 0; i < n; i++) {
      const name = c.str();
      const vertexCount = c.count();
      const verticesPerElement = c.u8();
      const elements = c.uints(verticesPerElement * c.count());
      const surface = c.uints(3 * c.count());
      softBodies.push({ name, vertexCount, verticesPerElement, elements, surface });
    }
    this.header = { version, timestep, gravity, bodies, shapes, joints, softBodies };
    this.headerEnd = c.pos;
    this.scan(c.pos);
  }

  // Lists the whole frames from byte `pos` on.
  private scan(pos: number): void {
    this.truncated = false;
    while (pos < this.view.byteLength) {
      // A last frame cut short (the writer was killed mid-frame) is left out, not an error.
      const left = this.view.byteLength - pos;
      if (left < 4 || left - 4 < this.view.getUint32(pos, true)) { this.truncated = true; break; }
      const length = this.view.getUint32(pos, true);
      this.frameOffsets.push(pos + 4);
      this.frameEnds.push(pos + 4 + length);
      pos += 4 + length;
    }
  }

  /**
   * Live mode: the recording has grown to `data`, which starts with every byte read so far
   * (the header and the frames already listed). Lists the frames that are now whole and
   * returns how many there are new; a frame still arriving counts as `truncated` until it is whole.
   */
  extend(data: ArrayBuffer | Uint8Array): number {
    const bytes = data instanceof Uint8Array ? data : new Uint8Array(data);
    if (bytes.byteLength < this.view.byteLength) throw new RecordingError('a live recording cannot shrink');
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const before = this.frameCount;
    this.scan(before > 0 ? this.frameEnds[before - 1] : this.headerEnd);
    return this.frameCount - before;
  }

  get frameCount(): number { return this.frameOffsets.length; }

  /** Frame i, decoded (the last few are cached for scrubbing back and forth). */
  frame(i: number): Frame {
    if (i < 0 || i >= this.frameCount) throw new RangeError(`frame ${i} of ${this.frameCount}`);
    const hit = this.cache.get(i);
    if (hit) return hit;
    const f = this.decode(i);
    if (this.cache.size > 64) this.cache.delete(this.cache.keys().next().value as number);
    this.cache.set(i, f);
    return f;
  }

  /** Stage times and energies of every frame, for the charts (reads only those fields). */
  series(): { time: Float64Array; profile: Float32Array[]; kinetic: Float32Array; potential: Float32Array; soft: Float32Array } {
    const n = this.frameCount;
    const time = new Float64Array(n);
    const profile = Array.from({ length: PROFILE_ENTRIES }, () => new Float32Array(n));
    const kinetic = new Float32Array(n), potential = new Float32Array(n), soft = new Float32Array(n);
    for (let i = 0; i < n; i++) {
      const c = new Cursor(this.view, this.frameOffsets[i] + 4);
      time[i] = c.f64();
      for (let s = 0; s < PROFILE_ENTRIES; s++) profile[s][i] = c.f32();
      kinetic[i] = c.f32(); potential[i] = c.f32(); soft[i] = c.f32();
    }
    return { time, profile, kinetic, potential, soft };
  }

  private decode(i: number): Frame {
    const h = this.header;
    const c = new Cursor(this.view, this.frameOffsets[i]);
    const step = c.u32();
    const time = c.f64();
    const profile = new Float32Array(PROFILE_ENTRIES);
    c.floats(profile, 0, PROFILE_ENTRIES);
    const kinetic = c.f32(), potential = c.f32(), softEnergy = c.f32();
    const nb = h.bodies.length;
    const positions = new Float32Array(3 * nb), rotations = new Float32Array(4 * nb), bodyFlags = new Uint8Array(nb);
    for (let b = 0; b < nb; b++) {
      c.floats(positions, 3 * b, 3);
      c.floats(rotations, 4 * b, 4);
      bodyFlags[b] = c.u8();
    }
    const contactCount = c.count();
    const contacts = new Float32Array(8 * contactCount), contactBodies = new Int32Array(2 * contactCount);
    for (let k = 0; k < contactCount; k++) {
      c.floats(contacts, 8 * k, 8);
      contactBodies[2 * k] = c.i32();
      contactBodies[2 * k + 1] = c.i32();
    }
    const nj = h.joints.length;
    const joints = new Float32Array(16 * nj), jointFlags = new Uint8Array(nj);
    for (let j = 0; j < nj; j++) {
      c.floats(joints, 16 * j, 16);
      jointFlags[j] = c.u8();
    }
    const softPositions: Float32Array[] = [], softJ: Float32Array[] = [], softStrain: Float32Array[] = [];
    for (const s of h.softBodies) {
      const p = new Float32Array(3 * s.vertexCount);
      c.floats(p, 0, p.length);
      const j = new Float32Array(s.elements.length / s.verticesPerElement);
      c.floats(j, 0, j.length);
      const e = new Float32Array(j.length);
      c.floats(e, 0, e.length);
      softPositions.push(p);
      softJ.push(j);
      softStrain.push(e);
    }
    if (c.pos !== this.frameEnds[i])
      throw new RecordingError(`frame ${i}: decoded ${c.pos - this.frameOffsets[i]} bytes, length says ${this.frameEnds[i] - this.frameOffsets[i]}`);
    return { step, time, profile, kinetic, potential, softEnergy, positions, rotations, bodyFlags, contactCount, contacts, contactBodies, joints, jointFlags, softPositions, softJ, softStrain };
  }
}

function readShape(c: Cursor): Shape {
  const s: Shape = { body: c.i32(), type: c.u8(), position: c.vec3(), rotation: c.quat() };
  switch (s.type) {
    case ShapeType.Sphere: s.radius = c.f32(); break;
    case ShapeType.Box: s.halfExtents = c.vec3(); break;
    case ShapeType.Capsule: s.radius = c.f32(); s.halfHeight = c.f32(); break;
    case ShapeType.Plane: s.normal = c.vec3(); s.offset = c.f32(); break;
    case ShapeType.ConvexHull: {
      const nv = c.count();
      s.vertices = new Float32Array(3 * nv);
      c.floats(s.vertices, 0, 3 * nv);
      s.faces = [];
      for (let n = c.count(), f = 0; f < n; f++) s.faces.push(Array.from(c.uints(c.count())));
      break;
    }
    case ShapeType.TriangleMesh: {
      const nv = c.count();
      s.vertices = new Float32Array(3 * nv);
      c.floats(s.vertices, 0, 3 * nv);
      s.indices = c.uints(c.count());
      break;
    }
    default: throw new RecordingError(`unknown shape type ${s.type}`);
  }
  return s;
}

/** Per-vertex value of a soft body: the mean of an element value over the elements that use each vertex (1 for none). */
export function vertexMean(body: SoftBody, elementJ: Float32Array, into?: Float32Array, none = 1): Float32Array {
  const out = into ?? new Float32Array(body.vertexCount);
  const count = new Uint16Array(body.vertexCount);
  out.fill(0);
  const per = body.verticesPerElement;
  for (let e = 0; e < elementJ.length; e++)
    for (let k = 0; k < per; k++) {
      const v = body.elements[per * e + k];
      out[v] += elementJ[e];
      count[v]++;
    }
  for (let v = 0; v < out.length; v++) out[v] = count[v] > 0 ? out[v] / count[v] : none;
  return out;
}
