// The 3D viewer of msmesh's HTML report (cli/report_page.cpp writes the page).
//
// The page holds the data in <script type="application/json" id="msmesh-data">: meshes with
// base64 little-endian arrays (positions float32 #V*3, indices uint32 #F*3, optional per-face
// error in degrees, edge field on the edges of build_topology, labels, highlighted faces).
// This script builds a three.js scene with a toolbar (mesh, colour mode, wireframe, reset),
// a legend, and orbit controls; it renders on demand only.
//
// Status for people and tests: document.body.dataset.viewer becomes "ready" after the first
// frame, "no-webgl" when WebGL is unavailable, "error" on failure (message shown in the page).
import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  DirectionalLight,
  DoubleSide,
  LinearSRGBColorSpace,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

// ---- colour maps: the same as the C++ side (draw/color_map.cpp heat_color, cli/field_files.cpp) ----

const HEAT = [
  [255, 255, 204], [255, 237, 160], [254, 217, 118], [254, 178, 76], [253, 141, 60],
  [252, 78, 42], [227, 26, 28], [189, 0, 38], [128, 0, 38],
];

export function heatColor(x) {
  if (!(x > 0)) x = 0;
  x = Math.min(x, 1) * 8;
  const i = Math.min(7, Math.floor(x));
  const t = x - i;
  return HEAT[i].map((c, k) => (c + t * (HEAT[i + 1][k] - c)) / 255);
}

export function fieldColor(x) {
  x = Math.min(1, Math.max(0, x));
  const a = [0.45, 0.0, 0.05], b = [1.0, 0.8, 0.1], c = [0.85, 0.85, 0.85];
  return x < 0.5 ? a.map((v, k) => v + (b[k] - v) * (x / 0.5)) : b.map((v, k) => v + (c[k] - v) * ((x - 0.5) / 0.5));
}

const BASE = [0.8, 0.8, 0.8];
const HIGHLIGHT = [0.45, 0.7, 0.95];
const FIELD_DRAW_BELOW = 0.9; // as cli/figures.cpp field_coloring: smooth edges are not drawn

// ---- decoding ----

function bytes(b64) {
  const bin = atob(b64);
  const u = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; ++i) u[i] = bin.charCodeAt(i);
  return u;
}
function float32s(b64) {
  const u = bytes(b64);
  const dv = new DataView(u.buffer);
  const out = new Float32Array(u.length / 4);
  for (let i = 0; i < out.length; ++i) out[i] = dv.getFloat32(4 * i, true);
  return out;
}
function uint32s(b64) {
  const u = bytes(b64);
  const dv = new DataView(u.buffer);
  const out = new Uint32Array(u.length / 4);
  for (let i = 0; i < out.length; ++i) out[i] = dv.getUint32(4 * i, true);
  return out;
}

// ---- page helpers ----

function el(tag, attrs = {}, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function fmt(x) {
  if (!isFinite(x)) return '-';
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1e-3 && a < 1e5) return String(Number(x.toPrecision(3)));
  return x.toExponential(1);
}

function setStatus(status, message) {
  document.body.dataset.viewer = status;
  if (message) {
    const host = document.getElementById('msmesh-viewer');
    if (host) host.appendChild(el('div', { class: 'msg' }, message));
  }
}

// ---- one mesh of the report ----

