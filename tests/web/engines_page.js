// The engine drop tests' page (engines.html, driven by engines_test.mjs): a packed torus loaded and
// dropped from z = 2 onto the plane z = 0 (gravity -z, 4 s at 240 Hz, as the native Bullet test) in
//  - three.js + Rapier: GLTFLoader with the hullpack plugin, the compound collider built from the
//    file's OMI_physics_shape hulls (gltf.userData.hullpackHulls, body-node space);
//  - Babylon.js + Havok: Babylon's glTF loader with the hullpack extension, the compound collider
//    built from the file's KHR_physics_rigid_bodies hulls (readCollisionHulls).
// Each returns the body origin's resting height and the hull points the engine was given.
// babylonEarlierHulls reads the hulls of a file of the earlier release (hull streams).
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
import RAPIER from '@dimforge/rapier3d-compat';
import HavokPhysics from '@babylonjs/havok';
import { NullEngine } from '@babylonjs/core/Engines/nullEngine.js';
import { Scene } from '@babylonjs/core/scene.js';
import { Vector3, Quaternion } from '@babylonjs/core/Maths/math.vector.js';
import { Mesh } from '@babylonjs/core/Meshes/mesh.js';
import { VertexData } from '@babylonjs/core/Meshes/mesh.vertexData.js';
import { TransformNode } from '@babylonjs/core/Meshes/transformNode.js';
import { VertexBuffer } from '@babylonjs/core/Buffers/buffer.js';
import { HavokPlugin } from '@babylonjs/core/Physics/v2/Plugins/havokPlugin.js';
import { PhysicsBody } from '@babylonjs/core/Physics/v2/physicsBody.js';
import {
  PhysicsShapeBox, PhysicsShapeContainer, PhysicsShapeConvexHull,
} from '@babylonjs/core/Physics/v2/physicsShape.js';
import { PhysicsMotionType } from '@babylonjs/core/Physics/v2/IPhysicsEnginePlugin.js';
import '@babylonjs/core/Physics/joinedPhysicsEngineComponent.js';
import '@babylonjs/loaders/glTF/index.js';
import { LoadAssetContainerAsync } from '@babylonjs/core/Loading/sceneLoader.js';
import { MeshoptCompression } from '@babylonjs/core/Meshes/Compression/meshoptCompression.js';
import { createDecoder } from '/web/hullpack_decoder.js';
import { HullpackMeshCompressionPlugin } from '/web/hullpack_gltf_plugin.js';
import {
  parseGlb, readAccessor, readCollisionHulls, registerHullpackExtension,
} from '/web/hullpack_babylon.js';

const STEPS = 4 * 240;
const WASM = '/samples/web/dist/hullpack_decoder_wasm.wasm';

// Packed files store animation key frames with EXT_meshopt_compression. three.js takes the decoder
// it ships; Babylon loads a script that defines the global MeshoptDecoder (by default from its
// CDN), here the same decoder already in place and an empty script, so nothing comes from the
// network.
globalThis.MeshoptDecoder = MeshoptDecoder;
MeshoptCompression.Configuration.decoder.url = 'data:text/javascript,';

function threeLoader(decoder) {
  const loader = new GLTFLoader();
  loader.register((parser) => new HullpackMeshCompressionPlugin(parser, decoder));
  loader.setMeshoptDecoder(MeshoptDecoder);
  return loader;
}

async function threeRapier(glbUrl) {
  const decoder = await createDecoder({ wasmUrl: WASM });
  const gltf = await threeLoader(decoder).loadAsync(glbUrl);
  let vertices = 0;
  gltf.scene.traverse((o) => { if (o.isMesh && !o.parent?.userData.hullpackHull) vertices += o.geometry.attributes.position.count; });
  const hulls = gltf.userData.hullpackHulls;
  await RAPIER.init();
  const world = new RAPIER.World({ x: 0, y: 0, z: -9.81 });
  world.timestep = 1 / 240;
  world.createCollider(RAPIER.ColliderDesc.cuboid(50, 50, 0.5).setTranslation(0, 0, -0.5));
  const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(0, 0, 2));
  const engineVertices = [];
  for (const h of hulls) {
    const collider = world.createCollider(RAPIER.ColliderDesc.convexHull(h.points), body);
    engineVertices.push(Array.from(collider.shape.vertices ?? []));
  }
  for (let i = 0; i < STEPS; ++i) world.step();
  const t = body.translation();
  const v = body.linvel();
  return {
    restZ: t.z, speed: Math.hypot(v.x, v.y, v.z), vertices,
    points: hulls.map((h) => Array.from(h.points)), engineVertices,
  };
}

