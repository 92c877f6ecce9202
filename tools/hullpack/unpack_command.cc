#include "hullpack/unpack_command.h"

#include <cctype>
#include <cstdio>
#include <optional>

#include "common/file_util.h"
#include "gltf/glb_reader.h"
#include "hullpack/cli_util.h"
#include "io/scene_io.h"
#include "mesh/convex_hull.h"
#include "packed/packed_glb_reader.h"

namespace hullpack {
namespace {

// Hulls `hullpack pack` writes have at most 1024 points (--max-vertices).
constexpr size_t kMaxUnpackedHullPoints = 16384;

// Where the extension of "dir/name.off" starts (the path's size when it has none).
size_t ExtensionStart(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.rfind('.');
  return dot == std::string::npos || (slash != std::string::npos && dot < slash) ? path.size()
                                                                                 : dot;
}

// "dir/name.off" -> "dir/name.hulls.off"
std::string HullsPath(const std::string& output) {
  const size_t dot = ExtensionStart(output);
  return output.substr(0, dot) + ".hulls" + output.substr(dot);
}

// "dir/name.gltf" -> "dir/name.bin": the .gltf's buffer, beside it.
std::string BufferPath(const std::string& output) {
  return output.substr(0, ExtensionStart(output)) + ".bin";
}

// A file name as a relative URI reference: every byte outside RFC 3986's unreserved set escaped.
std::string UriOfFileName(const std::string& name) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string uri;
  for (const unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
      uri += static_cast<char>(c);
    } else {
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 15];
    }
  }
  return uri;
}

// The plain document as NAME.gltf and, when it has a binary chunk, NAME.bin.
Status WriteGltfPair(const GltfDocument& plain, const std::string& output,
                     const std::string& buffer_path) {
  const size_t slash = buffer_path.find_last_of("/\\");
  const std::string buffer_name =
      slash == std::string::npos ? buffer_path : buffer_path.substr(slash + 1);
  Result<std::string> json = plain.SerializeJson(UriOfFileName(buffer_name));
  if (!json.ok()) return Status(json.status().code(), output + ": " + json.status().message());
  if (!plain.binary().empty()) {
    Status written = WriteFileAtomically(buffer_path, plain.binary());
    if (!written.ok()) return written;
  }
  return WriteFileAtomically(output, json.value().data(), json.value().size());
}

}  // namespace

