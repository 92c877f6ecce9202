// Cameras and KHR_lights_punctual lights, which nodes place in the scene.
#include <cmath>

#include "gltf/glb_reader_decoder.h"

namespace hullpack {
namespace glb_reader_internal {

Status Decoder::DecodeCameras(Scene* scene) {
  const json* cameras = nullptr;
  HP_RETURN_IF_ERROR(TopLevel("cameras", &cameras));
  if (cameras == nullptr) return Status::Ok();
  for (size_t i = 0; i < cameras->size(); ++i) {
    const json& j = (*cameras)[i];
    const std::string cw = Item("cameras", i);
    Camera camera;
    HP_RETURN_IF_ERROR(GetString(j, "name", cw, &camera.name));
    std::string type;
    HP_RETURN_IF_ERROR(GetString(j, "type", cw, &type));
    camera.perspective = type == "perspective";
    if (!camera.perspective && type != "orthographic")
      return Error(cw, "type '" + type + "' is not perspective or orthographic");
    auto it = j.find(type);
    if (it == j.end() || !it->is_object()) return Error(cw, "has no " + type + " object");
    const std::string pw = cw + "." + type;
    if (camera.perspective) {
      camera.yfov = camera.znear = 0;
      HP_RETURN_IF_ERROR(GetNumber(*it, "yfov", pw, &camera.yfov));
      HP_RETURN_IF_ERROR(GetNumber(*it, "aspectRatio", pw, &camera.aspect_ratio));
      HP_RETURN_IF_ERROR(GetNumber(*it, "znear", pw, &camera.znear));
      HP_RETURN_IF_ERROR(GetNumber(*it, "zfar", pw, &camera.zfar));
      if (!(camera.yfov > 0) || !(camera.znear > 0) || camera.aspect_ratio < 0 ||
          (camera.zfar != 0 && !(camera.zfar > camera.znear))) {
        return Error(pw, "needs yfov > 0, znear > 0, aspectRatio > 0 and zfar > znear when given");
      }
    } else {
      camera.xmag = camera.ymag = camera.znear = 0;
      HP_RETURN_IF_ERROR(GetNumber(*it, "xmag", pw, &camera.xmag));
      HP_RETURN_IF_ERROR(GetNumber(*it, "ymag", pw, &camera.ymag));
      HP_RETURN_IF_ERROR(GetNumber(*it, "znear", pw, &camera.znear));
      HP_RETURN_IF_ERROR(GetNumber(*it, "zfar", pw, &camera.zfar));
      if (camera.xmag == 0 || camera.ymag == 0 || camera.znear < 0 ||
          !(camera.zfar > camera.znear)) {
        return Error(pw, "needs xmag and ymag not 0, znear >= 0 and zfar > znear");
      }
    }
    scene->cameras.push_back(std::move(camera));
  }
  return Status::Ok();
}

Status Decoder::DecodeLights(Scene* scene) {
  auto ext = root_.find("extensions");
  if (ext == root_.end() || !ext->is_object()) return Status::Ok();
  auto punctual = ext->find("KHR_lights_punctual");
  if (punctual == ext->end()) return Status::Ok();
  const std::string ew = "extensions.KHR_lights_punctual";
  if (!punctual->is_object()) return Error(ew, "is not an object");
  const json* lights = nullptr;
  HP_RETURN_IF_ERROR(GetArray(*punctual, "lights", ew, &lights));
  if (lights == nullptr) return Status::Ok();
  for (size_t i = 0; i < lights->size(); ++i) {
    const json& j = (*lights)[i];
    const std::string lw = ew + "." + Item("lights", i);
    if (!j.is_object()) return Error(lw, "is not an object");
    Light light;
    HP_RETURN_IF_ERROR(GetString(j, "name", lw, &light.name));
    std::string type;
    HP_RETURN_IF_ERROR(GetString(j, "type", lw, &type));
    if (type == "directional") {
      light.type = LightType::kDirectional;
    } else if (type == "point") {
      light.type = LightType::kPoint;
    } else if (type == "spot") {
      light.type = LightType::kSpot;
    } else {
      return Error(lw, "type '" + type + "' is not directional, point or spot");
    }
    double color[3] = {1, 1, 1}, intensity = 1, range = 0;
    HP_RETURN_IF_ERROR(GetNumbers(j, "color", lw, 3, color));
    HP_RETURN_IF_ERROR(GetNumber(j, "intensity", lw, &intensity));
    HP_RETURN_IF_ERROR(GetNumber(j, "range", lw, &range));
    if (intensity < 0 || range < 0) return Error(lw, "intensity or range is negative");
    for (size_t c = 0; c < 3; ++c) light.color[c] = static_cast<float>(color[c]);
    light.intensity = static_cast<float>(intensity);
    light.range = static_cast<float>(range);
    if (light.type == LightType::kSpot) {
      auto spot = j.find("spot");
      double inner = 0, outer = M_PI / 4;
      if (spot != j.end()) {
        if (!spot->is_object()) return Error(lw, "spot is not an object");
        HP_RETURN_IF_ERROR(GetNumber(*spot, "innerConeAngle", lw + ".spot", &inner));
        HP_RETURN_IF_ERROR(GetNumber(*spot, "outerConeAngle", lw + ".spot", &outer));
      }
      if (inner < 0 || !(inner < outer) || outer > M_PI / 2 + 1e-6)
        return Error(lw, "spot cone angles need 0 <= inner < outer <= pi/2");
      light.inner_cone_angle = static_cast<float>(inner);
      light.outer_cone_angle = static_cast<float>(outer);
    }
    scene->lights.push_back(std::move(light));
  }
  return Status::Ok();
}

}  // namespace glb_reader_internal
}  // namespace hullpack
