// glb_container.mjs: a GLB file from a glTF document and its binary chunk, for the test scripts
// that generate inputs (make_glb.mjs, make_skinned_glb.mjs, make_morph_glb.mjs). The JSON chunk is
// padded with spaces and the binary chunk with zeros to 4 bytes, as the container wants.
export function glbBytes(doc, bin) {
  let json = Buffer.from(JSON.stringify(doc));
  json = Buffer.concat([json, Buffer.alloc(((json.length + 3) & ~3) - json.length, 0x20)]);
  const data = Buffer.concat([bin, Buffer.alloc(((bin.length + 3) & ~3) - bin.length)]);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + json.length + 8 + data.length, 8);
  const chunk = (length, type) => {
    const b = Buffer.alloc(8);
    b.writeUInt32LE(length, 0);
    b.writeUInt32LE(type, 4);
    return b;
  };
  return Buffer.concat([header, chunk(json.length, 0x4e4f534a), json, chunk(data.length, 0x004e4942), data]);
}
