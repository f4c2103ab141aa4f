// The visual report's script (embedded by cmake/EmbedReportAssets.cmake
// into the page that src/html/report_html.cpp writes).  It reads the two
// JSON blocks of the page (tmcert-data: result and witnesses;
// tmcert-geometry: bodies in their own frames and their poses at the
// slider's samples), draws the bodies with three.js, moves them with the
// time slider, and shows each witness (marker and features) at its time.
// The timeline bars are static HTML written with the exact result; this
// script only moves their playheads and lets them be clicked.
//
// State for tests and people: <html data-status="rendered"> after the
// first frame, data-time (the slider's t), data-witness-shown ("1" while a
// witness is drawn); errors are collected by the page's first script.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const data = JSON.parse(document.getElementById('tmcert-data').textContent);
const geometry = JSON.parse(document.getElementById('tmcert-geometry').textContent);
const root = document.documentElement;
const view = document.getElementById('view');
const canvas = document.getElementById('scene-canvas');
const slider = document.getElementById('time');
const timeLabel = document.getElementById('time-label');
const playButton = document.getElementById('play');
const witnessButton = document.getElementById('to-witness');

// Options in the address after '#': t=witness or t=<number> (the time
// shown first), view=<azimuth>,<elevation> and zoom=<factor> (the camera).
const pageOptions = new URLSearchParams(location.hash.slice(1));
const times = data.times;
const [tStart, tEnd] = data.range;
// "At the witness time": within half a slider step of it.
const witnessTolerance = (tEnd - tStart) / 480;
const movingColours = [0x2f73d0, 0xe0782f, 0x8a55cc, 0x16a0a0, 0xc9488a, 0x6d8f22];
const fixedColours = [0x9aa4ae, 0xb89f78, 0x7e9e8e, 0xa98fa6];

// A rational "p/q" or decimal string as a number (display only).
function displayNumber(text) {
  const slash = text.indexOf('/');
  return slash < 0 ? Number(text) : Number(text.slice(0, slash)) / Number(text.slice(slash + 1));
}

// ---------------------------------------------------------------- poses

// The pose of a body at t as a Matrix4: its sampled 3x4 matrices,
// interpolated linearly between neighbouring samples.
function poseAt(body, t, target) {
  const p = body.poses;
  let a = 0;
  let w = 0;
  if (p.length > 12) {
    let lo = 0;
    let hi = times.length - 1;
    if (t <= times[0]) hi = 0;
    else if (t >= times[hi]) lo = hi;
    else {
      while (hi - lo > 1) {
        const mid = (lo + hi) >> 1;
        if (times[mid] <= t) lo = mid; else hi = mid;
      }
      w = (t - times[lo]) / (times[hi] - times[lo]);
    }
    a = lo;
  }
  const m = new Array(12);
  for (let i = 0; i < 12; ++i) {
    const x = p[12 * a + i];
    m[i] = w > 0 ? x + w * (p[12 * (a + 1) + i] - x) : x;
  }
  return target.set(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], 0, 0, 0, 1);
}

function bufferGeometry(flat) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(flat, 3));
  return g;
}

// ---------------------------------------------------------------- scene

