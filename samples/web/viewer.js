// hullpack viewer: loads a packed GLB (HULLPACK_mesh_compression + OMI physics hulls) with three.js
// and the WebAssembly o3dgc decoder, or a bare .s3d stream.
// URL parameters: ?glb=URL (default dist/torus.glb; set-up also packs dist/mug.glb) | ?stream=URL ; &worker=1 decodes in a Web
// Worker ; &wasm=URL of the .wasm (default dist/hullpack_decoder_wasm.wasm) ; &hulls=1.
// The result is published as window.hullpackViewer.ready (a Promise of the figures shown).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
import { createDecoder, createWorkerDecoder, bounds } from '../../web/hullpack_decoder.js';
import { HullpackMeshCompressionPlugin, setHullsVisible } from '../../web/hullpack_gltf_plugin.js';

const params = new URLSearchParams(location.search);
const wasmUrl = params.get('wasm') || 'dist/hullpack_decoder_wasm.wasm';
const streamUrl = params.get('stream');
const glbUrl = params.get('glb') || (streamUrl ? null : 'dist/torus.glb');
const useWorker = params.get('worker') === '1';

const view = document.getElementById('view');
const statsEl = document.getElementById('stats');
const errorEl = document.getElementById('error');

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
renderer.setSize(view.clientWidth, view.clientHeight);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242a);
const camera = new THREE.PerspectiveCamera(45, view.clientWidth / view.clientHeight, 0.01, 1000);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = true;
scene.add(new THREE.HemisphereLight(0xffffff, 0x404050, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 2.0);
sun.position.set(3, 5, 4);
scene.add(sun);

let rendered = 0;
let mixer = null;  // plays the file's first animation clip, when it has one
const clock = new THREE.Clock();
function frame() {
  controls.update();
  if (mixer) mixer.update(clock.getDelta());
  renderer.render(scene, camera);
  rendered += 1;
  requestAnimationFrame(frame);
}
window.addEventListener('resize', () => {
  camera.aspect = view.clientWidth / view.clientHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(view.clientWidth, view.clientHeight);
});

function frameObject(object) {
  const box = new THREE.Box3().setFromObject(object);
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(1e-6, box.getSize(new THREE.Vector3()).length() / 2);
  const dist = radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
  camera.position.copy(center).add(new THREE.Vector3(0.55, 0.65, 0.75).normalize().multiplyScalar(dist * 1.05));
  camera.near = dist / 100;
  camera.far = dist * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(center);
}

async function fetchBytes(url) {
  const res = await fetch(url);
  if (!res.ok) throw new Error(`${url}: HTTP ${res.status}`);
  return new Uint8Array(await res.arrayBuffer());
}

function geometryFromMesh(mesh) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(mesh.positions, 3));
  if (mesh.normals) g.setAttribute('normal', new THREE.BufferAttribute(mesh.normals, 3));
  if (mesh.uvs[0]) g.setAttribute('uv', new THREE.BufferAttribute(mesh.uvs[0], 2));
  g.setIndex(new THREE.BufferAttribute(mesh.indices, 1));
  if (!mesh.normals) g.computeVertexNormals();
  return g;
}

const material = new THREE.MeshStandardMaterial({ color: 0xcc8c4d, roughness: 0.6, metalness: 0.1 });

async function load() {
  const t0 = performance.now();
  const decoder = useWorker ? await createWorkerDecoder({ wasmUrl }) : await createDecoder({ wasmUrl });
  const info = { source: glbUrl || streamUrl, worker: useWorker, initMs: performance.now() - t0 };
  let root;
  if (glbUrl) {
    const bytes = await fetchBytes(glbUrl);
    info.fileBytes = bytes.length;
    const loader = new GLTFLoader();
    loader.register((parser) => new HullpackMeshCompressionPlugin(parser, decoder));
    loader.setMeshoptDecoder(MeshoptDecoder);  // animation key frames (EXT_meshopt_compression)
    const t1 = performance.now();
    const gltf = await loader.parseAsync(bytes.buffer, new URL(glbUrl, location.href).href);
    info.loadMs = performance.now() - t1;
    info.decodeMs = gltf.userData.hullpackStats.decodeMs;
    info.streams = gltf.userData.hullpackStats.streams;
    root = gltf.scene;
    info.clips = gltf.animations.map((clip) => clip.name);
    if (gltf.animations.length > 0) {
      mixer = new THREE.AnimationMixer(root);
      mixer.clipAction(gltf.animations[0]).play();
    }
    // Render meshes only (the hull meshes the plugin added are counted separately).
    let vertices = 0;
    let triangles = 0;
    const box = new THREE.Box3();
    root.traverse((o) => {
      if (!o.isMesh || o.parent?.userData.hullpackHull) return;
      if (!o.material.isMeshBasicMaterial) o.material.side = THREE.DoubleSide;
      vertices += o.geometry.attributes.position.count;
      triangles += (o.geometry.index ? o.geometry.index.count : o.geometry.attributes.position.count) / 3;
      const b = bounds(o.geometry.attributes.position.array);
      box.expandByPoint(new THREE.Vector3(...b.min)).expandByPoint(new THREE.Vector3(...b.max));
    });
    Object.assign(info, { vertices, triangles, min: box.min.toArray(), max: box.max.toArray() });
    info.hulls = gltf.userData.hullpackHulls.map((h) => ({
      node: h.nodeIndex, points: h.points.length / 3, vertices: h.positions.length / 3,
      triangles: h.indices.length / 3, ...bounds(h.positions),
    }));
    const hullBox = document.getElementById('hulls');
    hullBox.checked = params.get('hulls') === '1';
    setHullsVisible(gltf, hullBox.checked);
    hullBox.onchange = () => setHullsVisible(gltf, hullBox.checked);
  } else {
    const bytes = await fetchBytes(streamUrl);
    info.fileBytes = bytes.length;
    const t1 = performance.now();
    const mesh = await decoder.decode(bytes);
    info.decodeMs = performance.now() - t1;
    Object.assign(info, { vertices: mesh.numVertices, triangles: mesh.numTriangles, ...bounds(mesh.positions), hulls: [], clips: [] });
    root = new THREE.Mesh(geometryFromMesh(mesh), material);
  }
  document.getElementById('wire').onchange = (e) => {
    root.traverse((o) => { if (o.isMesh && !o.parent?.userData.hullpackHull) o.material.wireframe = e.target.checked; });
  };
  scene.add(root);
  frameObject(root);
  if (decoder.terminate) decoder.terminate();
  statsEl.textContent = [
    `file      ${info.source}`,
    `size      ${info.fileBytes.toLocaleString()} bytes`,
    `vertices  ${info.vertices.toLocaleString()}`,
    `triangles ${info.triangles.toLocaleString()}`,
    `decode    ${info.decodeMs.toFixed(2)} ms${useWorker ? ' (worker)' : ''}`,
    `hulls     ${info.hulls.length}`,
    `clips     ${info.clips.length}${info.clips.length ? ` (playing '${info.clips[0]}')` : ''}`,
  ].join('\n');
  requestAnimationFrame(frame);
  // Resolve once a few frames have been drawn.
  await new Promise((resolve) => {
    const wait = () => (rendered >= 3 ? resolve() : requestAnimationFrame(wait));
    wait();
  });
  return info;
}

const ready = load().catch((err) => {
  errorEl.textContent = String(err && err.stack ? err.stack : err);
  throw err;
});
window.hullpackViewer = { ready, renderer, scene, camera };
