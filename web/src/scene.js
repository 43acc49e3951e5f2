// The three.js side: one BufferGeometry per layer part (made from the worker's transferred
// arrays, no copy), shared materials whose shaders hide what lies beyond the slicing plane or is
// of a filtered cell type, and a camera that renders only when something changed.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

export class Viewer {
  constructor(container) {
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(0xf4f4f6, 1);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
    this.scene.add(this.camera);
    this.scene.add(new THREE.AmbientLight(0xffffff, 1.2));
    const key = new THREE.DirectionalLight(0xffffff, 2.0);
    key.position.set(0.5, 0.8, 1.0);
    this.camera.add(key); // the light follows the view: every side can be lit
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => { this.request(); this.onView?.(); });
    this.layers = new Map(); // layer -> THREE.Group
    // Shared by every material: the slicing plane and the cell-type mask.
    this.uniforms = {
      uClipAxis: { value: new THREE.Vector3(1, 0, 0) },
      uClipPos: { value: 0 },
      uClipOn: { value: 0 },
      uTypeMask: { value: 31 },
    };
    this.container = container;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.request();
  }

  request() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.renderer.render(this.scene, this.camera);
    });
  }

  /** Renders now (the snapshot reads the canvas right after). */
  renderNow() {
    this.renderer.render(this.scene, this.camera);
  }

  frame(bbox) {
    const [lo, hi] = bbox;
    const c = new THREE.Vector3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    const d = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
    this.size = d;
    this.camera.near = d / 1000;
    this.camera.far = d * 100;
    // Far enough that the box's bounding sphere (radius d / 2) fits the narrower of the two angles
    // of view, with a margin: a wide box (subsheets side by side) in a tall canvas stays whole.
    const half = THREE.MathUtils.degToRad(this.camera.fov / 2);
    const narrow = Math.min(half, Math.atan(Math.tan(half) * this.camera.aspect));
    const dist = Math.max(1.9, 0.55 / Math.sin(narrow)) * d;
    this.camera.position.copy(c).add(new THREE.Vector3(0.9, 0.6, 1.3).normalize().multiplyScalar(dist));
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(c);
    this.controls.update();
    this.request();
  }

  /** Camera as 9 numbers (position, target, up) for the URL. */
  getView() {
    const p = this.camera.position;
    const t = this.controls.target;
    const u = this.camera.up;
    return [p.x, p.y, p.z, t.x, t.y, t.z, u.x, u.y, u.z];
  }

  setView(v) {
    if (!v || v.length < 6 || v.some((x) => !Number.isFinite(x))) return;
    this.camera.position.set(v[0], v[1], v[2]);
    this.controls.target.set(v[3], v[4], v[5]);
    if (v.length >= 9) this.camera.up.set(v[6], v[7], v[8]);
    this.controls.update();
    this.request();
  }

  setClip(on, axis, pos) {
    this.uniforms.uClipOn.value = on ? 1 : 0;
    this.uniforms.uClipAxis.value.set(axis === 0 ? 1 : 0, axis === 1 ? 1 : 0, axis === 2 ? 1 : 0);
    this.uniforms.uClipPos.value = pos;
    this.request();
  }

  setTypeMask(types) {
    this.uniforms.uTypeMask.value = types.reduce((m, on, t) => (on ? m | (1 << t) : m), 0);
    this.request();
  }

  /** A material whose shader discards fragments beyond the plane or of a filtered cell type. */
  material(kind, { opacity = 1, rgba = null, noClip = false } = {}) {
    let m;
    if (kind === 'mesh') {
      m = new THREE.MeshLambertMaterial({ vertexColors: true, flatShading: true, side: THREE.DoubleSide,
        transparent: opacity < 1, opacity, depthWrite: opacity >= 1 });
      m.polygonOffset = true; // lines drawn on a surface stay visible
      m.polygonOffsetFactor = 1;
      m.polygonOffsetUnits = 1;
    } else if (kind === 'lines') {
      m = new THREE.LineBasicMaterial({ vertexColors: true, transparent: true });
    } else {
      m = new THREE.PointsMaterial({ color: new THREE.Color(rgba[0], rgba[1], rgba[2]), size: 7, sizeAttenuation: false });
    }
    const typed = kind === 'mesh';
    const U = this.uniforms;
    m.onBeforeCompile = (shader) => {
      Object.assign(shader.uniforms, U);
      shader.vertexShader = shader.vertexShader
        .replace('#include <common>', `#include <common>
${typed ? 'attribute vec3 aAnchor;\nattribute float aType;\nvarying float vType;' : ''}
varying vec3 vAnchor;`)
        .replace('#include <begin_vertex>', `#include <begin_vertex>
${typed ? 'vAnchor = aAnchor; vType = aType;' : 'vAnchor = position;'}`);
      shader.fragmentShader = shader.fragmentShader
        .replace('#include <common>', `#include <common>
uniform vec3 uClipAxis; uniform float uClipPos; uniform float uClipOn; uniform int uTypeMask;
varying vec3 vAnchor;
${typed ? 'varying float vType;' : ''}`)
        .replace(/void main\(\) \{/, `void main() {
  ${noClip ? '' : 'if (uClipOn > 0.5 && dot(vAnchor, uClipAxis) > uClipPos) discard;'}
  ${typed ? 'if (((uTypeMask >> int(vType + 0.5)) & 1) == 0) discard;' : ''}`);
    };
    m.customProgramCacheKey = () => `${kind}-${noClip}`;
    return m;
  }

  /** Replaces a layer's objects by the worker's parts. */
  setLayer(layer, parts, style = {}) {
    this.clearLayer(layer);
    const group = new THREE.Group();
    group.name = layer;
    for (const p of parts) {
      const g = new THREE.BufferGeometry();
      const pos = new THREE.BufferAttribute(p.position, 3);
      g.setAttribute('position', pos);
      let obj;
      if (p.kind === 'mesh') {
        g.setIndex(new THREE.BufferAttribute(p.index, 1));
        g.setAttribute('color', new THREE.BufferAttribute(p.color, 3, true));
        g.setAttribute('aAnchor', new THREE.BufferAttribute(p.anchor, 3));
        g.setAttribute('aType', new THREE.BufferAttribute(p.ctype, 1));
        const see = p.boundary ? style.boundaryOpacity ?? 1 : 1;
        // The cut surface is already cut by the core: the plane must not hide it again.
        obj = new THREE.Mesh(g, this.material('mesh', { opacity: see, noClip: !!p.cut }));
        if (p.boundary) obj.renderOrder = 2;
      } else if (p.kind === 'lines') {
        g.setIndex(new THREE.BufferAttribute(p.index, 1));
        g.setAttribute('color', new THREE.BufferAttribute(p.color, 4, true));
        obj = new THREE.LineSegments(g, this.material('lines'));
        obj.renderOrder = 3;
      } else {
        obj = new THREE.Points(g, this.material('points', { rgba: p.rgba }));
        obj.renderOrder = 4;
      }
      obj.name = p.name;
      obj.userData.part = p;
      if (style.offset) obj.position.set(...style.offset(p));
      group.add(obj);
    }
    this.layers.set(layer, group);
    this.scene.add(group);
    this.request();
  }

  clearLayer(layer) {
    const group = this.layers.get(layer);
    if (!group) return;
    group.traverse((o) => {
      if (o.geometry) o.geometry.dispose();
      if (o.material) o.material.dispose();
    });
    this.scene.remove(group);
    this.layers.delete(layer);
    this.request();
  }

  clearAll() {
    for (const layer of [...this.layers.keys()]) this.clearLayer(layer);
  }

  setBoundaryOpacity(opacity) {
    const group = this.layers.get('direct');
    if (!group) return;
    for (const o of group.children) {
      if (!o.userData.part?.boundary) continue;
      o.material.opacity = opacity;
      o.material.transparent = opacity < 1;
      o.material.depthWrite = opacity >= 1;
      o.material.needsUpdate = true;
    }
    this.request();
  }

  /** The first visible face under the pointer (x, y in pixels of the canvas) among the layers
   *  given, as {layer, owner}; faces the plane or the type filter hide are skipped. */
  pick(x, y, layers) {
    const el = this.renderer.domElement;
    const ndc = new THREE.Vector2((x / el.clientWidth) * 2 - 1, -(y / el.clientHeight) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const objects = [];
    for (const l of layers) {
      const g = this.layers.get(l);
      if (g) g.traverse((o) => { if (o.isMesh && o.userData.part?.owner) objects.push(o); });
    }
    const U = this.uniforms;
    const axis = U.uClipAxis.value;
    for (const hit of ray.intersectObjects(objects, false)) {
      const p = hit.object.userData.part;
      const v = hit.face.a;
      const anchor = p.anchor;
      const along = anchor[3 * v] * axis.x + anchor[3 * v + 1] * axis.y + anchor[3 * v + 2] * axis.z;
      if (U.uClipOn.value > 0.5 && along > U.uClipPos.value && !p.cut) continue;
      if (!((U.uTypeMask.value >> p.ctype[v]) & 1)) continue;
      return { layer: hit.object.parent.name, owner: p.owner[v], part: p.name };
    }
    return null;
  }

  snapshot() {
    this.renderNow();
    return this.renderer.domElement.toDataURL('image/png');
  }
}
