// bench_draco.js: the Draco side of the decode benchmark (web/bench.html, web/bench_draco_worker.js).
// A classic script (Draco's wrapper is one), loaded by the page with <script> and by the worker with
// importScripts. It decodes a Draco mesh the way three's DRACOLoader does: every attribute to a
// Float32Array and the triangles to a Uint32Array, all copied out of the wasm heap, so that the
// result is the same kind of thing hullpack's decode(bytes) returns.
/* global DracoDecoderModule */
(function (scope) {
  // Draco's attribute types, named as hullpack_decoder.js names its semantics.
  const SEMANTICS = ['position', 'normal', 'color', 'texcoord', 'generic'];

  // Instantiates the decoder from the wasm bytes already fetched (compile is not timed here).
  scope.hullpackBenchDracoModule = (wasmBinary) =>
    new Promise((resolve) => { DracoDecoderModule({ wasmBinary, onModuleLoaded: (m) => resolve(m) }); });

  scope.hullpackBenchDracoDecode = (D, bytes) => {
    const decoder = new D.Decoder();
    const mesh = new D.Mesh();
    try {
      const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
      if (!status.ok()) throw new Error(`draco: ${status.error_msg()}`);
      const nv = mesh.num_points();
      const nt = mesh.num_faces();
      const out = { numVertices: nv, numTriangles: nt, attributes: [], indices: null };
      for (let i = 0; i < mesh.num_attributes(); ++i) {
        const attr = decoder.GetAttribute(mesh, i);
        const n = nv * attr.num_components();
        const ptr = D._malloc(n * 4);
        decoder.GetAttributeDataArrayForAllPoints(mesh, attr, D.DT_FLOAT32, n * 4, ptr);
        out.attributes.push({ semantic: SEMANTICS[attr.attribute_type()] || 'generic', dimension: attr.num_components(),
          array: new Float32Array(D.HEAPF32.buffer, ptr, n).slice() });
        D._free(ptr);
      }
      const ip = D._malloc(nt * 12);
      decoder.GetTrianglesUInt32Array(mesh, nt * 12, ip);
      out.indices = new Uint32Array(D.HEAPU32.buffer, ip, nt * 3).slice();
      D._free(ip);
      return out;
    } finally {
      D.destroy(mesh);
      D.destroy(decoder);
    }
  };
})(self);
