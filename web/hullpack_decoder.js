// hullpack_decoder.js: decode o3dgc streams (the HULLPACK_mesh_compression payload) in the browser
// with the WebAssembly build of the project's decoder (web/decoder_wasm.cc).
//
//   import { createDecoder } from './hullpack_decoder.js';
//   const decoder = await createDecoder({ wasmUrl: 'dist/hullpack_decoder_wasm.wasm' });
//   const mesh = decoder.decode(bytes);   // Uint8Array -> { positions, indices, normals, uvs, ... }
//
// Off the main thread: `await createWorkerDecoder({wasmUrl})` gives the same decode(), returning a
// Promise; arrays come back as transferred buffers.
//
// Skin weights (semantic 'weight', 4 components) are renormalized per vertex, the packed format's
// decode rule (normalizeSkinWeights below).
//
// Every array of a result is a copy owned by JavaScript (the wasm heap is released before decode()
// returns). Errors are thrown as Error whose message and `.status` hold the decoder's status name
// ("corrupt", "truncated", "bad_magic", ...).

export const Semantic = Object.freeze({
  GENERIC: 0, POSITION: 1, NORMAL: 2, TEXCOORD: 3, COLOR: 4, WEIGHT: 5, JOINT_ID: 6,
});
const SEMANTIC_NAMES = ['generic', 'position', 'normal', 'texcoord', 'color', 'weight', 'joint'];

export class HullpackDecodeError extends Error {
  constructor(status) {
    super(`hullpack decode failed: ${status}`);
    this.name = 'HullpackDecodeError';
    this.status = status;
  }
}

function defaultModuleUrl(wasmUrl) {
  return String(wasmUrl).replace(/\.wasm(\?.*)?$/, '.js$1');
}

// Loads the emscripten module. `moduleUrl` (the .js next to the .wasm) defaults to wasmUrl with
// the extension changed; `wasmBinary` (ArrayBuffer) skips the fetch of wasmUrl.
export async function loadDecoderModule({ wasmUrl, moduleUrl, wasmBinary } = {}) {
  if (!wasmUrl && !moduleUrl) throw new Error('createDecoder: wasmUrl is required');
  const resolvedWasm = wasmUrl ? new URL(wasmUrl, globalThis.location?.href).href : undefined;
  const resolvedModule = new URL(moduleUrl || defaultModuleUrl(wasmUrl), globalThis.location?.href).href;
  const { default: factory } = await import(resolvedModule);
  const options = {};
  if (resolvedWasm) options.locateFile = (path) => (path.endsWith('.wasm') ? resolvedWasm : path);
  if (wasmBinary) options.wasmBinary = wasmBinary;
  return factory(options);
}

function copyF32(M, ptr, count) {
  return new Float32Array(M.HEAPF32.buffer, ptr, count).slice();
}
function copyU32(M, ptr, count) {
  return new Uint32Array(M.HEAPU32.buffer, ptr, count).slice();
}

// The packed format's one decode rule (docs/packed-gltf.md, tools/gltf/skin_weights.cc, bit for bit):
// a vertex's 4 skin weights with a positive, finite sum are divided by it (in double) and rounded to
// float, except the largest (the first of equal largest), which becomes 1 minus the others (summed
// in double from their float values, then rounded to float). All-zero vertices stay as they are.
// Quantization moves each weight by up to half a step, and glTF wants the float sum to be 1.
export function normalizeSkinWeights(weights) {
  for (let i = 0; i + 3 < weights.length; i += 4) {
    let sum = 0;
    let largest = 0;
    for (let k = 0; k < 4; ++k) {
      sum += weights[i + k];
      if (weights[i + k] > weights[i + largest]) largest = k;
    }
    if (!(sum > 0) || !Number.isFinite(sum)) continue;
    let others = 0;
    for (let k = 0; k < 4; ++k) {
      if (k === largest) continue;
      weights[i + k] = Math.fround(weights[i + k] / sum);
      others += weights[i + k];
    }
    weights[i + largest] = Math.fround(1 - others);
  }
  return weights;
}

function jointsArray(values) {
  let max = 0;
  for (let i = 0; i < values.length; ++i) if (values[i] > max) max = values[i];
  const out = max < 65536 ? new Uint16Array(values.length) : new Uint32Array(values.length);
  for (let i = 0; i < values.length; ++i) out[i] = values[i] < 0 ? 0 : values[i];
  return out;
}

