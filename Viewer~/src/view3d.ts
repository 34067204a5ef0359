// The 3D view of a recording: one group per body (its shapes as meshes), soft bodies as
// surface meshes coloured by J, and overlays for contacts, normals, joints and bounds.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import {
  Recording, Frame, Shape, ShapeType, BodyType, BODY_ASLEEP, BODY_REMOVED, JOINT_BROKEN, vertexMean,
} from './reader';

export interface Toggles {
  contacts: boolean;
  normals: boolean;
  joints: boolean;
  aabbs: boolean;
  sleep: boolean;
  strain: boolean;
  /** what the soft colours show: 'strain' (|E|) or 'j' (volume ratio) */
  measure: 'strain' | 'j';
  wireframe: boolean;
}

const BACKGROUND = 0x20242a;
const STATIC_COLOUR = new THREE.Color(0x7d848c);
const SLEEP_COLOUR = new THREE.Color(0x55627a);
const SELECTED_EMISSIVE = new THREE.Color(0x664400);
/** |J - 1| and |E| at which the colour maps saturate. */
export const FULL_SCALE_STRAIN = 0.1;

/** J: blue (compressed, J = 1 - full scale) through white (J = 1) to red (stretched). */
export function jColour(j: number, out: THREE.Color): THREE.Color {
  const t = Math.max(-1, Math.min(1, (j - 1) / FULL_SCALE_STRAIN));
  return t < 0 ? out.setRGB(1 + t, 1 + 0.6 * t, 1) : out.setRGB(1, 1 - 0.8 * t, 1 - t);
}

/** |E|: white (unstrained) through yellow (half scale) to red (full scale and beyond). */
export function strainColour(e: number, out: THREE.Color): THREE.Color {
  const t = Math.max(0, Math.min(1, e / FULL_SCALE_STRAIN));
  return t < 0.5 ? out.setRGB(1, 1, 1 - 2 * t) : out.setRGB(1, 1 - 1.6 * (t - 0.5), 0);
}

function dynamicColour(i: number): THREE.Color {
  // Golden-ratio hues: neighbours in a stack get clearly different colours.
  return new THREE.Color().setHSL((0.08 + i * 0.618034) % 1, 0.55, 0.58);
}

function shapeGeometry(s: Shape): THREE.BufferGeometry {
  switch (s.type) {
    case ShapeType.Sphere: return new THREE.SphereGeometry(s.radius!, 24, 16);
    case ShapeType.Box: {
      const e = s.halfExtents!;
      return new THREE.BoxGeometry(2 * e[0], 2 * e[1], 2 * e[2]);
    }
    case ShapeType.Capsule: return new THREE.CapsuleGeometry(s.radius!, 2 * s.halfHeight!, 8, 16);
    case ShapeType.ConvexHull: {
      const index: number[] = [];
      for (const f of s.faces!) for (let k = 1; k + 1 < f.length; k++) index.push(f[0], f[k], f[k + 1]);
      // Flat shading: one copy of each vertex per triangle.
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(s.vertices!, 3));
      g.setIndex(index);
      const flat = g.toNonIndexed();
      flat.computeVertexNormals();
      return flat;
    }
    case ShapeType.TriangleMesh: {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(s.vertices!, 3));
      g.setIndex(new THREE.BufferAttribute(s.indices!, 1));
      const flat = g.toNonIndexed();
      flat.computeVertexNormals();
      return flat;
    }
    case ShapeType.Plane: {
      // A finite patch of the plane around its point nearest the origin.
      const g = new THREE.PlaneGeometry(40, 40);
      const n = new THREE.Vector3(...s.normal!);
      g.applyQuaternion(new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 0, 1), n));
      g.translate(n.x * s.offset!, n.y * s.offset!, n.z * s.offset!);
      return g;
    }
  }
}

export class View3D {
  readonly renderer: THREE.WebGLRenderer;
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  readonly scene = new THREE.Scene();
  toggles: Toggles = { contacts: true, normals: true, joints: true, aabbs: false, sleep: true, strain: true, measure: 'strain', wireframe: false };
  selected = -1;

  private rec?: Recording;
  private frame?: Frame;
  private root = new THREE.Group();
  private bodies: THREE.Group[] = [];
  private materials: THREE.MeshStandardMaterial[] = [];
  private baseColours: THREE.Color[] = [];
  private softMeshes: THREE.Mesh[] = [];
  private softMaterials: THREE.MeshStandardMaterial[] = [];
  private softScratch: Float32Array[] = [];
  private contactPoints!: THREE.Points;
  private normalLines!: THREE.LineSegments;
  private jointLines!: THREE.LineSegments;
  private aabbLines!: THREE.LineSegments;
  private grid: THREE.GridHelper;

