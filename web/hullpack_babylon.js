// hullpack_babylon.js: Babylon.js glTF loader extension for hullpack's packed GLB
// (docs/packed-gltf.md), on the same WebAssembly decoder as the three.js plugin, and a reader of the
// file's collision hulls for any physics engine.
//
//   import '@babylonjs/loaders/glTF/index.js';                 // Babylon's glTF loader
//   import { createDecoder } from './hullpack_decoder.js';
//   import { registerHullpackExtension, readCollisionHulls } from './hullpack_babylon.js';
//   registerHullpackExtension(await createDecoder({ wasmUrl }));
//   const container = await LoadAssetContainerAsync('model.glb', scene);
//   const hulls = await readCollisionHulls(await (await fetch('model.glb')).arrayBuffer(), decoder);
//
// HULLPACK_mesh_compression primitives get their vertex data and morph-target offsets from the
// decoded stream (each bufferView decoded once, the primitive's group cut out); everything else is
// Babylon's own path.
// The collision hulls `hullpack pack` writes are plain glTF (quantized POINTS meshes referenced by
// OMI_physics_shape or KHR_physics_rigid_bodies colliders), so readCollisionHulls needs no decoder
// for them; files of the earlier release hold their hulls as HULLPACK_mesh_compression streams,
// which it decodes with the decoder when one is given.
import { VertexBuffer } from '@babylonjs/core/Buffers/buffer.js';
import { Geometry } from '@babylonjs/core/Meshes/geometry.js';
import { GLTFLoader } from '@babylonjs/loaders/glTF/2.0/glTFLoader.js';
import {
  registerGLTFExtension, unregisterGLTFExtension,
} from '@babylonjs/loaders/glTF/2.0/glTFLoaderExtensionRegistry.js';
import { selectGroup } from './hullpack_decoder.js';

export const EXTENSION_NAME = 'HULLPACK_mesh_compression';

const KINDS = {
  POSITION: VertexBuffer.PositionKind, NORMAL: VertexBuffer.NormalKind, TANGENT: VertexBuffer.TangentKind,
  TEXCOORD_0: VertexBuffer.UVKind, TEXCOORD_1: VertexBuffer.UV2Kind, TEXCOORD_2: VertexBuffer.UV3Kind,
  TEXCOORD_3: VertexBuffer.UV4Kind, COLOR_0: VertexBuffer.ColorKind,
  JOINTS_0: VertexBuffer.MatricesIndicesKind, WEIGHTS_0: VertexBuffer.MatricesWeightsKind,
};

export class HullpackBabylonExtension {
  // decoder: {decode(Uint8Array) -> mesh | Promise<mesh>} from createDecoder or createWorkerDecoder.
  constructor(loader, decoder) {
    this.name = EXTENSION_NAME;
    this.enabled = true;
    this._loader = loader;
    this._decoder = decoder;
    this._streams = new Map();  // bufferView index -> Promise<decoded mesh>
  }

  dispose() {
    this._loader = null;
    this._streams.clear();
  }

  _decodeBufferView(context, index) {
    if (!this._streams.has(index)) {
      const bufferView = this._loader.gltf.bufferViews?.[index];
      if (!bufferView) throw new Error(`${context}: ${EXTENSION_NAME}: bufferView ${index} does not exist`);
      this._streams.set(index, this._loader.loadBufferViewAsync(`/bufferViews/${index}`, bufferView)
        .then((data) => this._decoder.decode(new Uint8Array(data.buffer, data.byteOffset, data.byteLength))));
    }
    return this._streams.get(index);
  }

