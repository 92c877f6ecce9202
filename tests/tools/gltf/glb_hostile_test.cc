// The reader against hostile bytes: every failure must be an error Status, never a crash or hang.
#include <chrono>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "gltf/glb_reader.h"
#include "gltf/glb_writer.h"
#include "gltf_test_scenes.h"

namespace hullpack {
namespace {

using nlohmann::json;

std::vector<uint8_t> RichGlb() {
  Result<std::vector<uint8_t>> glb = EncodeGlb(testing_gltf::MakeRichScene());
  EXPECT_TRUE(glb.ok());
  return glb.ok() ? glb.value() : std::vector<uint8_t>();
}

void PutU32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + static_cast<size_t>(i)] = static_cast<uint8_t>(v >> (8 * i));
}

uint32_t GetU32(const std::vector<uint8_t>& b, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | b[at + static_cast<size_t>(i)];
  return v;
}

// Re-encodes the rich scene's document after `mutate` edits its JSON.
Result<Scene> DecodeMutated(const std::function<void(json&)>& mutate) {
  const std::vector<uint8_t> glb = RichGlb();
  Result<GltfDocument> doc = DecodeGlbDocument(glb.data(), glb.size(), "mutated.glb");
  EXPECT_TRUE(doc.ok());
  mutate(doc->json());
  GltfDocument edited(doc->json(), doc->binary(), true, glb.size());
  return DecodeGltfDocument(edited, "mutated.glb");
}

void ExpectError(const Result<Scene>& r, StatusCode code, const std::string& needle) {
  ASSERT_FALSE(r.ok()) << "expected an error mentioning " << needle;
  EXPECT_EQ(r.status().code(), code) << r.status().ToString();
  EXPECT_NE(r.status().message().find(needle), std::string::npos) << r.status().ToString();
  EXPECT_EQ(r.status().message().rfind("mutated.glb: ", 0), 0u) << r.status().ToString();
}

TEST(GlbHostileTest, EveryTruncationIsAnError) {
  const std::vector<uint8_t> glb = RichGlb();
  ASSERT_GT(glb.size(), 1000u);
  for (size_t len = 0; len < glb.size(); ++len) {
    Result<Scene> s = DecodeGlb(glb.data(), len, "cut.glb");
    ASSERT_FALSE(s.ok()) << "length " << len;
    EXPECT_EQ(s.status().code(), StatusCode::kParseError) << len << ": " << s.status().ToString();
    // The same cut with the header's length patched to match, so the chunk walk and the JSON parser
    // see the truncation instead of the header check.
    if (len >= 12) {
      std::vector<uint8_t> cut(glb.begin(), glb.begin() + static_cast<std::ptrdiff_t>(len));
      PutU32(cut, 8, static_cast<uint32_t>(len));
      Result<Scene> p = DecodeGlb(cut.data(), cut.size(), "cut.glb");
      ASSERT_FALSE(p.ok()) << "patched length " << len;
      EXPECT_EQ(p.status().code(), StatusCode::kParseError) << len << ": " << p.status().ToString();
    }
  }
  // A .gltf JSON text cut anywhere.
  const std::string text =
      R"({"asset":{"version":"2.0"},"nodes":[{"name":"a","children":[1]},{"matrix":)"
      R"([1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]}],"scenes":[{"nodes":[0]}]})";
  ASSERT_TRUE(DecodeGlb(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "t.gltf").ok());
  for (size_t len = 0; len < text.size(); ++len) {
    Result<Scene> s = DecodeGlb(reinterpret_cast<const uint8_t*>(text.data()), len, "t.gltf");
    ASSERT_FALSE(s.ok()) << len;
    EXPECT_EQ(s.status().code(), StatusCode::kParseError) << len;
  }
  EXPECT_TRUE(DecodeGlb(glb.data(), glb.size(), "whole.glb").ok());
}