class ReportMesh {
  constructor(d, labelColors, earlier) {
    this.name = d.name;
    this.positions = float32s(d.positions);
    // "indices_of": the faces of an earlier mesh (input, result and truth of a denoising share them).
    this.indices = d.indices ? uint32s(d.indices) : earlier[d.indices_of].indices;
    this.faces = this.indices.length / 3;
    this.error = d.error ? float32s(d.error) : null;
    this.labels = d.labels ? uint32s(d.labels) : null;
    this.highlight = d.highlight ? uint32s(d.highlight) : null;
    this.edges = d.edges ? uint32s(d.edges) : null;
    this.field = d.field ? float32s(d.field) : null;
    this.fieldMin = d.field_min;
    this.fieldMax = d.field_max;
    this.labelColors = labelColors;

    // Unshared vertices: one normal and one colour per face (flat shading).
    const n = this.faces;
    const pos = new Float32Array(9 * n);
    for (let f = 0; f < n; ++f)
      for (let k = 0; k < 3; ++k) {
        const v = this.indices[3 * f + k];
        pos.set(this.positions.subarray(3 * v, 3 * v + 3), 9 * f + 3 * k);
      }
    this.geometry = new BufferGeometry();
    this.geometry.setAttribute('position', new BufferAttribute(pos, 3));
    this.geometry.setAttribute('color', new BufferAttribute(new Float32Array(9 * n), 3));
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingBox();
    this.material = new MeshLambertMaterial({
      vertexColors: true,
      side: DoubleSide,
      flatShading: true,
      polygonOffset: true, // lines drawn on top of the faces win the depth test
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    this.mesh = new Mesh(this.geometry, this.material);
    this.fieldLines = null;
    this.wireframe = null;
  }

  has(mode) {
    if (mode === 'shaded') return true;
    if (mode === 'error') return !!this.error;
    if (mode === 'field') return !!this.field;
    if (mode === 'labels') return !!this.labels;
    return false;
  }

  colorFaces(mode, errorMax) {
    const col = this.geometry.getAttribute('color');
    const a = col.array;
    for (let f = 0; f < this.faces; ++f) {
      let c = BASE;
      if (mode === 'error' && this.error) c = heatColor(this.error[f] / errorMax);
      else if (mode === 'labels' && this.labels) {
        const l = this.labels[f];
        c = this.labelColors.length >= 3 * (l + 1) ? this.labelColors.slice(3 * l, 3 * l + 3) : BASE;
      } else if (mode === 'shaded' && this.highlight && this.highlight[f]) c = HIGHLIGHT;
      for (let k = 0; k < 3; ++k) a.set(c, 9 * f + 3 * k);
    }
    col.needsUpdate = true;
  }

  getFieldLines() {
    if (this.fieldLines || !this.field) return this.fieldLines;
    const lo = this.fieldMin, hi = this.fieldMax, span = hi - lo > 1e-12 ? hi - lo : 0;
    const pos = [], col = [];
    for (let e = 0; e < this.field.length; ++e) {
      const vn = span ? (this.field[e] - lo) / span : 1;
      if (vn >= FIELD_DRAW_BELOW) continue;
      const c = fieldColor(vn);
      for (let k = 0; k < 2; ++k) {
        const v = this.edges[2 * e + k];
        pos.push(this.positions[3 * v], this.positions[3 * v + 1], this.positions[3 * v + 2]);
        col.push(c[0], c[1], c[2]);
      }
    }
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(new Float32Array(pos), 3));
    g.setAttribute('color', new BufferAttribute(new Float32Array(col), 3));
    this.fieldLines = new LineSegments(g, new LineBasicMaterial({ vertexColors: true }));
    return this.fieldLines;
  }

  getWireframe() {
    if (this.wireframe) return this.wireframe;
    const seen = new Set();
    const pos = [];
    const nv = this.positions.length / 3;
    for (let f = 0; f < this.faces; ++f)
      for (let k = 0; k < 3; ++k) {
        let a = this.indices[3 * f + k], b = this.indices[3 * f + ((k + 1) % 3)];
        if (a > b) [a, b] = [b, a];
        const key = a * nv + b;
        if (seen.has(key)) continue;
        seen.add(key);
        for (const v of [a, b]) pos.push(this.positions[3 * v], this.positions[3 * v + 1], this.positions[3 * v + 2]);
      }
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(new Float32Array(pos), 3));
    this.wireframe = new LineSegments(g, new LineBasicMaterial({ color: 0x333333, transparent: true, opacity: 0.35 }));
    return this.wireframe;
  }
}

// ---- the viewer ----

const MODE_NAMES = { shaded: 'shaded', error: 'angle error', field: 'edge field v', labels: 'segments' };

class Viewer {
  constructor(host, toolbar, data) {
    this.host = host;
    this.data = data;
    this.errorMax = data.error_max > 0 ? data.error_max : 1;
    this.meshes = [];
    for (const m of data.meshes) this.meshes.push(new ReportMesh(m, data.label_colors || [], this.meshes));
    this.current = Math.min(Math.max(0, data.initial_mesh | 0), this.meshes.length - 1);
    this.modes = ['shaded', 'error', 'field', 'labels'].filter((m) => this.meshes.some((x) => x.has(m)));
    this.mode = this.modes.includes(data.initial_color) ? data.initial_color : 'shaded';
    this.showWire = false;

    this.renderer = new WebGLRenderer({ antialias: true });
    this.renderer.outputColorSpace = LinearSRGBColorSpace; // colours as given, like the PNGs
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0xffffff, 1);
    host.appendChild(this.renderer.domElement);

