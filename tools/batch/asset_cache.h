// A content-addressed cache of packed outputs, shared by `hullpack pack --cache` and
// `hullpack batch` (docs/guide-batch.md). An entry is found again only when everything that decides
// the output is unchanged: the input's bytes and name, the bytes of every file it references
// (a glTF's buffers, an OBJ's material libraries, textures), the pack options and the tool itself.
//
// Layout under the cache folder (safe to share between processes and machines):
//   inputs/ab/<input key>.json   the files the input referenced when it was last packed
//   objects/ab/<key>.glb         a packed output
//   objects/ab/<key>.json        its report; written last, so an entry exists once this file does
// input key = SHA-256(salt, input name, input bytes); key = SHA-256(input key, each referenced
// file's relative path and bytes). Every file is written to a temporary name and renamed.
#ifndef HULLPACK_TOOLS_BATCH_ASSET_CACHE_H_
#define HULLPACK_TOOLS_BATCH_ASSET_CACHE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"

namespace hullpack {

struct CacheProbe {
  std::string input_key;  // hands the lookup's work to Store
  bool hit = false;
  std::vector<uint8_t> glb;  // on a hit: the output and its report
  std::string meta;
};

class AssetCache {
 public:
  // `salt`: everything besides the input that decides the output (CacheSalt).
  AssetCache(std::string dir, std::string salt);

  // Creates the folder and removes temporary files that a killed run left in it over an hour ago
  // (a live writer renames its file within seconds; hosts sharing the cache cannot see each
  // other's processes, so age decides). Errors name the folder.
  Status Prepare() const;

  // Hashes `input` (and the files it referenced last time) and looks the entry up. An error only
  // when the input cannot be read.
  Result<CacheProbe> Lookup(const std::string& input) const;

  // Stores the output of `input`; `referenced` are the files it read besides itself, relative to
  // its folder (ReferencedFiles). `input_key` is CacheProbe::input_key.
  Status Store(const std::string& input, const std::string& input_key,
               const std::vector<std::string>& referenced, const std::vector<uint8_t>& glb,
               const std::string& meta) const;

  const std::string& dir() const { return dir_; }

 private:
  std::string EntryKey(const std::string& input_key, const std::string& input_dir,
                       const std::vector<std::string>& referenced) const;
  std::string PathOf(const char* kind, const std::string& key, const char* ext) const;

  std::string dir_, salt_;
};

// The salt for pack options given as `output_args`: the cache layout version, the tool version
// and the SHA-256 of the running executable (a rebuilt tool never reuses an older one's outputs).
std::string CacheSalt(const std::vector<std::string>& output_args);

// The files `input` reads besides itself, relative to its folder: a glTF's external buffers, an
// OBJ's material libraries, and `image_uris` (the images its scene referenced) resolved as
// EmbedExternalImages resolves them. Sorted, without repeats.
std::vector<std::string> ReferencedFiles(const std::string& input,
                                         const std::vector<std::string>& image_uris);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BATCH_ASSET_CACHE_H_