  // Babylon calls this for every primitive; it answers only those carrying the extension.
  _loadVertexDataAsync(context, primitive, babylonMesh) {
    return GLTFLoader.LoadExtensionAsync(context, primitive, this.name, async (extensionContext, ext) => {
      if ((primitive.mode ?? 4) !== 4) throw new Error(`${context}: ${EXTENSION_NAME}: mode ${primitive.mode}`);
      const whole = await this._decodeBufferView(extensionContext, ext.bufferView);
      const mesh = ext.group === undefined ? whole : selectGroup(whole, ext.group, ext.compactVertices === true);
      const accessors = this._loader.gltf.accessors || [];
      const geometry = new Geometry(babylonMesh.name, this._loader.babylonScene);
      for (const [name, id] of Object.entries(ext.attributes || {})) {
        const a = mesh.attributes[id];
        if (!a) throw new Error(`${context}: ${EXTENSION_NAME}: attribute ${name} -> stream id ${id} is not in the stream`);
        const accessor = accessors[primitive.attributes?.[name]];
        if (!accessor || accessor.count !== mesh.numVertices) {
          throw new Error(`${context}: ${EXTENSION_NAME}: accessor of ${name} does not state the stream's ${mesh.numVertices} vertices`);
        }
        const kind = KINDS[name];
        if (!kind) continue;  // an attribute Babylon has no slot for
        geometry.setVerticesData(kind, Float32Array.from(a.array), false, a.dimension);
      }
      geometry.setIndices(mesh.indices, mesh.numVertices);
      // Morph targets: Babylon loads them after the vertex data, through the accessors' cached
      // data, which is where the decoded offsets go.
      (ext.targets || []).forEach((target, t) => {
        for (const [name, id] of Object.entries(target || {})) {
          const a = mesh.attributes[id];
          const accessor = accessors[primitive.targets?.[t]?.[name]];
          if (!a || !accessor || accessor.count !== mesh.numVertices || a.dimension !== 3) {
            throw new Error(`${context}: ${EXTENSION_NAME}: targets[${t}] ${name} -> stream id ${id} does not match its accessor`);
          }
          accessor._data = Promise.resolve(Float32Array.from(a.array));
        }
      });
      return geometry;
    });
  }
}

// Registers the extension for every glTF load from now on (Babylon needs it for files that list
// HULLPACK_mesh_compression in extensionsRequired).
export function registerHullpackExtension(decoder) {
  unregisterGLTFExtension(EXTENSION_NAME);
  registerGLTFExtension(EXTENSION_NAME, true, (loader) => new HullpackBabylonExtension(loader, decoder));
}

const COMPONENTS = { 5120: Int8Array, 5121: Uint8Array, 5122: Int16Array, 5123: Uint16Array, 5125: Uint32Array, 5126: Float32Array };
const NORMALIZE = { 5120: 127, 5121: 255, 5122: 32767, 5123: 65535 };
const WIDTH = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };

// Splits a GLB into its JSON and binary chunk.
export function parseGlb(arrayBuffer) {
  const view = new DataView(arrayBuffer);
  if (view.getUint32(0, true) !== 0x46546c67) throw new Error('not a GLB');
  let json;
  let bin = new Uint8Array(0);
  for (let at = 12; at + 8 <= view.byteLength;) {
    const length = view.getUint32(at, true);
    const type = view.getUint32(at + 4, true);
    const bytes = new Uint8Array(arrayBuffer, at + 8, length);
    if (type === 0x4e4f534a) json = JSON.parse(new TextDecoder().decode(bytes));
    else if (type === 0x004e4942) bin = bytes;
    at += 8 + length;
  }
  if (!json) throw new Error('GLB without a JSON chunk');
  return { json, bin };
}

export function readAccessor(json, bin, index) {
  const a = json.accessors?.[index];
  const view = json.bufferViews?.[a?.bufferView];
  const Type = COMPONENTS[a?.componentType];
  const width = WIDTH[a?.type];
  if (!a || !view || !Type || !width) throw new Error(`accessors[${index}]: unreadable (no data or a compressed primitive)`);
  // Views on another buffer than the binary chunk (EXT_meshopt_compression's fallback buffer:
  // compressed key frames) are not in `bin`.
  if ((view.buffer || 0) !== 0 || view.extensions?.EXT_meshopt_compression) {
    throw new Error(`accessors[${index}]: its bufferView is not plain data of the binary chunk`);
  }
  const size = Type.BYTES_PER_ELEMENT;
  const stride = view.byteStride || width * size;
  const start = (view.byteOffset || 0) + (a.byteOffset || 0);
  if (a.count > 0 && start + (a.count - 1) * stride + width * size > (view.byteOffset || 0) + view.byteLength) {
    throw new Error(`accessors[${index}] lies outside its bufferView`);
  }
  const dv = new DataView(bin.buffer, bin.byteOffset, bin.byteLength);
  const get = {
    5120: (o) => dv.getInt8(o), 5121: (o) => dv.getUint8(o), 5122: (o) => dv.getInt16(o, true),
    5123: (o) => dv.getUint16(o, true), 5125: (o) => dv.getUint32(o, true), 5126: (o) => dv.getFloat32(o, true),
  }[a.componentType];
  const scale = a.normalized ? NORMALIZE[a.componentType] : 0;
  const out = new Array(a.count * width);
  for (let i = 0; i < a.count; ++i) {
    for (let c = 0; c < width; ++c) {
      const v = get(start + i * stride + c * size);
      out[i * width + c] = scale ? Math.max(v / scale, -1) : v;
    }
  }
  return { values: out, width };
}

