// Images a scene references by URI (a .gltf beside its textures, an OBJ's material library) are
// read and embedded, so a GLB written from the scene stands alone wherever it is copied.
#ifndef HULLPACK_TOOLS_GLTF_EXTERNAL_IMAGES_H_
#define HULLPACK_TOOLS_GLTF_EXTERNAL_IMAGES_H_

#include <string>
#include <vector>

#include "scene/scene.h"

namespace hullpack {

struct EmbedReport {
  size_t embedded = 0;
  std::vector<std::string> kept_as_references;  // one line per image left as a URI, and why
};

// Embeds every image of `scene` that has a URI relative to `base_dir` (no "..", no absolute path,
// no scheme: RelativePathFromUri) and holds PNG, JPEG or WebP bytes. Other images keep their URI.
EmbedReport EmbedExternalImages(Scene& scene, const std::string& base_dir);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_EXTERNAL_IMAGES_H_
