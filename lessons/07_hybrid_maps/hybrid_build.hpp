#pragma once
// The hybrid map's build on the GPU (lesson 07), as OpenGL 4.1 render passes, word for word what
// common/algorithms/hybrid_map computes on the CPU (tests/gpu/test_hybrid_gl.cpp checks it):
//   1. merge sweep   per level k = 1..L a fragment pass over the level-k grid: each texel reads its
//                    2x2 children, writes their mean (merged) or -1 (kept), and its subtree's record
//                    count (shaders/07_hybrid_maps/merge.frag)
//   2. count         above the root level, the counts summed up to one texel: the total (count.frag)
//   3. starts        top down, each texel's first record: a prefix sum over the quadtree (starts.frag)
//   4. root          the root grid's words: leaf depth or pointer (root.frag)
//   5. records       one point per texel of each level, scattered onto its record's texel with its
//                    children's words (records.vert: GL 4.1 has no scattered writes from fragments)
// Between 3 and 4 the total is read back (4 bytes) to size the record texture: the stored map is
// allocated to fit, and its bytes are counted as allocated. The same structure can be uploaded
// from the CPU instead (upload): the CPU path, and a student's sweep.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/hybrid_map.hpp"
#include "gl/program.hpp"
#include "gl/shadow_map.hpp"
#include "gl/timer.hpp"

namespace shadowlab::tech {

// One stored hybrid map on the GPU, and the work textures of its build.
struct HybridMapGpu {
  static constexpr int kRecordRow = 1024;  // records a row of the record texture (HYBRID_RECORD_ROW_BITS)
  struct Level {
    int size = 0;
    gl::Texture values, counts, starts;  // R32F merge grid (levels 1..L), RGBA32UI counts, R32UI starts
  };
  int sourceSize = 0, levels = 0, rootSize = 0, recordRows = 0;
  gl::Texture root, records;  // R32UI rootSize^2; RGBA32UI kRecordRow x recordRows (none without records)
  std::uint32_t recordCount = 0;
  std::array<std::uint32_t, 4> recordsAt{};  // records owned by level-1, 2, 3 texels ([0] unused)
  std::vector<Level> pyramid;                // [0] the source level (no textures), [1..top]
  std::uint64_t workBytes = 0;               // the pyramid's textures: not read by a lookup
  int allocatedSize = 0, allocatedLevels = -1;
  // The stored map as allocated: 4 bytes a root word, 16 a record slot of the record texture.
  std::uint64_t storedBytes() const;
};

class HybridBuilder {
 public:
  explicit HybridBuilder(std::string label = "hybrid map");
  void init();  // programs, the empty vertex array, the framebuffer (GL context current)

  // The sweep and the index from `depth` (a 2D map of size N) into `map`, levels 0..3. Throws
  // std::invalid_argument for levels outside that range or a cube map, std::runtime_error when
  // the records do not fit a texture. Leaves the framebuffer and viewport to the caller. With
  // `timers`, the passes are timed as "hybrid merge", "hybrid index" and "hybrid records", each
  // name followed by `suffix`.
  void build(const gl::ShadowMap& depth, const hybrid::MergeRule& rule, int levels, HybridMapGpu& map,
             gl::GpuTimers* timers = nullptr, const std::string& suffix = "");
  // A map built on the CPU (the CPU path; a student's sweep), uploaded into `map`.
  static void upload(const hybrid::HybridMap& source, HybridMapGpu& map);
  // The stored map read back (tests; the CPU check).
  static hybrid::HybridMap download(const HybridMapGpu& map);
  // A 2D depth map as the passes read it (row 0 at v = 0): through texelFetch, which may convert a
  // 24-bit depth to float one ulp away from what glGetTexImage gives. The CPU path sweeps these,
  // so it sees the very depths the GPU sweeps. (A levels-0 build: its root words are the depths.)
  shadow::DepthMap readDepth(const gl::ShadowMap& depth);

 private:
  void allocate(HybridMapGpu& map, int size, int levels);
  void attach(std::initializer_list<GLuint> colour, int width, int height);
  void sweep(const gl::ShadowMap& depth, const hybrid::MergeRule& rule, HybridMapGpu& map);
  void countAndStarts(HybridMapGpu& map);
  void writeRoot(const gl::ShadowMap& depth, HybridMapGpu& map);
  void writeRecords(const gl::ShadowMap& depth, HybridMapGpu& map);

  std::string label_;
  gl::Program merge_, count_, starts_, rootPass_, recordsPass_;
  gl::VertexArray vao_;
  gl::Framebuffer fbo_;
  gl::Texture dummyUint_;  // bound where a pass reads no counts or starts
  HybridMapGpu scratch_;   // readDepth's levels-0 map
};

}  // namespace shadowlab::tech
