#include "gltf/external_images.h"

#include "common/file_util.h"
#include "gltf/glb_reader.h"
#include "gltf/glb_writer.h"

namespace hullpack {

EmbedReport EmbedExternalImages(Scene& scene, const std::string& base_dir) {
  EmbedReport report;
  for (Image& image : scene.images) {
    if (image.uri.empty()) continue;
    std::string path, error;
    if (!RelativePathFromUri(image.uri, &path, &error)) {
      report.kept_as_references.push_back("image '" + image.uri +
                                          "' kept as a reference: " + error);
      continue;
    }
    Result<std::vector<uint8_t>> bytes =
        ReadFileBytes(base_dir.empty() ? path : base_dir + "/" + path);
    if (!bytes.ok()) {
      report.kept_as_references.push_back("image '" + image.uri +
                                          "' kept as a reference: cannot read it");
      continue;
    }
    const std::string mime = SniffImageMime(bytes.value());
    if (mime.empty()) {
      report.kept_as_references.push_back("image '" + image.uri +
                                          "' kept as a reference: not PNG, JPEG or WebP");
      continue;
    }
    image.bytes = std::move(bytes.value());
    image.mime_type = mime;
    image.uri.clear();
    ++report.embedded;
  }
  return report;
}

}  // namespace hullpack
