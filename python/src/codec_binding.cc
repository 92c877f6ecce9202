// hullpack.encode / decode / stream_info: the o3dgc codec on numpy arrays and bytes.
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <thread>

#include "o3dgc/o3dgc.h"
#include "py_util.h"

namespace hullpack::python {
namespace {

// The codec calls its progress hook on the calling thread: with the GIL released there, the hook
// takes it back at most every 20 ms to run the signal handlers and the callback.
class CodecProgress {
 public:
  explicit CodecProgress(py::object callback) : callback_(std::move(callback)) {}
  o3dgc::ProgressFn Fn() {
    return [this](float fraction) {
      if (stop_) return false;
      const auto now = std::chrono::steady_clock::now();
      if (std::this_thread::get_id() != thread_ || now - last_ < std::chrono::milliseconds(20))
        return true;
      last_ = now;
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        error_ = std::make_unique<py::error_already_set>();
        stop_ = true;
      } else if (!callback_.is_none()) {
        try {
          if (callback_(100.0 * fraction, stage_).ptr() == Py_False) stop_ = by_callback_ = true;
        } catch (py::error_already_set& e) {
          error_ = std::make_unique<py::error_already_set>(std::move(e));
          stop_ = true;
        }
      }
      return !stop_;
    };
  }
  // With the GIL held, after the call: re-raises what stopped it.
  void RaiseIfStopped(o3dgc::Status status, const char* what) {
    if (error_) {
      py::error_already_set e = *error_;
      error_.reset();
      throw e;
    }
    if (status == o3dgc::Status::kCancelled) ThrowCancelled(std::string(what) + ": cancelled");
  }
  void set_stage(const char* stage) { stage_ = stage; }