    this.scene = new Scene();
    this.camera = new PerspectiveCamera(30, 1, 0.01, 100);
    // Lights as in render.h: ambient 0.3 + diffuse 0.7 from the upper left of the camera
    // (three.js lights carry a factor pi since r155).
    this.scene.add(new AmbientLight(0xffffff, 0.3 * Math.PI));
    const key = new DirectionalLight(0xffffff, 0.7 * Math.PI);
    key.position.set(-0.4, 0.55, 1.0); // in camera coordinates: the light turns with the view
    this.camera.add(key);
    this.camera.add(key.target); // target at the camera's origin: direction fixed in camera space
    this.scene.add(this.camera);

    // Frame all meshes together: centre and size of their union box.
    const lo = new Vector3(Infinity, Infinity, Infinity), hi = new Vector3(-Infinity, -Infinity, -Infinity);
    for (const m of this.meshes) {
      if (!m.faces) continue;
      lo.min(m.geometry.boundingBox.min);
      hi.max(m.geometry.boundingBox.max);
    }
    if (!isFinite(lo.x)) {
      lo.set(-1, -1, -1);
      hi.set(1, 1, 1);
    }
    this.center = lo.clone().add(hi).multiplyScalar(0.5);
    this.radius = Math.max(1e-9, hi.clone().sub(lo).length() / 2);
    this.camera.near = this.radius / 100;
    this.camera.far = this.radius * 100;

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    this.resetView();

    this.buildToolbar(toolbar);
    this.legend = el('div', { class: 'legend' });
    host.appendChild(this.legend);
    host.appendChild(el('div', { class: 'hint' }, 'drag: rotate · wheel: zoom · right-drag: pan'));