TEST(GlbHostileTest, TruncatedGlbWithPatchedLengthIsAnError) {
  // Same cut, but the header and BIN chunk claim the shorter length, so only the JSON references
  // reach past the end of the data.
  const std::vector<uint8_t> glb = RichGlb();
  const size_t json_len = GetU32(glb, 12);
  const size_t bin_data = 20 + json_len + 8;
  size_t failures = 0;
  for (size_t len = bin_data; len < glb.size() - 4; len += 4) {
    std::vector<uint8_t> cut(glb.begin(), glb.begin() + static_cast<std::ptrdiff_t>(len));
    PutU32(cut, 8, static_cast<uint32_t>(len));
    PutU32(cut, 20 + json_len, static_cast<uint32_t>(len - bin_data));
    Result<Scene> s = DecodeGlb(cut.data(), cut.size(), "cut.glb");
    ASSERT_FALSE(s.ok()) << len;
    EXPECT_EQ(s.status().code(), StatusCode::kParseError) << s.status().ToString();
    ++failures;
  }
  EXPECT_GT(failures, 100u);
}

TEST(GlbHostileTest, RandomByteFlipsNeverCrash) {
  const std::vector<uint8_t> glb = RichGlb();
  std::mt19937 rng(12345);
  size_t ok = 0, errors = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    std::vector<uint8_t> b = glb;
    const int flips = 1 + static_cast<int>(rng() % 8);
    for (int f = 0; f < flips; ++f) {
      const size_t at = rng() % b.size();
      b[at] = static_cast<uint8_t>(iter % 3 == 0 ? rng() : b[at] ^ (1u << (rng() % 8)));
    }
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "flipped.glb");
    if (s.ok()) {
      ++ok;
      // A scene that decodes is internally consistent: indices within the vertices.
      for (const Mesh& m : s->meshes) {
        for (uint32_t i : m.indices) ASSERT_LT(i, m.vertex_count());
      }
    } else {
      ++errors;
      EXPECT_FALSE(s.status().message().empty());
    }
  }
  EXPECT_GT(errors, 100u);
  EXPECT_GT(ok, 100u);  // flips in the binary payload are just different numbers
}

// Replaces one random number in the JSON with a hostile value.
bool MutateRandomNumber(json& j, std::mt19937& rng, const json& replacement) {
  std::vector<json*> numbers;
  std::vector<json*> stack = {&j};
  while (!stack.empty()) {
    json* at = stack.back();
    stack.pop_back();
    if (at->is_number()) numbers.push_back(at);
    if (at->is_structured()) {
      for (auto& child : *at) stack.push_back(&child);
    }
  }
  if (numbers.empty()) return false;
  *numbers[rng() % numbers.size()] = replacement;
  return true;
}

TEST(GlbHostileTest, HostileNumbersInTheJsonNeverCrash) {
  const std::vector<uint8_t> glb = RichGlb();
  Result<GltfDocument> doc = DecodeGlbDocument(glb.data(), glb.size(), "n.glb");
  ASSERT_TRUE(doc.ok());
  const json values[] = {0,
                         1,
                         3,
                         -1,
                         255,
                         65535,
                         65536,
                         4294967295ull,
                         4294967296ull,
                         18446744073709551615ull,
                         9223372036854775807ll,
                         -9223372036854775807ll,
                         1.5,
                         1e300,
                         "7",
                         nullptr,
                         json::array(),
                         json::object(),
                         true};
  std::mt19937 rng(777);
  size_t errors = 0;
  for (int iter = 0; iter < 3000; ++iter) {
    json j = doc->json();
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e)
      MutateRandomNumber(j, rng, values[rng() % (sizeof values / sizeof values[0])]);
    GltfDocument mutated(j, doc->binary(), true, glb.size());
    Result<Scene> s = DecodeGltfDocument(mutated, "n.glb");
    if (!s.ok()) {
      ++errors;
      continue;
    }
    for (const Mesh& m : s->meshes) {
      for (uint32_t i : m.indices) ASSERT_LT(i, m.vertex_count());
      EXPECT_TRUE(m.material_ids.empty() || m.material_ids.size() == m.triangle_count());
      for (uint32_t id : m.material_ids) ASSERT_LT(id, s->materials.size());
    }
    for (const Node& n : s->nodes) {
      for (int c : n.children) ASSERT_LT(static_cast<size_t>(c), s->nodes.size());
      for (int mi : n.meshes) ASSERT_LT(static_cast<size_t>(mi), s->meshes.size());
    }
  }
  EXPECT_GT(errors, 1000u);
}