async function babylonHavok(glbUrl, refUrl) {
  const engine = new NullEngine();
  const scene = new Scene(engine);
  registerHullpackExtension(await createDecoder({ wasmUrl: WASM }));
  // The render mesh through Babylon's loader and the hullpack extension.
  const container = await LoadAssetContainerAsync(glbUrl, scene);
  const rendered = container.meshes.filter((m) => m.getTotalVertices() > 0);
  const positions = rendered.length ? Array.from(rendered[0].getVerticesData(VertexBuffer.PositionKind)) : [];
  const ref = parseGlb(await (await fetch(refUrl)).arrayBuffer());
  const refPrim = ref.json.meshes[0].primitives[0];
  const refPositions = readAccessor(ref.json, ref.bin, refPrim.attributes.POSITION).values;
  // Physics from the file's own collider description.
  const hulls = await readCollisionHulls(await (await fetch(glbUrl)).arrayBuffer());
  const havok = await HavokPhysics({ locateFile: () => '/node_modules/@babylonjs/havok/lib/esm/HavokPhysics.wasm' });
  scene.enablePhysics(new Vector3(0, 0, -9.81), new HavokPlugin(false, havok));
  const physics = scene.getPhysicsEngine();
  const groundNode = new TransformNode('ground', scene);
  groundNode.position.set(0, 0, -0.5);
  const ground = new PhysicsBody(groundNode, PhysicsMotionType.STATIC, false, scene);
  ground.shape = new PhysicsShapeBox(Vector3.Zero(), Quaternion.Identity(), new Vector3(100, 100, 1), scene);
  const bodyNode = new TransformNode('body', scene);
  bodyNode.position.set(0, 0, 2);
  bodyNode.rotationQuaternion = Quaternion.Identity();
  const compound = new PhysicsShapeContainer(scene);
  for (const h of hulls) {
    const mesh = new Mesh(`hull${h.colliderNode}`, scene);
    const data = new VertexData();
    data.positions = h.points;
    data.applyToMesh(mesh);
    compound.addChild(new PhysicsShapeConvexHull(mesh, scene));
  }
  const body = new PhysicsBody(bodyNode, PhysicsMotionType.DYNAMIC, false, scene);
  body.shape = compound;
  for (let i = 0; i < STEPS; ++i) physics._step(1 / 240);
  const v = body.getLinearVelocity();
  return {
    restZ: bodyNode.position.z, speed: v.length(), vertices: positions.length / 3,
    samePositions: positions.length > 0 && positions.length === refPositions.length &&
      positions.every((x, i) => x === refPositions[i]),
    points: hulls.map((h) => Array.from(h.points)),
  };
}

// readCollisionHulls on a file whose hulls are HULLPACK_mesh_compression streams (the earlier
// form, tests/web/make_glb.mjs): with the decoder it gives the points; without, a clear error.
async function babylonEarlierHulls(glbUrl) {
  const glb = await (await fetch(glbUrl)).arrayBuffer();
  const hulls = await readCollisionHulls(glb, await createDecoder({ wasmUrl: WASM }));
  let withoutDecoder = '';
  try {
    await readCollisionHulls(glb);
  } catch (e) {
    withoutDecoder = String(e.message);
  }
  return { points: hulls.map((h) => Array.from(h.points)), withoutDecoder };
}

// An animated packed file (the Kenney character): the clips three.js and Babylon see, and whether
// playing in three.js a clip that rotates a node for 0.3 s turns that node.
async function animatedClips(glbUrl) {
  const decoder = await createDecoder({ wasmUrl: WASM });
  const gltf = await threeLoader(decoder).loadAsync(glbUrl);
  const isTurn = (t) => t.name.endsWith('.quaternion');
  const clip = gltf.animations.find((a) => a.tracks.some(isTurn));
  const track = clip.tracks.find(isTurn);
  const node = gltf.scene.getObjectByName(track.name.slice(0, -'.quaternion'.length));
  const before = node.quaternion.clone();
  const mixer = new THREE.AnimationMixer(gltf.scene);
  mixer.clipAction(clip).play();
  mixer.update(0.3);
  const turned = node.quaternion.angleTo(before);
  const scene = new Scene(new NullEngine());
  registerHullpackExtension(decoder);
  const container = await LoadAssetContainerAsync(glbUrl, scene);
  return {
    threeClips: gltf.animations.map((a) => a.name),
    turned,
    babylonClips: container.animationGroups.map((g) => g.name),
  };
}

// A packed file with morph targets (make_morph_glb.mjs: a unit sphere whose "inflate" target moves
// every vertex 0.25 out): the largest offset each engine gets per target, the target names, and
// the first weight three.js shows after playing the clip for 1 s (its keys: 0 at 0 s, 1 at 1 s).
async function morphTargets(glbUrl) {
  const decoder = await createDecoder({ wasmUrl: WASM });
  const gltf = await threeLoader(decoder).loadAsync(glbUrl);
  let mesh = null;
  gltf.scene.traverse((o) => { if (o.isMesh && o.morphTargetInfluences && !mesh) mesh = o; });
  const largest = (array) => {
    let m = 0;
    for (let i = 0; i < array.length; i += 3) m = Math.max(m, Math.hypot(array[i], array[i + 1], array[i + 2]));
    return m;
  };
  const threeOffsets = (mesh?.geometry.morphAttributes.position || []).map((a) => largest(a.array));
  const mixer = new THREE.AnimationMixer(gltf.scene);
  mixer.clipAction(gltf.animations[0]).play();
  mixer.update(1.0);
  const scene = new Scene(new NullEngine());
  registerHullpackExtension(decoder);
  const container = await LoadAssetContainerAsync(glbUrl, scene);
  const manager = container.meshes.map((m) => m.morphTargetManager).find((m) => m);
  const babylonOffsets = [];
  const babylonNames = [];
  for (let t = 0; manager && t < manager.numTargets; ++t) {
    const target = manager.getTarget(t);
    babylonNames.push(target.name);
    // Babylon stores a target's positions (base + offset); the offset is their difference.
    const base = container.meshes.find((m) => m.morphTargetManager === manager).getVerticesData(VertexBuffer.PositionKind);
    const moved = target.getPositions();
    babylonOffsets.push(largest(moved.map((v, i) => v - base[i])));
  }
  return {
    threeNames: Object.keys(mesh?.morphTargetDictionary || {}),
    threeOffsets,
    threeWeightAt1s: mesh ? mesh.morphTargetInfluences[0] : -1,
    babylonNames,
    babylonOffsets,
    babylonClips: container.animationGroups.map((g) => g.name),
  };
}

window.engineTests = { threeRapier, babylonHavok, babylonEarlierHulls, animatedClips, morphTargets };
window.engineTestsReady = true;