 private:
  py::object callback_;
  std::thread::id thread_ = std::this_thread::get_id();
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  bool stop_ = false, by_callback_ = false;
  const char* stage_ = "";
  std::unique_ptr<py::error_already_set> error_;
};

[[noreturn]] void Raise(o3dgc::Status s, const char* what) {
  const std::string text = std::string(what) + ": " + o3dgc::StatusName(s);
  if (s == o3dgc::Status::kUnsupported) throw std::runtime_error(text);
  throw py::value_error(text);
}

const char* SemanticName(o3dgc::Semantic s) {
  switch (s) {
    case o3dgc::Semantic::kGeneric:
      return "generic";
    case o3dgc::Semantic::kPosition:
      return "position";
    case o3dgc::Semantic::kNormal:
      return "normal";
    case o3dgc::Semantic::kTexCoord:
      return "texcoord";
    case o3dgc::Semantic::kColor:
      return "color";
    case o3dgc::Semantic::kWeight:
      return "weight";
    case o3dgc::Semantic::kJointId:
      return "joint";
  }
  return "?";
}

void CheckBits(const char* name, int bits) {
  if (bits < 1 || bits > 30)
    throw py::value_error(std::string(name) + " must be in [1, 30], not " + std::to_string(bits));
}

py::bytes Encode(py::handle vertices, py::handle faces, py::object normals, py::object uvs,
                 py::object colors, int position_bits, int normal_bits, int uv_bits, int color_bits,
                 bool keep_order, bool keep_degenerate_triangles, bool fast_decode,
                 bool max_compression, bool ascii, py::object progress) {
  CheckBits("position_bits", position_bits);
  CheckBits("normal_bits", normal_bits);
  CheckBits("uv_bits", uv_bits);
  CheckBits("color_bits", color_bits);
  const PointsIn points = ReadPoints(vertices, "vertices", 3, true);
  const IndicesIn triangles = ReadIndices(faces, "faces", points.count);
  o3dgc::MeshView mesh;
  mesh.positions = points.f;
  mesh.position_stride = points.stride * sizeof(float);
  mesh.num_vertices = points.count;
  mesh.indices = triangles.data;
  mesh.num_triangles = triangles.count;
  auto same_count = [&](const PointsIn& in, const char* what) {
    if (in.count != points.count) {
      throw py::value_error(std::string(what) + " has " + std::to_string(in.count) +
                            " rows but there are " + std::to_string(points.count) + " vertices");
    }
  };
  PointsIn n, t, c;
  if (!normals.is_none()) {
    n = ReadPoints(normals, "normals", 3, true);
    same_count(n, "normals");
    mesh.normals = n.f;
    mesh.normal_stride = n.stride * sizeof(float);
  }
  if (!uvs.is_none()) {
    t = ReadPoints(uvs, "uvs", 2, true);
    same_count(t, "uvs");
    o3dgc::FloatAttributeView a;
    a.data = t.f;
    a.stride = t.stride * sizeof(float);
    a.dimension = 2;
    a.semantic = o3dgc::Semantic::kTexCoord;
    a.bits = uv_bits;
    mesh.float_attributes.push_back(a);
  }
  if (!colors.is_none()) {
    py::array probe = py::array::ensure(colors);
    const size_t width = probe && probe.ndim() == 2 && probe.shape(1) == 4 ? 4 : 3;
    c = ReadPoints(colors, "colors", width, true);
    same_count(c, "colors");
    o3dgc::FloatAttributeView a;
    a.data = c.f;
    a.stride = c.stride * sizeof(float);
    a.dimension = static_cast<uint32_t>(width);
    a.semantic = o3dgc::Semantic::kColor;
    a.bits = color_bits;
    mesh.float_attributes.push_back(a);
  }
  o3dgc::EncodeParams params;
  params.stream_type = ascii ? o3dgc::StreamType::kAscii : o3dgc::StreamType::kBinary;
  params.keep_order = keep_order;
  params.keep_degenerate_triangles = keep_degenerate_triangles;
  params.fast_decode = fast_decode;
  params.max_compression = max_compression;
  params.position_bits = position_bits;
  params.normal_bits = normal_bits;
  CodecProgress watch(std::move(progress));
  watch.set_stage("encode");
  params.progress = watch.Fn();
  std::vector<uint8_t> out;
  o3dgc::Status s;
  {
    py::gil_scoped_release release;
    s = o3dgc::Encode(mesh, params, &out);
  }
  watch.RaiseIfStopped(s, "encode");
  if (s != o3dgc::Status::kOk) Raise(s, "encode");
  return py::bytes(reinterpret_cast<const char*>(out.data()), out.size());
}

py::dict InfoDict(const o3dgc::StreamInfo& i) {
  py::dict d;
  d["format"] = i.format == o3dgc::StreamFormat::kNative ? "o3dgc" : "open3dgc-2013";
  d["ascii"] = i.stream_type == o3dgc::StreamType::kAscii;
  d["version"] = std::to_string(i.version_major) + "." + std::to_string(i.version_minor);
  d["keep_order"] = i.keep_order;
  d["fast_decode"] = i.fast_decode;
  d["max_compression"] = i.all_adaptive;
  d["vertices"] = i.num_vertices;
  d["triangles"] = i.num_triangles;
  py::dict bytes;
  bytes["total"] = i.total;
  bytes["header"] = i.header;
  bytes["connectivity"] = i.connectivity;
  bytes["positions"] = i.positions;
  bytes["normals"] = i.normals;
  bytes["float_attributes"] = i.float_attributes;
  bytes["int_attributes"] = i.int_attributes;
  bytes["groups"] = i.groups;
  d["bytes"] = bytes;
  return d;
}

py::dict Decode(py::buffer data, bool verify_checksum, size_t max_vertices, size_t max_triangles,
                py::object progress) {
  py::buffer_info buffer = data.request();
  if (buffer.ndim > 1 && !(buffer.strides.back() == buffer.itemsize))
    throw py::value_error("data must be a contiguous bytes-like object");
  const auto* bytes = static_cast<const uint8_t*>(buffer.ptr);
  const size_t size = static_cast<size_t>(buffer.size * buffer.itemsize);
  o3dgc::DecodeOptions options;
  options.verify_checksum = verify_checksum;
  options.max_vertices = max_vertices;
  options.max_triangles = max_triangles;
  CodecProgress watch(std::move(progress));
  watch.set_stage("decode");
  options.progress = watch.Fn();
  o3dgc::DecodedMesh mesh;
  o3dgc::StreamInfo info;
  o3dgc::Status s;
  {
    py::gil_scoped_release release;
    s = o3dgc::Decode(bytes, size, options, &mesh, &info);
  }
  watch.RaiseIfStopped(s, "decode");
  if (s != o3dgc::Status::kOk) Raise(s, "decode");
  const size_t nv = mesh.num_vertices(), nt = mesh.num_triangles();
  py::dict d;
  d["vertices"] = OwnedArray(std::move(mesh.positions), nv, 3);
  d["faces"] = OwnedArray(std::move(mesh.indices), nt, 3);
  d["normals"] = mesh.normals.empty() ? py::object(py::none())
                                      : py::object(OwnedArray(std::move(mesh.normals), nv, 3));
  d["uvs"] = py::none();
  d["colors"] = py::none();
  py::list attributes;
  for (o3dgc::DecodedFloatAttribute& a : mesh.float_attributes) {
    py::object values = OwnedArray(std::move(a.values), nv, a.dimension);
    if (a.semantic == o3dgc::Semantic::kTexCoord && d["uvs"].is_none()) d["uvs"] = values;
    if (a.semantic == o3dgc::Semantic::kColor && d["colors"].is_none()) d["colors"] = values;
    attributes.append(
        py::dict(py::arg("semantic") = SemanticName(a.semantic), py::arg("values") = values));
  }
  for (o3dgc::DecodedIntAttribute& a : mesh.int_attributes) {
    attributes.append(
        py::dict(py::arg("semantic") = SemanticName(a.semantic),
                 py::arg("values") = OwnedArray(std::move(a.values), nv, a.dimension)));
  }
  d["attributes"] = attributes;
  d["groups"] = mesh.triangle_groups.empty()
                    ? py::object(py::none())
                    : py::object(OwnedArray(std::move(mesh.triangle_groups), nt, 0));
  d["info"] = InfoDict(info);
  return d;
}

py::dict StreamInfo(py::buffer data) {
  py::buffer_info buffer = data.request();
  o3dgc::StreamInfo info;
  const o3dgc::Status s =
      o3dgc::ReadStreamInfo(static_cast<const uint8_t*>(buffer.ptr),
                            static_cast<size_t>(buffer.size * buffer.itemsize), &info);
  if (s != o3dgc::Status::kOk) Raise(s, "stream_info");
  return InfoDict(info);
}

}  // namespace

