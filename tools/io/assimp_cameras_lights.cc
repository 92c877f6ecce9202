#include "io/assimp_cameras_lights.h"

#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace hullpack {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Vec = std::array<double, 3>;

Vec ToVec(const aiVector3D& v) { return {v.x, v.y, v.z}; }
double Dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec Cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// `v` scaled to length 1, or `fallback` when it has no direction (or is not finite).
Vec Unit(const Vec& v, const Vec& fallback) {
  const double n = std::sqrt(Dot(v, v));
  if (!(n > 1e-12) || !std::isfinite(n)) return fallback;
  return {v[0] / n, v[1] / n, v[2] / n};
}

// The transform of a node at `position` whose -z axis points along `forward` and whose +y axis
// is as near `up` as a right angle to `forward` allows (column-major). Identity when they are
// glTF's own (the origin, -z, +y).
Matrix4 Placement(const Vec& position, const Vec& forward_in, const Vec& up_in) {
  const Vec forward = Unit(forward_in, {0, 0, -1});
  const Vec back = {-forward[0], -forward[1], -forward[2]};
  Vec right = Unit(Cross(Unit(up_in, {0, 1, 0}), back), {0, 0, 0});
  if (right == Vec{0, 0, 0}) right = Unit(Cross({0, 1, 0}, back), {0, 0, 0});
  if (right == Vec{0, 0, 0}) right = Unit(Cross({1, 0, 0}, back), {1, 0, 0});
  const Vec up = Cross(back, right);
  Matrix4 m = kIdentity;
  for (int k = 0; k < 3; ++k) {
    m[k] = right[k];
    m[4 + k] = up[k];
    m[8 + k] = back[k];
    m[12 + k] = std::isfinite(position[k]) ? position[k] : 0.0;
  }
  return m;
}

bool NearIdentity(const Matrix4& m) {
  for (size_t k = 0; k < 16; ++k) {
    if (std::fabs(m[k] - kIdentity[k]) > 1e-9) return false;
  }
  return true;
}

Camera ConvertCamera(const aiCamera& c) {
  Camera out;
  out.name = c.mName.C_Str();
  const double aspect = std::isfinite(c.mAspect) && c.mAspect > 0 ? c.mAspect : 0.0;
  out.znear = std::isfinite(c.mClipPlaneNear) && c.mClipPlaneNear > 0 ? c.mClipPlaneNear : 0.01;
  out.zfar = std::isfinite(c.mClipPlaneFar) && c.mClipPlaneFar > out.znear ? c.mClipPlaneFar : 0;
  if (std::isfinite(c.mOrthographicWidth) && c.mOrthographicWidth > 0) {
    out.perspective = false;
    out.xmag = c.mOrthographicWidth;
    out.ymag = aspect > 0 ? out.xmag / aspect : out.xmag;
    if (out.zfar == 0) out.zfar = out.znear + 1000.0;  // glTF needs one for orthographic cameras
    return out;
  }
  // The whole horizontal angle, as assimp's COLLADA and FBX importers store it (its header says
  // half of it; its importers and its glTF exporter disagree).
  const double xfov =
      std::isfinite(c.mHorizontalFOV) && c.mHorizontalFOV > 0 && c.mHorizontalFOV < kPi
          ? c.mHorizontalFOV
          : kPi / 4;
  out.aspect_ratio = aspect;
  out.yfov = 2 * std::atan(std::tan(xfov / 2) / (aspect > 0 ? aspect : 1.0));
  return out;
}