TEST(GlbHostileTest, HeaderProblems) {
  std::vector<uint8_t> glb = RichGlb();
  {
    std::vector<uint8_t> b = glb;
    b[0] = 'X';
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "magic.glb");
    ASSERT_FALSE(s.ok());  // without the magic it is parsed as JSON text and fails there
    EXPECT_EQ(s.status().code(), StatusCode::kParseError);
    Result<GltfDocument> d = ParseGlb(b.data(), b.size(), "magic.glb");
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.status().message().find("magic"), std::string::npos);
  }
  {
    std::vector<uint8_t> b = glb;
    PutU32(b, 4, 1);
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "v1.glb");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.status().code(), StatusCode::kUnsupported);
    EXPECT_NE(s.status().message().find("version 1"), std::string::npos);
  }
  {
    std::vector<uint8_t> b = glb;
    PutU32(b, 8, static_cast<uint32_t>(b.size() + 1));
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "len.glb");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.status().message().find("truncated"), std::string::npos);
  }
  for (uint32_t bad : {0xFFFFFFFFu, 0xFFFFFFF8u, static_cast<uint32_t>(glb.size())}) {
    std::vector<uint8_t> b = glb;
    PutU32(b, 12, bad);  // JSON chunk length past the end
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "chunk.glb");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.status().message().find("chunk 0 declares"), std::string::npos)
        << s.status().ToString();
  }
  {
    std::vector<uint8_t> b = glb;
    const size_t bin_header = 20 + GetU32(b, 12);
    PutU32(b, bin_header, 0x7FFFFFFF);  // BIN chunk length past the end
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "bin.glb");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.status().message().find("chunk 1 declares"), std::string::npos)
        << s.status().ToString();
  }
  {
    std::vector<uint8_t> b = glb;
    PutU32(b, 16, gltf::kChunkBin);
    Result<Scene> s = DecodeGlb(b.data(), b.size(), "order.glb");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.status().message().find("not JSON"), std::string::npos);
  }
}

TEST(GlbHostileTest, AccessorAndViewBounds) {
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["count"] = 1000000; }),
              StatusCode::kParseError, "accessors[0]: byteOffset 0 + count 1000000");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["count"] = 18446744073709551615ull; }),
              StatusCode::kParseError, "accessors[0]");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["count"] = 0; }),
              StatusCode::kParseError, "count is 0");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["byteOffset"] = 4; }),
              StatusCode::kParseError, "exceeds bufferViews[");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["componentType"] = 5124; }),
              StatusCode::kParseError, "unknown componentType 5124");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["type"] = "VEC7"; }),
              StatusCode::kParseError, "unknown type");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["bufferView"] = 999; }),
              StatusCode::kParseError, "bufferView 999 does not exist");
  ExpectError(DecodeMutated([](json& j) { j["bufferViews"][1]["byteOffset"] = 1u << 30; }),
              StatusCode::kParseError, "exceed buffers[0]");
  ExpectError(DecodeMutated([](json& j) { j["bufferViews"][1]["byteLength"] = 4294967295ull; }),
              StatusCode::kParseError, "exceed buffers[0]");
  ExpectError(DecodeMutated([](json& j) { j["bufferViews"][1]["byteStride"] = 2; }),
              StatusCode::kParseError, "byteStride 2");
  ExpectError(DecodeMutated([](json& j) { j["buffers"][0]["byteLength"] = 1u << 30; }),
              StatusCode::kParseError, "exceeds the GLB binary chunk");
  ExpectError(DecodeMutated([](json& j) { j["buffers"][0]["byteLength"] = -5; }),
              StatusCode::kParseError, "not a non-negative integer");
  ExpectError(DecodeMutated([](json& j) { j["accessors"] = json::object(); }),
              StatusCode::kParseError, "'accessors' is not an array");
  ExpectError(DecodeMutated([](json& j) { j["accessors"][0]["normalized"] = true; }),
              StatusCode::kParseError, "normalized");
}

