// hullpack_gltf_plugin.js: three.js GLTFLoader plugin for hullpack's packed GLB (docs/packed-gltf.md):
//  - HULLPACK_mesh_compression: primitives whose attributes and indices come from an o3dgc stream;
//  - OMI_physics_shape / OMI_physics_body (or the KHR_physics_rigid_bodies draft): convex collision
//    hulls (plain glTF, no decoder needed), exposed as data in gltf.userData.hullpackHulls and as
//    hidden meshes under their collider nodes.
//
//   import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
//   import { createDecoder } from './hullpack_decoder.js';
//   import { HullpackMeshCompressionPlugin, setHullsVisible } from './hullpack_gltf_plugin.js';
//   const decoder = await createDecoder({ wasmUrl });          // or createWorkerDecoder({wasmUrl})
//   const loader = new GLTFLoader();
//   loader.register((parser) => new HullpackMeshCompressionPlugin(parser, decoder));
//   const gltf = await loader.loadAsync('model.glb');
//   setHullsVisible(gltf, true);
//
// How it plugs in: three's GLTFLoader calls decodePrimitive() only for KHR_draco_mesh_compression,
// so this plugin decodes every stream in beforeRoot() (each bufferView once, groups cut out per
// primitive) and answers the parser's accessor requests for the compressed primitives' accessors
// with the decoded arrays; everything else (materials, skins, bounds from accessor min/max) is
// three's normal path. decodePrimitive(primitiveDef) is also available and returns a BufferGeometry.
import {
  BufferAttribute, BufferGeometry, Mesh, MeshBasicMaterial, Group, Vector3,
} from 'three';
import { ConvexGeometry } from 'three/addons/geometries/ConvexGeometry.js';
import { selectGroup } from './hullpack_decoder.js';

export const EXTENSION_NAME = 'HULLPACK_mesh_compression';

const COMPONENT_ARRAYS = {
  5120: Int8Array, 5121: Uint8Array, 5122: Int16Array, 5123: Uint16Array, 5125: Uint32Array, 5126: Float32Array,
};
const TYPE_SIZES = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT2: 4, MAT3: 9, MAT4: 16 };
const THREE_NAMES = {
  POSITION: 'position', NORMAL: 'normal', TANGENT: 'tangent', TEXCOORD_0: 'uv', TEXCOORD_1: 'uv1',
  TEXCOORD_2: 'uv2', TEXCOORD_3: 'uv3', COLOR_0: 'color', WEIGHTS_0: 'skinWeight', JOINTS_0: 'skinIndex',
};

const COMPONENT_LIMITS = {
  Int8Array: [-128, 127], Uint8Array: [0, 255], Int16Array: [-32768, 32767], Uint16Array: [0, 65535],
  Uint32Array: [0, 4294967295],
};

// Converts decoded values to the accessor's component type as the C++ reader does
// (tools/packed/packed_glb_reader.cc): floats as they are; normalized integers scaled by the type's
// maximum and rounded half away from zero; plain integers only when whole. A value the type cannot
// hold is an error, not a wrapped number.
function toAccessorArray(values, accessorDef, where) {
  const Type = COMPONENT_ARRAYS[accessorDef?.componentType] || values.constructor;
  if (values instanceof Type) return values;
  const out = new Type(values.length);
  if (Type === Float32Array) {
    out.set(values);
    return out;
  }
  const [lo, hi] = COMPONENT_LIMITS[Type.name];
  const scale = accessorDef?.normalized ? hi : 0;
  for (let i = 0; i < values.length; ++i) {
    let v = values[i];
    if (scale) v = Math.sign(v) * Math.round(Math.abs(v * scale));
    if (!(v >= lo && v <= hi) || v !== Math.floor(v)) {
      throw new Error(`${EXTENSION_NAME}: ${where}: value ${values[i]} does not fit its component type`);
    }
    out[i] = v;
  }
  return out;
}

