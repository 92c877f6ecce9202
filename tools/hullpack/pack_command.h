// `hullpack pack IN... -o OUT`: one packed GLB per input (docs/packed-gltf.md).
#ifndef HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_
#define HULLPACK_TOOLS_HULLPACK_PACK_COMMAND_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch/asset_cache.h"
#include "common/status.h"
#include "pipeline/pack.h"

namespace hullpack {

// Exit code: 0 when every input was packed, else the number that failed (at most 63); kExitUsage
// for a command-line mistake.
int RunPackCommand(const std::vector<std::string>& args);

// Pack's command line, parsed (`hullpack batch` takes the same pack options).
struct PackArgs {
  std::vector<std::string> inputs;
  std::string output, report_path, cache_dir;
  PackOptions options;
  bool force = false, quiet = false;
  long jobs = 0;  // 0 = every core
  // The options that can change an output's bytes, as given: what the cache key holds.
  std::vector<std::string> output_args;
};

// Parses `args` into `out`. Returns -1 when they are well formed, 0 after printing `usage` for
// --help, kExitUsage (message on stderr, naming `command`) for a mistake.
int ParsePackArgs(const std::vector<std::string>& args, const char* command, const char* usage,
                  PackArgs* out);

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
