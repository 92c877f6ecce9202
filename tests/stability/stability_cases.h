// The generated cases of the stability suite (docs/stability.md): stiff, extreme and broken meshes,
// each with the outcome every stage must give. Meshes are made in code, in double; the stages that
// take floats get the same numbers rounded to float.
#ifndef HULLPACK_TESTS_STABILITY_STABILITY_CASES_H_
#define HULLPACK_TESTS_STABILITY_STABILITY_CASES_H_

#include <cstdint>
#include <string>
#include <vector>

namespace hullpack::stability {

// What a stage must give for a case.
enum class Expect {
  kOk,      // a valid result (checked in full)
  kError,   // a clear error status (never an internal error)
  kEither,  // either of the two; a result must still be valid
};

struct Case {
  std::string name;
  std::string description;
  std::vector<double> points;      // 3 per point
  std::vector<uint32_t> indices;   // 3 per triangle
  Expect decompose = Expect::kOk;  // vhacd::Decompose on the double points
  Expect codec = Expect::kOk;      // o3dgc::Encode + Decode, and the pipeline's mesh codec
  Expect pack = Expect::kOk;       // PackScene + ReadPackedGltf
};

// Names of the cases, in table order. `heavy` selects the 2-million-triangle case alone.
std::vector<std::string> CaseNames(bool heavy);

// Builds the named case (generation happens here, so a test pays only for its own case).
Case MakeCase(const std::string& name);

}  // namespace hullpack::stability

#endif  // HULLPACK_TESTS_STABILITY_STABILITY_CASES_H_
