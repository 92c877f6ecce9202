// `hullpack pack IN... -o OUT`: one packed GLB per input (docs/packed-gltf.md).
#ifndef HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch/asset_cache.h"
#include "common/cli_args.h"
#include "common/status.h"
#include "pipeline/pack.h"

namespace hullpack {

// Exit code: 0 when every input was packed, else the number that failed (at most 63); kExitUsage
// for a command-line mistake.
int RunPackCommand(const std::vector<std::string>& args);

// Declares the options that decide an output's bytes (--max-error, --qp/--qn/--qt, --hull-error,
// --ascii, --keep-order, --fast-decode, --fallback, --hulls, --skinned-hulls, --physics, --quality,
// --resolution, --max-hulls, --max-vertices, --concavity) on `cli`, applied to `options`.
// `hullpack batch` takes the same.
void AddPackOptions(CliArgs& cli, PackOptions* options);

// After parsing: with --method hacd, carries --max-hulls, --concavity, --max-concavity and --hulls
// N over to HACD's parameters (a cluster budget, the concavity limit as a fraction of the
// diagonal, the target error, an exact cluster count); returns the usage error for the V-HACD-only
// --resolution and --quality, "" otherwise.
std::string ApplyMethodOptions(const CliArgs& cli, PackOptions* options);

// `args` without the operands and without the options that only steer a run (-o, --report,
// --jobs, --cache, --force, --quiet, batch's --manifest/--shard/--shards/--merge, and their
// values): what can change an output's bytes, as given. The cache key holds it.
std::vector<std::string> OutputArgs(const std::vector<std::string>& args,
                                    const std::vector<std::string>& operands);

struct PackedFile {
  std::vector<uint8_t> glb;
  nlohmann::json report;                // what `pack --report` writes for the file
  std::vector<std::string> image_uris;  // the images the file referenced (embedded if found)
};

// Reads `input`, embeds the images beside it and packs it. Errors name the file.
Result<PackedFile> PackFile(const std::string& input, const PackOptions& options,
                            PackObserver* observer);

struct CachedPack {
  std::vector<uint8_t> glb;
  nlohmann::json report;
  bool cache_hit = false;
};

// PackFile through `cache` (may be null): an unchanged input is not packed again, a packed one is
// stored.
Result<CachedPack> PackFileCached(const std::string& input, const PackOptions& options,
                                  const AssetCache* cache, PackObserver* observer);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_