// The accessor a stream fills must state the decoded data's count and item size
// (docs/packed-gltf.md); a file that says otherwise is rejected, as the C++ reader does.
function checkAccessor(accessorDef, count, itemSize, where) {
  if (!accessorDef) throw new Error(`${EXTENSION_NAME}: ${where} does not exist`);
  if (accessorDef.count !== count) {
    throw new Error(`${EXTENSION_NAME}: ${where} count ${accessorDef.count} does not match the stream (${count})`);
  }
  if (TYPE_SIZES[accessorDef.type] !== itemSize) {
    throw new Error(`${EXTENSION_NAME}: ${where} is ${accessorDef.type} but the stream attribute has ${itemSize} components`);
  }
}

export class HullpackMeshCompressionPlugin {
  // decoder: {decode(Uint8Array) -> mesh | Promise<mesh>} from createDecoder or createWorkerDecoder.
  constructor(parser, decoder, { hullColor = 0x00ff88, hullOpacity = 0.35 } = {}) {
    if (!decoder) throw new Error('HullpackMeshCompressionPlugin: a decoder is required');
    this.name = EXTENSION_NAME;
    this.parser = parser;
    this.decoder = decoder;
    this.hullColor = hullColor;
    this.hullOpacity = hullOpacity;
    this.streams = new Map();     // bufferView index -> Promise<decoded mesh>
    this.accessors = new Map();   // accessor index -> BufferAttribute from a decoded stream
    this.stats = { streams: 0, bytes: 0, decodeMs: 0 };
  }

  decodeBufferView(index) {
    if (!this.streams.has(index)) {
      const p = this.parser.getDependency('bufferView', index).then(async (buffer) => {
        const bytes = new Uint8Array(buffer);
        const t0 = performance.now();
        const mesh = await this.decoder.decode(bytes);
        this.stats.decodeMs += performance.now() - t0;
        this.stats.streams += 1;
        this.stats.bytes += bytes.length;
        return mesh;
      });
      this.streams.set(index, p);
    }
    return this.streams.get(index);
  }

  // The decoded mesh of one primitive (its group cut out), as {mesh, attributes: {glTF name: array}}.
  async decodePrimitiveData(primitiveDef) {
    const ext = primitiveDef.extensions[EXTENSION_NAME];
    const whole = await this.decodeBufferView(ext.bufferView);
    const mesh = ext.group === undefined ? whole : selectGroup(whole, ext.group, ext.compactVertices === true);
    const attributes = {};
    for (const [name, id] of Object.entries(ext.attributes || {})) {
      const a = mesh.attributes[id];
      if (!a) throw new Error(`${EXTENSION_NAME}: attribute ${name} -> stream id ${id} is not in the stream`);
      attributes[name] = a;
    }
    // Morph targets: per target, glTF attribute name (POSITION, NORMAL) -> decoded offsets.
    const targets = (ext.targets || []).map((target, t) => {
      const out = {};
      for (const [name, id] of Object.entries(target || {})) {
        const a = mesh.attributes[id];
        if (!a) throw new Error(`${EXTENSION_NAME}: targets[${t}] ${name} -> stream id ${id} is not in the stream`);
        out[name] = a;
      }
      return out;
    });
    if (targets.length && targets.length !== (primitiveDef.targets || []).length) {
      throw new Error(`${EXTENSION_NAME}: targets must have one entry per morph target of the primitive`);
    }
    return { mesh, attributes, targets };
  }

  // A BufferGeometry for one primitive (like GLTFDracoMeshCompressionExtension.decodePrimitive).
  async decodePrimitive(primitiveDef) {
    const json = this.parser.json;
    const { mesh, attributes, targets } = await this.decodePrimitiveData(primitiveDef);
    const geometry = new BufferGeometry();
    for (const [name, a] of Object.entries(attributes)) {
      const accessorDef = json.accessors?.[primitiveDef.attributes?.[name]];
      const array = toAccessorArray(a.array, accessorDef, `attribute ${name}`);
      geometry.setAttribute(THREE_NAMES[name] || name.toLowerCase(),
        new BufferAttribute(array, a.dimension, accessorDef?.normalized === true));
    }
    geometry.setIndex(new BufferAttribute(mesh.indices, 1));
    targets.forEach((target, t) => {
      for (const [name, a] of Object.entries(target)) {
        const key = name === 'POSITION' ? 'position' : name === 'NORMAL' ? 'normal' : name.toLowerCase();
        const accessorDef = json.accessors?.[primitiveDef.targets[t][name]];
        const list = geometry.morphAttributes[key] || (geometry.morphAttributes[key] = []);
        list[t] = new BufferAttribute(toAccessorArray(a.array, accessorDef, `targets[${t}] ${name}`), a.dimension);
      }
    });
    if (targets.length) geometry.morphTargetsRelative = true;  // glTF targets are offsets
    return geometry;
  }