void BindCodec(py::module_& m) {
  m.def("encode", &Encode, R"(Compress a triangle mesh into an o3dgc stream.

Parameters
----------
vertices : array_like, shape (n, 3)
    Positions; float32 C-ordered rows are read in place, anything else is converted to
    float32 once. Every value must be finite.
faces : array_like, shape (m, 3)
    Triangles as vertex indices (any integer dtype; uint32 C-ordered read in place).
normals : array_like, shape (n, 3), optional
    Per-vertex normals, predicted from the decoded surface.
uvs : array_like, shape (n, 2), optional
    Per-vertex texture coordinates, predicted from the 3D shape.
colors : array_like, shape (n, 3) or (n, 4), optional
    Per-vertex colours (0..1).
position_bits : int
    Quantization bits per position component, 1 to 30 (default 14): the decoded positions
    are within half a step (largest extent / (2^bits - 1) / 2) of the input.
normal_bits, uv_bits, color_bits : int
    The same for normals (10), texture coordinates (12) and colours (10).
keep_order : bool
    Keep vertex, triangle and corner order exactly (larger stream). Default False.
keep_degenerate_triangles : bool
    Code the faces with two corners at one position too (no area; left out by default with the
    vertices only they use, as Draco does). keep_order keeps them. Default False.
fast_decode : bool
    Code values in vertex order: faster decoding for 2-5 % more bytes. Default False.
max_compression : bool
    The smallest stream (format 1.3): meshes of 4096 vertices or more 2-5 % smaller, decoding
    about 1.2-1.5x slower. Not with fast_decode. Default False.
ascii : bool
    Write the 7-bit ASCII form (serve it gzip'd). Default False.
progress : callable, optional
    progress(percent, "encode") every 20 ms at most; return False to stop (hullpack.Cancelled).

Returns
-------
bytes
    The stream (hullpack.decode reads it back).

Raises
------
ValueError
    A wrong shape or dtype, a non-finite value, an index out of range, bits out of range.

The GIL is released while encoding.)",
        py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("normals") = py::none(),
        py::arg("uvs") = py::none(), py::arg("colors") = py::none(), py::arg("position_bits") = 14,
        py::arg("normal_bits") = 10, py::arg("uv_bits") = 12, py::arg("color_bits") = 10,
        py::arg("keep_order") = false, py::arg("keep_degenerate_triangles") = false,
        py::arg("fast_decode") = false, py::arg("max_compression") = false,
        py::arg("ascii") = false, py::arg("progress") = py::none());
  m.def("decode", &Decode, R"(Decompress an o3dgc stream (or an original Open3DGC one).

Parameters
----------
data : bytes-like
    The stream: bytes, bytearray, memoryview or a uint8 array (read in place). Every byte is
    treated as hostile: a malformed stream raises ValueError, never crashes.
verify_checksum : bool
    Check the stream's CRC32 (default True).
max_vertices, max_triangles : int
    Refuse streams declaring more (default 2**28 each).
progress : callable, optional
    progress(percent, "decode") every 20 ms at most; return False to stop (hullpack.Cancelled).

Returns
-------
dict
    "vertices" float32 (n, 3), "faces" uint32 (m, 3), "normals" float32 (n, 3) or None, "uvs"
    (n, 2) or None, "colors" or None, "attributes" (every attribute: {"semantic", "values"}),
    "groups" uint32 (m,) or None, and "info" (as stream_info). The arrays own the decoder's
    memory (no copy).

Raises
------
ValueError
    Not a stream, truncated, corrupt, checksum mismatch, or above the limits.)",
        py::arg("data"), py::kw_only(), py::arg("verify_checksum") = true,
        py::arg("max_vertices") = size_t(1) << 28, py::arg("max_triangles") = size_t(1) << 28,
        py::arg("progress") = py::none());
  m.def("stream_info", &StreamInfo, R"(Read an o3dgc stream's header without decoding it.

Parameters
----------
data : bytes-like
    The stream (at least its header).

Returns
-------
dict
    "format" ("o3dgc" or "open3dgc-2013"), "ascii", "version", "keep_order", "fast_decode",
    "max_compression" (format 1.3's adaptive low bits), "vertices", "triangles", and "bytes" per part ("total", "header", "connectivity",
    "positions", "normals", "float_attributes", "int_attributes", "groups").

Raises
------
ValueError
    Not a stream, or a truncated header.)",
        py::arg("data"));
}

}  // namespace hullpack::python
