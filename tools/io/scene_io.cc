#include "io/scene_io.h"

#include <string_view>

#include "common/file_util.h"
#include "gltf/glb_writer.h"
#include "io/assimp_reader.h"
#include "io/obj_reader.h"
#include "io/obj_writer.h"
#include "io/off_format.h"
#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "io/threemf_reader.h"
#include "io/wrl_format.h"
#include "packed/packed_glb_reader.h"

namespace hullpack {
namespace {

Result<Scene> RequireTriangles(Result<Scene> scene, const std::string& name) {
  if (scene.ok() && scene.value().triangle_count() == 0) {
    return Status(StatusCode::kInvalidMesh, name + ": contains no triangles");
  }
  return scene;
}

Result<Scene> ParseOwnFormat(const uint8_t* data, size_t size, FileFormat format,
                             const std::string& name, const ObjParseOptions& obj_options) {
  const char* text = reinterpret_cast<const char*>(data);
  switch (format) {
    case FileFormat::kObj:
      return ParseObj(text, size, name, obj_options);
    case FileFormat::kOff:
      return ParseOff(text, size, name);
    case FileFormat::kWrl:
      return ParseWrl(text, size, name);
    case FileFormat::kPly:
      return ParsePly(data, size, name);
    case FileFormat::kThreeMf:
      return Parse3mf(data, size, name);
    default:
      return Status(StatusCode::kInternal, name + ": not a format of the project's own parsers");
  }
}

bool HasOwnParser(FileFormat format) {
  return format == FileFormat::kObj || format == FileFormat::kOff || format == FileFormat::kWrl ||
         format == FileFormat::kPly || format == FileFormat::kThreeMf;
}

}  // namespace

FileFormat FormatFromExtension(const std::string& path) {
  const std::string ext = LowerExtension(path);
  if (ext == "obj") return FileFormat::kObj;
  if (ext == "off") return FileFormat::kOff;
  if (ext == "wrl" || ext == "vrml") return FileFormat::kWrl;
  if (ext == "ply") return FileFormat::kPly;
  if (ext == "stl") return FileFormat::kStl;
  if (ext == "gltf") return FileFormat::kGltf;
  if (ext == "glb") return FileFormat::kGlb;
  if (ext == "fbx") return FileFormat::kFbx;
  if (ext == "dae") return FileFormat::kDae;
  if (ext == "3mf") return FileFormat::kThreeMf;
  return FileFormat::kUnknown;
}

const char* FormatName(FileFormat format) {
  switch (format) {
    case FileFormat::kObj:
      return "OBJ";
    case FileFormat::kOff:
      return "OFF";
    case FileFormat::kWrl:
      return "VRML";
    case FileFormat::kPly:
      return "PLY";
    case FileFormat::kStl:
      return "STL";
    case FileFormat::kGltf:
      return "glTF";
    case FileFormat::kGlb:
      return "GLB";
    case FileFormat::kFbx:
      return "FBX";
    case FileFormat::kDae:
      return "COLLADA";
    case FileFormat::kThreeMf:
      return "3MF";
    case FileFormat::kUnknown:
      break;
  }
  return "unknown";
}

Result<Scene> ReadScene(const std::string& path, const ReadOptions& options) {
  const FileFormat format = FormatFromExtension(path);
  if (format == FileFormat::kUnknown) {
    const std::string ext = LowerExtension(path);
    return Status(StatusCode::kUnknownFormat,
                  path + ": unknown format " + (ext.empty() ? "(no extension)" : "'." + ext + "'") +
                      " (reads .obj .off .wrl .ply .stl .gltf .glb .fbx .dae .3mf)");
  }
  ObjParseOptions obj_options;
  if (HasOwnParser(format)) {
    obj_options.progress = options.progress;
    obj_options.threads = options.threads;
    const std::string folder = FolderOf(path) + "/";
    obj_options.load_material_library =
        [folder](const std::string& library) -> Result<std::string> {
      Result<std::vector<uint8_t>> mtl = ReadFileBytes(folder + library);
      if (!mtl.ok()) return mtl.status();
      return std::string(mtl.value().begin(), mtl.value().end());
    };
  }
  // OBJ files, often the largest text meshes, are parsed part by part; anything that is not a
  // regular file (a pipe) is read whole below.
  if (format == FileFormat::kObj) {
    Result<RandomAccessFile> file = RandomAccessFile::Open(path);
    if (file.ok()) {
      if (file->size() == 0) return Status(StatusCode::kParseError, path + ": empty file");
      return RequireTriangles(ParseObjFile(file.value(), path, obj_options), path);
    }
  }
  Result<std::vector<uint8_t>> bytes = ReadFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  if (bytes.value().empty()) return Status(StatusCode::kParseError, path + ": empty file");
  if (HasOwnParser(format)) {
    return RequireTriangles(
        ParseOwnFormat(bytes.value().data(), bytes.value().size(), format, path, obj_options),
        path);
  }
  if (format == FileFormat::kGlb || format == FileFormat::kGltf) {
    // The project's own hardened reader; it also decodes HULLPACK_mesh_compression primitives.
    // External buffers resolve next to the file.
    return RequireTriangles(
        ReadPackedGltf(bytes.value().data(), bytes.value().size(), path, FolderOf(path), nullptr),
        path);
  }
  // Through the file name, so that assimp finds companion files.
  return RequireTriangles(ReadWithAssimp(path, format), path);
}

Result<Scene> ReadSceneFromMemory(const uint8_t* data, size_t size, FileFormat format,
                                  const std::string& name) {
  if (format == FileFormat::kUnknown)
    return Status(StatusCode::kUnknownFormat, name + ": unknown format");
  if (size == 0) return Status(StatusCode::kParseError, name + ": empty file");
  if (HasOwnParser(format))
    return RequireTriangles(ParseOwnFormat(data, size, format, name, {}), name);
  if (format == FileFormat::kGlb || format == FileFormat::kGltf) {
    return RequireTriangles(ReadPackedGltf(data, size, name, "", nullptr), name);
  }
  return RequireTriangles(ReadWithAssimpFromMemory(data, size, format, name), name);
}

Result<std::vector<uint8_t>> EncodeScene(const Scene& scene, FileFormat format) {
  auto bytes = [](std::string s) { return std::vector<uint8_t>(s.begin(), s.end()); };
  switch (format) {
    case FileFormat::kObj:
      return bytes(EncodeObj(scene));
    case FileFormat::kOff:
      return bytes(EncodeOff(scene));
    case FileFormat::kWrl:
      return bytes(EncodeWrl(scene));
    case FileFormat::kPly:
      return EncodePly(scene);
    case FileFormat::kGlb:
      return EncodeGlb(scene);
    default:
      break;
  }
  return Status(StatusCode::kUnsupported,
                std::string("writing ") + FormatName(format) + " is not supported");
}

Status WriteScene(const Scene& scene, const std::string& path) {
  const FileFormat format = FormatFromExtension(path);
  if (format == FileFormat::kUnknown) {
    return Status(StatusCode::kUnknownFormat,
                  path + ": unknown output format (writes .obj .off .wrl .ply .glb)");
  }
  if (format == FileFormat::kObj) {
    // In pieces: a large mesh's text would otherwise be held whole, twice.
    Result<AtomicFileWriter> file = AtomicFileWriter::Create(path);
    if (!file.ok()) return file.status();
    EncodeObj(scene, [&](std::string_view text) { file->Write(text.data(), text.size()); });
    return file->Commit();
  }
  Result<std::vector<uint8_t>> bytes = EncodeScene(scene, format);
  if (!bytes.ok()) return Status(bytes.status().code(), path + ": " + bytes.status().message());
  return WriteFileAtomically(path, bytes.value());
}

}  // namespace hullpack
