// OctahedralNormalKey: which normals the surface-normal coder stores alike.
#include <cmath>

#include "attribute_coder.h"
#include "o3dgc/o3dgc.h"
#include "predictors.h"

namespace o3dgc {

uint64_t OctahedralNormalKey(const float normal[3], int bits) {
  if (bits < 1 || bits > 16) return 0;
  // As EncodeOctNormals takes a normal: as given, or (0, 0, 1) without a usable length.
  double a[3] = {normal[0], normal[1], normal[2]};
  const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (!(len > 0) || !std::isfinite(len)) {
    a[0] = 0;
    a[1] = 0;
    a[2] = 1;
  }
  const uint32_t maxq = uint32_t((uint32_t(1) << bits) - 1);
  uint64_t key = 0;
  // The coder stores the codes of the normal or of its mirror in z, whichever side the decoded
  // surface's normal is on: equal codes for both keep two normals alike either way.
  for (const double z : {a[2], -a[2]}) {
    const double b[3] = {a[0], a[1], z};
    double u, v;
    OctEncode(b, &u, &v);
    key = (key << 32) | (uint64_t(OctQuantize(u, maxq)) << 16) | uint64_t(OctQuantize(v, maxq));
  }
  return key;
}

}  // namespace o3dgc
