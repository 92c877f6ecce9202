#include "pipeline/load.h"

#include "common/file_util.h"
#include "gltf/external_images.h"
#include "io/scene_io.h"

namespace hullpack {

Result<LoadedScene> LoadScene(const std::string& path, const std::function<void(double)>& progress,
                              int threads) {
  ReadOptions options;
  options.progress = progress;
  options.threads = threads;
  Result<Scene> scene = ReadScene(path, options);
  if (!scene.ok()) return scene.status();
  LoadedScene out;
  out.scene = std::move(scene.value());
  for (const Image& image : out.scene.images)
    if (!image.uri.empty()) out.image_uris.push_back(image.uri);
  const EmbedReport images = EmbedExternalImages(out.scene, FolderOf(path));
  out.images_embedded = images.embedded;
  out.images_kept_outside = images.kept_as_references;
  return out;
}

}  // namespace hullpack
