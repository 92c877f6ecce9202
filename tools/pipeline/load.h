// "Load": the first stage of the pipeline. A file of any supported format becomes the scene model
// (io/scene_io.h), and the images it references beside it (a .gltf's textures, an OBJ's material
// library) are embedded, so the packed GLB stands alone wherever it is copied.
#ifndef HULLPACK_TOOLS_PIPELINE_LOAD_H_
#define HULLPACK_TOOLS_PIPELINE_LOAD_H_

#include <functional>
#include <string>
#include <vector>

#include "common/status.h"
#include "scene/scene.h"

namespace hullpack {

struct LoadedScene {
  Scene scene;
  std::vector<std::string> image_uris;  // every image URI the file referenced, before embedding
  size_t images_embedded = 0;
  std::vector<std::string> images_kept_outside;  // one line per image left as a URI, and why
};

// Errors start with the path. `progress` (may be empty) gets the fraction of the file read;
// `threads` (0 = every core) is what the reader may use.
Result<LoadedScene> LoadScene(const std::string& path,
                              const std::function<void(double)>& progress = {}, int threads = 0);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_PIPELINE_LOAD_H_
