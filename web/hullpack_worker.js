// hullpack_worker.js: module Web Worker that decodes o3dgc streams off the main thread.
// Protocol (see createWorkerDecoder in hullpack_decoder.js):
//   {id, type:'init', wasmUrl, moduleUrl?}  -> {id}
//   {id, type:'decode', bytes: Uint8Array}  -> {id, mesh} (buffers transferred) or {id, error, status}
import { createDecoder, transferables } from './hullpack_decoder.js';

let decoder = null;

self.onmessage = async (e) => {
  const { id, type } = e.data;
  try {
    if (type === 'init') {
      decoder = await createDecoder({ wasmUrl: e.data.wasmUrl, moduleUrl: e.data.moduleUrl });
      self.postMessage({ id });
    } else if (type === 'decode') {
      if (!decoder) throw new Error('hullpack worker: not initialised');
      const t0 = performance.now();
      const mesh = decoder.decode(e.data.bytes);
      mesh.decodeMs = performance.now() - t0;
      self.postMessage({ id, mesh }, transferables(mesh));
    } else {
      throw new Error(`hullpack worker: unknown message ${type}`);
    }
  } catch (err) {
    self.postMessage({ id, error: String(err && err.message ? err.message : err), status: err && err.status });
  }
};