  constructor(private readonly container: HTMLElement) {
    // preserveDrawingBuffer: tests and screenshots read the canvas back between frames.
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(2, window.devicePixelRatio));
    container.appendChild(this.renderer.domElement);
    this.scene.background = new THREE.Color(BACKGROUND);
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 2000);
    this.camera.position.set(8, 6, 10);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    this.scene.add(new THREE.HemisphereLight(0xdfe8ff, 0x303030, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(5, 12, 7);
    this.scene.add(sun);
    this.grid = new THREE.GridHelper(40, 40, 0x3b4350, 0x2b3139);
    this.scene.add(this.grid);
    this.scene.add(this.root);
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize(): void {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  load(rec: Recording): void {
    this.rec = rec;
    this.scene.remove(this.root);
    this.root = new THREE.Group();
    this.scene.add(this.root);
    this.bodies = [];
    this.materials = [];
    this.baseColours = [];
    this.softMeshes = [];
    this.softMaterials = [];
    this.softScratch = [];
    this.selected = -1;
    const h = rec.header;
    h.bodies.forEach((b, i) => {
      const colour = b.type === BodyType.Static ? STATIC_COLOUR.clone() : dynamicColour(i);
      const material = new THREE.MeshStandardMaterial({ color: colour, roughness: 0.75, metalness: 0.05, side: THREE.DoubleSide });
      const group = new THREE.Group();
      group.userData.body = i;
      this.bodies.push(group);
      this.materials.push(material);
      this.baseColours.push(colour);
      this.root.add(group);
    });
    for (const s of h.shapes) {
      const mesh = new THREE.Mesh(shapeGeometry(s), this.materials[s.body]);
      mesh.position.set(...s.position);
      mesh.quaternion.set(...s.rotation);
      mesh.userData.body = s.body;
      this.bodies[s.body].add(mesh);
    }
    h.softBodies.forEach((sb, k) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * sb.vertexCount), 3));
      g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(3 * sb.vertexCount), 3));
      g.setIndex(new THREE.BufferAttribute(sb.surface, 1));
      const material = new THREE.MeshStandardMaterial({ color: 0xffffff, vertexColors: true, roughness: 0.6, side: THREE.DoubleSide });
      const mesh = new THREE.Mesh(g, material);
      mesh.userData.soft = k;
      mesh.frustumCulled = false;
      this.softMeshes.push(mesh);
      this.softMaterials.push(material);
      this.softScratch.push(new Float32Array(sb.vertexCount));
      this.root.add(mesh);
    });
    const overlay = () => new THREE.BufferGeometry();
    this.contactPoints = new THREE.Points(overlay(), new THREE.PointsMaterial({ color: 0xff3b3b, size: 6, sizeAttenuation: false, depthTest: false }));
    this.normalLines = new THREE.LineSegments(overlay(), new THREE.LineBasicMaterial({ color: 0xffe14d, depthTest: false }));
    this.jointLines = new THREE.LineSegments(overlay(), new THREE.LineBasicMaterial({ vertexColors: true, depthTest: false }));
    this.aabbLines = new THREE.LineSegments(overlay(), new THREE.LineBasicMaterial({ color: 0x5aa9ff }));
    for (const o of [this.contactPoints, this.normalLines, this.jointLines, this.aabbLines]) {
      o.frustumCulled = false;
      o.renderOrder = 10;
      this.root.add(o);
    }
    this.show(rec.frame(0));
    this.frameCamera();
  }

  /** Points the camera at the moving things of the first frame (statics only if nothing moves). */
  frameCamera(): void {
    if (!this.rec) return;
    const box = new THREE.Box3();
    const h = this.rec.header;
    this.root.updateMatrixWorld(true);
    this.bodies.forEach((g, i) => { if (h.bodies[i].type !== BodyType.Static) box.expandByObject(g); });
    for (const m of this.softMeshes) { m.geometry.computeBoundingBox(); box.union(m.geometry.boundingBox!); }
    if (box.isEmpty()) this.bodies.forEach((g, i) => { if (!h.shapes.some(s => s.body === i && s.type === ShapeType.Plane)) box.expandByObject(g); });
    if (box.isEmpty()) box.set(new THREE.Vector3(-1, 0, -1), new THREE.Vector3(1, 2, 1));
    const centre = box.getCenter(new THREE.Vector3());
    const radius = Math.max(0.5, box.getSize(new THREE.Vector3()).length() / 2);
    const distance = radius / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.1;
    const direction = new THREE.Vector3(1, 0.55, 1.35).normalize();
    this.camera.position.copy(centre).addScaledVector(direction, distance);
    this.camera.near = distance / 200;
    this.camera.far = distance * 50;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.grid.position.y = Math.min(0, box.min.y);
    this.render();
  }

  show(frame: Frame): void {
    if (!this.rec) return;
    this.frame = frame;
    const h = this.rec.header;
    const t = this.toggles;
    this.bodies.forEach((g, i) => {
      g.position.fromArray(frame.positions, 3 * i);
      g.quaternion.fromArray(frame.rotations, 4 * i);
      g.visible = (frame.bodyFlags[i] & BODY_REMOVED) === 0;
      const asleep = (frame.bodyFlags[i] & BODY_ASLEEP) !== 0;
      const m = this.materials[i];
      m.color.copy(t.sleep && asleep ? SLEEP_COLOUR : this.baseColours[i]);
      m.emissive.copy(i === this.selected ? SELECTED_EMISSIVE : new THREE.Color(0));
      m.wireframe = t.wireframe;
    });
    const colour = new THREE.Color();
    h.softBodies.forEach((sb, k) => {
      const mesh = this.softMeshes[k];
      const position = mesh.geometry.getAttribute('position') as THREE.BufferAttribute;
      (position.array as Float32Array).set(frame.softPositions[k]);
      position.needsUpdate = true;
      const colours = mesh.geometry.getAttribute('color') as THREE.BufferAttribute;
      const c = colours.array as Float32Array;
      if (t.strain && t.measure === 'j') {
        const j = vertexMean(sb, frame.softJ[k], this.softScratch[k], 1);
        for (let v = 0; v < sb.vertexCount; v++) jColour(j[v], colour).toArray(c, 3 * v);
      } else if (t.strain) {
        const e = vertexMean(sb, frame.softStrain[k], this.softScratch[k], 0);
        for (let v = 0; v < sb.vertexCount; v++) strainColour(e[v], colour).toArray(c, 3 * v);
      } else {
        colour.set(0xe87fb0);
        for (let v = 0; v < sb.vertexCount; v++) colour.toArray(c, 3 * v);
      }
      colours.needsUpdate = true;
      mesh.geometry.computeVertexNormals();
      mesh.geometry.computeBoundingSphere();
      this.softMaterials[k].wireframe = t.wireframe;
    });
    this.updateContacts(frame);
    this.updateJoints(frame);
    this.updateAabbs();
    this.render();
  }

  // Overlays keep one buffer per attribute and grow it by doubling, so that stepping through
  // a recording does not create GPU buffers every frame; the draw range says how much is used.
  // (Overlays are never frustum-culled or picked, so they need no bounding sphere.)
  private static setPositions(o: THREE.Points | THREE.LineSegments, data: Float32Array, colours?: Float32Array): void {
    const g = o.geometry;
    View3D.fill(g, 'position', data);
    if (colours) View3D.fill(g, 'color', colours);
    g.setDrawRange(0, data.length / 3);
  }

  private static fill(g: THREE.BufferGeometry, name: string, data: Float32Array): void {
    let a = g.getAttribute(name) as THREE.BufferAttribute | undefined;
    if (!a || a.array.length < data.length) {
      a = new THREE.BufferAttribute(new Float32Array(Math.max(3, data.length, 2 * (a?.array.length ?? 0))), 3);
      a.setUsage(THREE.DynamicDrawUsage);
      g.setAttribute(name, a);
    }
    (a.array as Float32Array).set(data);
    a.needsUpdate = true;
  }

  private updateContacts(frame: Frame): void {
    const n = frame.contactCount, c = frame.contacts;
    const points = new Float32Array(3 * n), lines = new Float32Array(6 * n);
    // Normal length: 0.3 m at the frame's largest impulse, at least 0.05 m.
    let maxImpulse = 0;
    for (let k = 0; k < n; k++) maxImpulse = Math.max(maxImpulse, c[8 * k + 6]);
    for (let k = 0; k < n; k++) {
      const o = 8 * k;
      points.set(c.subarray(o, o + 3), 3 * k);
      const length = 0.05 + (maxImpulse > 0 ? 0.25 * c[o + 6] / maxImpulse : 0);
      for (let a = 0; a < 3; a++) {
        lines[6 * k + a] = c[o + a];
        lines[6 * k + 3 + a] = c[o + a] + c[o + 3 + a] * length;
      }
    }
    View3D.setPositions(this.contactPoints, points);
    View3D.setPositions(this.normalLines, lines);
    this.contactPoints.visible = this.toggles.contacts;
    this.normalLines.visible = this.toggles.normals;
  }

  private updateJoints(frame: Frame): void {
    const h = this.rec!.header;
    const n = h.joints.length;
    // Per joint: anchor A to anchor B (green when together, red with error), and each frame's
    // x axis (the joint axis) 0.2 m long.
    const p = new Float32Array(18 * n), col = new Float32Array(18 * n);
    const q = new THREE.Quaternion(), x = new THREE.Vector3();
    const red = new THREE.Color(0xff4040), green = new THREE.Color(0x40ff80), axis = new THREE.Color(0x40c0ff), grey = new THREE.Color(0x808080);
    for (let j = 0; j < n; j++) {
      const d = frame.joints.subarray(16 * j, 16 * j + 16);
      const broken = (frame.jointFlags[j] & JOINT_BROKEN) !== 0;
      const error = d[14];
      const link = broken ? grey : green.clone().lerp(red, Math.min(1, error / 0.01));
      const seg = (s: number, a: ArrayLike<number>, b: ArrayLike<number>, c: THREE.Color) => {
        for (let k = 0; k < 3; k++) { p[18 * j + 6 * s + k] = a[k]; p[18 * j + 6 * s + 3 + k] = b[k]; }
        c.toArray(col, 18 * j + 6 * s); c.toArray(col, 18 * j + 6 * s + 3);
      };
      seg(0, d.subarray(0, 3), d.subarray(3, 6), link);
      for (let side = 0; side < 2; side++) {
        q.fromArray(d, 6 + 4 * side);
        x.set(0.2, 0, 0).applyQuaternion(q);
        const a = d.subarray(3 * side, 3 * side + 3);
        seg(1 + side, a, [a[0] + x.x, a[1] + x.y, a[2] + x.z], axis);
      }
    }
    View3D.setPositions(this.jointLines, p, col);
    this.jointLines.visible = this.toggles.joints;
  }

  private updateAabbs(): void {
    this.aabbLines.visible = this.toggles.aabbs;
    if (!this.toggles.aabbs || !this.rec) return;
    const boxes: THREE.Box3[] = [];
    this.root.updateMatrixWorld(true);
    const h = this.rec.header;
    this.bodies.forEach((g, i) => {
      if (!g.visible || h.shapes.some(s => s.body === i && s.type === ShapeType.Plane)) return;
      boxes.push(new THREE.Box3().setFromObject(g));
    });
    for (const m of this.softMeshes) { m.geometry.computeBoundingBox(); boxes.push(m.geometry.boundingBox!.clone()); }
    const p = new Float32Array(boxes.length * 72);
    const corner = (b: THREE.Box3, i: number) => [i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z];
    const edges = [[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7], [0, 4], [1, 5], [2, 6], [3, 7]];
    boxes.forEach((b, k) => edges.forEach(([a, c], e) => { p.set(corner(b, a), 72 * k + 6 * e); p.set(corner(b, c), 72 * k + 6 * e + 3); }));
    View3D.setPositions(this.aabbLines, p);
  }

  /** Re-applies the toggles to the frame on screen. */
  refresh(): void { if (this.frame) this.show(this.frame); }

  render(): void { this.renderer.render(this.scene, this.camera); }

  /** The body under a canvas pixel, or -1. */
  pick(clientX: number, clientY: number): number {
    const r = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    for (const hit of ray.intersectObjects(this.bodies, true))
      if (hit.object.userData.body !== undefined && hit.object.visible) return hit.object.userData.body as number;
    return -1;
  }

  /** Where a world point lands on the page, in CSS pixels (for tests and labels). */
  project(p: THREE.Vector3): { x: number; y: number } {
    const r = this.renderer.domElement.getBoundingClientRect();
    const v = p.clone().project(this.camera);
    return { x: r.left + ((v.x + 1) / 2) * r.width, y: r.top + ((1 - v.y) / 2) * r.height };
  }

  bodyCentre(i: number): THREE.Vector3 {
    this.root.updateMatrixWorld(true);
    return new THREE.Box3().setFromObject(this.bodies[i]).getCenter(new THREE.Vector3());
  }

  softCentre(k: number): THREE.Vector3 {
    this.softMeshes[k].geometry.computeBoundingBox();
    return this.softMeshes[k].geometry.boundingBox!.getCenter(new THREE.Vector3());
  }
}