TEST(GlbHostileTest, IndexAndReferenceBounds) {
  // Rewrite one index past the vertex count through the binary chunk.
  const std::vector<uint8_t> glb = RichGlb();
  Result<GltfDocument> doc = DecodeGlbDocument(glb.data(), glb.size(), "mutated.glb");
  ASSERT_TRUE(doc.ok());
  const json& j = doc->json();
  const int acc = j["meshes"][2]["primitives"][0]["indices"].get<int>();
  const int view = j["accessors"][acc]["bufferView"].get<int>();
  const size_t offset = j["bufferViews"][view]["byteOffset"].get<size_t>();
  std::vector<uint8_t> bin = doc->binary();
  bin[offset] = 4;  // the tetrahedron has 4 vertices (UNSIGNED_SHORT indices)
  bin[offset + 1] = 0;
  ExpectError(DecodeGltfDocument(GltfDocument(j, bin, true, glb.size()), "mutated.glb"),
              StatusCode::kParseError, "index 0 is 4 but the primitive has 4 vertices");

  ExpectError(DecodeMutated([](json& js) { js["meshes"][0]["primitives"][0]["material"] = 3; }),
              StatusCode::kParseError, "material 3 does not exist");
  ExpectError(DecodeMutated([](json& js) { js["nodes"][0]["mesh"] = 3; }), StatusCode::kParseError,
              "mesh 3 does not exist");
  ExpectError(DecodeMutated([](json& js) { js["nodes"][0]["children"].push_back(0); }),
              StatusCode::kParseError, "lists itself");
  ExpectError(DecodeMutated([](json& js) { js["nodes"][4]["children"].push_back(2); }),
              StatusCode::kParseError, "already has parent");
  ExpectError(DecodeMutated([](json& js) {
                js["nodes"][2]["children"] = {0};  // 0 -> 1 -> 2 -> 0
              }),
              StatusCode::kParseError, "cycle");
  ExpectError(DecodeMutated([](json& js) { js["skins"][0]["joints"] = {1}; }),
              StatusCode::kParseError, "inverseBindMatrices has 2 matrices for 1 joints");
  ExpectError(DecodeMutated([](json& js) {
                js["skins"][0]["joints"] = {1};
                js["skins"][0].erase("inverseBindMatrices");
              }),
              StatusCode::kParseError, "uses joint 1 but skin 0 has 1");
  ExpectError(DecodeMutated([](json& js) {
                js["skins"][0]["joints"] = {1, 1};
              }),
              StatusCode::kParseError, "twice");
  ExpectError(DecodeMutated([](json& js) { js["materials"][0]["normalTexture"]["index"] = 40; }),
              StatusCode::kParseError, "texture 40 does not exist");
  ExpectError(DecodeMutated([](json& js) { js["textures"][0]["source"] = 40; }),
              StatusCode::kParseError, "source image 40");
  ExpectError(DecodeMutated([](json& js) { js["images"][0]["bufferView"] = -1; }),
              StatusCode::kParseError, "images[0]");
  ExpectError(DecodeMutated([](json& js) {
                js["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
                    js["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
              }),
              StatusCode::kParseError, "TANGENT (accessors[0]): has type VEC3");
}

TEST(GlbHostileTest, AttributeCountsMustAgree) {
  Result<Scene> s = DecodeMutated([](json& js) {
    // NORMAL of mesh 0 pointed at mesh 1's normals (fewer vertices).
    js["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
        js["meshes"][1]["primitives"][0]["attributes"]["NORMAL"];
  });
  ExpectError(s, StatusCode::kParseError, "NORMAL has 9 elements but POSITION has 20");
}

TEST(GlbHostileTest, AmplificationIsCapped) {
  // A zero-filled accessor (no bufferView) of 100 million vertices in a 5 KB file.
  Result<Scene> s = DecodeMutated([](json& js) {
    js["accessors"].push_back(
        {{"componentType", gltf::kFloat}, {"count", 100000000}, {"type", "VEC3"}});
    js["meshes"][2]["primitives"][0]["attributes"]["POSITION"] = js["accessors"].size() - 1;
    js["meshes"][2]["primitives"][0].erase("indices");
  });
  ExpectError(s, StatusCode::kUnsupported, "exceed the limit");
  // Many primitives re-reading the largest accessor through distinct accessor copies.
  Result<Scene> many = DecodeMutated([](json& js) {
    json prim = js["meshes"][0]["primitives"][0];
    json copy = js["accessors"][prim["attributes"]["POSITION"].get<int>()];
    for (int i = 0; i < 20000; ++i) {
      js["accessors"].push_back(copy);
      prim["attributes"]["POSITION"] = js["accessors"].size() - 1;
      js["meshes"][0]["primitives"].push_back(prim);
    }
  });
  // The JSON grew with the copies, so this may legitimately decode; what matters is the bound.
  if (!many.ok()) {
    EXPECT_EQ(many.status().code(), StatusCode::kUnsupported) << many.status().ToString();
  }
}

TEST(GlbHostileTest, LargeHierarchiesAndManyAccessorsStayLinear) {
  const auto start = std::chrono::steady_clock::now();
  // Reader: a 200000-node chain, a root with 200000 children, and the chain closed into a cycle.
  for (int shape = 0; shape < 3; ++shape) {
    json j = {{"asset", {{"version", "2.0"}}}, {"nodes", json::array()}};
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      json node = json::object();
      if (shape == 0 && i + 1 < n) node["children"] = {i + 1};
      if (shape == 2) node["children"] = {(i + 1) % n};
      j["nodes"].push_back(std::move(node));
    }
    if (shape == 1) {
      for (int i = 1; i < n; ++i) j["nodes"][0]["children"].push_back(i);
    }
    Result<Scene> s = DecodeGltfDocument(GltfDocument(j, {}, false, 0), "big.gltf");
    if (shape == 2) {
      ASSERT_FALSE(s.ok());
      EXPECT_NE(s.status().message().find("cycle"), std::string::npos);
    } else {
      ASSERT_TRUE(s.ok()) << s.status().ToString();
      EXPECT_EQ(s->nodes.size(), static_cast<size_t>(n));
      EXPECT_EQ(s->nodes[static_cast<size_t>(n - 1)].parent, shape == 0 ? n - 2 : 0);
    }
  }
  // Writer: the chain again, written and read back (a 2 MB JSON text: the parse must stay linear).
  Scene chain;
  chain.meshes.push_back(testing_gltf::MakeGrid(1, 1, 0, 0.0f));
  chain.nodes.resize(100000);
  for (size_t i = 0; i + 1 < chain.nodes.size(); ++i) {
    chain.nodes[i].children = {static_cast<int>(i + 1)};
    chain.nodes[i + 1].parent = static_cast<int>(i);
  }
  chain.nodes.back().meshes = {0};
  Result<std::vector<uint8_t>> glb = EncodeGlb(chain);
  ASSERT_TRUE(glb.ok()) << glb.status().ToString();
  Result<Scene> back = DecodeGlb(glb->data(), glb->size(), "chain.glb");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  EXPECT_EQ(back->nodes.back().meshes, std::vector<int>({0}));
  // Quadratic checks would take minutes here; linear ones take well under a second. Loose on
  // purpose: the ASan+UBSan build on a loaded 2-core machine took 35 s (the plain build 3 s).
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(120));
}

TEST(GlbHostileTest, ExpansionLimitIsAnOption) {
  Result<std::vector<uint8_t>> glb = EncodeGlb(testing_gltf::MakeLargeScene());
  ASSERT_TRUE(glb.ok());
  Result<GltfDocument> doc = DecodeGlbDocument(glb->data(), glb->size(), "large.glb");
  ASSERT_TRUE(doc.ok());
  EXPECT_TRUE(DecodeGltfDocument(doc.value(), "large.glb").ok());
  GltfReadOptions tight;
  tight.max_expansion =
      1;  // decoded floats + 32-bit indices exceed the 16-bit-index file plus 1 MiB
  Result<Scene> s = DecodeGltfDocument(doc.value(), "large.glb", tight);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.status().code(), StatusCode::kUnsupported);
  EXPECT_NE(s.status().message().find("exceed the limit of 1 bytes per input byte"),
            std::string::npos)
      << s.status().ToString();
}