bool ConvertLight(const aiLight& l, Light* out) {
  out->name = l.mName.C_Str();
  switch (l.mType) {
    case aiLightSource_DIRECTIONAL:
      out->type = LightType::kDirectional;
      break;
    case aiLightSource_POINT:
      out->type = LightType::kPoint;
      break;
    case aiLightSource_SPOT:
      out->type = LightType::kSpot;
      break;
    default:
      return false;  // ambient, area, undefined: KHR_lights_punctual has none of them
  }
  const double c[3] = {l.mColorDiffuse.r, l.mColorDiffuse.g, l.mColorDiffuse.b};
  double largest = 0;
  for (double v : c) {
    if (std::isfinite(v)) largest = std::max(largest, v);
  }
  for (int k = 0; k < 3; ++k) {
    out->color[k] = largest > 0 && std::isfinite(c[k]) && c[k] > 0 ? float(c[k] / largest) : 0.0f;
  }
  if (largest == 0) out->color = {1, 1, 1};
  out->intensity = static_cast<float>(largest);
  if (out->type == LightType::kSpot) {
    // assimp's COLLADA and FBX importers give whole cone angles; glTF's are half angles.
    const float limit = 1.5707963f;
    float outer = std::isfinite(l.mAngleOuterCone) ? l.mAngleOuterCone / 2 : limit / 2;
    outer = std::clamp(outer, 1e-4f, limit);
    float inner = std::isfinite(l.mAngleInnerCone) ? l.mAngleInnerCone / 2 : 0.0f;
    if (!(inner >= 0 && inner < outer)) inner = 0;
    out->outer_cone_angle = outer;
    out->inner_cone_angle = inner;
  }
  return true;
}

// Attaches camera or light `index` (`field` of Node) to the node named `name`: on it when
// `placement` is the identity and the node has none yet, else on a new child of it.
bool Attach(const std::string& name, const Matrix4& placement, int index, int Node::*field,
            const std::unordered_map<std::string, int>& node_of_name, Scene* scene) {
  const auto it = node_of_name.find(name);
  if (it == node_of_name.end()) return false;
  const int parent = it->second;
  if (NearIdentity(placement) && scene->nodes[static_cast<size_t>(parent)].*field < 0) {
    scene->nodes[static_cast<size_t>(parent)].*field = index;
    return true;
  }
  Node child;
  child.name = name;
  child.parent = parent;
  child.local_transform = placement;
  child.*field = index;
  scene->nodes[static_cast<size_t>(parent)].children.push_back(
      static_cast<int>(scene->nodes.size()));
  scene->nodes.push_back(std::move(child));
  return true;
}

}  // namespace

CamerasAndLightsLost ConvertCamerasAndLights(
    const aiScene& ai, const std::unordered_map<std::string, int>& node_of_name, Scene* scene) {
  CamerasAndLightsLost lost;
  for (unsigned i = 0; ai.mCameras && i < ai.mNumCameras; ++i) {
    const aiCamera* c = ai.mCameras[i];
    if (!c) continue;
    const int index = static_cast<int>(scene->cameras.size());
    const Matrix4 placement = Placement(ToVec(c->mPosition), ToVec(c->mLookAt), ToVec(c->mUp));
    if (Attach(c->mName.C_Str(), placement, index, &Node::camera, node_of_name, scene)) {
      scene->cameras.push_back(ConvertCamera(*c));
    } else {
      ++lost.cameras;
    }
  }
  for (unsigned i = 0; ai.mLights && i < ai.mNumLights; ++i) {
    const aiLight* l = ai.mLights[i];
    Light light;
    if (!l || !ConvertLight(*l, &light)) {
      ++lost.lights;
      continue;
    }
    // A point light has no direction; a directional light no position.
    const Vec position = light.type == LightType::kDirectional ? Vec{0, 0, 0} : ToVec(l->mPosition);
    const Vec forward = light.type == LightType::kPoint ? Vec{0, 0, -1} : ToVec(l->mDirection);
    const Vec up = light.type == LightType::kPoint ? Vec{0, 1, 0} : ToVec(l->mUp);
    const int index = static_cast<int>(scene->lights.size());
    if (Attach(light.name, Placement(position, forward, up), index, &Node::light, node_of_name,
               scene)) {
      scene->lights.push_back(std::move(light));
    } else {
      ++lost.lights;
    }
  }
  return lost;
}

}  // namespace hullpack