function buildScene(initialTime) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xeef1f5);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x7a8696, 1.8));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  scene.add(sun);

  // Bounds of everything the bodies sweep, from each body's box under its
  // samples (for the clipping planes), and of the bodies at the first time
  // shown (what the camera frames).
  const box = new THREE.Box3();
  const framed = new THREE.Box3();
  const matrix = new THREE.Matrix4();
  const legend = document.getElementById('bodies-legend');
  let moving = 0;
  let fixed = 0;
  const groups = geometry.bodies.map((body) => {
    const colour = body.moving ? movingColours[moving++ % movingColours.length]
                               : fixedColours[fixed++ % fixedColours.length];
    const group = new THREE.Group();
    group.matrixAutoUpdate = false;
    const local = new THREE.Box3();
    if (body.triangles.length) {
      const g = bufferGeometry(body.triangles);
      g.computeVertexNormals();
      local.union(g.computeBoundingBox() || g.boundingBox);
      group.add(new THREE.Mesh(g, new THREE.MeshLambertMaterial({
        color: colour, side: THREE.DoubleSide, flatShading: true,
        polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 })));
    }
    if (body.outlines.length) {
      const g = bufferGeometry(body.outlines);
      g.computeBoundingBox();
      local.union(g.boundingBox);
      group.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({
        color: new THREE.Color(colour).multiplyScalar(0.45), transparent: true, opacity: 0.35 })));
    }
    if (body.segments.length) {
      const g = bufferGeometry(body.segments);
      g.computeBoundingBox();
      local.union(g.boundingBox);
      group.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: colour })));
    }
    if (body.points.length) {
      const g = bufferGeometry(body.points);
      g.computeBoundingBox();
      local.union(g.boundingBox);
      group.add(new THREE.Points(g, new THREE.PointsMaterial({ color: colour, size: 7, sizeAttenuation: false })));
    }
    if (!local.isEmpty()) {
      const samples = body.poses.length / 12;
      for (let k = 0; k < samples; ++k) {
        const p = body.poses.slice(12 * k, 12 * k + 12);
        matrix.set(...p, 0, 0, 0, 1);
        box.union(local.clone().applyMatrix4(matrix));
      }
      framed.union(local.clone().applyMatrix4(poseAt(body, initialTime, matrix)));
    }
    scene.add(group);
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = '#' + new THREE.Color(colour).getHexString();
    legend.append(swatch, document.createTextNode(body.name + (body.moving ? '' : ' (fixed)')));
    return group;
  });

  const size = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-9);
  const centre = (framed.isEmpty() ? box : framed).getCenter(new THREE.Vector3());
  const framedSize = framed.isEmpty() ? size : Math.max(framed.getSize(new THREE.Vector3()).length(), size / 100);

  // Witnesses: a marker at the common point (drawn over everything), the
  // two features highlighted on their bodies; shown at the witness time.
  const witnesses = [];
  const markerRadius = size * 0.012;
  for (const check of data.checks) {
    const w = check.witness;
    if (!w || !w.marker) continue;
    const objects = [];
    const marker = new THREE.Group();
    // Both transparent, so that renderOrder puts the ball over its halo.
    const ball = new THREE.Mesh(new THREE.SphereGeometry(markerRadius, 24, 16),
      new THREE.MeshBasicMaterial({ color: 0xe0140c, depthTest: false, transparent: true, opacity: 1 }));
    const halo = new THREE.Mesh(new THREE.SphereGeometry(markerRadius * 1.9, 24, 16),
      new THREE.MeshBasicMaterial({ color: 0xffffff, depthTest: false, transparent: true, opacity: 0.6 }));
    ball.renderOrder = 12;
    halo.renderOrder = 11;
    marker.add(halo, ball);
    marker.position.fromArray(w.marker);
    objects.push(marker);
    if (w.points) {
      const g = bufferGeometry([...w.points[0], ...w.points[1]]);
      const line = new THREE.Line(g, new THREE.LineBasicMaterial({ color: 0xd91e18, depthTest: false }));
      line.renderOrder = 11;
      objects.push(line);
    }
    for (const h of w.highlight) {
      const parent = groups[h.body];
      if (h.triangles && h.triangles.length) {
        const g = bufferGeometry(h.triangles);
        g.computeVertexNormals();
        // Drawn through whatever hides it: contacts are often inside clutter.
        const face = new THREE.Mesh(g, new THREE.MeshBasicMaterial({
          color: 0xffc400, side: THREE.DoubleSide, transparent: true, opacity: 0.85, depthTest: false }));
        face.renderOrder = 9;
        objects.push(parentTo(parent, face));
      }
      if (h.lines && h.lines.length) {
        const line = new THREE.LineSegments(bufferGeometry(h.lines),
          new THREE.LineBasicMaterial({ color: 0x9a5200, depthTest: false, transparent: true }));
        line.renderOrder = 10;
        objects.push(parentTo(parent, line));
      }
      if (h.points) {
        for (let i = 0; i + 2 < h.points.length; i += 3) {
          const dot = new THREE.Mesh(new THREE.SphereGeometry(markerRadius * 0.7, 16, 12),
            new THREE.MeshBasicMaterial({ color: 0xff7a00, depthTest: false, transparent: true }));
          dot.renderOrder = 13;
          dot.position.set(h.points[i], h.points[i + 1], h.points[i + 2]);
          objects.push(parentTo(parent, dot));
        }
      }
    }
    for (const o of objects) {
      if (!o.parent) scene.add(o);
      o.visible = false;
    }
    witnesses.push({ t: w.t_display, objects });
  }

  // The camera looks at the centre of the bodies at the first time shown, z
  // up, from azimuth and elevation in degrees (#view=az,el in the address;
  // default -60,26) at 1.5 times their box's diagonal (#zoom=z divides it).
  const camera = new THREE.PerspectiveCamera(35, 1, size / 2000, size * 100);
  camera.up.set(0, 0, 1);
  const [az, el] = (pageOptions.get('view') || '-60,26').split(',').map((x) => Number(x) * Math.PI / 180);
  const zoom = Number(pageOptions.get('zoom')) > 0 ? Number(pageOptions.get('zoom')) : 1;
  const direction = new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
  if (!(direction.lengthSq() > 0.5)) direction.set(0.46, -0.78, 0.44);
  camera.position.copy(centre).addScaledVector(direction, framedSize * 1.5 / zoom);
  sun.position.copy(direction).add(new THREE.Vector3(0.4, 0.2, 0.6));
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(centre);
  controls.update();
  return { scene, camera, controls, groups, witnesses };
}