TEST(GlbHostileTest, DeeplyNestedJsonIsAnErrorNotAStackOverflow) {
  std::string text = R"({"asset":{"version":"2.0"},"extras":)";
  text += std::string(200000, '[') + std::string(200000, ']') + "}";
  Result<Scene> s =
      DecodeGlb(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "deep.gltf");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.status().code(), StatusCode::kParseError);
  EXPECT_NE(s.status().message().find("nests deeper than 256"), std::string::npos)
      << s.status().ToString();
  // 200 levels of extras are fine.
  std::string ok_text = R"({"asset":{"version":"2.0"},"extras":)";
  ok_text += std::string(200, '[') + std::string(200, ']') + "}";
  EXPECT_TRUE(
      DecodeGlb(reinterpret_cast<const uint8_t*>(ok_text.data()), ok_text.size(), "ok.gltf").ok());
  // Brackets inside strings (with escaped quotes) do not count.
  std::string in_string =
      R"({"asset":{"version":"2.0"},"nodes":[{"name":"\")" + std::string(1000, '[') + R"("}]})";
  Result<Scene> named =
      DecodeGlb(reinterpret_cast<const uint8_t*>(in_string.data()), in_string.size(), "s.gltf");
  ASSERT_TRUE(named.ok()) << named.status().ToString();
  EXPECT_EQ(named->nodes[0].name, "\"" + std::string(1000, '['));
  std::string unclosed = std::string(100000, '[');
  Result<Scene> u =
      DecodeGlb(reinterpret_cast<const uint8_t*>(unclosed.data()), unclosed.size(), "deep.gltf");
  ASSERT_FALSE(u.ok());
  EXPECT_EQ(u.status().code(), StatusCode::kParseError);
}