// The node's local transform applied to point p (scale, then rotation, then translation), in
// double precision as the C++ reader does (tools/packed/packed_glb_reader.cc).
function transformPoint(node, p) {
  if (node.matrix) {
    const m = node.matrix;
    return [0, 1, 2].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
  }
  const t = node.translation || [0, 0, 0];
  const [qx, qy, qz, qw] = node.rotation || [0, 0, 0, 1];
  const s = node.scale || [1, 1, 1];
  const v = [p[0] * s[0], p[1] * s[1], p[2] * s[2]];
  const c = [qy * v[2] - qz * v[1], qz * v[0] - qx * v[2], qx * v[1] - qy * v[0]];
  const cc = [qy * c[2] - qz * c[1], qz * c[0] - qx * c[2], qx * c[1] - qy * c[0]];
  return [0, 1, 2].map((k) => v[k] + 2 * (qw * c[k] + cc[k]) + t[k]);
}

// Every convex collider of a packed GLB (either collider form, and the hulls of either release:
// docs/packed-gltf.md), in node order: a Promise of [{colliderNode, bodyNode, mesh, points:
// Float32Array}], points in the body node's space (the collider node's transform applied, which
// dequantizes the hull) -- what a physics engine is given. `decoder` ({decode(Uint8Array) -> mesh |
// Promise<mesh>}, from createDecoder or createWorkerDecoder) is needed only for hulls stored as
// HULLPACK_mesh_compression streams (the earlier form); without it such a file is an error.
export async function readCollisionHulls(arrayBuffer, decoder) {
  const { json, bin } = parseGlb(arrayBuffer);
  const nodes = json.nodes || [];
  const parents = new Map();
  nodes.forEach((n, i) => (n.children || []).forEach((c) => parents.set(c, i)));
  const shapes = json.extensions?.OMI_physics_shape?.shapes || [];
  const streams = new Map();  // bufferView -> decoded mesh (hulls of one render mesh share a stream)
  const streamPositions = async (prim) => {
    const ext = prim.extensions[EXTENSION_NAME];
    if (!decoder) throw new Error(`${EXTENSION_NAME}: this file's hulls are compressed streams (the earlier form): pass a decoder`);
    const view = json.bufferViews?.[ext.bufferView];
    if (!view) throw new Error(`${EXTENSION_NAME}: bufferViews[${ext.bufferView}] does not exist`);
    if (!streams.has(ext.bufferView)) {
      const start = view.byteOffset || 0;
      if (start + view.byteLength > bin.byteLength) throw new Error(`bufferViews[${ext.bufferView}] lies outside the binary chunk`);
      streams.set(ext.bufferView, decoder.decode(bin.slice(start, start + view.byteLength)));
    }
    const whole = await streams.get(ext.bufferView);
    const mesh = ext.group === undefined ? whole : selectGroup(whole, ext.group, ext.compactVertices === true);
    const id = ext.attributes?.POSITION;
    const positions = id === undefined ? mesh.positions : mesh.attributes[id]?.array;
    if (!positions) throw new Error(`${EXTENSION_NAME}: POSITION -> stream id ${id} is not in the stream`);
    return positions;
  };
  const hulls = [];
  for (let i = 0; i < nodes.length; ++i) {
    const node = nodes[i];
    const omi = node.extensions?.OMI_physics_body?.collider;
    const khr = node.extensions?.KHR_physics_rigid_bodies?.collider?.geometry;
    let mesh;
    if (omi?.shape !== undefined) {
      const shape = shapes[omi.shape];
      if (shape?.type === 'convex') mesh = shape.convex?.mesh;
    } else if (khr?.convexHull) {
      mesh = khr.node !== undefined ? nodes[khr.node]?.mesh : khr.mesh;
    }
    if (mesh === undefined) continue;
    const points = [];
    for (const prim of json.meshes?.[mesh]?.primitives || []) {
      const values = prim.extensions?.[EXTENSION_NAME]
        ? await streamPositions(prim)
        : readAccessor(json, bin, prim.attributes.POSITION).values;
      for (let v = 0; v < values.length; v += 3) points.push(...transformPoint(node, [values[v], values[v + 1], values[v + 2]]));
    }
    hulls.push({ colliderNode: i, bodyNode: parents.get(i), mesh, points: Float32Array.from(points) });
  }
  return hulls;
}
