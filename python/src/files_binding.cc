// hullpack.pack / unpack / info / collision: the command-line jobs on file paths.
#include <pybind11/stl.h>

#include <optional>
#include <utility>

#include "common/file_util.h"
#include "hullpack/cli_util.h"
#include "hullpack/scene_summary.h"
#include "hullpack/unpack_command.h"
#include "io/scene_io.h"
#include "mesh/flatten.h"
#include "mesh/validate.h"
#include "packed/packed_glb_reader.h"
#include "pipeline/pack.h"
#include "py_util.h"
#include "robot/collision_export.h"

namespace hullpack::python {
namespace {

// A failed Status as the matching Python exception.
[[noreturn]] void Raise(const Status& s) {
  switch (s.code()) {
    case StatusCode::kIoError:
      PyErr_SetString(PyExc_OSError, s.message().c_str());
      throw py::error_already_set();
    case StatusCode::kCancelled:
      ThrowCancelled(s.message());
    case StatusCode::kUnknownFormat:
    case StatusCode::kParseError:
    case StatusCode::kInvalidMesh:
    case StatusCode::kInvalidArgument:
      throw py::value_error(s.message());
    default:
      throw std::runtime_error(s.message());
  }
}

py::object FromJson(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

class PackWatch : public PackObserver {
 public:
  explicit PackWatch(Watch& watch) : watch_(watch) {}
  void OnProgress(double fraction, const std::string& stage) override {
    watch_.Report(100 * fraction, stage.c_str());
  }
  bool IsCancelled() override { return watch_.cancelled(); }

 private:
  Watch& watch_;
};

class VhacdWatch : public vhacd::Observer {
 public:
  explicit VhacdWatch(Watch& watch) : watch_(watch) {}
  void OnProgress(double overall, double, double, const char* stage, const char*) override {
    watch_.Report(overall, stage);
  }
  bool IsCancelled() override { return watch_.cancelled(); }

 private:
  Watch& watch_;
};

py::dict PackReportDict(const PackReport& r) {
  py::list meshes;
  for (const MeshPackReport& m : r.meshes) {
    py::dict d;
    d["name"] = m.name;
    d["triangles"] = m.triangles;
    d["vertices"] = m.vertices;
    d["bytes_before"] = m.bytes_before;
    d["bytes_after"] = m.bytes_after;
    d["bits_per_vertex"] = m.bits_per_vertex;
    d["parts"] = m.parts;
    d["position_bits"] = m.position_bits;
    d["max_error"] = m.max_error;
    d["max_error_fraction"] = m.max_error_fraction;
    d["no_hulls"] = m.no_hulls_reason;
    d["hull_count"] = m.hull_count;
    d["hull_vertices"] = m.hull_vertices;
    d["hull_bytes"] = m.hull_bytes;
    d["hull_concavity"] = m.hull_concavity;
    d["hull_iou"] = m.hull_iou;
    meshes.append(d);
  }
  py::dict d;
  d["meshes"] = meshes;
  d["left_out"] = r.left_out;
  d["not_kept"] = r.not_kept;
  d["output_bytes"] = r.output_bytes;
  d["key_frame_bytes_before"] = r.key_frame_bytes_before;
  d["key_frame_bytes_after"] = r.key_frame_bytes_after;
  return d;
}

// `hulls`: "all", "none", "auto" or a count 1-100000 (an int or its digits); returns the count
// (0 for the words, whose policy it sets).
uint32_t ApplyHulls(py::handle hulls, HullPolicy* policy) {
  const char* const kWhat = "hulls must be 'all', 'none', 'auto' or a count 1-100000, not ";
  if (py::isinstance<py::str>(hulls)) {
    const std::string v = hulls.cast<std::string>();
    if (v == "all") {
      *policy = HullPolicy::kAll;
    } else if (v == "none") {
      *policy = HullPolicy::kNone;
    } else if (v != "auto") {
      if (v.empty() || v.size() > 6 || v.find_first_not_of("0123456789") != std::string::npos ||
          std::stol(v) < 1 || std::stol(v) > 100000)
        throw py::value_error(kWhat + ("'" + v + "'"));
      return static_cast<uint32_t>(std::stol(v));
    }
    return 0;
  }
  if (py::isinstance<py::int_>(hulls) && !py::isinstance<py::bool_>(hulls)) {
    const long long n = hulls.cast<long long>();
    if (n < 1 || n > 100000) throw py::value_error(kWhat + std::to_string(n));
    return static_cast<uint32_t>(n);
  }
  throw py::value_error(kWhat + py::repr(hulls).cast<std::string>());
}

void ApplyDecomposition(vhacd::Parameters* p, const std::string& quality,
                        std::optional<uint32_t> resolution, std::optional<uint32_t> max_hulls,
                        std::optional<double> concavity, std::optional<double> max_concavity) {
  if (quality == "high") {
    *p = vhacd::Parameters::High();
  } else if (quality != "default") {
    throw py::value_error("quality must be 'default' or 'high', not '" + quality + "'");
  }
  if (resolution) p->resolution = *resolution;
  if (max_hulls) p->max_convex_hulls = *max_hulls;
  if (concavity) p->concavity = *concavity;
  if (max_concavity) p->max_concavity = *max_concavity;
  std::string why;
  if (vhacd::ValidateParameters(*p, &why) != vhacd::Status::kOk)
    throw py::value_error("invalid decomposition parameter: " + why);
}

py::dict Pack(const std::string& input, const std::string& output, double max_error,
              double hull_error, std::optional<int> position_bits, int normal_bits, int uv_bits,
              bool ascii, bool keep_order, bool fast_decode, bool max_compression,
              int64_t part_triangles, bool fallback, bool quantized_hulls, bool plain_animations,
              py::handle hulls, const std::string& physics, const std::string& method,
              const std::string& quality, std::optional<uint32_t> resolution,
              std::optional<uint32_t> max_hulls, std::optional<uint32_t> max_vertices,
              std::optional<double> concavity, std::optional<double> max_concavity, bool force,
              py::object progress) {
  PackOptions o;
  if (!(max_error > 0 && max_error <= 0.5)) throw py::value_error("max_error must be in (0, 0.5]");
  if (!(hull_error > 0 && hull_error <= 0.5))
    throw py::value_error("hull_error must be in (0, 0.5]");
  o.max_error = max_error;
  o.hull_error = hull_error;
  for (int bits : {position_bits.value_or(14), normal_bits, uv_bits})
    if (bits < 1 || bits > 30) throw py::value_error("bits must be in [1, 30]");
  o.position_bits = position_bits.value_or(0);
  o.normal_bits = normal_bits;
  o.uv_bits = uv_bits;
  o.stream_type = ascii ? o3dgc::StreamType::kAscii : o3dgc::StreamType::kBinary;
  o.keep_order = keep_order;
  o.fast_decode = fast_decode;
  o.max_compression = max_compression;
  if (fast_decode && max_compression)
    throw py::value_error("fast_decode and max_compression exclude each other");
  if (part_triangles < 0) throw py::value_error("part_triangles must be >= 0");
  o.part_triangles = static_cast<size_t>(part_triangles);
  o.glb.fallback = fallback;
  o.glb.quantized_hulls = quantized_hulls;
  o.glb.compress_animations = !plain_animations;
  // As `hullpack pack --hulls all|none|auto|N`: a count asks for exactly N hulls per mesh (with
  // the automatic choice of meshes).
  const uint32_t hull_count = ApplyHulls(hulls, &o.collision.policy);
  if (physics != "omi" && physics != "khr")
    throw py::value_error("physics must be 'omi' or 'khr', not '" + physics + "'");
  o.glb.physics = physics == "omi" ? PhysicsForm::kOmi : PhysicsForm::kKhr;
  if (method == "hacd") {
    // As `hullpack pack --method hacd`: testHACD's recommended line; the voxel options do not
    // apply, so giving one is an error rather than silently ignored.
    o.collision.method = DecompositionMethod::kHacd;
    if (quality != "default" || resolution) {
      throw py::value_error(
          "quality and resolution are V-HACD options (method=\"vhacd\"), not options of "
          "method=\"hacd\"");
    }
  } else if (method != "vhacd") {
    throw py::value_error("method must be 'vhacd' or 'hacd', not '" + method + "'");
  }
  ApplyDecomposition(&o.collision.parameters, quality, resolution, max_hulls, concavity,
                     max_concavity);
  o.collision.parameters.hull_count = hull_count;
  if (method == "hacd") {
    // As ApplyMethodOptions for the command.
    vhacd::HacdParameters& h = o.collision.hacd_parameters;
    if (max_hulls) h.max_clusters = *max_hulls;
    if (concavity) h.concavity = *concavity * 2.0 * h.scale_factor;
    if (max_concavity) h.max_concavity = *max_concavity;
    h.hull_count = hull_count;
  }
  if (max_vertices) {
    if (*max_vertices < 4 || *max_vertices > 1024)
      throw py::value_error("max_vertices must be in [4, 1024]");
    o.collision.parameters.max_vertices_per_hull = *max_vertices;
    o.collision.hacd_parameters.max_vertices_per_hull = *max_vertices;
  }
  if (FormatFromExtension(output) != FileFormat::kGlb)
    throw py::value_error(output + ": the output must be a .glb file");

  Watch watch(std::move(progress));
  PackWatch observer(watch);
  Status failed;
  PackReport report;
  // The command's path: check the output, PackInput (load, embed images, the stages), write
  // atomically.
  watch.Run([&] {
    failed = CheckOutputPath(output, {input}, force);
    if (!failed.ok()) return;
    Result<PackResult> packed = PackInput(input, o, &observer);
    if (!packed.ok()) {
      failed = packed.status();
      return;
    }
    failed = WriteFileAtomically(output, packed->glb);
    report = std::move(packed->report);
  });
  if (!failed.ok()) Raise(failed);
  py::dict d = PackReportDict(report);
  d["input"] = input;
  d["output"] = output;
  return d;
}

py::dict Unpack(const std::string& input, const std::string& output, bool force) {
  if (FormatFromExtension(output) == FileFormat::kUnknown)
    throw py::value_error(output + ": unknown output format (.glb .gltf .obj .off .wrl .ply)");
  Result<UnpackSummary> done = UnpackSummary();
  {
    py::gil_scoped_release release;
    done = hullpack::Unpack(input, output, force);
  }
  if (!done.ok()) Raise(done.status());
  py::dict d;
  d["input"] = input;
  d["output"] = output;
  d["meshes"] = done->meshes;
  d["triangles"] = done->triangles;
  d["hulls"] = done->hulls;
  if (!done->hulls_path.empty()) d["hulls_output"] = done->hulls_path;
  if (!done->buffer_path.empty()) d["buffer_output"] = done->buffer_path;
  return d;
}

py::object Info(const std::string& path) {
  nlohmann::json j;
  Status failed;
  {
    py::gil_scoped_release release;
    Result<Scene> scene = ReadScene(path);
    if (!scene.ok()) {
      failed = scene.status();
    } else {
      for (size_t i = 0; i < scene->meshes.size() && failed.ok(); ++i) {
        Status valid = ValidateMesh(scene->meshes[i]);
        if (!valid.ok())
          failed =
              Status(valid.code(), path + ": mesh " + std::to_string(i) + ": " + valid.message());
      }
      if (failed.ok()) {
        j = SummaryToJson(scene.value(), Summarize(scene.value()));
        j["file"] = path;
        j["format"] = FormatName(FormatFromExtension(path));
        Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
        j["bytes"] = bytes.ok() ? bytes.value().size() : 0;
      }
    }
  }
  if (!failed.ok()) Raise(failed);
  return FromJson(j);
}

py::dict Collision(const std::string& input, const std::string& output_dir,
                   const std::string& format, std::optional<std::string> name, double density,
                   std::optional<int> max_hull_vertices, const std::string& quality,
                   std::optional<uint32_t> resolution, std::optional<uint32_t> max_hulls,
                   std::optional<double> concavity, bool force, py::object progress) {
  CollisionExportOptions o;
  if (!ParseRobotFormat(format, &o.format))
    throw py::value_error("format must be 'urdf', 'mjcf' or 'sdf', not '" + format + "'");
  o.name = name.value_or("");
  o.density = density;
  o.max_hull_vertices = max_hull_vertices.value_or(0);
  if (max_hull_vertices && *max_hull_vertices == 0)
    throw py::value_error("max_hull_vertices must be at least 4");
  o.force = force;
  ApplyDecomposition(&o.parameters, quality, resolution, max_hulls, concavity, std::nullopt);
  Watch watch(std::move(progress));
  VhacdWatch observer(watch);
  Status failed;
  CollisionExportReport r;
  watch.Run([&] {
    Result<Scene> scene = ReadScene(input);
    if (!scene.ok()) {
      failed = scene.status();
      return;
    }
    Result<CollisionExportReport> done =
        ExportCollision(std::move(scene).value(), input, output_dir, o, &observer);
    if (!done.ok()) {
      failed = done.status();
      return;
    }
    r = std::move(done.value());
  });
  if (!failed.ok()) Raise(failed);
  py::dict d;
  d["name"] = r.name;
  d["description"] = r.description;
  d["files"] = r.files;
  d["hull_count"] = r.hull_count;
  d["largest_hull_vertices"] = r.largest_hull_vertices;
  d["volume"] = r.mass.volume;
  d["mass"] = r.mass.mass;
  d["center_of_mass"] = r.mass.center;
  d["inertia"] = r.mass.inertia;
  d["concavity"] = r.decomposition.concavity;
  d["volume_iou"] = r.decomposition.volume_iou;
  return d;
}

py::dict LoadMesh(const std::string& path) {
  Status failed;
  Mesh mesh;
  {
    py::gil_scoped_release release;
    Result<Scene> scene = ReadScene(path);
    if (!scene.ok()) {
      failed = scene.status();
    } else {
      mesh = FlattenScene(scene.value());
      failed = ValidateMesh(mesh);
      if (!failed.ok()) failed = Status(failed.code(), path + ": " + failed.message());
    }
  }
  if (!failed.ok()) Raise(failed);
  const size_t nv = mesh.vertex_count(), nt = mesh.triangle_count();
  py::dict d;
  d["vertices"] = OwnedArray(std::move(mesh.positions), nv, 3);
  d["faces"] = OwnedArray(std::move(mesh.indices), nt, 3);
  d["normals"] = mesh.normals.empty() ? py::object(py::none())
                                      : py::object(OwnedArray(std::move(mesh.normals), nv, 3));
  d["uvs"] = mesh.uv_sets.empty() ? py::object(py::none())
                                  : py::object(OwnedArray(std::move(mesh.uv_sets[0]), nv, 2));
  return d;
}

}  // namespace

void BindFiles(py::module_& m) {
  m.def("pack", &Pack, R"(Pack a mesh or scene file into one GLB: compressed meshes + convex hulls.

The same job as `hullpack pack INPUT -o OUTPUT.glb` (docs/packed-gltf.md).

Parameters
----------
input : str
    .glb .gltf .fbx .obj .dae .ply .stl .off .wrl file.
output : str
    The .glb to write (atomically; never the input).
max_error : float
    Largest position error, as a fraction of each mesh's bounding-box diagonal (0.0005).
hull_error : float
    The same for hull vertices (0.002).
position_bits : int, optional
    Explicit position bits (1 to 30) instead of max_error.
normal_bits, uv_bits : int
    Bits for normals (10) and texture coordinates (12).
ascii, keep_order, fast_decode, max_compression, fallback, quantized_hulls, plain_animations : bool
    As the command's --ascii, --keep-order, --fast-decode, --max-compression, --fallback,
    --quantized-hulls, --plain-animations.
part_triangles : int
    As --part-triangles: a render mesh of more triangles is coded in compact parts of at most
    this many, one stream and glTF mesh each, on one grid (1000000; 0: never).
hulls : str or int
    As --hulls: which meshes get hulls, "auto" (default), "all" or "none"; or a count N
    (1 to 100000, an int or its digits): exactly N hulls per mesh (on the meshes "auto"
    picks; both methods).
physics : str
    "omi" (OMI_physics_shape/body, default) or "khr" (the KHR_physics_rigid_bodies draft).
method : str
    Decomposer: "vhacd" (V-HACD 2.0, default) or "hacd" (HACD with testHACD's recommended
    settings and 24 vertices per hull; for open and thin shapes). quality and resolution
    are V-HACD options: giving one with "hacd" raises ValueError.
quality : str
    Decomposition preset: "default" or "high".
resolution, max_hulls : int, optional
    Voxels (V-HACD only) and hull budget (HACD: the cheapest merges go on past the concavity
    limit down to max_hulls clusters).
max_vertices : int, optional
    Vertex cap per hull, 4 to 1024 (both methods).
concavity : float, optional
    Largest concavity of a part (HACD: of a merge), fraction of the diagonal (0 to 1).
max_concavity : float, optional
    As --max-concavity D: hulls within D times the mesh's bounding-box diagonal of its
    surface, as few as that allows (0 to 1; 0 or None = no target); both methods.
force : bool
    Replace an existing output.
progress : callable, optional
    progress(percent, stage) every 20 ms at most; return False to stop (hullpack.Cancelled).

Returns
-------
dict
    Per mesh ("meshes"): triangles, vertices, bytes before/after, bits per vertex, streams
    ("parts"), position
    error, hull count/vertices/bytes, hull concavity and IoU; "left_out", "not_kept",
    "output_bytes", "key_frame_bytes_before" and "key_frame_bytes_after" (animation key
    frames as plain accessors and as written).

Raises
------
ValueError
    Unreadable or invalid input, an existing output without force, a bad option.
OSError
    A file cannot be read or written.)",
        py::arg("input"), py::arg("output"), py::kw_only(), py::arg("max_error") = 0.0005,
        py::arg("hull_error") = 0.002, py::arg("position_bits") = py::none(),
        py::arg("normal_bits") = 10, py::arg("uv_bits") = 12, py::arg("ascii") = false,
        py::arg("keep_order") = false, py::arg("fast_decode") = false,
        py::arg("max_compression") = false,
        py::arg("part_triangles") = static_cast<int64_t>(kDefaultPartTriangles),
        py::arg("fallback") = false, py::arg("quantized_hulls") = false,
        py::arg("plain_animations") = false, py::arg("hulls") = "auto", py::arg("physics") = "omi",
        py::arg("method") = "vhacd", py::arg("quality") = "default",
        py::arg("resolution") = py::none(), py::arg("max_hulls") = py::none(),
        py::arg("max_vertices") = py::none(), py::arg("concavity") = py::none(),
        py::arg("max_concavity") = py::none(), py::arg("force") = false,
        py::arg("progress") = py::none());
  m.def("unpack", &Unpack, R"(Decode a packed GLB back to plain glTF (.glb, .gltf) or a mesh file.

Parameters
----------
input : str
    A GLB written by pack.
output : str
    .glb (every compressed primitive decoded into plain accessors, colliders and hulls kept);
    .obj .wrl (the render meshes, then each hull as a closed mesh named hull_N); .off .ply
    (the render meshes; the hulls go to STEM.hulls.off / .ply beside it), .gltf (the document
    as JSON, its buffer in STEM.bin beside it).
force : bool
    Replace an existing output.

Returns
-------
dict
    "input", "output", "meshes" (render meshes; .glb: every mesh), "triangles" (of those),
    "hulls", "hulls_output" when the hulls went to a file of their own, and "buffer_output"
    for a .gltf's buffer.)",
        py::arg("input"), py::arg("output"), py::kw_only(), py::arg("force") = false);
  m.def("load_mesh", &LoadMesh, R"(Read a mesh or scene file into numpy arrays.

Parameters
----------
path : str
    .glb .gltf .fbx .obj .dae .ply .stl .off .wrl file.

Returns
-------
dict
    Every mesh of the file merged into one (node transforms are not applied): "vertices"
    float32 (n, 3), "faces" uint32 (m, 3), "normals" float32 (n, 3) or None, "uvs" float32
    (n, 2) or None (glTF convention, v = 0 at the top), ready for decompose and encode.

Raises
------
OSError, ValueError
    The file cannot be read, or holds an invalid mesh; the message names it.)",
        py::arg("path"));
  m.def("info", &Info, R"(Counts, attributes, bounds and topology of a mesh or scene file.

Parameters
----------
path : str
    Any file `hullpack info` reads (packed GLBs included).

Returns
-------
dict
    What `hullpack info --json` prints: "file", "format", "bytes", "meshes" (per mesh
    counts, attributes, bounds, topology), scene totals.)",
        py::arg("path"));
  m.def("collision", &Collision, R"(Convex collision hulls as a robot description.

The same job as `hullpack collision INPUT -o OUTPUT_DIR --format FORMAT`: writes
OUTPUT_DIR/NAME.urdf (.xml for MJCF, .sdf) and OUTPUT_DIR/meshes/ with the visual mesh and
one file per hull (STL for URDF and SDF, OBJ for MJCF), with the mass, centre of mass and
inertia of the union of the hulls (docs/guide-simulation.md).

Parameters
----------
input : str
    The mesh or scene file (every mesh becomes one rigid body).
output_dir : str
    Folder to write into (created when missing).
format : str
    "urdf" (default), "mjcf" or "sdf".
name : str, optional
    Link/body/model name and file prefix (default: the input's stem), sanitized to letters,
    digits and '_'.
density : float
    Mass per cubic unit of the mesh (1000: water in kg/m^3 for a mesh in metres).
max_hull_vertices : int, optional
    Vertex cap per hull (default 64; at most 255 for URDF and SDF, 1024 for MJCF).
quality : str
    Decomposition preset: "default" (hullpack pack's) or "high".
resolution, max_hulls : int, optional
    Voxels and hull budget of the decomposition.
concavity : float, optional
    Largest concavity of a part (0 to 1).
force : bool
    Replace existing files.
progress : callable, optional
    progress(percent, stage) every 20 ms at most; return False to stop (hullpack.Cancelled).

Returns
-------
dict
    "name", "description" (its path), "files", "hull_count", "largest_hull_vertices",
    "volume", "mass", "center_of_mass", "inertia" (ixx, iyy, izz, ixy, ixz, iyz about the
    centre of mass), "concavity", "volume_iou".)",
        py::arg("input"), py::arg("output_dir"), py::kw_only(), py::arg("format") = "urdf",
        py::arg("name") = py::none(), py::arg("density") = 1000.0,
        py::arg("max_hull_vertices") = py::none(), py::arg("quality") = "default",
        py::arg("resolution") = py::none(), py::arg("max_hulls") = py::none(),
        py::arg("concavity") = py::none(), py::arg("force") = false,
        py::arg("progress") = py::none());
}

}  // namespace hullpack::python