TEST(GlbHostileTest, JsonShapeErrors) {
  for (
      const char* text :
      {"", "null", "[]", "42", R"({"asset":1})", R"({"asset":{"version":2}})",
       R"({"asset":{"version":"2.0"},"meshes":[1]})",
       R"({"asset":{"version":"2.0"},"meshes":[{"primitives":{}}]})",
       R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{}}]}]})",
       R"({"asset":{"version":"2.0"},"nodes":[{"children":[5]}]})",
       R"({"asset":{"version":"2.0"},"nodes":[{"matrix":[1,2]}]})",
       R"({"asset":{"version":"2.0"},"nodes":[{"translation":[1,"x",3]}]})",
       R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4}],"bufferViews":[{"buffer":0,"byteLength":4}],
                               "accessors":[{"bufferView":0,"componentType":5126,"count":1,"type":"SCALAR"}],
                               "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}]})"}) {
    Result<Scene> s =
        DecodeGlb(reinterpret_cast<const uint8_t*>(text), std::strlen(text), "shape.gltf");
    ASSERT_FALSE(s.ok()) << text;
    EXPECT_EQ(s.status().code(), StatusCode::kParseError)
        << text << " -> " << s.status().ToString();
    EXPECT_EQ(s.status().message().rfind("shape.gltf: ", 0), 0u) << s.status().message();
  }
}