Result<UnpackSummary> Unpack(const std::string& input, const std::string& output, bool force) {
  const FileFormat format = FormatFromExtension(output);
  if (format != FileFormat::kGlb && format != FileFormat::kGltf && format != FileFormat::kObj &&
      format != FileFormat::kOff && format != FileFormat::kWrl && format != FileFormat::kPly) {
    return Status(StatusCode::kInvalidArgument,
                  output + ": unknown output format (.glb .gltf .obj .off .wrl .ply)");
  }
  const bool separate_hulls = format == FileFormat::kOff || format == FileFormat::kPly;
  UnpackSummary summary;
  if (separate_hulls) summary.hulls_path = HullsPath(output);
  Status writable = CheckOutputPath(output, {input}, force);
  if (!writable.ok()) return writable;
  if (format == FileFormat::kGltf) {
    summary.buffer_path = BufferPath(output);
    writable = CheckOutputPath(summary.buffer_path, {input, output}, force);
    if (!writable.ok()) return writable;
  }
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(input);
  if (!bytes.ok()) return bytes.status();
  GltfDocument plain;
  Result<Scene> scene =
      ReadPackedGltf(bytes.value().data(), bytes.value().size(), input, "", &plain);
  if (!scene.ok()) return scene.status();
  if (format == FileFormat::kGlb || format == FileFormat::kGltf) {
    summary.meshes = scene->meshes.size();
    summary.triangles = scene->triangle_count();
    if (format == FileFormat::kGltf) {
      if (plain.binary().empty()) summary.buffer_path.clear();
      Status written = WriteGltfPair(plain, output, summary.buffer_path);
      if (!written.ok()) return written;
      return summary;
    }
    Result<std::vector<uint8_t>> glb = plain.Serialize();
    if (!glb.ok()) return glb.status();
    Status written = WriteFileAtomically(output, glb.value());
    if (!written.ok()) return written;
    return summary;
  }
  Result<std::vector<CollisionHull>> hulls = ReadCollisionHulls(plain, input);
  if (!hulls.ok()) return hulls.status();
  // Formats without points or colliders: the render meshes, then each hull as triangles.
  std::vector<bool> is_hull(scene->meshes.size(), false);
  for (const CollisionHull& h : hulls.value()) {
    if (h.gltf_mesh >= 0 && static_cast<size_t>(h.gltf_mesh) < is_hull.size())
      is_hull[h.gltf_mesh] = true;
  }
  Scene render, hull_scene;
  render.materials = scene->materials;
  render.images = scene->images;
  for (size_t m = 0; m < scene->meshes.size(); ++m) {
    if (is_hull[m] || scene->meshes[m].triangle_count() == 0) continue;
    render.meshes.push_back(scene->meshes[m]);
    summary.triangles += scene->meshes[m].triangle_count();
  }
  summary.meshes = render.meshes.size();
  Scene& hull_target = separate_hulls ? hull_scene : render;
  for (const CollisionHull& h : hulls.value()) {
    // The hull's triangles cost O(points x faces): a file's hull may be hostile.
    if (h.hull.triangle_count() == 0 && h.hull.vertex_count() > kMaxUnpackedHullPoints) {
      return Status(StatusCode::kInvalidArgument,
                    input + ": nodes[" + std::to_string(h.collider_node) + "]: a hull of " +
                        std::to_string(h.hull.vertex_count()) + " points (unpack triangulates " +
                        "hulls of at most " + std::to_string(kMaxUnpackedHullPoints) + ")");
    }
    Mesh mesh = h.hull.triangle_count() > 0 ? h.hull : ConvexHullOfPoints(h.hull.positions);
    mesh.name = "hull_" + std::to_string(summary.hulls);
    mesh.normals.clear();
    mesh.material_ids.clear();
    hull_target.meshes.push_back(std::move(mesh));
    ++summary.hulls;
  }
  if (separate_hulls && !hull_scene.meshes.empty()) {
    Status hulls_writable = CheckOutputPath(summary.hulls_path, {input}, force);
    if (!hulls_writable.ok()) return hulls_writable;
  }
  Status written = WriteScene(render, output);
  if (!written.ok()) return written;
  if (separate_hulls) {
    if (hull_scene.meshes.empty()) {
      summary.hulls_path.clear();
    } else {
      written = WriteScene(hull_scene, summary.hulls_path);
      if (!written.ok()) return written;
    }
  }
  return summary;
}

int RunUnpackCommand(const std::vector<std::string>& args) {
  std::vector<std::string> inputs;
  std::string output;
  bool force = false;
  CliArgs cli("hullpack unpack", "PACKED.glb -o OUTPUT [--force]",
              "Decodes a packed GLB.\n"
              "  OUTPUT .glb: the same glTF with every compressed primitive decoded into plain\n"
              "               accessors (collider nodes and hull meshes kept);\n"
              "  OUTPUT .gltf: the same as JSON, its binary buffer in STEM.bin beside it;\n"
              "  OUTPUT .obj .wrl: the render meshes, then each collision hull as a closed mesh\n"
              "               (the convex hull of its points), one object/Shape hull_N each;\n"
              "  OUTPUT .off .ply: the render meshes; the hulls go to STEM.hulls.off/.ply");
  cli.VersionDetail(FormatVersionText());
  cli.Positional("PACKED.glb", &inputs, 1, 1);
  cli.String("-o, --output", "OUTPUT", &output,
             "the file to write (.glb .gltf .obj .off .wrl .ply)")
      .Required();
  cli.Flag("--force", &force, "replace an existing OUTPUT");
  if (std::optional<int> exit_code = cli.Parse(args)) return *exit_code;
  const std::string& input = inputs[0];
  if (FormatFromExtension(output) == FileFormat::kUnknown) {
    std::fprintf(stderr,
                 "hullpack unpack: %s: unknown output format (.glb .gltf .obj .off .wrl .ply)\n",
                 output.c_str());
    return kExitUsage;
  }
  Result<UnpackSummary> done = Unpack(input, output, force);
  if (!done.ok()) {
    std::fprintf(stderr, "hullpack unpack: %s\n", done.status().message().c_str());
    return 1;
  }
  std::printf("%s -> %s%s%s: %zu meshes, %zu triangles", input.c_str(), output.c_str(),
              done->buffer_path.empty() ? "" : " + ", done->buffer_path.c_str(), done->meshes,
              done->triangles);
  if (done->hulls > 0) {
    std::printf(", %zu hulls%s%s", done->hulls, done->hulls_path.empty() ? "" : " -> ",
                done->hulls_path.c_str());
  }
  std::printf("\n");
  return 0;
}

}  // namespace hullpack