  // Decodes every compressed primitive and routes its accessors to the decoded data.
  async beforeRoot() {
    const json = this.parser.json;
    const jobs = [];
    (json.meshes || []).forEach((meshDef) => {
      for (const prim of meshDef.primitives || []) {
        const ext = prim.extensions?.[EXTENSION_NAME];
        if (!ext) continue;
        jobs.push(this.decodePrimitiveData(prim).then(({ mesh, attributes, targets }) => {
          const route = (accessorIndex, a, what) => {
            if (accessorIndex === undefined) {
              throw new Error(`${EXTENSION_NAME}: ${what} has no accessor in the primitive`);
            }
            if (this.accessors.has(accessorIndex)) return;  // shared by the mesh's primitives
            const accessorDef = json.accessors?.[accessorIndex];
            const where = `accessors[${accessorIndex}]`;
            checkAccessor(accessorDef, mesh.numVertices, a.dimension, where);
            const array = toAccessorArray(a.array, accessorDef, where);
            this.accessors.set(accessorIndex, new BufferAttribute(array, a.dimension, accessorDef.normalized === true));
          };
          for (const [name, a] of Object.entries(attributes)) route(prim.attributes?.[name], a, `attribute ${name}`);
          targets.forEach((target, t) => {
            for (const [name, a] of Object.entries(target)) route(prim.targets[t]?.[name], a, `targets[${t}] ${name}`);
          });
          if (prim.indices !== undefined) {
            if (this.accessors.has(prim.indices)) return;
            const accessorDef = json.accessors?.[prim.indices];
            const where = `accessors[${prim.indices}]`;
            checkAccessor(accessorDef, mesh.indices.length, 1, where);
            this.accessors.set(prim.indices, new BufferAttribute(toAccessorArray(mesh.indices, accessorDef, where), 1));
          } else if (mesh.indices.length !== mesh.numVertices ||
                     (ext.group !== undefined && ext.compactVertices === true && mesh.numVertices > 0)) {
            // Without an index accessor the vertices are drawn in order (as the C++ reader rules).
            throw new Error(`${EXTENSION_NAME}: a non-indexed primitive cannot hold an indexed stream`);
          }
        }));
      }
    });
    await Promise.all(jobs);
    if (this.accessors.size) {
      const parser = this.parser;
      const original = parser.loadAccessor.bind(parser);
      const decoded = this.accessors;
      parser.loadAccessor = (index) => (decoded.has(index) ? Promise.resolve(decoded.get(index)) : original(index));
    }
  }

