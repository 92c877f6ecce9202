// bench_draco_worker.js: classic Web Worker running Draco's WASM decoder for web/bench.html, with
// the protocol of hullpack_worker.js: {id, type:'init', wrapperUrl, wasmUrl} -> {id};
// {id, type:'decode', bytes} -> {id, mesh} where mesh.decodeMs is the time spent in the worker
// (decode + copy out), and the arrays are transferred.
/* global hullpackBenchDracoModule, hullpackBenchDracoDecode */
let D = null;

self.onmessage = async (e) => {
  const { id, type } = e.data;
  try {
    if (type === 'init') {
      importScripts(e.data.wrapperUrl, new URL('bench_draco.js', self.location.href).href);
      const wasmBinary = await (await fetch(e.data.wasmUrl)).arrayBuffer();
      D = await hullpackBenchDracoModule(wasmBinary);
      self.postMessage({ id });
    } else if (type === 'decode') {
      const t0 = performance.now();
      const mesh = hullpackBenchDracoDecode(D, e.data.bytes);
      mesh.decodeMs = performance.now() - t0;
      self.postMessage({ id, mesh }, [mesh.indices.buffer, ...mesh.attributes.map((a) => a.array.buffer)]);
    }
  } catch (err) {
    self.postMessage({ id, error: String(err && err.message ? err.message : err) });
  }
};