function parentTo(parent, object) {
  parent.add(object);
  return object;
}

// ---------------------------------------------------------------- page

let renderer = null;
let world = null;
try {
  // preserveDrawingBuffer: a page screenshot (headless Chromium, software
  // WebGL) otherwise catches a swapped, empty buffer; it also lets people
  // save the canvas as an image.
  renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
} catch (e) {
  const message = document.getElementById('view-message');
  message.hidden = false;
  message.textContent = 'This browser cannot draw the scene (WebGL is not available); the timeline below is complete.';
  throw e;  // recorded by the page's error handler
}
const firstWitness = data.checks.find((c) => c.witness)?.witness.t_display ?? null;
const shownFirst = pageOptions.get('t');
const initialTime = shownFirst === 'witness' && firstWitness !== null ? firstWitness
  : shownFirst !== null && Number.isFinite(Number(shownFirst)) ? Number(shownFirst) : tStart;
world = buildScene(initialTime);
if (data.undrawable) {
  const message = document.getElementById('view-message');
  message.hidden = false;
  message.textContent = 'The scene is not drawn: ' + data.undrawable + '. The timeline below is complete.';
}

let time = tStart;
let pending = false;
let frames = 0;

function render() {
  pending = false;
  const m = new THREE.Matrix4();
  geometry.bodies.forEach((body, i) => {
    poseAt(body, time, m);
    world.groups[i].matrix.copy(m);
    world.groups[i].matrixWorldNeedsUpdate = true;
  });
  let shown = false;
  for (const w of world.witnesses) {
    const visible = Math.abs(time - w.t) <= witnessTolerance;
    shown = shown || visible;
    for (const o of w.objects) o.visible = visible;
  }
  renderer.render(world.scene, world.camera);
  root.dataset.witnessShown = shown ? '1' : '0';
  root.dataset.time = String(time);
  if (++frames === 1) root.dataset.status = 'rendered';
}

function requestRender() {
  if (!pending) {
    pending = true;
    requestAnimationFrame(render);
  }
}

function resize() {
  const w = Math.max(1, view.clientWidth);
  const h = Math.max(1, view.clientHeight);
  renderer.setSize(w, h, false);
  world.camera.aspect = w / h;
  world.camera.updateProjectionMatrix();
  requestRender();
}

const bars = [...document.querySelectorAll('.bar')].map((bar) => ({
  bar, playhead: bar.querySelector('.playhead'),
  t0: displayNumber(bar.dataset.t0), t1: displayNumber(bar.dataset.t1) }));

function setTime(t) {
  time = Math.min(tEnd, Math.max(tStart, t));
  slider.value = String(time);
  const atWitness = world.witnesses.some((w) => Math.abs(time - w.t) <= witnessTolerance);
  timeLabel.textContent = 't = ' + time.toFixed(5) + (atWitness ? '  (witness)' : '');
  for (const b of bars) {
    const f = b.t1 > b.t0 ? (time - b.t0) / (b.t1 - b.t0) : 0;
    b.playhead.style.left = (100 * Math.min(1, Math.max(0, f))) + '%';
  }
  requestRender();
}

slider.addEventListener('input', () => { stop(); setTime(Number(slider.value)); });
world.controls.addEventListener('change', requestRender);
new ResizeObserver(resize).observe(view);

for (const b of bars) {
  b.bar.addEventListener('click', (e) => {
    stop();
    const mark = e.target.closest('.witness-mark');
    if (mark) return setTime(Number(mark.dataset.tDisplay));
    const r = b.bar.getBoundingClientRect();
    setTime(b.t0 + (b.t1 - b.t0) * (e.clientX - r.left) / r.width);
  });
}

// Play: the whole range in eight seconds.
let playing = null;
function stop() {
  if (playing !== null) cancelAnimationFrame(playing);
  playing = null;
  playButton.textContent = 'Play';
}
playButton.addEventListener('click', () => {
  if (playing !== null) return stop();
  if (time >= tEnd) setTime(tStart);
  playButton.textContent = 'Pause';
  let last = performance.now();
  const step = (now) => {
    setTime(time + (tEnd - tStart) * (now - last) / 8000);
    last = now;
    if (time >= tEnd) return stop();
    playing = requestAnimationFrame(step);
  };
  playing = requestAnimationFrame(step);
});

if (witnessButton) witnessButton.addEventListener('click', () => { stop(); setTime(firstWitness); });

setTime(initialTime);
resize();