// Reads a decoded handle into plain typed arrays.
function readResult(M, h) {
  const nv = M._hp_num_vertices(h);
  const nt = M._hp_num_triangles(h);
  const mesh = {
    numVertices: nv,
    numTriangles: nt,
    streamType: M._hp_stream_type(h) === 1 ? 'ascii' : 'binary',
    positions: nv ? copyF32(M, M._hp_positions(h), 3 * nv) : new Float32Array(0),
    indices: nt ? copyU32(M, M._hp_indices(h), 3 * nt) : new Uint32Array(0),
    normals: undefined,
    uvs: [],
    colors: undefined,
    joints: undefined,
    weights: undefined,
    groups: undefined,
    // One entry per stream attribute, indexed by the attribute id of HULLPACK_mesh_compression.
    attributes: [],
  };
  mesh.attributes.push({ id: 0, kind: 'float', semantic: 'position', dimension: 3, array: mesh.positions });
  const normalsPtr = M._hp_normals(h);
  if (normalsPtr && nv) {
    mesh.normals = copyF32(M, normalsPtr, 3 * nv);
    mesh.attributes.push({ id: mesh.attributes.length, kind: 'float', semantic: 'normal', dimension: 3, array: mesh.normals });
  }
  const nf = M._hp_num_float_attributes(h);
  for (let i = 0; i < nf; ++i) {
    const semantic = SEMANTIC_NAMES[M._hp_float_attribute_semantic(h, i)] || 'generic';
    const dimension = M._hp_float_attribute_dimension(h, i);
    const ptr = M._hp_float_attribute_values(h, i);
    const array = ptr ? copyF32(M, ptr, dimension * nv) : new Float32Array(0);
    if (semantic === 'weight' && dimension === 4) normalizeSkinWeights(array);
    mesh.attributes.push({ id: mesh.attributes.length, kind: 'float', semantic, dimension, array });
    if (semantic === 'texcoord') mesh.uvs.push(array);
    else if (semantic === 'color' && !mesh.colors) mesh.colors = array;
    else if (semantic === 'weight' && !mesh.weights) mesh.weights = array;
  }
  const ni = M._hp_num_int_attributes(h);
  for (let i = 0; i < ni; ++i) {
    const semantic = SEMANTIC_NAMES[M._hp_int_attribute_semantic(h, i)] || 'generic';
    const dimension = M._hp_int_attribute_dimension(h, i);
    const ptr = M._hp_int_attribute_values(h, i);
    const ints = ptr ? new Int32Array(M.HEAP32.buffer, ptr, dimension * nv).slice() : new Int32Array(0);
    const array = semantic === 'joint' ? jointsArray(ints) : ints;
    mesh.attributes.push({ id: mesh.attributes.length, kind: 'int', semantic, dimension, array });
    if (semantic === 'joint' && !mesh.joints) mesh.joints = array;
  }
  const groupsPtr = M._hp_groups(h);
  if (groupsPtr && nt) mesh.groups = copyU32(M, groupsPtr, nt);
  return mesh;
}

// Synchronous decoder over an instantiated module.
export function decoderFromModule(M) {
  return {
    module: M,
    // options.verifyChecksum (default true): false skips the stream's CRC check.
    decode(bytes, { verifyChecksum = true } = {}) {
      if (!(bytes instanceof Uint8Array)) {
        if (bytes instanceof ArrayBuffer) bytes = new Uint8Array(bytes);
        else if (ArrayBuffer.isView(bytes)) bytes = new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
        else throw new TypeError('decode: expected a Uint8Array');
      }
      const input = M._malloc(Math.max(1, bytes.length));
      if (!input) throw new HullpackDecodeError('out_of_memory');
      let h = 0;
      try {
        M.HEAPU8.set(bytes, input);
        h = M._hp_decode_ex(input, bytes.length, verifyChecksum ? 1 : 0);
      } finally {
        M._free(input);
      }
      if (!h) throw new HullpackDecodeError('out_of_memory');
      try {
        if (M._hp_status(h) !== 0) {
          const namePtr = M._hp_status_name(h);
          let name = '';
          for (let p = namePtr; M.HEAPU8[p] !== 0 && name.length < 64; ++p) name += String.fromCharCode(M.HEAPU8[p]);
          throw new HullpackDecodeError(name || 'unknown');
        }
        return readResult(M, h);
      } finally {
        M._hp_free(h);
      }
    },
  };
}

// createDecoder({wasmUrl, moduleUrl?, wasmBinary?}) -> { decode(Uint8Array) -> mesh }
export async function createDecoder(options = {}) {
  return decoderFromModule(await loadDecoderModule(options));
}