TEST(GlbHostileTest, MalformedAnimationsAreErrors) {
  ExpectError(
      DecodeMutated([](json& j) { j["animations"][0]["channels"][0]["target"]["node"] = 99; }),
      StatusCode::kParseError, "node 99 does not exist");
  ExpectError(DecodeMutated([](json& j) { j["animations"][0]["channels"][0]["sampler"] = 7; }),
              StatusCode::kParseError, "sampler 7 does not exist");
  ExpectError(
      DecodeMutated([](json& j) { j["animations"][0]["samplers"][0]["interpolation"] = "SMOOTH"; }),
      StatusCode::kParseError, "interpolation 'SMOOTH'");
  ExpectError(DecodeMutated(
                  [](json& j) { j["animations"][0]["channels"][0]["target"]["path"] = "colour"; }),
              StatusCode::kParseError, "path 'colour'");
  // Key times that go back, and outputs for fewer keys than the times.
  ExpectError(DecodeMutated([](json& j) {
                const int input = j["animations"][0]["samplers"][0]["input"];
                j["accessors"][input]["byteOffset"] = 4;
                j["accessors"][input]["count"] = 2;
              }),
              StatusCode::kParseError, "values for 2 key times");
  ExpectError(DecodeMutated([](json& j) {
                // The rotation's output read as key times: 0, 0, ... is not ascending.
                j["animations"][0]["samplers"][0]["input"] =
                    j["animations"][0]["samplers"][0]["output"];
              }),
              StatusCode::kParseError, "");
}

TEST(GlbHostileTest, AnimationChannelsItCannotKeepAreDroppedWithANote) {
  Result<Scene> s = DecodeMutated([](json& j) {
    json& channels = j["animations"][0]["channels"];
    channels.push_back(channels[1]);  // the same node and path again
    channels[0]["target"]["path"] = "weights";
  });
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  ASSERT_EQ(s->animations.size(), 1u);
  EXPECT_EQ(s->animations[0].channels.size(), 3u);
  // The weights channel of a node without morph targets: its sampler is not read.
  EXPECT_EQ(s->animations[0].samplers.size(), 3u);
  std::string notes;
  for (const std::string& d : s->dropped) notes += d + "\n";
  EXPECT_NE(notes.find("morph-target weights"), std::string::npos) << notes;
  EXPECT_NE(notes.find("repeat a node and path"), std::string::npos) << notes;
}

TEST(GlbHostileTest, AnAnimatedMatrixNodeGetsItsTrsOrLosesItsChannels) {
  // glTF forbids animating a node given as a matrix; files that do it anyway still play.
  Result<Scene> rotated = DecodeMutated(
      [](json& j) { j["nodes"][1]["matrix"] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1}; });
  ASSERT_TRUE(rotated.ok()) << rotated.status().ToString();
  ASSERT_TRUE(rotated->nodes[1].trs.has_value());
  EXPECT_FLOAT_EQ(static_cast<float>(rotated->nodes[1].trs->translation[0]), 3.0f);
  EXPECT_NEAR(rotated->nodes[1].trs->rotation[2], std::sqrt(0.5), 1e-12);
  EXPECT_EQ(rotated->animations[0].channels.size(), 4u);
  Result<Scene> sheared = DecodeMutated([](json& j) {
    j["nodes"][1]["matrix"] = {1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  });
  ASSERT_TRUE(sheared.ok()) << sheared.status().ToString();
  EXPECT_FALSE(sheared->nodes[1].trs.has_value());
  EXPECT_EQ(sheared->animations[0].channels.size(), 3u);
}

TEST(GlbHostileTest, MalformedMaterialFieldsAreErrors) {
  ExpectError(DecodeMutated([](json& j) { j["materials"][0]["alphaMode"] = "CUTOUT"; }),
              StatusCode::kParseError, "alphaMode 'CUTOUT'");
  ExpectError(DecodeMutated([](json& j) { j["materials"][0]["alphaCutoff"] = -1; }),
              StatusCode::kParseError, "alphaCutoff is negative");
  ExpectError(DecodeMutated([](json& j) { j["textures"][0]["sampler"] = 5; }),
              StatusCode::kParseError, "sampler 5 does not exist");
  // Codes glTF does not define fall back to what a viewer would do.
  Result<Scene> s = DecodeMutated([](json& j) {
    j["samplers"][0]["magFilter"] = 1234;
    j["samplers"][0]["wrapS"] = 1;
  });
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->materials[0].base_color_texture.sampler.mag_filter, 0);
  EXPECT_EQ(s->materials[0].base_color_texture.sampler.wrap_s, 10497);
  EXPECT_EQ(s->materials[0].base_color_texture.sampler.min_filter, 9728);
}

}  // namespace
}  // namespace hullpack