  // Collision hulls: gltf.userData.hullpackHulls = [{nodeIndex, node, bodyNodeIndex, shapeIndex,
  // meshIndex, type, points, positions, indices, mesh}], one per collider node, in node order.
  // Colliders come in either form `hullpack pack` writes (docs/packed-gltf.md): OMI_physics_body ->
  // OMI_physics_shape convex/trimesh shapes, or KHR_physics_rigid_bodies collider geometry (the
  // draft's `node`, or the earlier `mesh`; convexHull true -> type 'convex'); shapeIndex is
  // undefined for the latter. `points` (Float32Array, 3 per vertex) are the hull's vertices in its
  // body node's space (the collider node's transform applied: that dequantizes the
  // KHR_mesh_quantization hulls), what a physics engine is given; `positions`/`indices` are the
  // displayed mesh in the collider node's space (for a POINTS hull, the convex hull of its points).
  // `mesh` is a hidden child of the collider node (toggle with setHullsVisible).
  async afterRoot(gltf) {
    const json = this.parser.json;
    const shapes = json.extensions?.OMI_physics_shape?.shapes || [];
    const hulls = [];
    const nodes = json.nodes || [];
    const parents = new Map();
    nodes.forEach((n, i) => (n.children || []).forEach((c) => parents.set(c, i)));
    for (let n = 0; n < nodes.length; ++n) {
      const omi = nodes[n].extensions?.OMI_physics_body?.collider;
      const khr = nodes[n].extensions?.KHR_physics_rigid_bodies?.collider?.geometry;
      let meshIndex;
      let type;
      let shapeIndex;
      if (omi && omi.shape !== undefined) {
        const shape = shapes[omi.shape];
        shapeIndex = omi.shape;
        type = shape?.type;
        meshIndex = type === 'convex' ? shape.convex?.mesh : type === 'trimesh' ? shape.trimesh?.mesh : undefined;
      } else if (khr && (khr.node !== undefined || khr.mesh !== undefined)) {
        meshIndex = khr.node !== undefined ? nodes[khr.node]?.mesh : khr.mesh;
        type = khr.convexHull ? 'convex' : 'trimesh';
      } else {
        continue;
      }
      const meshDef = json.meshes?.[meshIndex];
      if (!meshDef || !meshDef.primitives?.length) continue;
      const prim = meshDef.primitives[0];
      const pos = await this.parser.getDependency('accessor', prim.attributes.POSITION);
      // Quantized integers or floats, as stored (the attribute may be interleaved: padded elements).
      const local = new Float32Array(pos.count * 3);
      for (let i = 0; i < pos.count; ++i) {
        local[i * 3] = pos.getX(i);
        local[i * 3 + 1] = pos.getY(i);
        local[i * 3 + 2] = pos.getZ(i);
      }
      let positions = local;
      let indices;
      if ((prim.mode ?? 4) === 0) {  // points: the hull of the points
        const points = [];
        for (let i = 0; i < local.length; i += 3) points.push(new Vector3(local[i], local[i + 1], local[i + 2]));
        const hull = new ConvexGeometry(points);
        positions = Float32Array.from(hull.getAttribute('position').array);
        indices = Uint32Array.from({ length: positions.length / 3 }, (_, i) => i);
      } else if (prim.indices !== undefined) {
        indices = Uint32Array.from((await this.parser.getDependency('accessor', prim.indices)).array);
      } else {
        indices = Uint32Array.from({ length: pos.count }, (_, i) => i);
      }
      const node = await this.parser.getDependency('node', n);
      node.updateMatrix();
      const points = new Float32Array(local.length);
      const v = new Vector3();
      for (let i = 0; i < local.length; i += 3) {
        v.set(local[i], local[i + 1], local[i + 2]).applyMatrix4(node.matrix);
        points[i] = v.x;
        points[i + 1] = v.y;
        points[i + 2] = v.z;
      }
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', new BufferAttribute(positions, 3));
      geometry.setIndex(new BufferAttribute(indices, 1));
      const material = new MeshBasicMaterial({
        color: this.hullColor, wireframe: true, transparent: true, opacity: Math.min(1, this.hullOpacity * 2),
        depthWrite: false,
      });
      const fill = new MeshBasicMaterial({
        color: this.hullColor, transparent: true, opacity: this.hullOpacity, depthWrite: false,
      });
      const group = new Group();
      group.name = 'hullpack_hull';
      group.add(new Mesh(geometry, fill), new Mesh(geometry, material));
      group.visible = false;
      group.userData.hullpackHull = true;
      node.add(group);
      hulls.push({
        nodeIndex: n, node, bodyNodeIndex: parents.get(n), shapeIndex, meshIndex, type, points, positions,
        indices, mesh: group,
      });
    }
    gltf.userData.hullpackHulls = hulls;
    gltf.userData.hullpackStats = { ...this.stats };
  }
}

// Shows or hides the hull meshes the plugin added.
export function setHullsVisible(gltf, visible) {
  for (const h of gltf.userData.hullpackHulls || []) h.mesh.visible = visible;
}