// The triangles of `mesh` whose group id equals `group`, with the vertices they use renumbered
// in increasing order of their stream index (HULLPACK_mesh_compression `group`). Returns a mesh of
// the same shape (attributes sliced accordingly).
// The triangles of one group (docs/packed-gltf.md). With compactVertices the vertices are only those
// the triangles use, renumbered in increasing order; otherwise all vertices are kept, so the
// primitives of one mesh share them.
export function selectGroup(mesh, group, compactVertices = false) {
  if (group === undefined || group === null) return mesh;
  if (!compactVertices) {
    const groups = mesh.groups;
    let tris = 0;
    for (let t = 0; t < mesh.numTriangles; ++t) if ((groups ? groups[t] : 0) === group) ++tris;
    const indices = new Uint32Array(3 * tris);
    let k = 0;
    for (let t = 0; t < mesh.numTriangles; ++t) {
      if ((groups ? groups[t] : 0) !== group) continue;
      for (let c = 0; c < 3; ++c) indices[k++] = mesh.indices[3 * t + c];
    }
    return { ...mesh, numTriangles: tris, indices, groups: new Uint32Array(tris).fill(group) };
  }
  const groups = mesh.groups;
  const nt = mesh.numTriangles;
  const used = new Uint8Array(mesh.numVertices);
  let tris = 0;
  for (let t = 0; t < nt; ++t) {
    if ((groups ? groups[t] : 0) !== group) continue;
    ++tris;
    used[mesh.indices[3 * t]] = used[mesh.indices[3 * t + 1]] = used[mesh.indices[3 * t + 2]] = 1;
  }
  const remap = new Uint32Array(mesh.numVertices);
  let nv = 0;
  for (let v = 0; v < mesh.numVertices; ++v) if (used[v]) remap[v] = nv++;
  const indices = new Uint32Array(3 * tris);
  let k = 0;
  for (let t = 0; t < nt; ++t) {
    if ((groups ? groups[t] : 0) !== group) continue;
    for (let c = 0; c < 3; ++c) indices[k++] = remap[mesh.indices[3 * t + c]];
  }
  const slice = (array, dim) => {
    const out = new array.constructor(nv * dim);
    let o = 0;
    for (let v = 0; v < mesh.numVertices; ++v) {
      if (!used[v]) continue;
      for (let d = 0; d < dim; ++d) out[o++] = array[v * dim + d];
    }
    return out;
  };
  const out = { ...mesh, numVertices: nv, numTriangles: tris, indices, uvs: [], groups: new Uint32Array(tris).fill(group) };
  out.attributes = mesh.attributes.map((a) => ({ ...a, array: slice(a.array, a.dimension) }));
  const byArray = new Map(mesh.attributes.map((a, i) => [a.array, out.attributes[i].array]));
  for (const key of ['positions', 'normals', 'colors', 'joints', 'weights']) {
    if (mesh[key]) out[key] = byArray.get(mesh[key]);
  }
  out.uvs = mesh.uvs.map((u) => byArray.get(u));
  return out;
}

// Axis-aligned bounds of a positions array: {min: [x,y,z], max: [x,y,z]}.
export function bounds(positions) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let c = 0; c < 3; ++c) {
      const x = positions[i + c];
      if (x < min[c]) min[c] = x;
      if (x > max[c]) max[c] = x;
    }
  }
  return { min, max };
}

// Buffers of a mesh, for postMessage transfer lists.
export function transferables(mesh) {
  const set = new Set();
  for (const a of mesh.attributes) set.add(a.array.buffer);
  set.add(mesh.indices.buffer);
  if (mesh.groups) set.add(mesh.groups.buffer);
  return [...set];
}

// Rebuilds the convenience fields of a mesh that went through postMessage (structured clone keeps
// typed arrays, but not their identity with `attributes`).
function relink(mesh) {
  const find = (semantic) => mesh.attributes.find((a) => a.semantic === semantic)?.array;
  mesh.positions = find('position');
  mesh.normals = find('normal');
  mesh.uvs = mesh.attributes.filter((a) => a.semantic === 'texcoord').map((a) => a.array);
  mesh.colors = find('color');
  mesh.weights = find('weight');
  mesh.joints = mesh.attributes.find((a) => a.semantic === 'joint' && a.kind === 'int')?.array;
  return mesh;
}

// createWorkerDecoder({wasmUrl, moduleUrl?, workerUrl?}) -> { decode(Uint8Array) -> Promise<mesh>,
// terminate() }. The bytes passed to decode() are copied (the caller keeps its array).
export async function createWorkerDecoder({ wasmUrl, moduleUrl, workerUrl } = {}) {
  const url = workerUrl || new URL('./hullpack_worker.js', import.meta.url);
  const worker = new Worker(url, { type: 'module' });
  const pending = new Map();
  let nextId = 1;
  let failed = null;
  worker.onmessage = (e) => {
    const { id, mesh, error, status } = e.data;
    const p = pending.get(id);
    if (!p) return;
    pending.delete(id);
    if (error) {
      p.reject(status ? new HullpackDecodeError(status) : new Error(error));
    } else {
      p.resolve(mesh ? relink(mesh) : undefined);
    }
  };
  worker.onerror = (e) => {
    failed = new Error(`hullpack worker failed: ${e.message || 'error'}`);
    for (const p of pending.values()) p.reject(failed);
    pending.clear();
  };
  const call = (msg, transfer = []) => {
    if (failed) return Promise.reject(failed);
    const id = nextId++;
    return new Promise((resolve, reject) => {
      pending.set(id, { resolve, reject });
      worker.postMessage({ id, ...msg }, transfer);
    });
  };
  const abs = (u) => (u ? new URL(u, globalThis.location?.href).href : undefined);
  await call({ type: 'init', wasmUrl: abs(wasmUrl), moduleUrl: abs(moduleUrl) });
  return {
    worker,
    decode(bytes) {
      const copy = bytes instanceof Uint8Array ? bytes.slice() : new Uint8Array(bytes).slice();
      return call({ type: 'decode', bytes: copy }, [copy.buffer]);
    },
    terminate() {
      worker.terminate();
      failed = new Error('hullpack worker terminated');
      for (const p of pending.values()) p.reject(failed);
      pending.clear();
    },
  };
}
