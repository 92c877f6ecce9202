// Cameras and lights of an aiScene as the scene model holds them (glTF cameras and
// KHR_lights_punctual lights), for the assimp reader.
//
// assimp places a camera or light on the node of its name, at a position, looking (shining) along
// a direction with an up vector, all in that node's space; glTF puts it at its node's origin,
// looking (shining) down the node's -z axis with +y up. Where the two differ, the camera or light
// goes on a new child node (named after it) whose transform makes them agree.
//
// Conversions: a camera's horizontal field of view (the whole angle, as assimp's COLLADA and FBX
// importers give it) and aspect give glTF's vertical one (square when assimp gives no aspect);
// orthographic half widths become xmag and ymag; the clip planes stay, a far plane not beyond
// the near one becomes an infinite one. A light's colour, which assimp scales by its intensity,
// is split back into a colour whose largest component is 1 and that intensity; spot cone angles
// (whole angles there, half angles in glTF) are halved and clamped to glTF's
// 0 <= inner < outer <= pi / 2.
#ifndef HULLPACK_TOOLS_IO_ASSIMP_CAMERAS_LIGHTS_H_
#define HULLPACK_TOOLS_IO_ASSIMP_CAMERAS_LIGHTS_H_

#include <cstddef>
#include <string>
#include <unordered_map>

#include "scene/scene.h"

struct aiScene;

namespace hullpack {

struct CamerasAndLightsLost {
  size_t cameras = 0;  // no node of that name
  size_t lights = 0;   // no node of that name, or ambient, area or undefined lights
};

// Appends the cameras and lights of `ai` to scene->cameras and scene->lights and attaches them
// to nodes (appending child nodes where needed). `node_of_name`: the scene node of each aiNode
// name. Returns what could not be kept.
CamerasAndLightsLost ConvertCamerasAndLights(
    const aiScene& ai, const std::unordered_map<std::string, int>& node_of_name, Scene* scene);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_IO_ASSIMP_CAMERAS_LIGHTS_H_