    new ResizeObserver(() => this.resize()).observe(host);
    this.resize();
    this.update();
  }

  resetView() {
    // The iso view of the PNGs: from the (1, 1, 1) octant, +y up.
    const dist = this.radius / Math.sin((this.camera.fov * Math.PI) / 360);
    const dir = new Vector3(1, 1, 1).normalize();
    this.camera.position.copy(this.center).addScaledVector(dir, dist);
    this.camera.up.set(0, 1, 0);
    this.controls.target.copy(this.center);
    this.controls.update();
    this.render();
  }

  buildToolbar(bar) {
    const meshGroup = el('div', { class: 'group' });
    meshGroup.appendChild(el('span', {}, 'Mesh:'));
    this.meshButtons = this.meshes.map((m, i) => {
      const b = el('button', { type: 'button', 'data-mesh': m.name }, m.name);
      b.addEventListener('click', () => {
        this.current = i;
        this.update();
      });
      meshGroup.appendChild(b);
      return b;
    });
    bar.appendChild(meshGroup);

    const modeGroup = el('div', { class: 'group' });
    modeGroup.appendChild(el('label', { for: 'msmesh-mode' }, 'Colour:'));
    this.modeSelect = el('select', { id: 'msmesh-mode' });
    for (const m of this.modes) this.modeSelect.appendChild(el('option', { value: m }, MODE_NAMES[m]));
    this.modeSelect.value = this.mode;
    this.modeSelect.addEventListener('change', () => {
      this.mode = this.modeSelect.value;
      this.update();
    });
    modeGroup.appendChild(this.modeSelect);
    bar.appendChild(modeGroup);

    const wire = el('label', { class: 'group' });
    const box = el('input', { type: 'checkbox', id: 'msmesh-wire' });
    box.addEventListener('change', () => {
      this.showWire = box.checked;
      this.update();
    });
    wire.appendChild(box);
    wire.appendChild(document.createTextNode('wireframe'));
    bar.appendChild(wire);

    const reset = el('button', { type: 'button' }, 'reset view');
    reset.addEventListener('click', () => this.resetView());
    bar.appendChild(reset);
  }

  update() {
    const m = this.meshes[this.current];
    this.meshButtons.forEach((b, i) => b.classList.toggle('on', i === this.current));
    const mode = m.has(this.mode) ? this.mode : 'shaded';
    m.colorFaces(mode, this.errorMax);
    for (const o of this.shown || []) this.scene.remove(o);
    this.shown = [m.mesh];
    if (mode === 'field') this.shown.push(m.getFieldLines());
    if (this.showWire) this.shown.push(m.getWireframe());
    for (const o of this.shown) this.scene.add(o);
    this.updateLegend(m, mode);
    this.render();
  }

  updateLegend(m, mode) {
    const L = this.legend;
    L.textContent = '';
    const gradient = (fn) =>
      'linear-gradient(to right,' +
      Array.from({ length: 11 }, (_, i) => {
        const c = fn(i / 10).map((x) => Math.round(x * 255));
        return `rgb(${c[0]},${c[1]},${c[2]}) ${i * 10}%`;
      }).join(',') +
      ')';
    const addBar = (title, fn, lo, hi) => {
      L.appendChild(el('div', {}, title));
      const b = el('div', { class: 'bar' });
      b.style.background = gradient(fn);
      L.appendChild(b);
      const ends = el('div', { class: 'ends' });
      ends.appendChild(el('span', {}, lo));
      ends.appendChild(el('span', {}, hi));
      L.appendChild(ends);
    };
    if (mode === 'error') {
      addBar('angle error (deg)', heatColor, '0', fmt(this.errorMax) + '+');
      const row = el('div', {}, 'scale top ');
      const input = el('input', { type: 'number', min: '0.001', step: 'any', value: String(this.errorMax), id: 'msmesh-error-max' });
      input.addEventListener('change', () => {
        const v = parseFloat(input.value);
        if (v > 0) {
          this.errorMax = v;
          this.update();
        }
      });
      row.appendChild(input);
      row.appendChild(document.createTextNode(' deg'));
      L.appendChild(row);
    }
    else if (mode === 'field') addBar('edge field v (features dark)', fieldColor, fmt(m.fieldMin), fmt(m.fieldMax));
    else if (mode === 'labels') {
      let count = 0;
      for (let f = 0; f < m.faces; ++f) count = Math.max(count, m.labels[f] + 1);
      L.appendChild(el('div', {}, `${count} segments`));
    } else if (m.highlight) L.appendChild(el('div', {}, 'blue: faces added by inpainting'));
    let note = `${m.name}: ${m.positions.length / 3} vertices, ${m.faces} faces`;
    if (mode !== this.mode) note += ` (no ${MODE_NAMES[this.mode]} for this mesh)`;
    L.appendChild(el('div', { class: 'note' }, note));
  }

  resize() {
    const w = Math.max(1, this.host.clientWidth), h = Math.max(1, this.host.clientHeight);
    this.renderer.setSize(w, h, true);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    if (!this.renderer) return;
    this.renderer.render(this.scene, this.camera);
    if (document.body.dataset.viewer !== 'ready') document.body.dataset.viewer = 'ready';
  }

  /// Renders and counts the canvas pixels that are not the white background (for tests).
  coveredPixels() {
    this.render();
    const gl = this.renderer.getContext();
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const px = new Uint8Array(4 * w * h);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let n = 0;
    for (let i = 0; i < px.length; i += 4) if (px[i] < 250 || px[i + 1] < 250 || px[i + 2] < 250) ++n;
    return { covered: n, total: w * h };
  }
}

function webglAvailable() {
  try {
    const c = document.createElement('canvas');
    return !!(window.WebGLRenderingContext && (c.getContext('webgl2') || c.getContext('webgl')));
  } catch (e) {
    return false;
  }
}

function start() {
  const host = document.getElementById('msmesh-viewer');
  const toolbar = document.getElementById('msmesh-toolbar');
  const dataEl = document.getElementById('msmesh-data');
  if (!host || !dataEl) return;
  try {
    const data = JSON.parse(dataEl.textContent);
    if (!webglAvailable()) {
      setStatus('no-webgl', 'This browser cannot show the 3D view (WebGL is not available). The tables and plots below are complete.');
      return;
    }
    window.msmeshViewer = new Viewer(host, toolbar, data);
  } catch (e) {
    (window.msmeshErrors = window.msmeshErrors || []).push(String(e && e.stack ? e.stack : e));
    setStatus('error', 'The 3D view failed: ' + e);
    throw e;
  }
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
