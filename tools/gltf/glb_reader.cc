#include "gltf/glb_reader.h"

#include <cstring>
#include <utility>

#include "common/file_util.h"
#include "gltf/glb_reader_decoder.h"

namespace hullpack {
namespace glb_reader_internal {

Result<Scene> Decoder::Run() {
  Scene scene;
  auto asset = root_.find("asset");
  if (asset == root_.end() || !asset->is_object()) return Error("asset", "is missing");
  std::string version, min_version;
  HP_RETURN_IF_ERROR(GetString(*asset, "version", "asset", &version));
  HP_RETURN_IF_ERROR(GetString(*asset, "minVersion", "asset", &min_version));
  if (version.compare(0, 2, "2.") != 0)
    return Unsupported("asset", "glTF version '" + version + "' (need 2.x)");
  if (!min_version.empty() && min_version != "2.0") {
    return Unsupported("asset", "minVersion '" + min_version + "' is newer than 2.0");
  }
  HP_RETURN_IF_ERROR(CheckExtensions());
  HP_RETURN_IF_ERROR(DecodeImages(&scene));
  HP_RETURN_IF_ERROR(DecodeMaterials(&scene));
  const json* meshes = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("meshes", &meshes));
  if (meshes != nullptr) {
    scene.meshes.resize(meshes->size());
    for (size_t i = 0; i < meshes->size(); ++i) {
      HP_RETURN_IF_ERROR(DecodeMesh(static_cast<int64_t>(i), &scene, &scene.meshes[i]));
    }
  }
  HP_RETURN_IF_ERROR(DecodeSkins(&scene));
  HP_RETURN_IF_ERROR(DecodeAnimations(&scene));
  HP_RETURN_IF_ERROR(DecodeCameras(&scene));
  HP_RETURN_IF_ERROR(DecodeLights(&scene));
  HP_RETURN_IF_ERROR(DecodeNodes(&scene));
  GiveAnimatedNodesTrs(&scene);

  // Skinned meshes: every joint index must name one of the skin's joints.
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    const Node& node = scene.nodes[i];
    if (node.skin < 0) continue;
    const size_t joint_count = scene.skins[static_cast<size_t>(node.skin)].joints.size();
    for (int m : node.meshes) {
      for (uint16_t jn : scene.meshes[static_cast<size_t>(m)].joints) {
        if (jn >= joint_count) {
          return Error(Item("nodes", i), "mesh " + std::to_string(m) + " uses joint " +
                                             std::to_string(jn) + " but skin " +
                                             std::to_string(node.skin) + " has " +
                                             std::to_string(joint_count));
        }
      }
    }
  }

  if (TopCount("scenes") > 1) {
    Drop("dropped " + std::to_string(TopCount("scenes") - 1) +
         " extra scenes (all nodes are kept)");
  }
  if (non_triangle_primitives_ > 0) {
    Drop("dropped " + std::to_string(non_triangle_primitives_) + " point/line primitives");
  }
  if (!dropped_attributes_.empty()) {
    std::string list;
    for (const std::string& a : dropped_attributes_) list += (list.empty() ? "" : ", ") + a;
    Drop("dropped vertex attributes: " + list);
  }
  scene.dropped = std::move(dropped_);
  return scene;
}

}  // namespace glb_reader_internal

using glb_reader_internal::Decoder;
using glb_reader_internal::ReadWholeFile;

bool RelativePathFromUri(const std::string& uri, std::string* path, std::string* error) {
  std::string decoded;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%') {
      if (i + 2 >= uri.size()) {
        *error = "truncated percent escape";
        return false;
      }
      auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
      };
      const int hi = hex(uri[i + 1]);
      const int lo = hex(uri[i + 2]);
      if (hi < 0 || lo < 0) {
        *error = "bad percent escape";
        return false;
      }
      decoded.push_back(static_cast<char>(hi * 16 + lo));
      i += 2;
    } else {
      decoded.push_back(uri[i]);
    }
  }
  if (decoded.empty()) {
    *error = "empty URI";
    return false;
  }
  if (decoded.find('\0') != std::string::npos || decoded.find('\\') != std::string::npos) {
    *error = "URI contains a NUL or backslash";
    return false;
  }
  if (decoded[0] == '/') {
    *error = "absolute URIs are not followed";
    return false;
  }
  const size_t colon = decoded.find(':');
  if (colon != std::string::npos && decoded.find('/') > colon) {
    *error = "URIs with a scheme are not followed";
    return false;
  }
  size_t start = 0;
  while (start <= decoded.size()) {
    size_t end = decoded.find('/', start);
    if (end == std::string::npos) end = decoded.size();
    if (decoded.compare(start, end - start, "..") == 0 && end - start == 2) {
      *error = "URIs containing '..' are not followed";
      return false;
    }
    start = end + 1;
  }
  *path = decoded;
  return true;
}

Result<GltfDocument> DecodeGlbDocument(const uint8_t* data, size_t size, const std::string& name) {
  return ParseGltfBytes(data, size, name);
}

Result<Scene> DecodeGltfDocument(const GltfDocument& doc, const std::string& name,
                                 const GltfReadOptions& options) {
  try {
    Decoder decoder(doc, name, options);
    return decoder.Run();
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kUnsupported, name + ": out of memory while decoding");
  } catch (const std::exception& e) {
    // The checks above should make this unreachable; keep malformed input an error, never a crash.
    return Status(StatusCode::kParseError, name + ": malformed glTF: " + e.what());
  }
}

Result<Scene> DecodeGlb(const uint8_t* data, size_t size, const std::string& name) {
  Result<GltfDocument> doc = DecodeGlbDocument(data, size, name);
  if (!doc.ok()) return doc.status();
  return DecodeGltfDocument(doc.value(), name);
}

Result<GltfDocument> ReadGltfDocumentFile(const std::string& path) {
  std::vector<uint8_t> bytes;
  Status s = ReadWholeFile(path, &bytes);
  if (!s.ok()) return s;
  return ParseGltfBytes(bytes.data(), bytes.size(), path);
}

Result<Scene> ReadGltfFile(const std::string& path) {
  Result<GltfDocument> doc = ReadGltfDocumentFile(path);
  if (!doc.ok()) return doc.status();
  GltfReadOptions options;
  options.base_dir = FolderOf(path);
  return DecodeGltfDocument(doc.value(), path, options);
}

}  // namespace hullpack
